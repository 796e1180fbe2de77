"""Reference scenarios of the test suite, in one place (STYLE.md sections 6 and 9).

Like JiTCODE's ``tests/scenarios.py``: every route to a number (generated code, live SymPy,
finite differences, closed forms, chart vs chart, chart vs ambient, the runner, the command
line) is checked against the same values, and those values live here:

* the paper's printed numbers (section 2) and the project's own full-preset reference values
  (``charts reproduce --full``, docs/reproduce.md);
* mass sets and initial states (seeds with a meaning, and the explicit states tests use);
* closed forms written from the paper *independently of the package* (plain NumPy, no import
  of ``charts``): eq (8), eq (13), eq (15), eq (22) and the Gauss equation of the hypersurface.
  A package formula is only ever compared with one of these or with another route, never with
  a copy of itself;
* named tolerances, each with the reason for its size (``TOL``).

This module imports nothing from ``charts`` except in :func:`state` (which only draws inputs).
"""
from __future__ import annotations

import math

import numpy as np

# ------------------------------------------------------------------------ the paper's values
#: Lyapunov exponents printed in section 2 (unit speed, equal masses), largest first,
#: transcribed from the paper (not from charts.runs.paper).
PAPER_EXPONENTS = {3: (0.500,), 4: (0.385, 0.230), 5: (0.298, 0.227, 0.121)}

# --------------------------------------------------------- the project's own reference values
#: ``charts reproduce --full`` (8 independent trajectories x t = 2.5e4 per N, unit speed, equal
#: masses, RK4 dt = 0.01), as re-run after the one-engine rewrite (docs/reproduce.md): leading
#: exponents and two-sided standard errors.  The paper's values lie within 2.4 s.e. of these
#: (the run before the rewrite gave 0.5021, 0.3857/0.2274, 0.2981/0.2257/0.1237, within 2
#: combined s.e. of these).
REFERENCE_EXPONENTS = {3: (0.5004,), 4: (0.3843, 0.2292), 5: (0.2977, 0.2255, 0.1227)}
REFERENCE_STDERR = {3: (0.0005,), 4: (0.0008, 0.0006), 5: (0.0007, 0.0006, 0.0007)}
#: same run, 10^6 angle samples per N: the N = 3 minimum angles (rad) of the two variants.
REFERENCE_N3_MIN_ANGLE = {"full": 0.265, "restricted": 0.588}
#: same run: fraction of samples with K_ii > 0 (exact route), i = 1..N-2.
REFERENCE_FRACTION_POSITIVE = {3: (0.0,), 4: (0.0643, 0.1074), 5: (0.1334, 0.1931, 0.3087)}

# ------------------------------------------------------------------------ named tolerances
TOL = {
    # pure rounding of sums of O(10) terms of size O(1) (a few hundred ulp)
    "round": 1e-12,
    # closed forms (13), (15) vs generated code: the same rational functions of sin/cos
    # evaluated in a different order, ~1e2 ulp at well-conditioned points
    "closed_form": 1e-12,
    # closed forms for N = 7 (terms of O(1e2) size: the metric has entries up to
    # m_k/(1 - C^2) ~ 1e2 at the points used), relative to the largest entry
    "closed_form_n7": 1e-11,
    # exact sectional curvature (generated Riemann tensor) vs the Gauss equation: rounding in
    # the O(1e3)-term Riemann expressions and in the frame, relative
    "gauss": 1e-8,
    # central differences with h = 1e-6: truncation ~h^2 = 1e-12, cancellation ~1e-16/h =
    # 1e-10 relative to |f|; allow 1e-8 of the largest Jacobian entry
    "fd_jacobian": 1e-8,
    # two-sided statistical margin in standard errors: |z| > 4 has probability 6e-5
    "n_sigma": 4.0,
    # the acceptance band around the paper's three-digit exponents (the paper's rounding and
    # up to ~2 units of its third digit against our full-preset reference)
    "paper_band": 0.004,
    # one DOP853 step of h = 0.1 on the harmonic oscillator (omega = 2): the 8th-order local
    # error is ~(omega h)^9/9! ~ 1e-12
    "dop853_one_step": 1e-12,
    # our DOP853 step against SciPy's DOP853 on the same step (same tableau, same formulas,
    # different summation order): a few ulp of the state
    "dop853_vs_scipy_state": 1e-15,
    # the same for the error norm, relative, on top of the rounding of the cancelling sum
    # Σ E_j K_j that it measures (bounded in the test): ~1e2 ulp of a ratio of sums of squares
    "dop853_vs_scipy_error": 1e-10,
}


