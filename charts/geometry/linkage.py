"""The flat four-rotor linkage of the paper's Appendix: its configuration manifold, the
projections onto its invariants and the degeneracy of its kinetic metric.

Coordinates q = (θ₀, θ₁, θ₂, θ₃, x, y, α), shape (7,): the rotor angles and the disk's centre
and angle.  The manifold M = {F(q) = 0} (four constraints, ``charts.codegen.linkage``) is
3-dimensional.  Kinetic metric: T = ½ vᵀ M v with M = diag(1, 1, 1, 1, m_d, m_d, I_d); the
Appendix has massless disk (m_d = I_d = 0), the metric Σ dθᵢ² pulled back to M.

Degeneracy.  Write J = ∂F/∂q = [A | C] with A = ∂F/∂θ (4 × 4, diagonal: constraint i holds
only θᵢ) and C = ∂F/∂(x, y, α) (4 × 3).  A tangent vector with dθ = 0 is a δ(x, y, α) with
C δ = 0: the disk moves while the rotors stand still.  So the pulled-back metric is positive
definite exactly where C has rank 3; with m_d = I_d = 0 the flow needs that.  For ε → 0,
ρ = rε the Appendix's first-order solution has cos α = (cos θ₁ + cos θ₃)/(2r) and C loses rank
where sin α = 0, i.e. |cos θ₁ + cos θ₃| = 2r: never for r > 1, on two of the six cone points
of Σ cos θ = 0 for r = 1, on a fold bounding the reachable angles for r < 1.  The default
ρ = 2ε keeps |cos α| ≤ ½.  A small disk mass and moment of inertia make the metric
positive definite everywhere on M (``LinkageSystem(disk_mass=…, disk_inertia=…)``).

State y = (q, v), shape (14,); tangent vectors ξ = (δq, δv), shape (14,).  Invariants:
F(q) = 0, J(q) v = 0, and the energy ½ vᵀ M v.  Perturbations that keep them form
T_r = {J δq = 0, J δv + H(δq) v = 0} (H(w) = ∂J/∂q·w), which the flow preserves.
The position projection is a Euclidean minimum-norm Newton step in R⁷, the velocity
projection is orthogonal in the kinetic metric (a KKT solve), the tangent-vector projection
Euclidean.
"""
from __future__ import annotations

import math

import numpy as np
from ..jit import njit

from ..codegen.shipped import import_shipped
from .checks import finite_array, integer, number, shown
from .projection import rescale_speed
from .system import RotorSystem

__all__ = ["LinkageSystem", "NQ", "NC", "gen_constraints", "gen_jacobian", "gen_hessian_vector",
           "gen_third_form", "lu_factor", "lu_solve", "project_configuration",
           "project_velocity_linkage", "kkt_matrix", "project_state_linkage", "project_tangent_linkage", "PROJ_OK", "PROJ_SHAPE",
           "PROJ_SINGULAR", "PROJ_ZERO_SPEED"]

_gen = import_shipped("linkage")
NQ = _gen.NQ
NC = _gen.NC
#: The range of the crank ε and the disk radius ρ: [LENGTH_MIN, LENGTH_MAX).  Above, the
#: Appendix's small-linkage picture fails (rods R = 1, axes at distance 1).  Below about
#: 2.5e-7 the kinetic projection's KKT matrix (entries of order ε²) falls under its pivot
#: threshold and the rotor angles jump 0.1 rad off both the ε → 0 limit and the trend of
#: larger ε (``python scripts/linkage_eps_floor.py``, docs/linkage.md): the floor keeps a
#: factor four from that edge.
LENGTH_MIN = 1e-6
LENGTH_MAX = 0.5
#: The generated kernels (``generated/linkage.py``), compiled.
gen_constraints = njit(cache=True)(_gen.constraints)
gen_jacobian = njit(cache=True)(_gen.jacobian)
gen_hessian_vector = njit(cache=True)(_gen.hessian_vector)
gen_third_form = njit(cache=True)(_gen.third_form)

