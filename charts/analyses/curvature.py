"""Sectional curvatures along trajectories, section 3 (eqs 19-22), two routes.

Route (a), the paper's numerical algorithm.  At a sample point of the trajectory the
frame p⁽⁰⁾ = u/|u|, p⁽¹⁾…p⁽ᴺ⁻²⁾ is built from the θ-parts of the N−2 leading Lyapunov
vectors (kept in the constraint-preserving subspace, see `charts.analyses.lyapunov`): the
component along the flow is removed from each vector by subtracting a multiple of the
flow-direction perturbation (u, u̇) (itself a solution of eq 17, so the result is still a
Jacobi field), and the θ-parts are M-orthonormalised (metric Σ mᵢ aᵢ bᵢ).  One RK4 step
of ±Δt then moves the trajectory, the Jacobi fields J⁽ʲ⁾ (eq 17) and the frame (parallel
transport, eq 19) together, and the coefficients c_i⁽ʲ⁾ = ⟨J⁽ʲ⁾, p⁽ⁱ⁾⟩ give, from the
Jacobi equation c̈ + K c = 0 (eq 20 with the curvature operator of J'' + R(J, u)u = 0),

    K_ij = −[c_i⁽ʲ⁾(t−Δt) − 2δ_ij + c_i⁽ʲ⁾(t+Δt)] / (Δt² |u|²).

Eq (21) as printed lacks the minus sign: with it the N = 3 result matches eq (22),
which is negative.  Dividing by |u|² makes K independent of the speed.

Route (b), exact: K_ij = ⟨R(p⁽ʲ⁾, p⁽⁰⁾)p⁽⁰⁾, p⁽ⁱ⁾⟩ at the same points and frames: for the N
with generated kernels R_abcd p_i^a p_0^b p_j^c p_0^d from the generated Riemann tensor in
the best-conditioned chart (weights and level of Σ aᵢ cos θᵢ = c as its arguments); for the others (``charts.geometry.kernels.source``) the Gauss
equation of the hypersurface in ambient form, [h(p_i,p_j)h(p_0,p_0) − h(p_i,p_0)h(p_j,p_0)] / |∇F|²
(``charts.geometry.structured.gauss_frame_curvature``, O(N k²) instead of O(N⁴)).

For N = 3 with equal masses, eq (22) gives the Gaussian curvature in closed form
(`gaussian_curvature_eq22`).
"""
from __future__ import annotations

from collections import namedtuple
from dataclasses import dataclass
from math import sqrt

import numpy as np
from numba import types
from ..jit import njit

from ..io.archive import Archivable, attributes, dataset, index_coordinate
from ..io.result_words import ANGULAR_VELOCITY
from ..jit.compilation import announces_compilation
from ..jit.kernel_calls import CallsKernel
from ..flows.ambient import (flow_rhs, multiplier, state_rate, state_stage, tangent_factors,
                             tangent_rate, transport_rate)
from ..geometry.primitives import sincos
from ..geometry.checks import finite_array, option
from ..geometry.system import TOL
from ..solvers.rk import rk4_combine, rk4_point, rk4_stages
from ..solvers.driver import Phases
from ..solvers.status import RUNNING, status_error
from ..solvers.tangent import (Records, Stack, TangentFlow, orthonormalize, reorth_steps,
                               shift_sincos, tangent_kernel, tangent_kernel_types)
from .arguments import (flag, positive_int, positive_time, progress_reporter, project_steps,
                        samples_of, start_state, steps_of, Documented)
from .exact_curvature import exact_curvature_matrix, exact_curvatures
from .arguments import rotor_system
from .mechanism_route import mechanism_route
from .lyapunov import resolve_transient
from .transients import transient_rule

__all__ = ["CurvatureResult", "curvature_along_trajectory", "exact_curvature_matrix",
           "exact_curvatures", "gaussian_curvature_eq22", "curvature_frame", "frame_step", "numerical_curvature"]


