"""The tangent flow of a Mechanism: its ambient constrained flow and k phase-space tangent
vectors, advanced together by classical RK4 (the one body ``charts.solvers.rk.rk4_stages``
with the hooks of this layout), compiled.

One step of size h advances the state y = (q, v), shape (2n,), by the KKT equations of motion
and each tangent vector (δq, δv) by their exact linearisation (both from
``charts.mechanism.kernels``, on the jets of the mechanism's compiled function,
``Mechanism.compiled_jets``).  Every ``reorth`` steps the vectors are re-orthonormalised by
eq (18)'s Gram–Schmidt (``charts.geometry.gram_schmidt.orthonormalize``) in the kinetic
metric: ⟨a, b⟩ = δq_aᵀ M(q) δq_b ("theta", the rotors' θ-only product with M = diag(m)) or
that plus δv_aᵀ M(q) δv_b ("full"); the log-norms are summed in ``logsum``.  Every
``project`` steps the state is projected back onto F = 0 and ker J and the vectors onto the
tangent space of TC, compiled (`_project`: ``project_point``, ``project_velocity`` and
``project_phase_tangent`` of ``charts.mechanism.dynamics`` on the generated jets, F
included); where it refuses (no convergence, a near rank-deficient J), NumPy's route
(`MechanismTangentFlow.project_now`) projects or says why.  The KKT systems are solved by the
flow's own small LU (``charts.mechanism.kernels.lu_in_place``), one factorisation per stage
for the state and all the vectors; where M is constant and definite (``SCHUR_COND``: the
rotors, a triple linkage with a massive joint) through the Schur complement J M⁻¹ Jᵀ with M⁻¹
computed once (``schur_factor``: a k × k factorisation, not (n + k) × (n + k)), and the
metric's factor for Gram–Schmidt once too.  The driver and its kernels allocate nothing and
are compiled without numba's reference counting (``charts.solvers.rk.NO_REFCOUNT``: its
atomic pairs on the arrays of the work tuples cost more than the arithmetic, 2.1 → 1.0 µs a
step of the state alone on rotors(3)); `_rate` is inlined into the RK4 hooks (its calls passed
both work tuples' arrays field by field: 1.0 → 0.63 µs, ``scripts/mechanism_cost.py``).

The metric enters Gram–Schmidt through a factor M = LᵀL (from its eigenvalues, so a
semi-definite M, e.g. the triple linkage's massless joint, is fine: it is definite on ker J,
where the vectors lie): the rows handed to ``orthonormalize`` are (L δq [, L δv], δq, δv)
with weights (1 …, 0 …), so that its row operations act on the vectors themselves while its
inner products are the metric's.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

from ..geometry.gram_schmidt import orthonormalize
from ..jit import njit
from ..jit.kernel_calls import CallsKernel
from ..solvers.rk import NO_REFCOUNT, rk4_combine, rk4_point, rk4_stages
from ..solvers.tangent import StackedFlow
from .dynamics import RANK_TOL
from .errors import MechanismError
from .kernels import (apply_tangent_matrix, kkt_matrix, lu_in_place, lu_solve_columns,
                      motion_rhs, schur_factor, schur_solve_columns, tangent_motion_matrix)
from .symbolic import JET_ORDER

__all__ = ["MechanismTangentFlow", "INNER_PRODUCTS"]

#: The inner products of eq (18) on a mechanism's phase tangent vectors (module docstring).
INNER_PRODUCTS = ("theta", "full")


@njit(cache=True, inline="always")
def _solve(work, J, B, first, last):
    """Columns ``first`` … ``last − 1`` of B overwritten by the KKT system's solutions: by
    the Schur complement where ``work`` says so (`schur_solve_columns`), else by the
    factored KKT matrix (`lu_solve_columns`)."""
    if work[5]:
        schur_solve_columns(work[6], J, work[7], work[8], work[9], B, first, last, work[10])
    else:
        lu_solve_columns(work[0], work[1], B, first, last)


@njit(cache=True, inline="always", error_model="numpy", **NO_REFCOUNT)
def _rate(jets, p, Z, out, jq, jv, jt, work):
    """out = d/dt Z for Z = [y; X], shape (1 + kv, 2n): the ambient flow of the state (row 0)
    and its linearisation for the vector rows.  ``jt``: the jets (F, J, F2, F3, M, dM, d2M),
    ``jq``, ``jv``: the state's q and v, ``work``: (KKT matrix, its pivots, right-hand sides
    (n + k, 1 + kv): the state's in column 0, the vectors' after it, the linearisation's
    matrix (n + k, 2n), whether M is constant, whether the Schur complement serves (M
    constant and definite), M⁻¹ then, W = M⁻¹Jᵀ, S = J W and its pivots, an n-vector), the
    KKT matrix factored once (`lu_in_place`; or S, `schur_factor`) and the linearisation
    built once (`tangent_motion_matrix`) for all of them; a singular K (or S) makes the
    rates NaN."""
    F, J, F2, F3, M, dM, d2M = jt
    K, piv, B, T, flat, schur, Minv, W, S, spiv, u = work[:11]
    n = jq.shape[0]
    kv = Z.shape[0] - 1
    for i in range(n):
        jq[i] = Z[0, i]
        jv[i] = Z[0, n + i]
    jets(jq, p, F, J, F2, F3, M, dM, d2M)
    if schur:
        ok = schur_factor(Minv, J, W, S, spiv) != 0.0
    else:
        kkt_matrix(M, J, -1.0, K)
        ok = lu_in_place(K, piv) != 0.0
    if not ok:
        out[:] = np.nan
        return
    motion_rhs(dM, F2, jv, B[:, 0], flat)
    _solve(work, J, B, 0, 1)
    x = B[:, 0]
    for i in range(n):
        out[0, i] = jv[i]
        out[0, n + i] = x[i]
    if kv == 0:
        return
    tangent_motion_matrix(dM, d2M, F2, F3, jv, x, T, flat)
    for r in range(kv):
        apply_tangent_matrix(T, Z[1 + r, :n], Z[1 + r, n:], B[:, 1 + r])
    _solve(work, J, B, 1, 1 + kv)
    for r in range(kv):
        for i in range(n):
            out[1 + r, i] = Z[1 + r, n + i]
            out[1 + r, n + i] = B[i, 1 + r]


#: The smallest eigenvalue ratio of a constant M for which the flow solves its KKT systems by
#: the Schur complement with M⁻¹ (a semi-definite M, a massless joint, keeps the KKT matrix).
SCHUR_COND = 1e-8

#: Newton's tolerance on max |F| and its iterations in `_project`, as ``project_point``'s
#: defaults (``charts.mechanism.dynamics``).
NEWTON_TOL, NEWTON_ITERATIONS = 1e-13, 50


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def _jets_at(jets, p, jq, jt):
    """The jets at jq into jt; returns max |F|."""
    F, J, F2, F3, M, dM, d2M = jt
    jets(jq, p, F, J, F2, F3, M, dM, d2M)
    out = 0.0
    for c in range(F.shape[0]):
        out = max(out, abs(F[c]))
    return out


@njit(cache=True)
def _project(jets, p, Z, periodic, eye, jq, jt, work):
    """`MechanismTangentFlow.project_now` compiled, in place: the state's q onto F = 0 by
    Newton's minimum-norm steps (the KKT system [[1, Jᵀ], [J, 0]], which gives J⁺F), its
    periodic coordinates into (−π, π], v M-orthogonally onto ker J, each vector's δq likewise
    and δv onto J δv + ∂²F(v, δq) = 0 (``charts.mechanism.dynamics``' projections, one KKT
    matrix factored for all of them).  Returns False, Z untouched, where Newton does not
    converge, Z is not finite, or J is near rank-deficient (its Gram matrix's pivots below
    RANK_TOL² of the largest): the caller then takes NumPy's route, which says why."""
    F, J, F2, F3, M, dM, d2M = jt
    K, piv, B = work[:3]
    n = jq.shape[0]
    k = F.shape[0]
    kv = Z.shape[0] - 1
    for r in range(Z.shape[0]):
        for i in range(2 * n):
            if not np.isfinite(Z[r, i]):
                return False
    for i in range(n):
        jq[i] = Z[0, i]
    fmax = _jets_at(jets, p, jq, jt)
    for _ in range(NEWTON_ITERATIONS):
        if fmax <= NEWTON_TOL:
            break
        kkt_matrix(eye, J, 1.0, K)
        if lu_in_place(K, piv) == 0.0:
            return False
        for i in range(n):
            B[i, 0] = 0.0
        for c in range(k):
            B[n + c, 0] = F[c]
        lu_solve_columns(K, piv, B, 0, 1)
        for i in range(n):
            jq[i] -= B[i, 0]
        fmax = _jets_at(jets, p, jq, jt)
    if not fmax <= 1e3 * NEWTON_TOL:
        return False
    for i in range(n):
        if periodic[i]:
            jq[i] = np.arctan2(np.sin(jq[i]), np.cos(jq[i]))
    _jets_at(jets, p, jq, jt)
    for a in range(k):                                  # the rank: J Jᵀ's pivots
        for b in range(k):
            s = 0.0
            for i in range(n):
                s += J[a, i] * J[b, i]
            K[a, b] = s
    if lu_in_place(K[:k, :k], piv) < RANK_TOL * RANK_TOL:
        return False
    kkt_matrix(M, J, 1.0, K)
    if lu_in_place(K, piv) == 0.0:
        return False
    for r in range(1 + kv):                             # v, then the vectors' δq
        col = 0 if r == 0 else r
        off = n if r == 0 else 0
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += M[i, j] * Z[r, off + j]
            B[i, col] = s
        for c in range(k):
            B[n + c, col] = 0.0
        if r == 0:
            lu_solve_columns(K, piv, B, 0, 1)
            for i in range(n):
                Z[0, i] = jq[i]
                Z[0, n + i] = B[i, 0]
    if kv == 0:
        return True
    lu_solve_columns(K, piv, B, 1, 1 + kv)
    for r in range(kv):
        for i in range(n):
            Z[1 + r, i] = B[i, 1 + r]
    for r in range(kv):                                 # δv: J δv = −∂²F(v, δq)
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += M[i, j] * Z[1 + r, n + j]
            B[i, 1 + r] = s
        for c in range(k):
            s = 0.0
            for i in range(n):
                for j in range(n):
                    s += F2[c, i, j] * Z[0, n + i] * Z[1 + r, j]
            B[n + c, 1 + r] = -s
    lu_solve_columns(K, piv, B, 1, 1 + kv)
    for r in range(kv):
        for i in range(n):
            Z[1 + r, n + i] = B[i, 1 + r]
    return True


