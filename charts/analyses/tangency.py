"""The closest passage of E_u to E_cs resolved at every step, and the orientation of the
splitting: an invariant of each orbit (section 4; docs/families-study.md).

The oriented volume

    V(t) = det[Q_u, Q_cs, a, b] / |a ∧ b|,

Q_u, Q_cs orthonormal bases of E_u = span(v¹…vᵐ) and E_cs = span(vᵐ⁺¹…v^D) (the covariant
Lyapunov vectors of ``charts.analyses.covariant`` in T_r, each group orthonormalised by
Gram–Schmidt, which keeps its orientation), a, b the normals of T_r
(``charts.geometry.projection.constraint_normals``), has |V| = the product of the sines of
the principal angles between E_u and E_cs, so |V| ≤ sin φ, φ the angle of the test.

**Its sign cannot change along an orbit**, for two reasons.  Dynamically: E_u and E_cs are
invariant, E(t) = M(t) E(0), M(t) the linearised flow (eq 17), and the computed bases are
the transported ones times triangular factors with positive diagonals (Gram–Schmidt,
Ginelli's positive column scalings), so V(t) = det M(t)·V(0)·(positive factors) with
det M(t) > 0 (M is continuous from the identity and invertible): a tangency at one time
would be a tangency along the whole orbit.  By construction: the CLVs are v = Q C with Q the
Gram–Schmidt basis of T_r and C upper triangular with a positive diagonal, so sign V =
sign det[Q, a, b], which never vanishes.  A sign change of V between samples of one orbit
can therefore only be rounding where |V| ≈ 10⁻¹⁶, and a certificate of a tangency by a sign
change along one orbit is impossible (docs/families-study.md).  (The sign is a convention of the
run, set by its random initial vectors: two runs of one orbit may differ in it.)

What can be resolved is the closest passage itself: `closest_passage` finds it in a scan and
samples it at every step, again with the step halved and with the transients halved, so that
the resolved minimum carries its numerical uncertainty.  The resolved runs restart from the
scan's states; a restart follows the scan's orbit to rounding amplified by e^{λ₁t}, so the
reference's transient can be at most some fifteen Lyapunov times (40 time units at N = 4)
before the window lies on another orbit — the report gives that difference.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..geometry.checks import finite_array, integer
from ..geometry.projection import normals_of
from ..geometry.system import plane_area2
from ..geometry.topology import check_weights
from ..solvers.tangent import TangentFlow
from .arguments import positive_time, start_state
from .covariant import covariant_lyapunov_vectors

__all__ = ["oriented_volume", "sign_changes", "closest_passage", "ClosestPassage",
           "ResolvedWindow"]


def _oriented_basis(V):
    """Orthonormal columns spanning the columns of V (2N, k), with the orientation of V
    (QR with a positive diagonal: Gram–Schmidt)."""
    Q, R = np.linalg.qr(V)
    return Q * np.sign(np.diag(R))


def oriented_volume(vectors, m, states, weights):
    """V(t) of the module docstring at each sample: ``vectors`` (S, D, 2N) the CLVs of the
    restricted variant (D = 2N − 2, unit, largest exponent first), ``m`` the dimension of
    E_u, ``states`` (S, 2N), ``weights`` the constraint's weights.  Returns (S,), finite.

    Degenerate input: CLVs that do not span their space (a zero vector, or E_u and E_cs
    sharing a direction: a tangency) have V = 0, the volume of the parallelotope they span;
    a state where the normals a, b of T_r are dependent (a singular point of the manifold,
    every sin θᵢ = 0, where T_r is not defined) is refused with a ValueError naming the
    sample, as is non-finite or mis-shaped input: V is never NaN."""
    vectors = finite_array("vectors", vectors, ndim=3)
    S, D, d = vectors.shape
    m = integer("m", m)
    if D != d - 2 or not 0 < m < D:
        raise ValueError(f"oriented_volume needs the {d - 2} CLVs of the restricted variant "
                         f"(T_r) and 0 < m < {d - 2}; got {D} vectors, m = {m}")
    states = finite_array("states", states, shape=(S, d))
    weights = check_weights(weights, d // 2)
    out = np.empty(S)
    for j in range(S):
        a, b = normals_of(np.ascontiguousarray(states[j]), weights)
        try:
            area2 = plane_area2(a @ a, b @ b, a @ b)
        except ValueError:
            raise ValueError(f"states[{j}] is a singular point of the manifold: the normals "
                             "a = grad F, b = grad G of T_r there are zero or parallel, so T_r "
                             "and the volume V are not defined") from None
        Qu = _oriented_basis(vectors[j, :m].T)
        Qc = _oriented_basis(vectors[j, m:].T)
        out[j] = np.linalg.det(np.column_stack([Qu, Qc, a, b])) / np.sqrt(area2)
    return out


def sign_changes(t, v):
    """Times where v changes sign between consecutive samples (linear interpolation), with
    the smaller |v| of each bracketing pair: (times, margins), in time order.  A sample where
    v is exactly 0 is a crossing at its time with margin 0, whatever the signs around it (V =
    0 is the tangency itself); consecutive zero samples are one crossing, at the middle of
    their times.  ``t`` and ``v``: 1-D, finite, of one length (ValueError naming them)."""
    v = finite_array("v", v, ndim=1)
    t = finite_array("t", t, shape=(v.size,))
    s = np.sign(v)
    i = np.flatnonzero(s[:-1] * s[1:] < 0)
    times = t[i] + (t[i + 1] - t[i]) * v[i] / (v[i] - v[i + 1])
    margins = np.minimum(np.abs(v[i]), np.abs(v[i + 1]))
    zero = np.concatenate([[False], s == 0, [False]])
    starts = np.flatnonzero(zero[1:] & ~zero[:-1])        # runs of exact zeros
    ends = np.flatnonzero(zero[:-1] & ~zero[1:]) - 1
    times = np.concatenate([times, (t[starts] + t[ends]) / 2])
    margins = np.concatenate([margins, np.zeros(starts.size)])
    order = np.argsort(times, kind="stable")
    return times[order], margins[order]


@dataclass
class ResolvedWindow:
    """One resolved window: ``dt``, ``t_transient``, sample times ``t`` (from the scan's
    start), the oriented volume ``volume`` and the angle ``phi`` (rad) of the CLV route,
    and the sign changes of V (``crossings``, times; ``margins``, the smaller |V| beside
    each): numerical noise wherever they occur (module docstring)."""
    dt: float
    t_transient: float
    t: np.ndarray
    volume: np.ndarray
    phi: np.ndarray
    crossings: np.ndarray
    margins: np.ndarray

    @property
    def phi_min(self) -> float:
        return float(np.nanmin(self.phi))

    @property
    def t_min(self) -> float:
        return float(self.t[np.nanargmin(self.phi)])


@dataclass
class ClosestPassage:
    """What `closest_passage` found.

    t_scan_min, phi_scan_min : time and angle (rad) of the scan's closest sample.
    runs : the resolved windows — [0] the reference (dt, t_transient), [1] the transients
        halved (dt, t_transient/2, starting later on the same orbit), [2] the step halved
        (dt/2, t_transient).
    phi_min, phi_uncertainty : the reference's smallest angle at every step, and the largest
        difference of the other two runs' smallest angles from it.
    differences : max Δ|V| of runs 1 and 2 from run 0 over the window (``transient``,
        ``step``; |V|, as the runs' orientations are independent conventions); the largest
        differences of the trajectory (θ, u) of run 2 from run 0's
        (``state_difference``) and of run 0's from the scan's at their common samples
        (``scan_difference``: small, the same passage).
    sign_kept : whether V keeps one sign along each resolved run (a consistency check: by
        construction it can fail only where |V| ≈ 10⁻¹⁶).
    """
    t_scan_min: float
    phi_scan_min: float
    runs: list
    differences: dict
    sign_kept: bool
    params: dict = field(default_factory=dict)

    @property
    def phi_min(self) -> float:
        return self.runs[0].phi_min

    @property
    def phi_uncertainty(self) -> float:
        return float(max(abs(r.phi_min - self.phi_min) for r in self.runs[1:]))

    def summary(self) -> str:
        ref = self.runs[0]
        lines = [f"closest sample of the scan: φ = {self.phi_scan_min:.3g} rad at "
                 f"t = {self.t_scan_min:.2f}",
                 f"resolved at every step over t = {ref.t[0]:.2f}…{ref.t[-1]:.2f}:"]
        for r in self.runs:
            lines.append(f"  dt = {r.dt:g}, transients {r.t_transient:g}: min φ = "
                         f"{r.phi_min:.3e} rad at t = {r.t_min:.3f}, sign changes of V: "
                         f"{r.crossings.size}")
        d = self.differences
        lines.append(f"resolved minimum: φ = {self.phi_min:.3e} ± {self.phi_uncertainty:.1e} rad "
                     f"(V differs by {d['transient']:.1e} with the transients halved, "
                     f"{d['step']:.1e} with the step halved; trajectory with the step halved "
                     f"{d['state_difference']:.1e}, the reference from the scan "
                     f"{d['scan_difference']:.1e})")
        lines.append("V keeps its sign along each resolved run (as it must, by "
                     "construction and by the invariance of E_u and E_cs): "
                     f"{'yes' if self.sign_kept else 'NO (rounding where |V| ≈ 1e-16)'}")
        return "\n".join(lines)


def _state_at(system, theta0, u0, t, dt, project):
    """The state at time t of the trajectory that the CLV runs from (theta0, u0) follow (the
    tangent kernel's bits do not depend on its vectors)."""
    f = TangentFlow(system, theta0, u0, 0, dt=dt, project_every=project)
    f.advance(round(t / dt))
    return f.y[: system.n].copy(), f.y[system.n:].copy()


def _resolved(system, theta, u, t0, window, dt, transient, sample, seed):
    clv = covariant_lyapunov_vectors(system, theta, u, window, dt=dt, t_transient=transient,
                                     sample_every=sample, seed=seed, keep_vectors=True)
    vol = oriented_volume(clv.vectors, clv.params["n_unstable"], clv.states, system.weights)
    t = t0 + clv.t
    cr, mg = sign_changes(t, vol)
    return ResolvedWindow(dt, transient, t, vol, clv.phi, cr, mg), clv.states


def closest_passage(system, theta0, u0, t_scan, *, window=6.0, t_transient=40.0, dt=0.01,
                    seed=0) -> ClosestPassage:
    """The closest passage of E_u to E_cs along the trajectory from (theta0, u0), resolved
    (module docstring).

    The scan: `covariant_lyapunov_vectors` (restricted, samples every 0.1; its CLVs are not
    kept, so the scan's memory does not grow with N²·t_scan) over ``t_scan`` after a transient of ``t_transient`` + ``window``, so that the closest
    sample has room for the resolved runs before it.  The window of ``window`` time units
    around it (≥ 2, so that the closest sample lies inside) is sampled at every step ``dt``
    three times: after transients (forward and backward) of ``t_transient``, of
    ``t_transient``/2 (starting later on the same trajectory) and of ``t_transient`` with
    the step dt/2 (``t_transient`` rounded up to an even number of time units, the
    projection interval, so that every run starts at a projection of the scan's
    trajectory).  Returns a `ClosestPassage` (``.summary()`` for the report)."""
    t_transient = 2 * float(np.ceil(positive_time("t_transient", t_transient) / 2))
    half_tr = t_transient / 2
    window = positive_time("window", window)
    if window < 2.0:
        raise ValueError(f"window must be at least 2 time units (the runs start at whole time "
                         f"units), got {window!r}")
    dt = positive_time("dt", dt)
    theta0, u0 = start_state(system, theta0, u0)
    lead = float(np.ceil(t_transient + window))
    scan = covariant_lyapunov_vectors(system, theta0, u0, t_scan, dt=dt, t_transient=lead,
                                      seed=seed)
    project = round(scan.params["project_every"] / dt) if scan.params["project_every"] else 0
    j = int(np.nanargmin(scan.phi))
    t_min, phi_min = float(scan.t[j]), float(scan.phi[j])
    t_start = float(np.round(t_min - window / 2))            # a whole time unit: a projection
    a = t_start - t_transient                                # the reference run's start
    window = 2 * round(window / 2 / dt) * dt
    th_a, u_a = _state_at(system, theta0, u0, a, dt, project)
    th_b, u_b = _state_at(system, theta0, u0, a + half_tr, dt, project)
    ref, st_ref = _resolved(system, th_a, u_a, a, window, dt, t_transient, dt, seed)
    short, _ = _resolved(system, th_b, u_b, a + half_tr, window, dt, half_tr, dt, seed)
    fine, st_fine = _resolved(system, th_a, u_a, a, window, dt / 2, t_transient, dt, seed)
    # the scan's samples inside the window, and the reference's samples at the same times
    inside = np.flatnonzero((scan.t >= ref.t[0] - dt / 2) & (scan.t <= ref.t[-1] + dt / 2))
    at = np.rint((scan.t[inside] - ref.t[0]) / dt).astype(int)
    diffs = {"transient": float(np.max(np.abs(np.abs(short.volume) - np.abs(ref.volume)))),
             "step": float(np.max(np.abs(np.abs(fine.volume) - np.abs(ref.volume)))),
             "state_difference": float(np.max(np.abs(st_fine - st_ref))),
             "scan_difference": float(np.max(np.abs(scan.states[inside] - st_ref[at])))}
    kept = bool(all(np.unique(np.sign(r.volume)).size == 1 for r in (ref, short, fine)))
    params = dict(**system.describe(), t_scan=float(t_scan), window=window,
                  t_transient=t_transient, dt=dt, vectors_seed=seed, state_seed="given")
    return ClosestPassage(t_min, phi_min, [ref, short, fine], diffs, kept, params)
