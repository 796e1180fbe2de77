"""The compiled projections of the flat four-rotor linkage of the paper's Appendix, on its
generated kernels (the linkage itself, a `charts.Mechanism`, is
``charts.mechanism.linkage.LinkageSystem``; its degeneracy is described there).

Coordinates q = (θ₀, θ₁, θ₂, θ₃, x, y, α), shape (7,): the rotor angles and the disk's centre
and angle.  The manifold M = {F(q) = 0} (four constraints, ``charts.codegen.linkage``) is
3-dimensional.  Kinetic metric: T = ½ vᵀ M v with M = diag(1, 1, 1, 1, m_d, m_d, I_d); the
Appendix has massless disk (m_d = I_d = 0), the metric Σ dθᵢ² pulled back to M.

State y = (q, v), shape (14,); tangent vectors ξ = (δq, δv), shape (14,).  Invariants:
F(q) = 0, J(q) v = 0, and the energy ½ vᵀ M v.  Perturbations that keep them form
T_r = {J δq = 0, J δv + H(δq) v = 0} (H(w) = ∂J/∂q·w), which the flow preserves.
The position projection is a Euclidean minimum-norm Newton step in R⁷, the velocity
projection is orthogonal in the kinetic metric (a KKT solve), the tangent-vector projection
Euclidean.
"""
from __future__ import annotations

import numpy as np
from ..jit import njit

from ..codegen.shipped import import_shipped
from .projection import rescale_speed

__all__ = ["NQ", "NC", "gen_constraints", "gen_jacobian", "gen_hessian_vector",
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
