"""Lyapunov spectra of the geodesic flow, section 2 (eqs 8, 17, 18), with masses.

The reference trajectory y = (θ, u), shape (2N,), and k tangent vectors X, shape
(k, 2N), are advanced together by one fused RK4 kernel (sin/cos of each stage shared
between eq (8) and the variational eq (17), no allocation inside the loop).  Every
``reorth_every`` steps the rows of X are re-orthonormalised by modified Gram–Schmidt
(eq 18) in a weighted inner product

    ⟨a, b⟩ = Σ mᵢ aᵢ bᵢ  (θ-parts)  +  w_u Σ mᵢ a_{N+i} b_{N+i}  (u-parts),

``inner="theta"`` (w_u = 0, the paper's choice) or ``inner="full"`` (w_u = 1), and the
logarithms of the norms are accumulated.

Phase space.  Eq (8) lives in R^{2N} but the physical phase space is the tangent bundle
of the (N−1)-manifold: F = Σcos θ = 0 and G = Σ u sin θ = 0.  G is a first integral and
Ḟ = −G, so the subspace T_r = {ξ : δF(ξ) = δG(ξ) = 0} of dimension 2N−2 is invariant
under eq (17); the two directions outside it (δF, δG ≠ 0) carry two *non-physical* zero
exponents (δG is conserved, δF grows linearly).  ``space="restricted"`` (default) keeps
the vectors in T_r (projected at every re-orthonormalisation), so all 2N−2 computed
exponents are physical; ``space="full"`` does not, and up to 2N exponents can be
computed (the two extra zeros are then identified by `identify_nonphysical`).

Error bars are batch means: the time after the transient is cut into ``n_batches``
equal blocks, each block gives an estimate of every exponent, and the standard error
is std(blocks)/√n_batches (two-sided).  `lyapunov_ensemble` instead runs independent
trajectories in parallel processes and uses their spread.
"""
from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from math import cos, log, sin, sqrt

import numpy as np
from numba import njit

from ..flows.ambient import project_state, project_tangent, project_tangent_sc

__all__ = ["LyapunovResult", "lyapunov_spectrum", "lyapunov_ensemble", "reconstruct_spectrum",
           "identify_nonphysical", "advance_tangent", "orthonormalize", "inner_weights"]


# ----------------------------------------------------------------------------- kernels
@njit(cache=True, inline="always")
def _stage(y, X, minv, s, c, dy, dX):
    """dy = eq (8)(y), dX[r] = eq (17)(y, X[r]); s, c are scratch (N,) for sin/cos."""
    n = y.size // 2
    A = 0.0
    B = 0.0
    for j in range(n):
        sj = sin(y[j])
        cj = cos(y[j])
        s[j] = sj
        c[j] = cj
        A += y[n + j] * y[n + j] * cj
        B += sj * sj * minv[j]
    lam = A / B
    for i in range(n):
        dy[i] = y[n + i]
        dy[n + i] = -lam * s[i] * minv[i]
    for r in range(X.shape[0]):
        dA = 0.0
        dB = 0.0
        for j in range(n):
            u = y[n + j]
            dA += 2.0 * u * X[r, n + j] * c[j] - u * u * s[j] * X[r, j]
            dB += 2.0 * s[j] * c[j] * X[r, j] * minv[j]
        dlam = (dA - lam * dB) / B
        for i in range(n):
            dX[r, i] = X[r, n + i]
            dX[r, n + i] = -(dlam * s[i] + lam * c[i] * X[r, i]) * minv[i]