def gaussian_curvature_eq22(theta):
    """Eq (22): Gaussian curvature of the N = 3 surface (equal masses), theta (..., 3), every
    point on the manifold (|Σ cos θ| within ``charts.geometry.system.TOL['constraint']``)."""
    theta = finite_array("theta", theta)
    if theta.shape[-1:] != (3,):
        raise ValueError(f"eq (22) is the curvature of the N = 3 surface: theta must have shape "
                         f"(..., 3), got {theta.shape}")
    F = np.abs(np.cos(theta).sum(-1))
    if np.any(F > TOL["constraint"]):
        raise ValueError(f"theta is off the manifold: |sum(cos theta)| = {F.max():.3e} "
                         f"(tolerance {TOL['constraint']:g}); use RotorSystem.project_point")
    return -(np.cos(theta) ** 2).sum(-1) / (2.0 * ((np.sin(theta) ** 2).sum(-1)) ** 2)


#: The arrays and sizes of the frame steps' hooks (``work`` of ``charts.solvers.rk.rk4_stages``):
#: the packed state z = [y; X; P] (length L = 2N + 2N·k + N·kp), its stage point zt, the
#: stages K (4L), the result ``out`` (z itself, or a copy), the weighted sin/cos s0, c0 at z,
#: those s, c of the stage point, the angle shift dl, eq (17)'s factors f, g, p, q, M⁻¹, the
#: weights and the sizes N, k, kp, L.
FrameStep = namedtuple("FrameStep", ["z", "zt", "K", "out", "s0", "c0", "s", "c", "dl", "f", "g",
                                     "p", "q", "minv", "wts", "n", "k", "kp", "L"])


@njit(cache=True, inline="always")
def _frame_start(w, _eqs):
    """`rk4_stages`' start of `frame_step`: stage 0's point is a copy (`_frame_point`)."""
    return 0.0, 0


@njit(cache=True, inline="always")
def _frame_point(w, st, a):
    """`rk4_stages`' stage point of `frame_step`: zt = z + a·K_{st−1} (`rk4_point`), a copy
    of z at stage 0."""
    z, zt, L = w.z, w.zt, w.L
    if st == 0:
        for i in range(L):
            zt[i] = z[i]
    else:
        rk4_point(z, w.K, (st - 1) * L, a, L, zt)


@njit(cache=True, inline="always")
def _frame_rate(w, _eqs, st, hmin):
    """`rk4_stages`' stage rates of `frame_step` at zt (its sin/cos from libm,
    ``state_stage``) into stage st of K: eq (8), eq (17) for the k vectors, eq (19) for the
    kp frame vectors."""
    zt, K, s, c, f, g, p, q, minv, n, k = w.zt, w.K, w.s, w.c, w.f, w.g, w.p, w.q, w.minv, w.n, w.k
    d = 2 * n
    oP = d + k * d
    o = st * w.L
    lam, iB = state_stage(zt, 0, n, minv, w.wts, s, c, K, o)
    tangent_factors(zt, 0, n, minv, s, c, lam, f, g, p, q)
    for r in range(k):
        tangent_rate(zt, d + r * d, n, f, g, p, q, iB, K, o + d + r * d)
    for r in range(w.kp):
        transport_rate(zt, oP + r * n, n, zt, 0, f, c, iB, K, o + oP + r * n)
    return hmin


@njit(cache=True, inline="always")
def _frame_combine(w, h):
    """`rk4_stages`' end of the frame steps: ``out`` from z and the stages (`rk4_combine`)."""
    rk4_combine(w.z, w.K, h, w.L, w.out)