@njit(cache=True)
def _metric_factor(M, sw, U):
    """sw = √w and U of M = U diag(w) Uᵀ (``np.linalg.eigh``, negative rounding clipped), in
    place: the factor L = diag(sw) Uᵀ of M = LᵀL used by `_metric_rows` (its own allocations
    stay here: the driver, compiled without reference counting, allocates nothing)."""
    w, V = np.linalg.eigh(M)
    for a in range(w.shape[0]):
        sw[a] = np.sqrt(max(w[a], 0.0))
        for i in range(w.shape[0]):
            U[i, a] = V[i, a]


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def _metric_rows(sw, U, Z, full, A):
    """A[r] = (L δq [, L δv], δq, δv) for the vector rows r of Z, with M = LᵀL at the state's
    q, L = diag(sw) Uᵀ (`_metric_factor`)."""
    n = U.shape[0]
    m = 2 * n if full else n
    for r in range(Z.shape[0] - 1):
        for a in range(n):
            s = sw[a]
            lq = 0.0
            lv = 0.0
            for i in range(n):
                lq += U[i, a] * Z[1 + r, i]
                lv += U[i, a] * Z[1 + r, n + i]
            A[r, a] = s * lq
            if full:
                A[r, n + a] = s * lv
        for i in range(2 * n):
            A[r, m + i] = Z[1 + r, i]