@njit(cache=True)
def _rk4_step(y, X, minv, h, s, c, ky, kX, yt, Xt):
    """One classical RK4 step of (eq 8, eq 17) in place; ky (4, 2N), kX (4, k, 2N) scratch."""
    d = y.size
    k = X.shape[0]
    _stage(y, X, minv, s, c, ky[0], kX[0])
    for st in range(1, 4):
        a = 0.5 * h if st < 3 else h
        for i in range(d):
            yt[i] = y[i] + a * ky[st - 1, i]
        for r in range(k):
            for i in range(d):
                Xt[r, i] = X[r, i] + a * kX[st - 1, r, i]
        _stage(yt, Xt, minv, s, c, ky[st], kX[st])
    h6 = h / 6.0
    for i in range(d):
        y[i] += h6 * (ky[0, i] + 2.0 * ky[1, i] + 2.0 * ky[2, i] + ky[3, i])
    for r in range(k):
        for i in range(d):
            X[r, i] += h6 * (kX[0, r, i] + 2.0 * kX[1, r, i] + 2.0 * kX[2, r, i] + kX[3, r, i])


@njit(cache=True)
def orthonormalize(X, w, logs):
    """Modified Gram–Schmidt (eq 18) of the rows of X in ⟨a, b⟩ = Σ wᵢ aᵢ bᵢ, in place;
    logs[r] += log of the r-th norm."""
    k, d = X.shape
    for r in range(k):
        for q in range(r):
            p = 0.0
            for i in range(d):
                p += w[i] * X[r, i] * X[q, i]
            for i in range(d):
                X[r, i] -= p * X[q, i]
        nrm = 0.0
        for i in range(d):
            nrm += w[i] * X[r, i] * X[r, i]
        nrm = sqrt(nrm)
        logs[r] += log(nrm)
        for i in range(d):
            X[r, i] /= nrm


#: |δ| up to which sin/cos(θ + δ) (RK4 stages 2–4, and the new θ from the old) come from
#: the angle-addition formula with the Taylor polynomials below instead of libm (beyond
#: it: libm).  At |δ| = 0.05 the first omitted terms, δ¹¹/11! (relative to sin δ ≈ δ:
#: 2.4e-21) and δ¹⁰/10! (2.7e-20), are far below an ulp, so the polynomials are exact to
#: rounding; the shifts are |δ| ≤ dt·|u| ≈ 0.01 at unit speed and dt = 0.01.
_SHIFT_MAX = 0.05
_S = (-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0)
_C = (-0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0)


