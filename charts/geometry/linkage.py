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

import importlib
import math

import numpy as np
from numba import njit

from .projection import rescale_speed
from .system import RotorSystem

__all__ = ["LinkageSystem", "NQ", "NC", "gen_constraints", "gen_jacobian", "gen_hessian_vector",
           "gen_third_form", "lu_factor", "lu_solve", "project_configuration",
           "project_velocity_linkage", "kkt_matrix", "project_state_linkage", "project_tangent_linkage"]

_gen = importlib.import_module("charts.generated.linkage")
NQ = _gen.NQ
NC = _gen.NC
#: The generated kernels (``generated/linkage.py``), compiled.
gen_constraints = njit(cache=True)(_gen.constraints)
gen_jacobian = njit(cache=True)(_gen.jacobian)
gen_hessian_vector = njit(cache=True)(_gen.hessian_vector)
gen_third_form = njit(cache=True)(_gen.third_form)

#: |F| and |J v| above which a state is refused as off the manifold.
TOL = 1e-8


@njit(cache=True)
def lu_factor(A, piv):
    """LU factorisation with partial pivoting of the square A, in place; ``piv`` (n,) int.
    Returns the smallest |pivot| (0 for a singular matrix)."""
    n = A.shape[0]
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
        pmin = min(pmin, abs(A[k, k]))
        if A[k, k] == 0.0:
            return 0.0
        for i in range(k + 1, n):
            A[i, k] /= A[k, k]
            for j in range(k + 1, n):
                A[i, j] -= A[i, k] * A[k, j]
    return pmin


@njit(cache=True)
def lu_solve(A, piv, b):
    """Solve with the factors of `lu_factor`; b (n,) is overwritten by the solution."""
    n = A.shape[0]
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
    """x −= Jᵀ (J Jᵀ)⁻¹ r: the minimum-norm correction that changes J x by −r."""
    lu_solve(G, piv, r)
    for j in range(NQ):
        acc = 0.0
        for i in range(NC):
            acc += J[i, j] * r[i]
        x[j] -= acc


