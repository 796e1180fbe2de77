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
``project`` steps, between compiled segments, the state is projected back onto F = 0 and
ker J and the vectors onto the tangent space of TC (``project_point``, ``project_velocity``,
``project_phase_tangent``; NumPy, once per segment of many steps).

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
from ..solvers.rk import rk4_combine, rk4_point, rk4_stages
from ..solvers.tangent import StackedFlow
from .errors import MechanismError
from .kernels import kkt_matrix, motion_rhs, tangent_motion_rhs
from .symbolic import JET_ORDER

__all__ = ["MechanismTangentFlow", "INNER_PRODUCTS"]

#: The inner products of eq (18) on a mechanism's phase tangent vectors (module docstring).
INNER_PRODUCTS = ("theta", "full")


@njit(cache=True)
def _rate(jets, p, Z, out, jq, jv, jt, work):
    """out = d/dt Z for Z = [y; X], shape (1 + kv, 2n): the ambient flow of the state (row 0)
    and its linearisation for the vector rows.  ``jt``: the jets (J, F2, F3, M, dM, d2M),
    ``jq``, ``jv``: the state's q and v, ``work``: (KKT matrix, rhs, tangent rhs)."""
    J, F2, F3, M, dM, d2M = jt
    K, b, R = work
    n = jq.shape[0]
    kv = Z.shape[0] - 1
    for i in range(n):
        jq[i] = Z[0, i]
        jv[i] = Z[0, n + i]
    jets(jq, p, J, F2, F3, M, dM, d2M)
    kkt_matrix(M, J, -1.0, K)
    motion_rhs(dM, F2, jv, b)
    x = np.linalg.solve(K, b)
    for i in range(n):
        out[0, i] = jv[i]
        out[0, n + i] = x[i]
    if kv == 0:
        return
    for r in range(kv):
        tangent_motion_rhs(dM, d2M, F2, F3, jv, x, Z[1 + r, :n], Z[1 + r, n:], R[:, r])
    D = np.linalg.solve(K, R)
    for r in range(kv):
        for i in range(n):
            out[1 + r, i] = Z[1 + r, n + i]
            out[1 + r, n + i] = D[i, r]


@njit(cache=True)
def _metric_rows(M, Z, full, A):
    """A[r] = (L δq [, L δv], δq, δv) for the vector rows r of Z, with M = M(q) at the state's
    q = LᵀL (from its eigenvalues, negative rounding clipped)."""
    n = M.shape[0]
    w, U = np.linalg.eigh(M)
    m = 2 * n if full else n
    for r in range(Z.shape[0] - 1):
        for a in range(n):
            s = np.sqrt(max(w[a], 0.0))
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
#: KKT matrix and the right-hand sides), and L.
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


def _advance(jets, p, Z, first, steps, reorth, h, full, logs, wts, A, jq, jv, jt, work, K, Zs):
    """``steps`` RK4 steps of Z = [y; X] (step numbers first + 1 …; `rk4_stages` with the
    `FlowStep` hooks, stage rates in K, shape (4, 1 + k, 2n)), the vectors re-orthonormalised
    after every step number divisible by ``reorth`` (their log-norms added to ``logs``)."""
    n = jq.shape[0]
    m = 2 * n if full else n
    w = FlowStep(p, Z, Z.reshape(-1), Zs, Zs.reshape(-1), K, K.reshape(-1), jq, jv, jt, work,
                 np.uint64(Z.size))
    for s in range(steps):
        rk4_stages(w, jets, h, _flow_start, _flow_point, _flow_rate, _flow_combine)
        if (first + s + 1) % reorth == 0 and Z.shape[0] > 1:
            for i in range(n):
                jq[i] = Z[0, i]
            jets(jq, p, jt[0], jt[1], jt[2], jt[3], jt[4], jt[5])
            _metric_rows(jt[3], Z, full, A)
            orthonormalize(A, wts, logs)
            for r in range(Z.shape[0] - 1):
                for i in range(2 * n):
                    Z[1 + r, i] = A[r, m + i]


def _jets_types(p, Z, first, steps, reorth, h, full, logs, wts, A, jq, jv, jt, work, K, Zs):
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
        self._work = (np.zeros((nk, nk)), np.zeros(nk), np.zeros((nk, max(self.k, 1))))
        self._K = np.zeros((4,) + self.Z.shape)                # the RK4 stages' rates
        self._Zs = np.zeros_like(self.Z)
        self._driver = _driver_of(mech)
        if self.k:
            self._orthonormalize(np.zeros(self.k))

    def energy(self) -> float:
        """T = ½ vᵀ M(q) v of the state."""
        return self.mech.energy(self.Z[0, :self.n], self.Z[0, self.n:])

    def _orthonormalize(self, logs):
        """Gram–Schmidt of the vectors now (log-norms added to ``logs``)."""
        _metric_rows(self.mech.mass_matrix(self.Z[0, :self.n]), self.Z, self.full, self._A)
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
        """``steps`` RK4 steps (compiled segments, projected every ``project`` steps)."""
        left = int(steps)
        while left > 0:
            seg = left if not self.project else min(left, self.project - self.steps % self.project)
            self._driver(self.mech.param_values, self.Z, self.steps, seg, self.reorth, self.dt,
                         self.full, self.logsum, self._wts, self._A, self._jq, self._jv,
                         self._jt, self._work, self._K, self._Zs)
            self.counter[0] += seg
            left -= seg
            if not np.all(np.isfinite(self.Z)):
                raise MechanismError(f"{self.mech.name}: the tangent flow left the finite numbers "
                                     f"after {self.steps} steps of dt={self.dt:g} (a singular "
                                     "point, or dt too large)")
            if self.project and self.steps % self.project == 0:
                self.project_now()


def _driver_of(mech):
    """The compiled driver for ``mech``'s jets function (one per symbolic model, shared by
    its ``with_parameters`` copies; the driver's own code is compiled once and cached)."""
    jets = mech.compiled_jets()
    num = mech._num                                 # (shared by the copies, as the jets)
    if "driver" not in num:
        num["driver"] = CallsKernel(_advance, (jets, _jets_types))
    return num["driver"]