@njit(cache=True)
def _lyap_kernel(y, X, minv, m, speed, dt, nsteps, reorth_every, w, restricted,
                 project_every, rec_every, logsum, hist):
    """Advance (y, X) by ``nsteps`` RK4 steps; every ``reorth_every`` steps project X onto
    T_r (if ``restricted``) and re-orthonormalise, adding log-norms to ``logsum``; every
    ``rec_every`` steps copy ``logsum`` into the next row of ``hist``.

    The time loop is written out in one function on purpose: every array-valued call or
    view inside it costs two atomic reference-count updates per array (a first rewrite
    with stage helpers taking views spent over half of its time on them); only the
    projections and eq (18), every ``reorth_every`` / ``project_every`` steps, are calls.
    See docs/performance.md for the profile.

    Per step:
      * State and vectors are stacked in Z = [y; X], shape (1+k, 2N), so the RK4
        combinations run over one contiguous (1+k)·2N buffer.
      * Eq (8) at stage point Zt[0] and eq (17) at Zt[1:] share sin/cos and the factors
        fᵢ = sᵢ/mᵢ, gᵢ = λcᵢ/mᵢ, pᵢ = 2uᵢcᵢ, qᵢ = sᵢ(uᵢ² + 2gᵢ), so that eq (17) reads
        δλ = Σ(pⱼũⱼ − qⱼθ̃ⱼ)/B, dθ̃ᵢ/dt = ũᵢ, dũᵢ/dt = −(δλ fᵢ + gᵢθ̃ᵢ) (= `_stage` to rounding).
      * sin/cos of stage 1 are those of the step's start, s0, c0 (kept from the end of
        the previous step); stages 2–4 are θ + δ with δ = a·θ̇ small, and take
        sin(θ+δ) = s0 + (s0 (cos δ − 1) + c0 sin δ) with degree-9/8 Taylor polynomials
        (a few ulp from libm; libm where |δ| > _SHIFT_MAX), and so do those of the new θ
        from the old (δ = θ_new − θ_old), refreshed from libm after each projection of y,
        every ``project_every`` steps: 1 libm sin/cos pair per angle per 100 steps, not 4
        per step.  (libm at every stage instead: 2× the cost per step, same exponents.)
    """
    n = y.size // 2
    d = 2 * n
    k = X.shape[0]
    R = 1 + k
    L = R * d
    Z = np.empty((R, d))
    for i in range(d):          # explicit loops: a slice assignment would compile Numba's
        Z[0, i] = y[i]          # shape-mismatch error message (string formatting), which
        for r in range(k):      # was 40 % of this kernel's first-ever compile time
            Z[1 + r, i] = X[r, i]
    Zt = np.empty((R, d))
    K = np.empty((4, R, d))
    Zf = Z.reshape(L)
    Ztf = Zt.reshape(L)
    Kf = K.reshape((4, L))
    y_ = Z[0]
    X_ = Z[1:]
    th = np.empty(n)
    s0 = np.empty(n)
    c0 = np.empty(n)
    s = np.empty(n)
    c = np.empty(n)
    f = np.empty(n)
    g = np.empty(n)
    p = np.empty(n)
    q = np.empty(n)
    for j in range(n):
        s0[j] = sin(Z[0, j])
        c0[j] = cos(Z[0, j])
    h = dt
    h6 = h / 6.0
    row = 0
    to_proj = project_every
    to_reorth = reorth_every
    to_rec = rec_every
    for _ in range(nsteps):
        for st in range(4):
            # ---- stage point Zt and its sin/cos s, c
            if st == 0:
                for i in range(L):
                    Ztf[i] = Zf[i]
                for j in range(n):
                    s[j] = s0[j]
                    c[j] = c0[j]
            else:
                a = 0.5 * h if st < 3 else h
                for i in range(L):
                    Ztf[i] = Zf[i] + a * Kf[st - 1, i]
                for j in range(n):
                    dl = a * K[st - 1, 0, j]
                    d2 = dl * dl
                    sd = dl + dl * d2 * (_S[0] + d2 * (_S[1] + d2 * (_S[2] + d2 * _S[3])))
                    cm = d2 * (_C[0] + d2 * (_C[1] + d2 * (_C[2] + d2 * _C[3])))
                    s[j] = s0[j] + (s0[j] * cm + c0[j] * sd)
                    c[j] = c0[j] + (c0[j] * cm - s0[j] * sd)
                for j in range(n):
                    if abs(a * K[st - 1, 0, j]) > _SHIFT_MAX:
                        s[j] = sin(Zt[0, j])
                        c[j] = cos(Zt[0, j])
            # ---- eq (8) into K[st, 0], eq (17) into K[st, 1:]
            A = 0.0
            B = 0.0
            for j in range(n):
                u = Zt[0, n + j]
                A += u * u * c[j]
                B += s[j] * s[j] * minv[j]
            iB = 1.0 / B
            lam = A * iB
            for j in range(n):
                u = Zt[0, n + j]
                f[j] = s[j] * minv[j]
                g[j] = lam * c[j] * minv[j]
                p[j] = 2.0 * u * c[j]
                q[j] = s[j] * (u * u + 2.0 * g[j])
                K[st, 0, j] = u
                K[st, 0, n + j] = -lam * f[j]
            for r in range(1, R):
                acc = 0.0
                for j in range(n):
                    acc += p[j] * Zt[r, n + j] - q[j] * Zt[r, j]
                dlam = acc * iB
                for i in range(n):
                    K[st, r, i] = Zt[r, n + i]
                    K[st, r, n + i] = -(dlam * f[i] + g[i] * Zt[r, i])
        for j in range(n):
            th[j] = Z[0, j]
        for i in range(L):
            Zf[i] += h6 * (Kf[0, i] + 2.0 * Kf[1, i] + 2.0 * Kf[2, i] + Kf[3, i])
        # ---- sin/cos of the new θ: shifted by δ = θ_new − θ_old, libm after projections
        to_proj -= 1
        if to_proj == 0:
            to_proj = project_every
            project_state(y_, m, speed)
            for j in range(n):
                s0[j] = sin(Z[0, j])
                c0[j] = cos(Z[0, j])
        else:
            for j in range(n):
                dl = Z[0, j] - th[j]
                d2 = dl * dl
                sd = dl + dl * d2 * (_S[0] + d2 * (_S[1] + d2 * (_S[2] + d2 * _S[3])))
                cm = d2 * (_C[0] + d2 * (_C[1] + d2 * (_C[2] + d2 * _C[3])))
                sj = s0[j]
                s0[j] = sj + (sj * cm + c0[j] * sd)
                c0[j] = c0[j] + (c0[j] * cm - sj * sd)
            for j in range(n):
                if abs(Z[0, j] - th[j]) > _SHIFT_MAX:
                    s0[j] = sin(Z[0, j])
                    c0[j] = cos(Z[0, j])
        # ---- projection of X and re-orthonormalisation (eq 18)
        to_reorth -= 1
        if to_reorth == 0:
            to_reorth = reorth_every
            if restricted:
                project_tangent_sc(y_, X_, minv, s0, c0)
            orthonormalize(X_, w, logsum)
        if rec_every > 0:
            to_rec -= 1
            if to_rec == 0:
                to_rec = rec_every
                if row < hist.shape[0]:
                    for r in range(k):
                        hist[row, r] = logsum[r]
                    row += 1
    for i in range(d):
        y[i] = Z[0, i]
        for r in range(k):
            X[r, i] = Z[1 + r, i]