#: |F| and |J v| above which a state is refused as off the manifold.
TOL = 1e-8
#: Length of ``par`` = (ε, ρ, R, m_d, I_d) that the kernels read.
NPAR = 5
#: J Jᵀ is taken as singular (the four constraints dependent, M not a manifold there) where
#: the smallest singular value of J is below this fraction of the largest.
RANK_TOL = 1e-12

#: Statuses of the compiled projections: done; arrays of the wrong shape (nothing written);
#: J Jᵀ singular (the constraints lose rank); a speed asked of a velocity without energy.
PROJ_OK = 0
PROJ_SHAPE = -1
PROJ_SINGULAR = -2
PROJ_ZERO_SPEED = -3


@njit(cache=True)
def lu_factor(A, piv):
    """LU factorisation with partial pivoting of the square A, in place; ``piv`` (n,) int.
    Returns the smallest |pivot|: 0 for a singular matrix, a non-finite pivot, or arrays of
    shapes that do not fit (A not square, ``piv`` shorter than n).  ``piv`` is always filled
    with rows in range (the identity past a zero pivot), so `lu_solve` never indexes outside
    the arrays even when called after a failed factorisation."""
    n = A.shape[0]
    if A.shape[1] != n or piv.shape[0] < n:
        return 0.0
    for k in range(n):
        piv[k] = k
    pmin = 1e300
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(A[i, k]) > abs(A[p, k]):
                p = i
        piv[k] = p
        if p != k:
            for j in range(n):
                A[k, j], A[p, j] = A[p, j], A[k, j]
        if not (abs(A[k, k]) > 0.0 and abs(A[k, k]) < np.inf):
            return 0.0
        pmin = min(pmin, abs(A[k, k]))
        for i in range(k + 1, n):
            A[i, k] /= A[k, k]
            for j in range(k + 1, n):
                A[i, j] -= A[i, k] * A[k, j]
    return pmin


@njit(cache=True)
def lu_solve(A, piv, b):
    """Solve with the factors of `lu_factor`; b (n,) is overwritten by the solution.
    Returns True; False (b untouched) where the shapes do not fit, a pivot row is out of
    range or a diagonal entry is zero (factors of a singular matrix)."""
    n = A.shape[0]
    if A.shape[1] != n or piv.shape[0] < n or b.shape[0] != n:
        return False
    for k in range(n):
        if piv[k] < k or piv[k] >= n or A[k, k] == 0.0:
            return False
    for k in range(n):
        p = piv[k]
        if p != k:
            b[k], b[p] = b[p], b[k]
    for i in range(n):
        for j in range(i):
            b[i] -= A[i, j] * b[j]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, n):
            b[i] -= A[i, j] * b[j]
        b[i] /= A[i, i]
    return True


@njit(cache=True)
def _gram(J, G, piv):
    """G = J Jᵀ (4 × 4), factorised."""
    for i in range(NC):
        for k in range(NC):
            acc = 0.0
            for j in range(NQ):
                acc += J[i, j] * J[k, j]
            G[i, k] = acc
    return lu_factor(G, piv)


@njit(cache=True)
def _remove(J, G, piv, r, x):
    """x −= Jᵀ (J Jᵀ)⁻¹ r: the minimum-norm correction that changes J x by −r.  Returns
    False (x untouched) where the factors of J Jᵀ are those of a singular matrix."""
    if not lu_solve(G, piv, r):
        return False
    for j in range(NQ):
        acc = 0.0
        for i in range(NC):
            acc += J[i, j] * r[i]
        x[j] -= acc
    return True


@njit(cache=True)
def project_configuration(q, par, iterations):
    """Newton steps q −= Jᵀ(JJᵀ)⁻¹F onto F = 0, in place (stop once max|F| < 1e-15).
    Returns the final max|F|; inf (q as reached) where q or par is too short or J Jᵀ is
    singular at an iterate (the constraints lose rank there)."""
    if q.shape[0] < NQ or par.shape[0] < NPAR:
        return np.inf
    F = np.empty(NC)
    J = np.empty((NC, NQ))
    G = np.empty((NC, NC))
    piv = np.empty(NC, dtype=np.int64)
    res = 0.0
    for _ in range(iterations):
        gen_constraints(q, par, F)
        res = np.max(np.abs(F))
        if res < 1e-15:
            break
        gen_jacobian(q, par, J)
        if _gram(J, G, piv) == 0.0 or not _remove(J, G, piv, F, q):
            return np.inf
    gen_constraints(q, par, F)
    return np.max(np.abs(F))