@njit(cache=True)
def frame_step(y, X, P, minv, a, h, work):
    """One RK4 step of size h, in place, of eq (8) for y (2N,), eq (17) for the rows of X
    (k, 2N) and eq (19) for the rows of P (kp, N), the one body ``charts.solvers.rk.
    rk4_stages`` on the packed state [y; X; P]; weights a; ``work`` of at least 6L + 6N
    floats, L = 2N + 2Nk + N·kp (the packed state, its stage point, the stages, the
    factors)."""
    n = y.size // 2
    d = 2 * n
    k = X.shape[0]
    kp = P.shape[0]
    oP = d + k * d
    L = oP + kp * n
    z = work[:L]
    zt = work[L:2 * L]
    K = work[2 * L:6 * L]
    w6 = work[6 * L:6 * L + 6 * n]
    s, c, f, g, p, q = w6[:n], w6[n:2 * n], w6[2 * n:3 * n], w6[3 * n:4 * n], w6[4 * n:5 * n], \
        w6[5 * n:]
    z[:d] = y
    z[d:oP] = X.ravel()
    z[oP:] = P.ravel()
    rk4_stages(FrameStep(z, zt, K, z, s, c, s, c, s, f, g, p, q, minv, a, n, k, kp, L), 0, h,
               _frame_start, _frame_point, _frame_rate, _frame_combine)
    y[:] = z[:d]
    X[:, :] = z[d:oP].reshape((k, d))
    P[:, :] = z[oP:].reshape((kp, n))


@njit(cache=True)
def curvature_frame(y, X, minv, wts, m, Xj, P):
    """Jacobi fields Xj, shape (k, 2N), and the M-orthonormal frame P, shape (k + 1, N), at
    y from the Lyapunov vectors X (route a, see the module doc).  Returns |u|²."""
    n = y.size // 2
    k = X.shape[0]
    f = np.empty(2 * n)
    flow_rhs(y, minv, wts, f)  # the flow-direction perturbation (u, u̇), a solution of eq (17)
    uu = 0.0
    for i in range(n):
        uu += m[i] * y[n + i] * y[n + i]
    for r in range(k):
        a = 0.0
        for i in range(n):
            a += m[i] * X[r, i] * y[n + i]
        a /= uu
        for i in range(2 * n):
            Xj[r, i] = X[r, i] - a * f[i]
    w = np.zeros(2 * n)
    for i in range(n):          # loops, not slice copies: no shape-mismatch message to compile
        w[i] = m[i]
    orthonormalize(Xj, w, np.zeros(k))
    un = sqrt(uu)
    for i in range(n):
        P[0, i] = y[n + i] / un
    for r in range(k):
        for i in range(n):
            P[r + 1, i] = Xj[r, i]
    return uu


@njit(cache=True)
def _frame_rates(zt, n, k, kp, minv, s, c, f, g, p, q, K, o):
    """The rates of eq (8), eq (17) for the k vectors and eq (19) for the kp frame vectors of
    the packed state zt = [y; X; P] into K[o:], s, c = a sin θ, a cos θ of its angles.
    n, k, kp, o unsigned (no negative-index wraparound: see the tangent kernel's step)."""
    zero = np.uint64(0)
    d = n + n
    oP = d + k * d
    lam, B = multiplier(zt, zero, n, minv, s, c)
    iB = 1.0 / B if B > 0.0 else 0.0
    state_rate(zt, zero, n, minv, s, lam, K, o)
    tangent_factors(zt, zero, n, minv, s, c, lam, f, g, p, q)
    for r in range(k):
        tangent_rate(zt, d + r * d, n, f, g, p, q, iB, K, o + d + r * d)
    for r in range(kp):
        transport_rate(zt, oP + r * n, n, zt, 0, f, c, iB, K, o + oP + r * n)


@njit(cache=True, inline="always")
def _shared_start(w, _eqs):
    """`rk4_stages`' start of the steps of `numerical_curvature`: stage 0, the same for both,
    is in K already."""
    return 0.0, 1


@njit(cache=True, inline="always")
def _shifted_point(w, st, a):
    """`rk4_stages`' stage point of `numerical_curvature`: zt = z + a·K_{st−1} (`rk4_point`),
    its sin/cos shifted from those at z (``charts.solvers.tangent.shift_sincos``)."""
    z, zt, K, dl, n = w.z, w.zt, w.K, w.dl, w.n
    op = np.uint64(st - 1) * w.L
    rk4_point(z, K, op, a, w.L, zt)
    for j in range(n):
        dl[j] = a * K[op + j]
    shift_sincos(w.s0, w.c0, dl, zt, n, w.wts, w.s, w.c)