# ------------------------------------------------------------------------------- masses
#: Named mass sets.  "mixed": the general unequal case of the Lyapunov, curvature and integrate
#: API tests; "heavy_last": one heavy rotor; "strong": a factor 12 between extremes;
#: "n7": the N = 7 on-demand geometry.
MASSES = {
    "mixed": {4: (1.0, 2.0, 0.5, 1.5), 5: (1.0, 1.3, 0.7, 2.0, 1.1)},
    "heavy_last": {3: (1.0, 1.0, 4.0), 4: (1.0, 1.0, 1.0, 4.0)},
    "strong": {3: (0.25, 3.0, 1.0), 5: (0.25, 1.0, 3.0, 1.0, 0.6)},
    "n7": {7: (0.5, 1.0, 2.0, 0.8, 1.5, 3.0, 1.2)},
}


def masses(kind: str, n: int) -> np.ndarray:
    """Masses of ``kind`` for N = ``n``: a named set above, or "equal" (all 1), "ramp"
    (0.4..2.5 decreasing, the generated-geometry tests) or "linear" (0.7..1.6, the integrator
    accuracy tests)."""
    if kind == "equal":
        return np.ones(n)
    if kind == "ramp":
        return np.linspace(0.4, 2.5, n)[::-1].copy()
    if kind == "linear":
        return np.linspace(0.7, 1.6, n)
    return np.array(MASSES[kind][n], dtype=float)


# ------------------------------------------------------------------------------- states
#: Seeds with a meaning.  "paper": the statistical runs compared with the paper's values;
#: "angles": the section 4 runs of tests/test_hyperbolicity.py; "many_switches": (n, unequal,
#: seed, tau) whose chart run switches at least 10 times before t = 20 ("linear" masses when
#: unequal).
SEEDS = {
    "paper": 1,
    "angles": 1,
    "many_switches": [(3, False, 3, 0.9), (3, True, 18, 0.9), (4, False, 4, 0.9),
                      (4, True, 2, 0.9), (5, False, 6, 0.9), (5, True, 1, 0.95)],
}


def state(n: int, seed: int, masses_=None, speed: float = 1.0):
    """(system, theta, u): ``RotorSystem(n, masses_).random_state(seed, speed)``."""
    from charts import RotorSystem

    system = RotorSystem(n, masses_)
    theta, u = system.random_state(seed=seed, speed=speed)
    return system, theta, u


#: An exact point of the N = 3 manifold, 2 cos(2π/3) + cos 0 = 0, and a tangent velocity.
EXACT_N3 = ((2 * math.pi / 3, 2 * math.pi / 3, 0.0), (1.0, -1.0, 0.0))
#: One of the eight N = 3 points where all cosines vanish: K = 0 there (eq 22).
FLAT_N3 = (math.pi / 2, -math.pi / 2, math.pi / 2)
#: The N = 4 singular point (all sin θ = 0 on the manifold): no tangent space.
SINGULAR_N4 = (0.0, 0.0, math.pi, math.pi)


def singular_line_n4(a: float = 1.0):
    """(theta, u): the unit-speed straight geodesic (a − t/2, a − t/2, π − a + t/2,
    π − a + t/2) (Λ = 0), which reaches the singular point (0, 0, π, π) at t = 2a."""
    theta = np.array([a, a, math.pi - a, math.pi - a])
    u = np.array([-1.0, -1.0, 1.0, 1.0]) / 2.0
    return theta, u


#: The straight N = 4 geodesic θ(t) = S + (t − 1)v, v = (0.6, 0.8, 0.6, 0.8)/√2, on the
#: manifold for all t, through the singular point S at t = 1 (scenes of the runner and CLI tests).
_V = np.array([0.6, 0.8, 0.6, 0.8]) / math.sqrt(2.0)
THROUGH_SINGULAR_N4 = (tuple(np.array(SINGULAR_N4) - _V), tuple(_V))


def near_singular_n4(delta: float, seed: int = 0):
    """(theta, u): a point at distance ≈ δ√2 from (0, 0, π, π), generic unit velocity
    (equal masses)."""
    x0, x1, y2 = 0.6 * delta, 0.8 * delta, 0.7 * delta
    y3 = math.acos(math.cos(x0) + math.cos(x1) - math.cos(y2))
    theta = project_point(np.array([x0, x1, math.pi + y2, math.pi - y3]), np.ones(4))
    u = project_tangent(theta, np.random.default_rng(seed).normal(size=4), np.ones(4))
    return theta, u / math.sqrt(u @ u)


def chart_edge_n3(sin0: float):
    """(theta, u), N = 3, equal masses: θ0 = ``sin0`` (so |sin θ0| ≈ sin0, near the edge of
    chart 0), θ1 = 2, unit velocity with u0 < 0, i.e. heading for the edge sin θ0 = 0."""
    theta = np.array([sin0, 2.0, 0.0])
    theta[2] = -math.acos(-math.cos(theta[0]) - math.cos(theta[1]))
    theta = project_point(theta, np.ones(3))
    u = project_tangent(theta, np.array([-1.0, 0.3, -0.2]), np.ones(3))
    return theta, u / math.sqrt(u @ u)