@njit(cache=True)
def kkt_matrix(J, par, K):
    """The saddle-point matrix [[M, Jᵀ], [J, 0]], shape (11, 11), into K; par = (ε, ρ, R, m_d,
    I_d) and M = diag(1, 1, 1, 1, m_d, m_d, I_d).  Invertible exactly where M is positive
    definite on ker J (module doc)."""
    K[:, :] = 0.0
    for j in range(4):
        K[j, j] = 1.0
    K[4, 4] = par[3]
    K[5, 5] = par[3]
    K[6, 6] = par[4]
    for i in range(NC):
        for j in range(NQ):
            K[NQ + i, j] = J[i, j]
            K[j, NQ + i] = J[i, j]


@njit(cache=True)
def project_velocity_linkage(q, v, par):
    """v ← the tangent vector (J v = 0) nearest v in the kinetic metric, in place: the KKT
    solve [[M, Jᵀ], [J, 0]] (v', μ) = (M v, 0).  For a massless disk the θ-part is projected
    Σ dθ²-orthogonally and the disk's velocity follows from it.  Where the KKT matrix is
    singular (degenerate metric) the Euclidean projection v −= Jᵀ(JJᵀ)⁻¹ J v is used.
    Returns `PROJ_OK`; `PROJ_SHAPE` (nothing done) for arrays too short, `PROJ_SINGULAR`
    (v untouched) where J Jᵀ is singular too."""
    if q.shape[0] < NQ or v.shape[0] < NQ or par.shape[0] < NPAR:
        return PROJ_SHAPE
    J = np.empty((NC, NQ))
    gen_jacobian(q, par, J)
    K = np.empty((NQ + NC, NQ + NC))
    piv = np.empty(NQ + NC, dtype=np.int64)
    kkt_matrix(J, par, K)
    if lu_factor(K, piv) > 1e-12:
        b = np.zeros(NQ + NC)
        for j in range(NQ):
            b[j] = _kinetic_mass(par, j) * v[j]
        if lu_solve(K, piv, b):
            v[:NQ] = b[:NQ]
            return PROJ_OK
    G = np.empty((NC, NC))
    pg = np.empty(NC, dtype=np.int64)
    if _gram(J, G, pg) == 0.0:
        return PROJ_SINGULAR
    r = J @ v[:NQ]
    return PROJ_OK if _remove(J, G, pg, r, v) else PROJ_SINGULAR


@njit(cache=True, inline="always")
def _kinetic_mass(par, j):
    """Mⱼⱼ of the kinetic metric (see `kkt_matrix`)."""
    return 1.0 if j < 4 else (par[3] if j < 6 else par[4])


@njit(cache=True)
def project_state_linkage(y, par, mass, speed):
    """Put y = (q, v) back on F = 0 (3 Newton steps), J v = 0 (`project_velocity_linkage`;
    par = (ε, ρ, R, m_d, I_d)) and, if ``speed`` > 0,
    vᵀ M v = speed² (`charts.geometry.projection.rescale_speed`), in place.  Returns
    `PROJ_OK`; `PROJ_SHAPE` (y untouched) for y, par or mass too short; `PROJ_SINGULAR`
    where J Jᵀ is singular (the constraints lose rank); `PROJ_ZERO_SPEED` (v left as
    projected) where a speed is asked of a velocity without kinetic energy."""
    if y.shape[0] < 2 * NQ or par.shape[0] < NPAR or mass.shape[0] < NQ:
        return PROJ_SHAPE
    q = y[:NQ]
    v = y[NQ:2 * NQ]
    if not project_configuration(q, par, 3) < np.inf:
        return PROJ_SINGULAR
    status = project_velocity_linkage(q, v, par)
    if status != PROJ_OK:
        return status
    if speed > 0.0:
        E = 0.0
        for j in range(NQ):
            E += mass[j] * v[j] * v[j]
        if not E > 0.0:
            return PROJ_ZERO_SPEED
        rescale_speed(y, NQ, NQ, mass, speed)
    return PROJ_OK