#: The arrays and sizes of the flow's RK4 hooks (``work`` of ``charts.solvers.rk.rk4_stages``):
#: the parameters p, Z = [y; X], shape (1 + k, 2n), and its stage point Zs, with their flat
#: views Zf, Zsf (length L = (1 + k)·2n), the stage rates K, shape (4, 1 + k, 2n), and its flat
#: view Kf (stage st at offset st·L), `_rate`'s arrays jq, jv, jt and lin (its ``work``: the
#: KKT matrix, its pivots and the right-hand sides), and L.
FlowStep = namedtuple("FlowStep", ["p", "Z", "Zf", "Zs", "Zsf", "K", "Kf", "jq", "jv", "jt",
                                   "lin", "L"])


@njit(cache=True, inline="always")
def _flow_start(w, jets):
    """`rk4_stages`' stage 0 of the flow: the rates at Z itself into K[0]."""
    _rate(jets, w.p, w.Z, w.K[0], w.jq, w.jv, w.jt, w.lin)
    return 0.0, 1


@njit(cache=True, inline="always")
def _flow_point(w, st, a):
    """`rk4_stages`' stage point of the flow: Zs = Z + a·K[st − 1] (`rk4_point`, flat)."""
    rk4_point(w.Zf, w.Kf, np.uint64(st - 1) * w.L, a, w.L, w.Zsf)


@njit(cache=True, inline="always")
def _flow_rate(w, jets, st, hmin):
    """`rk4_stages`' stage rates of the flow at Zs into K[st] (`_rate`)."""
    _rate(jets, w.p, w.Zs, w.K[st], w.jq, w.jv, w.jt, w.lin)
    return hmin