@njit(cache=True, inline="always")
def _shifted_rate(w, _eqs, st, hmin):
    """`rk4_stages`' stage rates of `numerical_curvature` (`_frame_rates`)."""
    _frame_rates(w.zt, w.n, w.k, w.kp, w.minv, w.s, w.c, w.f, w.g, w.p, w.q, w.K,
                 np.uint64(st) * w.L)
    return hmin


@njit(cache=True)
def numerical_curvature(y, Xj, P, minv, wts, m, dt, uu, K, work=None):
    """Route (a), eqs (20)–(21) with the minus sign: K[i, j] from one RK4 step of ±dt of
    the trajectory, the Jacobi fields Xj and the frame P (`curvature_frame`): the steps of
    `frame_step`, sharing their first stage, with the sin/cos of the later stages shifted
    from those at y (``charts.solvers.tangent.shift_sincos``, as in the tangent kernel)
    instead of libm.  ``work`` from `curvature_work` (allocated when not given)."""
    n = y.size // 2
    d = 2 * n
    k = Xj.shape[0]
    kp = P.shape[0]
    if work is None:
        work = curvature_work(n, k)
    oP = d + k * d
    L = oP + kp * n
    z = work[:L]
    zt = work[L:2 * L]
    z2 = work[2 * L:3 * L]
    Kst = work[3 * L:7 * L]
    w = work[7 * L:7 * L + 10 * n]
    s0, c0, s, c, f = w[:n], w[n:2 * n], w[2 * n:3 * n], w[3 * n:4 * n], w[4 * n:5 * n]
    g, p, q, dl = w[5 * n:6 * n], w[6 * n:7 * n], w[7 * n:8 * n], w[8 * n:9 * n]
    cs = work[7 * L + 10 * n:7 * L + 10 * n + k * k].reshape((k, k))
    for i in range(d):
        z[i] = y[i]
    for r in range(k):
        for i in range(d):
            z[d + r * d + i] = Xj[r, i]
    for r in range(kp):
        for i in range(n):
            z[oP + r * n + i] = P[r, i]
    sincos(z, 0, n, wts, s0, c0)
    nu, ku, kpu, Lu = np.uint64(n), np.uint64(k), np.uint64(kp), np.uint64(L)
    _frame_rates(z, nu, ku, kpu, minv, s0, c0, f, g, p, q, Kst, np.uint64(0))  # stage 0, shared
    cs[:, :] = 0.0
    w = FrameStep(z, zt, Kst, z2, s0, c0, s, c, dl, f, g, p, q, minv, wts, nu, ku, kpu, Lu)
    for sign in (1.0, -1.0):
        rk4_stages(w, 0, sign * dt, _shared_start, _shifted_point, _shifted_rate, _frame_combine)
        for i in range(k):
            for j in range(k):
                acc = 0.0
                for r in range(n):
                    acc += m[r] * z2[d + j * d + r] * z2[oP + (i + 1) * n + r]
                cs[i, j] += acc
    for i in range(k):
        for j in range(k):
            K[i, j] = -(cs[i, j] - (2.0 if i == j else 0.0)) / (dt * dt * uu)


@njit(cache=True)
def curvature_work(n, k):
    """Work array of `numerical_curvature` for N = n and k Jacobi fields."""
    return np.empty(7 * (2 * n + k * 2 * n + (k + 1) * n) + 10 * n + k * k)


#: samples advanced per tangent-kernel call by `_sample_curvature` (their states buffered).
_BLOCK = 64