# ----------------------------------------------------------------------------- helpers
def inner_weights(system, inner):
    """Weights w, shape (2N,), of the tangent inner product Σ wᵢ aᵢ bᵢ (see module doc)."""
    if inner == "theta":
        return np.concatenate([system.masses, np.zeros(system.n)])
    if inner == "full":
        return np.concatenate([system.masses, system.masses])
    raise ValueError(f"inner must be 'theta' (the paper's θ-only product) or 'full', got {inner!r}")


def _initial_state(system, theta0, u0):
    theta0, u0 = system.check_state(theta0, u0)
    speed = float(system.speed(u0))
    if not speed > 0:
        raise ValueError("u0 is zero: the geodesic flow needs a nonzero speed")
    return np.concatenate([theta0, u0]).astype(float), speed


def _initial_vectors(system, y, k, seed, restricted, w):
    rng = np.random.default_rng(seed)
    X = rng.normal(size=(k, 2 * system.n))
    if restricted:
        project_tangent(y, X, system.minv)
    orthonormalize(X, w, np.zeros(k))
    return X


def advance_tangent(system, y, X, t, *, dt=0.01, inner="theta", space="restricted",
                    reorth_every=1, project_every=100, logsum=None):
    """Advance state y, shape (2N,), and tangent vectors X, shape (k, 2N), in place by
    time t (a whole number of steps dt) with re-orthonormalisation; returns the updated
    log-norm sums, shape (k,)."""
    nsteps = int(round(t / dt))
    w = inner_weights(system, inner)
    logsum = np.zeros(X.shape[0]) if logsum is None else logsum
    speed = float(np.sqrt(np.sum(system.masses * y[system.n:] ** 2)))
    _lyap_kernel(y, X, system.minv, system.masses, speed, float(dt), nsteps, int(reorth_every),
                 w, space == "restricted", int(project_every), 0, logsum, np.empty((0, X.shape[0])))
    return logsum


def reconstruct_spectrum(leading):
    """Full relevant spectrum of 2N−2 exponents from the leading N−2 (section 2: pairs
    ±λ from time reversibility and the symplectic structure, and two zeros: the flow
    direction and the energy shift)."""
    leading = np.asarray(leading, dtype=float)
    return np.concatenate([leading, [0.0, 0.0], -leading[::-1]])