@njit(cache=True, inline="always")
def _flow_combine(w, h):
    """`rk4_stages`' end of the flow: Z from Z and the stages, in place (`rk4_combine`)."""
    rk4_combine(w.Zf, w.Kf, h, w.L, w.Zf)


def _advance(jets, p, Z, first, steps, reorth, h, full, logs, wts, A, jq, jv, jt, work, K, Zs,
             project, periodic, eye):
    """``steps`` RK4 steps of Z = [y; X] (step numbers first + 1 …; `rk4_stages` with the
    `FlowStep` hooks, stage rates in K, shape (4, 1 + k, 2n)), the vectors re-orthonormalised
    after every step number divisible by ``reorth`` (their log-norms added to ``logs``) and
    everything projected (`_project`) after every one divisible by ``project`` (0: never).
    Returns the steps taken, negated where a projection was refused (after that step, which
    is taken but not projected)."""
    n = jq.shape[0]
    m = 2 * n if full else n
    w = FlowStep(p, Z, Z.reshape(-1), Zs, Zs.reshape(-1), K, K.reshape(-1), jq, jv, jt, work,
                 np.uint64(Z.size))
    for s in range(steps):
        rk4_stages(w, jets, h, _flow_start, _flow_point, _flow_rate, _flow_combine)
        if (first + s + 1) % reorth == 0 and Z.shape[0] > 1:
            for i in range(n):
                jq[i] = Z[0, i]
            if not work[4]:                 # (a constant metric: its factor, computed once)
                _jets_at(jets, p, jq, jt)
                _metric_factor(jt[4], work[11], work[12])
            _metric_rows(work[11], work[12], Z, full, A)
            orthonormalize(A, wts, logs)
            for r in range(Z.shape[0] - 1):
                for i in range(2 * n):
                    Z[1 + r, i] = A[r, m + i]
        if project and (first + s + 1) % project == 0:
            if not _project(jets, p, Z, periodic, eye, jq, jt, work):
                return -(s + 1)
    return steps


def _jets_types(p, Z, first, steps, reorth, h, full, logs, wts, A, jq, jv, jt, work, K, Zs,
                *_):
    """The argument types the driver calls the jets function with (``CallsKernel``)."""
    return (jq, p) + tuple(jt.types)