@njit(cache=True)
def project_configuration(q, par, iterations):
    """Newton steps q −= Jᵀ(JJᵀ)⁻¹F onto F = 0, in place (stop once max|F| < 1e-15).
    Returns the final max|F|."""
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
        _gram(J, G, piv)
        _remove(J, G, piv, F, q)
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
    singular (degenerate metric) the Euclidean projection v −= Jᵀ(JJᵀ)⁻¹ J v is used."""
    J = np.empty((NC, NQ))
    gen_jacobian(q, par, J)
    K = np.empty((NQ + NC, NQ + NC))
    piv = np.empty(NQ + NC, dtype=np.int64)
    kkt_matrix(J, par, K)
    if lu_factor(K, piv) > 1e-12:
        b = np.zeros(NQ + NC)
        for j in range(NQ):
            b[j] = _kinetic_mass(par, j) * v[j]
        lu_solve(K, piv, b)
        v[:] = b[:NQ]
        return
    G = np.empty((NC, NC))
    pg = np.empty(NC, dtype=np.int64)
    _gram(J, G, pg)
    r = J @ v
    _remove(J, G, pg, r, v)


@njit(cache=True, inline="always")
def _kinetic_mass(par, j):
    """Mⱼⱼ of the kinetic metric (see `kkt_matrix`)."""
    return 1.0 if j < 4 else (par[3] if j < 6 else par[4])


@njit(cache=True)
def project_state_linkage(y, par, mass, speed):
    """Put y = (q, v) back on F = 0 (3 Newton steps), J v = 0 (`project_velocity_linkage`;
    par = (ε, ρ, R, m_d, I_d)) and, if ``speed`` > 0,
    vᵀ M v = speed² (`charts.geometry.projection.rescale_speed`), in place."""
    q = y[:NQ]
    v = y[NQ:]
    project_configuration(q, par, 3)
    project_velocity_linkage(q, v, par)
    if speed > 0.0:
        rescale_speed(y, NQ, NQ, mass, speed)


@njit(cache=True)
def project_tangent_linkage(y, X, par):
    """Project each row (δq, δv) of X, shape (k, 14), onto T_r at y (module doc)."""
    q = y[:NQ]
    v = y[NQ:]
    J = np.empty((NC, NQ))
    G = np.empty((NC, NC))
    H = np.empty((NC, NQ))
    piv = np.empty(NC, dtype=np.int64)
    gen_jacobian(q, par, J)
    _gram(J, G, piv)
    for r in range(X.shape[0]):
        dq = X[r, :NQ]
        dv = X[r, NQ:]
        _remove(J, G, piv, J @ dq, dq)
        gen_hessian_vector(q, dq, par, H)
        _remove(J, G, piv, J @ dv + H @ v, dv)


class LinkageSystem:
    """The linkage of the Appendix with crank ε, disk radius ρ (default 2ε), rods R = 1, unit
    rotor moments, and disk mass ``disk_mass`` and moment ``disk_inertia`` (default 0: the
    Appendix's massless disk; see the module doc for when that needs the disk's inertia).

    ``par`` = (ε, ρ, R, m_d, I_d) for the kernels; ``mass`` = diag(M), shape (7,).
    """

    n = 4
    dim = 3

    def __init__(self, eps, rho=None, *, disk_mass=0.0, disk_inertia=0.0):
        eps = _positive("eps", eps)
        rho = 2.0 * eps if rho is None else _positive("rho", rho)
        if not eps < 0.5 or not rho < 0.5:
            raise ValueError(f"eps={eps:g} and rho={rho:g} must be < 0.5 (small against the rods "
                             "R = 1 and the axes at distance 1, as in the Appendix)")
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
        return gen_constraints(np.asarray(q, dtype=float), self.par, np.empty(NC))

    def jacobian(self, q):
        return gen_jacobian(np.asarray(q, dtype=float), self.par, np.empty((NC, NQ)))

    def disk_margin(self, q) -> float:
        """Smallest singular value of C = ∂F/∂(x, y, α) with the α column divided by ρ
        (dimensionless; 0 where the pulled-back metric degenerates, module doc)."""
        C = self.jacobian(q)[:, 4:].copy()
        C[:, 2] /= self.rho
        return float(np.linalg.svd(C, compute_uv=False)[-1])

    def speed(self, v) -> float:
        v = np.asarray(v, dtype=float)
        return float(np.sqrt(np.sum(self.mass * v * v)))

    def check_state(self, q, v):
        """Validated float copies of (q, v), shape (7,) each; ValueError off the manifold."""
        q = _vector("q", q)
        v = _vector("v", v)
        F = np.max(np.abs(self.constraints(q)))
        if F > TOL:
            raise ValueError(f"q is off the linkage's manifold (max|F| = {F:.2e} > {TOL:g}); "
                             "use LinkageSystem.project(q, v) or random_state")
        Jv = np.max(np.abs(self.jacobian(q) @ v))
        if Jv > TOL * max(1.0, np.max(np.abs(v))):
            raise ValueError(f"v is not tangent to the manifold (max|J v| = {Jv:.2e}); "
                             "use LinkageSystem.project(q, v)")
        return q, v

    # ------------------------------------------------------------------ states
    def project(self, q, v, speed=None):
        """(q, v) moved onto F = 0 and J v = 0 (and to ``speed`` if given): new arrays."""
        y = np.concatenate([_vector("q", q), _vector("v", v)])
        res = project_configuration(y[:NQ], self.par, 50)
        if not res < 1e-13:
            raise ValueError(f"could not put q on the manifold (max|F| = {res:.1e} after 50 "
                             "Newton steps); start nearer, e.g. from_rotor_state")
        project_state_linkage(y, self.par, self.mass, 0.0 if speed is None else float(speed))
        return y[:NQ].copy(), y[NQ:].copy()

    def first_order_disk(self, theta, branch=1):
        """(x, y, α) of the Appendix's first-order solution for the angles theta: x = ε(c₂ −
        c₀)/2, y = ε(c₁ − c₃)/2, cos α = ε(c₁ + c₃)/(2ρ), sign of sin α = ``branch``."""
        c = np.cos(np.asarray(theta, dtype=float))
        ca = np.clip(self.eps * (c[1] + c[3]) / (2.0 * self.rho), -1.0, 1.0)
        return np.array([self.eps * (c[2] - c[0]) / 2, self.eps * (c[1] - c[3]) / 2,
                         math.copysign(math.acos(ca), branch)])

    def from_rotor_state(self, theta, u, branch=1):
        """The linkage state nearest a state (θ, u) of Σ cos θ = 0: the first-order disk, then
        projected onto the invariants with θ-speed |u| (the ε → 0 comparison)."""
        theta = np.asarray(theta, dtype=float)
        u = np.asarray(u, dtype=float)
        q = np.concatenate([theta, self.first_order_disk(theta, branch)])
        return self.project(q, np.concatenate([u, np.zeros(3)]),
                            speed=float(np.linalg.norm(u)) if self.massless_disk else None)

    def random_state(self, seed=0, speed=1.0, branch=1):
        """A random state on M (uniform θ₀…θ₂ with |Σ cos| ≤ 1, random sign of sin θ₃, the
        disk on ``branch``) with a random tangent velocity of kinetic speed ``speed``."""
        theta, u = RotorSystem(4).random_state(seed=seed, speed=1.0)
        q, v = self.from_rotor_state(theta, u, branch)
        v = np.random.default_rng(seed + 7919).normal(size=NQ)
        return self.project(q, v, speed=_positive("speed", speed))


def _positive(name, x) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} must be a number, got {type(x).__name__}")
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name} must be a positive finite number, got {x!r}")
    return float(x)


def _nonnegative(name, x) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} must be a number, got {type(x).__name__}")
    if not (math.isfinite(x) and x >= 0):
        raise ValueError(f"{name} must be a finite number >= 0, got {x!r}")
    return float(x)


def _vector(name, x):
    a = np.array(x, dtype=float)
    if a.shape != (NQ,):
        raise ValueError(f"{name} must have shape ({NQ},) = (θ₀…θ₃, x, y, α), got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} has non-finite entries")
    return a