def _sample_curvature(kernel, frame, curvature, stack, rotors, stepping, project_every, reorth,
                      sample_steps, Ka, Ys, Ps):
    """Advance the tangent flow Z = [y; X] (``stack``: `Stack`) by ``kernel``
    (`tangent_kernel`) ``sample_steps`` steps per sample (re-orthonormalised every ``reorth``
    steps, a divisor of ``sample_steps``), `_BLOCK` samples per kernel call with their states
    recorded, and at each sample store y, the frame (``frame``: `curvature_frame`) and the
    route-(a) matrix (``curvature``: `numerical_curvature`); the three called by address
    (`sample_curvature`).  Returns (status, samples done).  ``stepping`` comes
    from the caller (restricted True): a literal True here would compile the tangent kernel
    a second time, beside the signature `TangentFlow.advance` compiled for the transient
    (10 s at the first call)."""
    Z, sc, counter = stack.Z, stack.sc, stack.counter
    minv, m, wts = rotors.minv, rotors.m, rotors.wts
    dt = stepping.dt
    n = Z.shape[1] // 2
    k = Z.shape[0] - 1
    logs = np.zeros(k)
    no_events = np.empty(0, dtype=np.int64)
    frames = Stack(Z, sc, counter, logs, no_events)   # the log-norm sums are not kept
    Xj = np.empty((k, 2 * n))
    P = np.empty((k + 1, n))
    work = curvature_work(n, k)
    S = Ka.shape[0]
    buf = np.empty((min(S, _BLOCK), Z.size))
    records = Records(buf, no_events, buf)
    for a in range(0, S, _BLOCK):
        nb = min(_BLOCK, S - a)
        status, done = kernel(
            frames, rotors, stepping,
            Phases(project_every, reorth, counter[0] + sample_steps, sample_steps), records,
            nb * sample_steps, None)
        if status != RUNNING:
            return status, a
        for b in range(nb):
            zb = buf[b].reshape((k + 1, 2 * n))
            y = zb[0]
            uu = frame(y, zb[1:], minv, wts, m, Xj, P)
            for i in range(2 * n):
                Ys[a + b, i] = y[i]
            for r in range(k + 1):
                for i in range(n):
                    Ps[a + b, r, i] = P[r, i]
            curvature(y, Xj, P, minv, wts, m, dt, uu, Ka[a + b], work)
    return RUNNING, S


def _frame_types(*_):
    """The argument types with which `_sample_curvature` calls `curvature_frame`."""
    vector, matrix = types.float64[::1], types.float64[:, ::1]
    return (vector, matrix, vector, vector, vector, matrix, matrix)


def _curvature_types(*_):
    """The argument types with which `_sample_curvature` calls `numerical_curvature`."""
    vector, matrix = types.float64[::1], types.float64[:, ::1]
    return (vector, matrix, matrix, vector, vector, vector, types.float64, types.float64,
            matrix, vector)


#: `_sample_curvature` compiled with the tangent kernel, the frames and route (a) called by
#: address (their code not compiled into the sampler a second time: ``charts.jit.kernel_calls``)
sample_curvature = CallsKernel(_sample_curvature, (tangent_kernel, tangent_kernel_types),
                               (curvature_frame, _frame_types),
                               (numerical_curvature, _curvature_types))