def identify_nonphysical(system, theta, u, X):
    """Fraction of each row of X, shape (k, 2N), lying outside the constraint-preserving
    subspace T_r (1 − |P_r x|/|x| in the Euclidean norm): ≈ 1 for the non-physical
    directions, ≈ 0 for physical ones."""
    y = np.concatenate([theta, u])
    Xp = np.array(X, dtype=float)
    project_tangent(y, Xp, system.minv)
    return 1.0 - np.linalg.norm(Xp, axis=1) / np.linalg.norm(X, axis=1)


# ----------------------------------------------------------------------------- results
@dataclass
class LyapunovResult:
    """Result of `lyapunov_spectrum`.

    exponents : (k,)  the computed exponents, largest first.
    stderr : (k,)  two-sided standard errors (batch means or ensemble spread).
    spectrum : (2N−2,)  the relevant spectrum: reconstructed from the leading N−2
        (pairs ±λ and two zeros) if only those were computed, else the computed values.
    history_t : (n_rec,)  times (after the transient) of the convergence history.
    history : (n_rec, k)  running estimates of the exponents at ``history_t``.
    batches : (n_batches, k)  per-block estimates behind ``stderr``.
    """
    exponents: np.ndarray
    stderr: np.ndarray
    spectrum: np.ndarray
    history_t: np.ndarray
    history: np.ndarray
    batches: np.ndarray
    params: dict = field(default_factory=dict)

    def __repr__(self):
        pm = ", ".join(f"{e:.4f}±{s:.4f}" for e, s in zip(self.exponents, self.stderr))
        return f"LyapunovResult([{pm}], T={self.params.get('t_final')})"


