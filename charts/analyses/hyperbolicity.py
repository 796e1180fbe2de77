"""Hyperbolicity test by angles between perturbation subspaces, section 4.

Along one reference trajectory x(t) of eq (8):

1. forward, m = N−2 tangent vectors V (eq 17) are integrated with QR re-orthonormalisation
   at every step; after a transient they span the expanding subspace E_u;
2. backward, m adjoint vectors W (ẇ = −J(x(t))ᵀ w) are integrated in reverse time with
   QR; after a transient they span the orthogonal complement of E_cs, the subspace of zero
   and negative exponents (the pairing ⟨w, ξ⟩ is conserved);
3. at each sample point sin φ = σ_min(WᵀV), φ the smallest angle between E_u and E_cs.

Both bases are orthonormal in the Euclidean product of R^{2N} (the paper's "full" product;
with unequal masses the angle is still well defined, its values depend on the product).

Two variants are computed from the same V and W:

* ``full`` (the paper's): E_cs is taken in all of R^{2N}, so it contains the two
  non-physical directions that break the constraint (δF, δG ≠ 0; zero exponents);
* ``restricted``: everything in the invariant constraint-preserving subspace
  T_r = {ξ : ∇F·ξ = ∇G·ξ = 0}, ∇F = (−sin θ, 0), ∇G = (u cos θ, sin θ): W is projected
  Euclidean-orthogonally onto T_r and re-orthonormalised (the complement of E_cs ∩ T_r in
  T_r is the projection of the complement of E_cs), V lies in T_r already.

Memory: the trajectory is kept only as checkpoints every ``checkpoint_every`` steps; the
backward pass restarts each segment from its checkpoint and integrates eq (8) backward
jointly with the adjoint (over one segment the backward RK4 retraces the forward one to
~1e-13).  The forward vectors are stored only at the S sample points: S·m·2N floats.
"""
from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from math import cos, sin, sqrt

import numpy as np
from numba import njit

from ..flows.ambient import adjoint_rhs, flow_rhs, project_state, project_tangent, project_tangent_sc
from .lyapunov import _initial_state, _rk4_step, orthonormalize

__all__ = ["AngleResult", "hyperbolicity_angles", "hyperbolicity_ensemble", "angle_statistics",
           "SMALL_ANGLE"]

#: threshold of the "near-tangency" fraction reported by `angle_statistics` (rad).
SMALL_ANGLE = 0.05
#: refuse to allocate more than this for the stored forward vectors (bytes).
MAX_STORE = 1 << 30