class MechanismTangentFlow(StackedFlow):
    """A mechanism's state and ``k`` phase tangent vectors under its flow (module docstring).

    Parameters
    ----------
    mech : Mechanism
    q0, v0 : ndarray, shape (n,)
        A point on F = 0 and a tangent velocity there.
    k : int
        Number of tangent vectors (0: the state alone); at most d = n − k_F with ``inner``
        "theta" (the position parts must stay independent), 2d with "full".
    dt : float
        RK4 step.
    reorth, project : int
        Steps between re-orthonormalisations and between projections (0: never project).
    inner : {"theta", "full"}
    seed : int
        Seed of the random initial vectors (Gaussian, projected, orthonormalised).

    Attributes: ``y`` (2n,) the state (q, v); ``X`` (k, 2n) the vectors (δq, δv); ``logsum``
    (k,) the summed log-norms; ``steps`` the steps taken.
    """

    def __init__(self, mech, q0, v0, k, *, dt, reorth, project, inner="theta", seed=0):
        n = mech.n
        if inner not in INNER_PRODUCTS:
            raise MechanismError(f"inner must be one of {INNER_PRODUCTS}, got {inner!r}")
        kmax = (2 if inner == "full" else 1) * mech.dim
        if not 0 <= int(k) <= kmax:
            raise MechanismError(f"k={k} tangent vectors: a {mech.dim}-dimensional manifold has "
                                 f"room for 0..{kmax} with inner={inner!r}")
        self.mech, self.n, self.k = mech, n, int(k)
        self.dt, self.reorth, self.project = float(dt), int(reorth), int(project)
        self.full = inner == "full"
        q0 = mech.check_point(q0, tol=1e-10)
        v0 = mech.check_tangent(q0, v0, "v0")
        self.Z = np.zeros((1 + self.k, 2 * n))
        self.Z[0] = np.concatenate([q0, v0])
        rng = np.random.default_rng(int(seed))
        for r in range(self.k):
            dq, dv = mech.project_phase_tangent(q0, v0, *rng.normal(size=(2, n)))
            self.Z[1 + r] = np.concatenate([dq, dv])
        self.logsum = np.zeros(self.k)
        self.counter = np.zeros(1, dtype=np.int64)          # the steps taken (`steps`)
        m = 2 * n if self.full else n
        self._wts = np.concatenate([np.ones(m), np.zeros(2 * n)])
        self._A = np.zeros((self.k, m + 2 * n))
        self._jq, self._jv = np.zeros(n), np.zeros(n)
        # the jets' arrays: zeroed once, the compiled function writes the non-zero entries
        self._jt = tuple(np.zeros(mech._eval(key, q0).shape) for key in JET_ORDER)
        nk = n + mech.k
        flat = bool(mech.constant_metric)
        mech.compiled_jets()(q0, mech.param_values, *self._jt)     # M as the flow reads it
        M0 = self._jt[4].copy()
        sw, U = np.zeros(n), np.zeros((n, n))
        _metric_factor(M0, sw, U)
        # the Schur complement where M is constant and definite (a massless joint keeps the
        # KKT matrix): M⁻¹ once, conditioned well enough that it loses no more than KKT's LU
        schur = flat and sw.min() ** 2 > SCHUR_COND * sw.max() ** 2
        self._work = (np.zeros((nk, nk)), np.zeros(nk, dtype=np.int64), np.zeros((nk, 1 + self.k)),
                      np.zeros((nk, 2 * n)), flat, bool(schur),
                      np.linalg.inv(M0) if schur else np.zeros((n, n)), np.zeros((n, mech.k)),
                      np.zeros((mech.k, mech.k)), np.zeros(mech.k, dtype=np.int64), np.zeros(n),
                      sw, U)
        self._K = np.zeros((4,) + self.Z.shape)                # the RK4 stages' rates
        self._Zs = np.zeros_like(self.Z)
        self._periodic = np.asarray(mech._periodic_mask, dtype=np.bool_)
        self._eye = np.eye(n)
        self._driver = _driver_of(mech)
        if self.k:
            self._orthonormalize(np.zeros(self.k))

    def energy(self) -> float:
        """T = ½ vᵀ M(q) v of the state."""
        return self.mech.energy(self.Z[0, :self.n], self.Z[0, self.n:])

    def _orthonormalize(self, logs):
        """Gram–Schmidt of the vectors now (log-norms added to ``logs``)."""
        sw, U = np.zeros(self.n), np.zeros((self.n, self.n))
        _metric_factor(self.mech.mass_matrix(self.Z[0, :self.n]), sw, U)
        _metric_rows(sw, U, self.Z, self.full, self._A)
        orthonormalize(self._A, self._wts, logs)
        m = self._A.shape[1] - 2 * self.n
        self.Z[1:] = self._A[:, m:]

    def project_now(self):
        """The state onto F = 0 and ker J (its angles taken into (−π, π], so that they keep
        their precision over long runs), the vectors onto the tangent space of TC."""
        n, mech = self.n, self.mech
        q = mech.wrap_angles(mech.project_point(self.Z[0, :n]))   # (the jets are periodic)
        v = mech.project_velocity(q, self.Z[0, n:])
        self.Z[0] = np.concatenate([q, v])
        for r in range(self.k):
            dq, dv = mech.project_phase_tangent(q, v, self.Z[1 + r, :n], self.Z[1 + r, n:])
            self.Z[1 + r] = np.concatenate([dq, dv])

    def advance(self, steps):
        """``steps`` RK4 steps, compiled, projected every ``project`` steps (compiled; where
        it refuses, by `project_now`, which raises a `MechanismError` saying why or projects)."""
        left = int(steps)
        while left > 0:
            done = self._driver(self.mech.param_values, self.Z, self.steps, left, self.reorth,
                                self.dt, self.full, self.logsum, self._wts, self._A, self._jq,
                                self._jv, self._jt, self._work, self._K, self._Zs, self.project,
                                self._periodic, self._eye)
            refused, done = done < 0, abs(done)
            self.counter[0] += done
            left -= done
            if not np.all(np.isfinite(self.Z)):
                raise MechanismError(f"{self.mech.name}: the tangent flow left the finite numbers "
                                     f"after {self.steps} steps of dt={self.dt:g} (a singular "
                                     "point, or dt too large)")
            if refused:
                self.project_now()


def _driver_of(mech):
    """The compiled driver for ``mech``'s jets function (one per symbolic model, shared by
    its ``with_parameters`` copies; the driver's own code is compiled once and cached)."""
    jets = mech.compiled_jets()
    num = mech._num                                 # (shared by the copies, as the jets)
    if "driver" not in num:
        num["driver"] = CallsKernel(_advance, (jets, _jets_types), error_model="numpy", **NO_REFCOUNT)
    return num["driver"]