def lyapunov_spectrum(system, theta0, u0, t_final, *, dt=0.01, n_exponents=None,
                      inner="theta", space="restricted", t_transient=50.0, n_batches=20,
                      reorth_every=10, project_every=100, record_every=1.0, seed=0,
                      progress=False):
    """Lyapunov exponents of eq (8) along the trajectory from (theta0, u0), eqs (17)-(18).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
        Initial point on the manifold and tangent velocity; the exponents scale with
        the speed |u0| = √(Σ mᵢ u0ᵢ²) (the paper uses unit speed).
    t_final : float
        Averaging time after the transient.
    dt : float
        RK4 step.
    n_exponents : int, optional
        Number of exponents (default N−2, the leading ones; at most 2N−2 in the
        restricted space, 2N in the full space, N−1 with ``inner='theta'``).
    inner : {'theta', 'full'}
        Inner product of eq (18): θ-parts only (the paper's) or θ- and u-parts.
    space : {'restricted', 'full'}
        Keep the tangent vectors in the constraint-preserving subspace T_r, or not.
    t_transient : float
        Time discarded first so that the vectors align with the Lyapunov vectors.
    n_batches : int
        Number of blocks for the batch-means standard error.
    reorth_every, project_every : int
        Steps between re-orthonormalisations and between projections of y onto the
        manifold.  The trajectory does not depend on ``reorth_every``, and the log-norm
        sums of eq (18) telescope, so every 10 steps (default) gives the exponents of
        every step to ~1e-10 (tests/test_lyapunov.py) at a quarter less cost.
    record_every : float
        Time between rows of the convergence history.

    Returns
    -------
    LyapunovResult
    """
    n = system.n
    k = n - 2 if n_exponents is None else int(n_exponents)
    kmax = {"restricted": 2 * n - 2, "full": 2 * n}.get(space)
    if kmax is None:
        raise ValueError(f"space must be 'restricted' or 'full', got {space!r}")
    if inner == "theta":
        kmax = min(kmax, n - 1 if space == "restricted" else n)
    if not 1 <= k <= kmax:
        raise ValueError(f"n_exponents={k} is out of range 1..{kmax} for inner={inner!r}, "
                         f"space={space!r}; use inner='full' for more than N−1 exponents")
    if n_batches < 2:
        raise ValueError("n_batches must be >= 2 to estimate a standard error")
    y, speed = _initial_state(system, theta0, u0)
    w = inner_weights(system, inner)
    restricted = space == "restricted"
    X = _initial_vectors(system, y, k, seed, restricted, w)
    args = (system.minv, system.masses, speed, float(dt))
    if t_transient > 0:
        _lyap_kernel(y, X, *args, int(round(t_transient / dt)), int(reorth_every), w, restricted,
                     int(project_every), 0, np.zeros(k), np.empty((0, k)))
    rec = max(1, int(round(record_every / dt)))
    rec = max(int(reorth_every), rec // int(reorth_every) * int(reorth_every))
    nrec = int(round(t_final / dt)) // rec
    nrec -= nrec % n_batches
    if nrec < n_batches:
        raise ValueError(f"t_final={t_final} is too short for {n_batches} batches of "
                         f"record_every={record_every}; increase t_final")
    hist = np.empty((nrec, k))
    logsum = np.zeros(k)
    chunks = np.array_split(np.arange(nrec), min(nrec, 100))
    bar = None
    if progress:
        from tqdm.auto import tqdm
        bar = tqdm(total=nrec * rec * dt, desc=f"Lyapunov N={n}", unit="t", leave=False)
    for ch in chunks:
        sub = np.empty((ch.size, k))
        _lyap_kernel(y, X, *args, ch.size * rec, int(reorth_every), w, restricted,
                     int(project_every), rec, logsum, sub)
        hist[ch] = sub
        if bar is not None:
            bar.update(ch.size * rec * dt)
    if bar is not None:
        bar.close()
    t_rec = np.arange(1, nrec + 1) * rec * dt
    running = hist / t_rec[:, None]
    per = nrec // n_batches
    ends = hist[per - 1::per]
    starts = np.vstack([np.zeros((1, k)), ends[:-1]])
    batches = (ends - starts) / (per * rec * dt)
    exps = hist[-1] / t_rec[-1]
    stderr = batches.std(axis=0, ddof=1) / np.sqrt(n_batches)
    if restricted and k == 2 * n - 2:
        spectrum = exps.copy()
    else:
        spectrum = reconstruct_spectrum(exps[: n - 2]) if k >= n - 2 else None
    params = dict(n=n, masses=system.masses.tolist(), t_final=float(t_rec[-1]), dt=dt,
                  inner=inner, space=space, t_transient=t_transient, n_batches=n_batches,
                  reorth_every=reorth_every, speed=speed, seed=seed)
    return LyapunovResult(exps, stderr, spectrum, t_rec, running, batches, params)


def _ensemble_member(args):
    n, masses, seed, speed, t_final, kwargs = args
    from ..geometry.system import RotorSystem
    system = RotorSystem(n, masses)
    theta0, u0 = system.random_state(seed=seed, speed=speed)
    return lyapunov_spectrum(system, theta0, u0, t_final, seed=seed, **kwargs)


def lyapunov_ensemble(system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                      progress=False, **kwargs):
    """Exponents from ``n_trajectories`` independent random initial states (seeds
    seed, seed+1, …), run in parallel processes (``workers``; default all cores).

    Returns (mean, stderr, members): mean and two-sided standard error over the
    trajectories, shape (k,), and the list of `LyapunovResult`."""
    if n_trajectories < 2:
        raise ValueError("n_trajectories must be >= 2 to estimate a standard error")
    jobs = [(system.n, system.masses, seed + i, speed, t_final, kwargs)
            for i in range(n_trajectories)]
    if workers == 1:
        members = [_ensemble_member(j) for j in jobs]
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            it = pool.map(_ensemble_member, jobs)
            if progress:
                from tqdm.auto import tqdm
                it = tqdm(it, total=len(jobs), desc=f"Lyapunov N={system.n} ensemble", leave=False)
            members = list(it)
    E = np.array([r.exponents for r in members])
    return E.mean(axis=0), E.std(axis=0, ddof=1) / np.sqrt(n_trajectories), members