@njit(cache=True)
def _forward_kernel(y, V, minv, m, speed, dt, nsteps, ck_every, ck, first_sample,
                    sample_every, Vs, w):
    """Forward pass: RK4 of (y, V) with projection onto T_r and QR every step; y stored
    in ck[i] at step i·ck_every (ck[0] = initial); V stored in Vs[k] at step
    first_sample + k·sample_every."""
    n = y.size // 2
    k = V.shape[0]
    s = np.empty(n)
    c = np.empty(n)
    ky = np.empty((4, 2 * n))
    kX = np.empty((4, k, 2 * n))
    yt = np.empty(2 * n)
    Xt = np.empty((k, 2 * n))
    logs = np.zeros(k)
    ck[0] = y
    for step in range(1, nsteps + 1):
        _rk4_step(y, V, minv, dt, s, c, ky, kX, yt, Xt)
        if step % 100 == 0:
            project_state(y, m, speed)
        for j in range(n):
            s[j] = sin(y[j])
            c[j] = cos(y[j])
        project_tangent_sc(y, V, minv, s, c)
        orthonormalize(V, w, logs)
        if step % ck_every == 0:
            ck[step // ck_every] = y
        j = step - first_sample
        if j >= 0 and j % sample_every == 0 and j // sample_every < Vs.shape[0]:
            Vs[j // sample_every] = V
    return logs


@njit(cache=True)
def _adjoint_rk4(y, W, minv, h, k1, k2, k3, k4, K1, K2, K3, K4, yt, Wt):
    d = y.size
    r_ = W.shape[0]
    flow_rhs(y, minv, k1)
    adjoint_rhs(y, W, minv, K1)
    for st in range(3):
        a = 0.5 * h if st < 2 else h
        ka = k1 if st == 0 else (k2 if st == 1 else k3)
        Ka = K1 if st == 0 else (K2 if st == 1 else K3)
        for i in range(d):
            yt[i] = y[i] + a * ka[i]
        for r in range(r_):
            for i in range(d):
                Wt[r, i] = W[r, i] + a * Ka[r, i]
        if st == 0:
            flow_rhs(yt, minv, k2)
            adjoint_rhs(yt, Wt, minv, K2)
        elif st == 1:
            flow_rhs(yt, minv, k3)
            adjoint_rhs(yt, Wt, minv, K3)
        else:
            flow_rhs(yt, minv, k4)
            adjoint_rhs(yt, Wt, minv, K4)
    h6 = h / 6.0
    for i in range(d):
        y[i] += h6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
    for r in range(r_):
        for i in range(d):
            W[r, i] += h6 * (K1[r, i] + 2.0 * K2[r, i] + 2.0 * K3[r, i] + K4[r, i])


@njit(cache=True)
def _project_tr(y, W):
    """Euclidean-orthogonal projection of the rows of W onto T_r at y."""
    n = y.size // 2
    a = np.zeros(2 * n)  # ∇F (sign irrelevant)
    b = np.zeros(2 * n)  # ∇G
    for i in range(n):
        a[i] = sin(y[i])
        b[i] = y[n + i] * cos(y[i])
        b[n + i] = sin(y[i])
    aa = 0.0
    ab = 0.0
    bb = 0.0
    for i in range(2 * n):
        aa += a[i] * a[i]
        ab += a[i] * b[i]
        bb += b[i] * b[i]
    det = aa * bb - ab * ab
    for r in range(W.shape[0]):
        wa = 0.0
        wb = 0.0
        for i in range(2 * n):
            wa += W[r, i] * a[i]
            wb += W[r, i] * b[i]
        ca = (bb * wa - ab * wb) / det
        cb = (aa * wb - ab * wa) / det
        for i in range(2 * n):
            W[r, i] -= ca * a[i] + cb * b[i]


@njit(cache=True)
def _backward_kernel(ck, W, minv, dt, ck_every, first_sample, sample_every, Vs, Mf, Mr, w):
    """Backward pass over all segments (last first); at sample steps store
    Mf[k] = W Vs[k]ᵀ (full) and Mr[k] = W_r Vs[k]ᵀ (restricted)."""
    d = ck.shape[1]
    kk = W.shape[0]
    k1 = np.empty(d)
    k2 = np.empty(d)
    k3 = np.empty(d)
    k4 = np.empty(d)
    K1 = np.empty((kk, d))
    K2 = np.empty((kk, d))
    K3 = np.empty((kk, d))
    K4 = np.empty((kk, d))
    yt = np.empty(d)
    Wt = np.empty((kk, d))
    Wr = np.empty((kk, d))
    logs = np.zeros(kk)
    nseg = ck.shape[0] - 1
    S = Vs.shape[0]
    y = np.empty(d)
    for seg in range(nseg - 1, -1, -1):
        y[:] = ck[seg + 1]
        for jj in range(ck_every):
            _adjoint_rk4(y, W, minv, -dt, k1, k2, k3, k4, K1, K2, K3, K4, yt, Wt)
            orthonormalize(W, w, logs)
            step = (seg + 1) * ck_every - jj - 1
            j = step - first_sample
            if j >= 0 and j % sample_every == 0 and j // sample_every < S:
                q = j // sample_every
                Wr[:, :] = W
                _project_tr(y, Wr)
                orthonormalize(Wr, w, np.zeros(kk))
                for r in range(kk):
                    for s_ in range(kk):
                        af = 0.0
                        ar = 0.0
                        for i in range(d):
                            af += W[r, i] * Vs[q, s_, i]
                            ar += Wr[r, i] * Vs[q, s_, i]
                        Mf[q, r, s_] = af
                        Mr[q, r, s_] = ar
    return logs


@dataclass
class AngleResult:
    """Angles φ (rad) between E_u and E_cs at the S sample points.

    t : (S,) sample times; phi_full, phi_restricted : (S,) the two variants;
    forward_exponents, adjoint_exponents : (m,) growth rates seen by V and (backward) W,
    a check that both passes converged to the expanding subspaces.
    """
    t: np.ndarray
    phi_full: np.ndarray
    phi_restricted: np.ndarray
    forward_exponents: np.ndarray
    adjoint_exponents: np.ndarray
    params: dict

    def statistics(self, variant="restricted", small=SMALL_ANGLE):
        return angle_statistics(self.phi_restricted if variant == "restricted" else self.phi_full,
                                small)


def angle_statistics(phi, small=SMALL_ANGLE):
    """dict(min, fraction below ``small`` rad, percentiles 0.1 % and 1 %, sample size)."""
    phi = np.asarray(phi)
    return dict(min=float(phi.min()), frac_small=float((phi < small).mean()),
                p001=float(np.percentile(phi, 0.1)), p01=float(np.percentile(phi, 1)),
                median=float(np.median(phi)), n=int(phi.size), small=small)


def _sin_to_angle(M):
    sv = np.linalg.svd(M, compute_uv=False)[:, -1]
    return np.arcsin(np.clip(sv, 0.0, 1.0))


def hyperbolicity_angles(system, theta0, u0, t_final, *, dt=0.01, n_unstable=None,
                         t_transient=100.0, sample_every=10, checkpoint_every=100, seed=0):
    """Angles between the expanding subspace and the zero-and-contracting subspace along
    the trajectory from (theta0, u0), both variants (see module docstring).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
    t_final : float
        Length of the analysed window; the trajectory runs t_transient + t_final +
        t_transient so that V (forward) and W (backward) converge before it.
    dt : float
        RK4 step of both passes.
    n_unstable : int, optional
        m, the dimension of E_u (default N−2, the number of positive exponents).
    sample_every : int
        Steps between sample points (memory S·m·2N·8 bytes for the forward vectors).
    checkpoint_every : int
        Steps between stored trajectory checkpoints.

    Returns
    -------
    AngleResult
    """
    n = system.n
    m = n - 2 if n_unstable is None else int(n_unstable)
    if not 1 <= m <= n - 2:
        raise ValueError(f"n_unstable must be in 1..{n - 2} (the positive exponents), got {m}")
    y, speed = _initial_state(system, theta0, u0)
    n_tr = int(round(t_transient / dt))
    n_win = int(round(t_final / dt))
    S = n_win // int(sample_every)
    if S < 1:
        raise ValueError(f"t_final={t_final} holds no sample; increase it or lower sample_every")
    need = S * m * 2 * n * 8
    if need > MAX_STORE:
        raise ValueError(f"storing {S} samples needs {need / 2**20:.0f} MB; increase sample_every "
                         f"or split t_final into several runs")
    ce = int(checkpoint_every)
    nseg = -(-(2 * n_tr + n_win) // ce)
    nsteps = nseg * ce
    w = np.ones(2 * n)
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(m, 2 * n))
    project_tangent(y, V, system.minv)
    orthonormalize(V, w, np.zeros(m))
    ck = np.empty((nseg + 1, 2 * n))
    Vs = np.empty((S, m, 2 * n))
    flog = _forward_kernel(y, V, system.minv, system.masses, speed, float(dt), nsteps, ce, ck,
                           n_tr, int(sample_every), Vs, w)
    W = rng.normal(size=(m, 2 * n))
    orthonormalize(W, w, np.zeros(m))
    Mf = np.empty((S, m, m))
    Mr = np.empty((S, m, m))
    blog = _backward_kernel(ck, W, system.minv, float(dt), ce, n_tr, int(sample_every), Vs,
                            Mf, Mr, w)
    T = nsteps * dt
    t = (n_tr + np.arange(S) * sample_every) * dt
    params = dict(n=n, masses=system.masses.tolist(), dt=dt, m=m, t_final=t_final,
                  t_transient=t_transient, sample_every=sample_every, speed=speed,
                  checkpoint_every=ce, seed=seed)
    return AngleResult(t, _sin_to_angle(Mf), _sin_to_angle(Mr), flog / T, blog / T, params)


def _member(args):
    n, masses, seed, t_final, kwargs = args
    from ..geometry.system import RotorSystem
    system = RotorSystem(n, masses)
    theta0, u0 = system.random_state(seed=seed)
    return hyperbolicity_angles(system, theta0, u0, t_final, seed=seed, **kwargs)


def hyperbolicity_ensemble(system, n_trajectories, t_final, *, seed=0, workers=None, **kwargs):
    """`hyperbolicity_angles` on independent random states in parallel processes; returns
    the list of `AngleResult` (concatenate the angles for statistics)."""
    jobs = [(system.n, system.masses, seed + i, t_final, kwargs) for i in range(n_trajectories)]
    if workers == 1:
        return [_member(j) for j in jobs]
    with ProcessPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(_member, jobs))