@dataclass(eq=False, repr=False)
class CurvatureResult(Archivable):
    """Curvature along a trajectory.

    t : (S,) sample times; theta, u : (S, N) states; frames : (S, N−1, N) the
    M-orthonormal frame (row 0 the unit velocity, rows 1.. from the Lyapunov vectors);
    K_numeric : (S, N−2, N−2) route (a); K_exact : (S, N−2, N−2) route (b) or None.
    """
    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    frames: np.ndarray
    K_numeric: np.ndarray
    K_exact: np.ndarray | None
    params: dict

    def diagonal(self, route="numerical"):
        """K_ii, shape (S, N−2), of route 'numerical' (a; the scenes' name, 'numeric' is
        accepted too) or 'exact' (b)."""
        route = option("route", route, ("numerical", "numeric", "exact"))
        if route in ("numerical", "numeric"):
            K = self.K_numeric
        elif route == "exact":
            if self.K_exact is None:
                raise ValueError("the exact route was not computed (exact=False)")
            K = self.K_exact
        else:
            raise ValueError(f"route must be 'numerical' or 'exact', got {route!r}")
        return np.diagonal(K, axis1=1, axis2=2)

    def fraction_positive(self, route="numerical"):
        """Fraction of positive values of each K_ii, shape (N−2,)."""
        return (self.diagonal(route) > 0).mean(axis=0)

    def summary_parts(self):
        """The share of positive K_ii of each direction (the exact route where computed)."""
        route = "numerical" if self.K_exact is None else "exact"
        shares = ", ".join(f"{100 * f:.0f} %" for f in self.fraction_positive(route)[:4])
        return [f"K_ii > 0 in {shares} of samples ({route})"]

    KIND = "curvature"

    def to_xarray(self):
        """Dataset: theta, u (t, rotor); frames (t, frame, rotor); K_numeric[, K_exact]
        (t, direction, direction2); the settings as attributes.  A Mechanism's result
        (``params["mechanism"]``, ``charts.analyses.mechanism_curvature``): kind
        ``mechanism_curvature``, q, v (t, coordinate) and frames (t, frame, coordinate)
        instead, the coordinate named by the mechanism's coordinates with the unit of each
        (`_coordinates`)."""
        dims = ("t", "direction", "direction2")
        k = self.K_numeric.shape[1]
        coords = {"t": (("t",), self.t, "time"),
                  "direction": index_coordinate("direction", k,
                                                "i of K_ij, from 1 as in the paper"),
                  "direction2": index_coordinate("direction2", k,
                                                 "j of K_ij, from 1 as in the paper")}
        if "mechanism" in self.params:
            data, unit_K = self._coordinates(coords)
        else:
            data, unit_K = {"theta": (("t", "rotor"), self.theta, "rad"),
                            "u": (("t", "rotor"), self.u, ANGULAR_VELOCITY),
                            "frames": (("t", "frame", "rotor"), self.frames, "rad",
                                       "M-orthonormal frame")}, "1 / rad²"
        data["K_numeric"] = (dims, self.K_numeric, unit_K, "route (a), eqs (19)–(21)")
        if self.K_exact is not None:
            data["K_exact"] = (dims, self.K_exact, unit_K, "route (b), Riemann tensor")
        kind = "mechanism_curvature" if "mechanism" in self.params else self.KIND
        return dataset(kind, data, attrs={"params": self.params}, coords=coords)

    def _coordinates(self, coords):
        """(q, v and frames along ``coordinate``, the unit of K) of a Mechanism's result; the
        ``coordinate`` and ``coordinate_units`` coordinates added to ``coords``: rad for the
        periodic coordinates (angles), length for the others."""
        names = self.params.get("coordinates") or [f"q{i}" for i in range(self.theta.shape[1])]
        periodic = set(self.params.get("periodic", names))
        units = ["rad" if c in periodic else "length" for c in names]
        coords["coordinate"] = (("coordinate",), np.array(names), "1",
                                "the mechanism's coordinate q_i (v holds their rates)")
        coords["coordinate_units"] = (("coordinate",), np.array(units), "1",
                                      "the unit of each coordinate (of v: the same per time)")
        unit_K = "1 / rad²" if periodic >= set(names) else "1 / length²"
        return {"q": (("t", "coordinate"), self.theta, "see coordinate_units",
                      "the sampled configuration q"),
                "v": (("t", "coordinate"), self.u, "see coordinate_units per time",
                      "the sampled velocity v"),
                "frames": (("t", "frame", "coordinate"), self.frames, "see coordinate_units",
                           "frame orthonormal in the kinetic metric")}, unit_K

    @classmethod
    def from_xarray(cls, ds):
        q, v = ("q", "v") if "q" in ds else ("theta", "u")     # a Mechanism's, a rotors'
        return cls(t=ds["t"].values, theta=ds[q].values, u=ds[v].values,
                   frames=ds["frames"].values, K_numeric=ds["K_numeric"].values,
                   K_exact=ds["K_exact"].values if "K_exact" in ds else None,
                   params=attributes(ds)["params"])

    def plot(self, route="numerical", ax=None, **kw):
        """Histograms of K_ii (tails beyond robust quantiles clipped, the clipped share
        stated); ``(fig, axes)`` (``charts.plotting.plot_curvature``)."""
        from ..plotting import plot_curvature
        return plot_curvature({route: self.diagonal(route)}, axes=ax, **kw)