# ----------------------------------------------------- manifold helpers (plain NumPy)
def project_point(theta, m, iterations=50):
    """Newton along M⁻¹∇F onto Σ cos θ = 0."""
    theta = np.array(theta, dtype=float)
    for _ in range(iterations):
        s = np.sin(theta)
        F = np.cos(theta).sum()
        theta += F / np.sum(s * s / m) * s / m
        if abs(F) < 1e-15:
            break
    return theta


def project_tangent(theta, v, m):
    """M-orthogonal projection of v onto {Σ vᵢ sin θᵢ = 0}."""
    s = np.sin(theta)
    v = np.asarray(v, dtype=float)
    return v - (v @ s) / np.sum(s * s / m) * s / m


def tangent_basis(theta):
    """Euclidean-orthonormal basis of T = {v : Σ sin θᵢ vᵢ = 0}, shape (N, N−1); T does not
    depend on the masses."""
    n = len(theta)
    s = np.sin(theta)[:, None]
    q, _ = np.linalg.qr(np.hstack([s, np.eye(n)[:, : n - 1]]))
    return q[:, 1:]


# --------------------------------------------------------- closed forms (the paper, by hand)
def eq8_rhs(y, m):
    """Eq (8) with masses: θ̇ = u, mᵢu̇ᵢ = −Λ sin θᵢ, Λ = Σ u² cos θ / Σ sin²θ/m."""
    y = np.asarray(y, dtype=float)
    n = y.size // 2
    theta, u = y[:n], y[n:]
    s, c = np.sin(theta), np.cos(theta)
    lam = np.sum(u * u * c) / np.sum(s * s / m)
    return np.concatenate([u, -lam * s / m])


def metric_eq13(theta, k, m):
    """Eq (13) in chart k with masses: g_αβ = m_α δ_αβ + m_k sin θ_α sin θ_β / sin²θ_k,
    sin²θ_k = 1 − C², C = Σ_{α≠k} cos θ_α (α, β ≠ k in increasing order)."""
    theta = np.asarray(theta, dtype=float)
    idx = [i for i in range(len(theta)) if i != k]
    s, C = np.sin(theta[idx]), np.cos(theta[idx]).sum()
    return np.diag(np.asarray(m)[idx]) + m[k] * np.outer(s, s) / (1 - C * C)


def christoffel_eq15(theta, k, m):
    """Eq (15) with masses: Γ^a_bc = (sin θ_a / m_a)(δ_bc cos θ_b − C s_b s_c/(1 − C²))
    / (Σ_α sin²θ_α/m_α + (1 − C²)/m_k); unit masses give the paper's expression."""
    theta = np.asarray(theta, dtype=float)
    m = np.asarray(m, dtype=float)
    idx = [i for i in range(len(theta)) if i != k]
    s, c, ml = np.sin(theta[idx]), np.cos(theta[idx]), m[idx]
    C = c.sum()
    inner = np.diag(c) - C * np.outer(s, s) / (1 - C * C)
    denom = np.sum(s * s / ml) + (1 - C * C) / m[k]
    return (s / ml)[:, None, None] * inner[None, :, :] / denom


def gaussian_curvature_eq22(theta):
    """Eq (22): K = −Σ cos²θ / (2 (Σ sin²θ)²), N = 3, equal masses; theta (..., 3)."""
    theta = np.asarray(theta, dtype=float)
    return -(np.cos(theta) ** 2).sum(-1) / (2.0 * ((np.sin(theta) ** 2).sum(-1)) ** 2)


def gauss_sectional_curvature(theta, v, w, m):
    """Sectional curvature of the plane (v, w) of the hypersurface F = Σ cos θ = 0 in
    (Rᴺ, diag m), by the Gauss equation: K = [h(v,v)h(w,w) − h(v,w)²] / (|∇F|²_{M⁻¹}
    (|v|²|w|² − ⟨v,w⟩²)_M), h = Hess F = −diag(cos θ), |∇F|² = Σ sin²θ/m."""
    theta, v, w, m = (np.asarray(a, dtype=float) for a in (theta, v, w, m))
    c = np.cos(theta)
    h = lambda a, b: -np.sum(c * a * b)
    ip = lambda a, b: np.sum(m * a * b)
    area2 = ip(v, v) * ip(w, w) - ip(v, w) ** 2
    return float((h(v, v) * h(w, w) - h(v, w) ** 2) / (np.sum(np.sin(theta) ** 2 / m) * area2))


def rel_err(a, b):
    """max |a − b| / max |b| (relative to the largest entry of the reference b)."""
    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))