@njit(cache=True)
def project_tangent_linkage(y, X, par):
    """Project each row (δq, δv) of X, shape (k, 14), onto T_r at y (module doc).  Returns
    `PROJ_OK`; `PROJ_SHAPE` (X untouched) for y shorter than 14, rows of X not of length 14
    or par too short; `PROJ_SINGULAR` (X untouched) where J Jᵀ is singular at y."""
    if y.shape[0] < 2 * NQ or X.shape[1] != 2 * NQ or par.shape[0] < NPAR:
        return PROJ_SHAPE
    q = y[:NQ]
    v = y[NQ:2 * NQ]
    J = np.empty((NC, NQ))
    G = np.empty((NC, NC))
    H = np.empty((NC, NQ))
    piv = np.empty(NC, dtype=np.int64)
    gen_jacobian(q, par, J)
    if _gram(J, G, piv) == 0.0:
        return PROJ_SINGULAR
    for r in range(X.shape[0]):
        dq = X[r, :NQ]
        dv = X[r, NQ:]
        _remove(J, G, piv, J @ dq, dq)
        gen_hessian_vector(q, dq, par, H)
        _remove(J, G, piv, J @ dv + H @ v, dv)
    return PROJ_OK


class LinkageSystem:
    """The linkage of the Appendix with crank ε, disk radius ρ (default 2ε), rods R = 1, unit
    rotor moments, and disk mass ``disk_mass`` and moment ``disk_inertia`` (default 0: the
    Appendix's massless disk; see the module doc for when that needs the disk's inertia).

    ``par`` = (ε, ρ, R, m_d, I_d) for the kernels; ``mass`` = diag(M), shape (7,).
    """

    n = 4
    dim = 3

    def __init__(self, eps, rho=None, *, disk_mass=0.0, disk_inertia=0.0):
        eps = _length("eps", eps)
        rho = 2.0 * eps if rho is None else _length("rho", rho)
        if not rho < LENGTH_MAX:
            raise ValueError(f"rho = 2 eps = {rho:g} must be < {LENGTH_MAX:g}: pass a smaller "
                             "eps or rho explicitly")
        dm = _nonnegative("disk_mass", disk_mass)
        di = _nonnegative("disk_inertia", disk_inertia)
        self.eps, self.rho = eps, rho
        self.disk_mass, self.disk_inertia = dm, di
        self.par = np.array([eps, rho, 1.0, dm, di])
        self.mass = np.array([1.0, 1.0, 1.0, 1.0, dm, dm, di])

    def __repr__(self):
        return (f"LinkageSystem(eps={self.eps:g}, rho={self.rho:g}, disk_mass={self.disk_mass:g}, "
                f"disk_inertia={self.disk_inertia:g})")

    @property
    def massless_disk(self) -> bool:
        return self.disk_mass == 0.0 or self.disk_inertia == 0.0

    # ------------------------------------------------------------------ evaluation
    def constraints(self, q):
        """F(q), shape (4,); q is checked (shape (7,), finite) before the compiled kernel."""
        return gen_constraints(finite_array("q", q, (NQ,)), self.par, np.empty(NC))

    def jacobian(self, q):
        """J = ∂F/∂q, shape (4, 7); q is checked (shape (7,), finite) first."""
        return gen_jacobian(finite_array("q", q, (NQ,)), self.par, np.empty((NC, NQ)))

    def constraint_rank_margin(self, q) -> float:
        """Smallest over largest singular value of J at q (0 where the four constraints are
        dependent: J Jᵀ is singular and no projection onto M is defined there)."""
        s = np.linalg.svd(self.jacobian(q), compute_uv=False)
        return float(s[-1] / s[0]) if s[0] > 0 else 0.0

    def _check_rank(self, name, q, what):
        margin = self.constraint_rank_margin(q)
        if not margin > RANK_TOL:
            raise ValueError(
                f"{name} = {np.array2string(np.asarray(q), precision=4)} is a singular "
                f"configuration of the linkage: the constraints' Jacobian J has dependent rows "
                f"there (smallest/largest singular value {margin:.1e} <= {RANK_TOL:g}), so "
                f"{what}; start from another point, e.g. LinkageSystem.random_state or "
                "from_rotor_state")

    def disk_margin(self, q) -> float:
        """Smallest singular value of C = ∂F/∂(x, y, α) with the α column divided by ρ
        (dimensionless; 0 where the pulled-back metric degenerates, module doc)."""
        C = self.jacobian(q)[:, 4:].copy()
        C[:, 2] /= self.rho
        return float(np.linalg.svd(C, compute_uv=False)[-1])

    def speed(self, v) -> float:
        """Kinetic speed √(Σ mᵢ vᵢ²) of v (7,); ValueError naming v unless finite, of that
        shape and within a float's range."""
        v = finite_array("v", v, (NQ,))
        with np.errstate(over="ignore"):
            s = float(np.sqrt(np.sum(self.mass * v * v)))
        if not np.isfinite(s):
            raise ValueError("v is too large: its kinetic speed is beyond a float's range")
        return s

    def check_state(self, q, v, names=("q", "v")):
        """Validated float copies of (q, v), shape (7,) each; ValueError off the manifold,
        naming the bad one by ``names`` (the caller's names, e.g. ("q0", "v0"))."""
        if not (isinstance(names, tuple) and len(names) == 2
                and all(isinstance(s, str) and s for s in names)):
            raise TypeError(f"names must be a pair of non-empty str, got {shown(names)}")
        nq, nv = names
        q = finite_array(nq, q, (NQ,)).copy()
        v = finite_array(nv, v, (NQ,)).copy()
        F = np.max(np.abs(self.constraints(q)))
        if F > TOL:
            raise ValueError(f"{nq} is off the linkage's manifold (max|F| = {F:.2e} > {TOL:g}); "
                             "use LinkageSystem.project(q, v) or random_state")
        with np.errstate(over="ignore", invalid="ignore"):
            Jv = np.max(np.abs(self.jacobian(q) @ v))
        if not Jv <= TOL * max(1.0, np.max(np.abs(v))):
            raise ValueError(f"{nv} is not tangent to the manifold (max|J v| = {Jv:.2e}); "
                             "use LinkageSystem.project(q, v)")
        self._check_rank(nq, q, "the linkage has no tangent space there to move in")
        return q, v

    # ------------------------------------------------------------------ states
    def project(self, q, v, speed=None):
        """(q, v) moved onto F = 0 and J v = 0 (and to kinetic ``speed`` if given): new
        arrays.  ValueError naming the argument for q or v not of shape (7,) or not finite,
        ``speed`` not a finite number >= 0, a singular configuration q (J Jᵀ singular: the
        Newton step is undefined), a q the Newton steps do not bring onto M, and a speed asked
        of a velocity without a tangent component."""
        y = np.concatenate([finite_array("q", q, (NQ,)), finite_array("v", v, (NQ,))])
        if speed is not None:
            speed = _nonnegative("speed", speed)
        self._check_rank("q", y[:NQ], "the Newton step onto the manifold is undefined")
        res = project_configuration(y[:NQ], self.par, 50)
        if not res < 1e-13:
            raise ValueError(f"could not put q on the manifold (max|F| = {res:.1e} after 50 "
                             "Newton steps); start nearer, e.g. from_rotor_state")
        status = project_state_linkage(y, self.par, self.mass, 0.0 if speed is None else speed)
        if status == PROJ_SINGULAR:
            self._check_rank("q", y[:NQ], "the tangent space is undefined")
            raise ValueError("q was projected onto a point where J Jᵀ is numerically singular; "
                             "start from another point, e.g. LinkageSystem.random_state")
        if status == PROJ_ZERO_SPEED:
            raise ValueError(f"v has no component tangent to the manifold at q, so it cannot be "
                             f"given the speed {speed:g}; pass a velocity with a tangent part "
                             "(e.g. from random_state) or speed=None")
        if status != PROJ_OK:
            raise ValueError(f"the projection of (q, v) failed (status {status}); check that q "
                             "and v have shape (7,)")
        return y[:NQ].copy(), y[NQ:].copy()

    def first_order_disk(self, theta, branch=1):
        """(x, y, α) of the Appendix's first-order solution for the angles theta: x = ε(c₂ −
        c₀)/2, y = ε(c₁ − c₃)/2, cos α = ε(c₁ + c₃)/(2ρ), sign of sin α = ``branch``."""
        branch = _branch(branch)
        c = np.cos(finite_array("theta", theta, (4,)))
        ca = np.clip(self.eps * (c[1] + c[3]) / (2.0 * self.rho), -1.0, 1.0)
        return np.array([self.eps * (c[2] - c[0]) / 2, self.eps * (c[1] - c[3]) / 2,
                         math.copysign(math.acos(ca), branch)])

    def from_rotor_state(self, theta, u, branch=1):
        """The linkage state nearest a state (θ, u) of Σ cos θ = 0: the first-order disk, then
        projected onto the invariants with θ-speed |u| (the ε → 0 comparison)."""
        theta = finite_array("theta", theta, (4,))
        u = finite_array("u", u, (4,))
        q = np.concatenate([theta, self.first_order_disk(theta, branch)])
        return self.project(q, np.concatenate([u, np.zeros(3)]),
                            speed=float(np.linalg.norm(u)) if self.massless_disk else None)

    def describe(self) -> dict:
        """The system as the settings of a result (``params``): the rotor count (4), ε, ρ, the
        disk's mass and moment."""
        return dict(n=self.n, eps=self.eps, rho=self.rho, disk_mass=self.disk_mass,
                    disk_inertia=self.disk_inertia)

    def random_state(self, seed=0, speed=1.0, branch=1):
        """A random state on M (the disk on ``branch``) with a random tangent velocity of
        kinetic speed ``speed``.

        The angles are the rotor state's of the same seed, ``RotorSystem(4).random_state(seed)``
        (uniform θ₀…θ₂ with |Σ cos| ≤ 1, random sign of sin θ₃, on Σ cos θ = 0), moved onto M
        by `from_rotor_state` (the first-order disk, then the Newton projection).  M lies O(ε)
        off Σ cos θ = 0, so the angles differ from the rotor's by O(ε), not by 0: max over i
        of |Δθᵢ| = c ε + O(ε²) with c set by the state, over seeds 0–19 from 0.055 (seed 1) to
        3.02 (seed 7), mean 1.19, for ε = 10⁻³ and 10⁻⁴ (0.040 to 3.11 at ε = 0.1;
        ``python scripts/linkage_seeds.py``).  The velocity is drawn anew in the linkage's
        seven coordinates (stream seed + 7919) and projected: it is not the rotor state's
        (max |Δθ̇ᵢ| 0.14 to 1.69 at speed 1 over those seeds), nor, therefore, is the
        trajectory.  `from_rotor_state` starts from a given rotor state, velocity included."""
        seed = integer("seed", seed, 0)
        theta, u = RotorSystem(4).random_state(seed=seed, speed=1.0)
        q, v = self.from_rotor_state(theta, u, branch)
        v = np.random.default_rng(seed + 7919).normal(size=NQ)
        return self.project(q, v, speed=_positive("speed", speed))


def _branch(branch) -> int:
    """``branch``: +1 or −1, the sign of sin α of the disk (ValueError otherwise)."""
    if isinstance(branch, bool) or np.ndim(branch) != 0 or branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1 (the sign of sin α), got {shown(branch)}")
    return int(branch)


def _length(name, x) -> float:
    """ε or ρ as a float in [`LENGTH_MIN`, `LENGTH_MAX`); ValueError naming it otherwise."""
    x = number(name, x)
    if not LENGTH_MIN <= x < LENGTH_MAX:
        raise ValueError(
            f"{name} = {x:g} is outside [{LENGTH_MIN:g}, {LENGTH_MAX:g}): above, the linkage is "
            "not small against its rods R = 1 (the Appendix); below, the kinetic projection "
            "loses its digits (docs/linkage.md)")
    return x


def _nonnegative(name, x) -> float:
    x = number(name, x)
    if not x >= 0:
        raise ValueError(f"{name} must be a finite number >= 0, got {x!r}")
    return x


def _positive(name, x) -> float:
    x = number(name, x)
    if not x > 0:
        raise ValueError(f"{name} must be a positive finite number, got {x!r}")
    return x