@mechanism_route("mechanism_curvature", "mechanism_curvature")
@announces_compilation
def curvature_along_trajectory(system, theta0, u0, t_final, *, dt=0.01,
                               sample_every=Documented(0.1), t_transient="scaled",
                               exact=True, project_every=Documented(1.0), seed=0,
                               progress=False) -> CurvatureResult:
    """Sectional curvatures K_ij along the trajectory from (theta0, u0), routes (a) and (b).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
    t_final : float
        Sampled time after the transient (a multiple of ``sample_every``).
    dt : float
        RK4 step of the trajectory, the Lyapunov vectors and the ±Δt frame steps.
    sample_every : float
        Time between sample points (a multiple of dt; default 0.1, the nearest whole
        number of steps at other dt that divides t_final: README, "Conventions").
    t_transient : float, "scaled" or "auto"
        Time for the Lyapunov vectors to converge before sampling: "scaled" (default), 5 N² /
        speed, at least 50, "auto" from a pilot run, as `lyapunov_spectrum`'s
        (``charts.analyses.transients``); a duration the nearest whole number of steps.
    exact : bool
        Also evaluate route (b) at the same points and frames.
    project_every : float or None
        Time between projections of the state onto the invariants (default 1.0, the nearest
        whole number of steps at other dt; None: never).
    seed : int
        Seed of the random initial tangent vectors.
    progress : bool or callable(t_done, t_total)

    Returns
    -------
    CurvatureResult
    """
    rotor_system(system)
    n = system.n
    dt = positive_time("dt", dt)
    total = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=total)
    S = samples_of(total, sample, t_final, sample_every)
    if transient_rule(t_transient) is None:
        steps_of("t_transient", t_transient, dt, allow_zero=True)
    project = project_steps(project_every, dt)
    seed = positive_int("seed", seed, 0)
    exact = flag("exact", exact)
    theta0, u0 = start_state(system, theta0, u0, dt)
    t_transient, rule = resolve_transient(t_transient, system, theta0, u0, dt=dt, seed=seed)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    k = n - 2
    reorth = reorth_steps(dt, sample, transient)  # orthonormal (and in T_r) at every sample
    flow = TangentFlow(system, theta0, u0, k, dt=dt, inner="theta", restricted=True,
                       reorth_every=reorth, project_every=project, seed=seed)
    rep = progress_reporter(progress, (transient + total) * dt, f"curvature N={n}")
    where = "curvature_along_trajectory (ambient RK4)"
    flow.advance(transient, where=where)
    rep.update(transient * dt)
    Ka = np.empty((S, k, k))
    Ys = np.empty((S, 2 * n))
    Ps = np.empty((S, k + 1, n))
    for ch in np.array_split(np.arange(S), min(S, 50)):
        a, b = ch[0], ch[-1] + 1
        status, done = sample_curvature(flow.stack(), flow.rotors(), flow.stepping(), project,
                                        reorth, sample, Ka[a:b], Ys[a:b], Ps[a:b])
        if status != RUNNING:
            raise status_error(status, flow.steps * dt, where)
        rep.update((b - a) * sample * dt)
    rep.close()
    Kb = None
    if exact:
        Kb = exact_curvatures(system, Ys[:, :n], Ps)
    t = (np.arange(1, S + 1) * sample) * dt
    params = dict(**system.describe(), dt=dt, sample_every=sample * dt,
                  t_transient=transient * dt, project_every=project * dt or None,
                  speed=flow.speed, t_final=float(t[-1]), vectors_seed=seed,
                  state_seed="given", exact=bool(exact),
                  theta0=np.asarray(theta0, dtype=float).tolist(),
                  u0=np.asarray(u0, dtype=float).tolist())
    if rule is not None:
        params["transient_rule"] = rule
    return CurvatureResult(t, Ys[:, :n], Ys[:, n:], Ps, Ka, Kb, params)
