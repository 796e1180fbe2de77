"""Integrals over the closed surface of three rotors: its area, its total curvature (the
Gauss–Bonnet theorem) and the bracket that the classical inequalities put on the leading
Lyapunov exponent of the geodesic flow.

**Quadrature.**  The surface S: Σ aᵢ cos θᵢ = c in T³ (N = 3, metric Σ mᵢ dθᵢ²) is covered by
the three charts (chart k eliminates θₖ, two branches sin θₖ ≷ 0).  A smooth partition of
unity wₖ = |aₖ sin θₖ|ᵖ / Σₗ |aₗ sin θₗ|ᵖ splits every integrand among them, and in chart k
the integral over its square [−π, π)² is the periodic trapezoidal rule of n_grid² points,
with the area element (eq 13: det g = Πm · |∇F|²_{M⁻¹} / (aₖ sin θₖ)²)

    dA = √(Πmᵢ · Σᵢ (aᵢ sin θᵢ)²/mᵢ) / |aₖ sin θₖ| dθ_α dθ_β.

Where chart k ends (sin θₖ → 0) wₖ dA vanishes like |sin θₖ|ᵖ⁻¹, so the integrand is
smooth enough (p = 8) for the trapezoidal rule to converge fast: ∫K dA meets 2πχ to 1e-11
relative at n_grid = 512 (tests/test_surface_integrals.py).

**Gauss–Bonnet.**  ∫_S K dA = 2πχ(S), χ from the Morse count of ``charts.geometry.topology``
(no metric): an exact invariant that the curvature routes (the generated chart Riemann tensor
and the ambient Gauss equation, ``charts.analyses.exact_curvature``) must reproduce for every
masses, weights and smooth level.

**The entropy bracket.**  At unit speed (Σ mᵢuᵢ² = 1) on a connected surface with χ < 0,
the Liouville entropy of the geodesic flow — its leading exponent λ₁, by Pesin's formula, for
the paper's Anosov case — obeys

    ⟨√(−K)⟩_A  ≤  λ₁  ≤  √(2π|χ| / A),

Katok's upper bound (Ergodic Theory Dynam. Systems 2, 1982: for every metric on a surface of
genus ≥ 2, with equality only at constant curvature) and Osserman–Sarnak's lower bound
(Invent. Math. 77, 1984: the mean of √(−K) over the area, for K ≤ 0).  Where K ≤ 0, Jensen's
inequality orders the two, and by Gauss–Bonnet the upper bound is also √⟨−K⟩_A.
"""
from __future__ import annotations

import math
import numpy as np
from ..jit import njit

from ..geometry.checks import integer, option
from ..geometry.projection import tangent_part
from ..solvers.gram_schmidt import orthonormal_rows
from ..solvers.tangent import check_memory, memory_budget
from ..geometry.surface_quadrature import (POU_POWER, SurfaceIntegrals, integrals_from_nodes,
                                           partition_of_unity, torus_grid)
from ..geometry.topology import euler_characteristic
from .exact_curvature import exact_curvatures
from .arguments import rotor_system
from .mechanism_route import mechanism_route

__all__ = ["SurfaceIntegrals", "surface_integrals", "surface_plan", "surface_nodes",
           "tangent_frames", "POU_POWER"]

#: Bytes per cell of the n_grid² grid that `surface_integrals` holds at its peak: nodes,
#: frames and curvatures of both branches of three charts (515–526 measured as the growth
#: of the peak RSS at n_grid = 1024 and 2048, both routes).
BYTES_PER_CELL = 600


def _surface_system(system):
    if system.n != 3:
        raise ValueError(f"surface integrals are over the surface of N = 3 rotors (a 2-manifold: "
                         f"Gauss–Bonnet); got N = {system.n}")
    return system


def surface_nodes(system, n_grid=256):
    """Quadrature nodes and weights on the surface of ``system`` (N = 3): (theta, dA, chart),
    theta shape (S, 3) the points, dA (S,) the weights (area element × partition of unity ×
    grid cell), chart (S,) the chart each node belongs to; Σ f(theta) dA ≈ ∫_S f dA."""
    _surface_system(system)
    n_grid = integer("n_grid", n_grid, 8, 1 << 14)
    a, m, c = system.weights, system.masses, system.level
    ti, tj, h = torus_grid(n_grid)
    thetas, weights, charts_ = [], [], []
    for k in range(3):
        i, j = [q for q in range(3) if q != k]
        C = a[i] * np.cos(ti) + a[j] * np.cos(tj) - c          # = −aₖ cos θₖ
        D = a[k] ** 2 - C ** 2                                 # = (aₖ sin θₖ)²
        inside = D > 0.0
        Ci, Di = C[inside], D[inside]
        for branch in (1.0, -1.0):
            theta = np.empty((Ci.size, 3))
            theta[:, i] = ti[inside]
            theta[:, j] = tj[inside]
            theta[:, k] = np.arctan2(branch * np.sqrt(Di), -Ci)  # aₖ(sin, cos) = (±√D, −C)
            s = np.abs(a * np.sin(theta))
            s[:, k] = np.sqrt(Di)                              # the chart's own |aₖ sin θₖ|
            pou = partition_of_unity(s, k)       # s[:, k]ᵖ / Σ sᵖ, p = POU_POWER
            dA = np.sqrt(np.prod(m) * np.sum(s ** 2 / m, axis=1)) / s[:, k]
            thetas.append(theta)
            weights.append(pou * dA * h * h)
            charts_.append(np.full(Ci.size, k))
    return np.concatenate(thetas), np.concatenate(weights), np.concatenate(charts_)


def tangent_frames(system, theta):
    """M-orthonormal frames (p₀, p₁) of the surface's tangent planes at theta (S, 3): the
    coordinate directions of the best chart there (``RotorSystem.best_chart``: the two angles
    it keeps, far from the normal) projected M-orthogonally onto the tangent plane
    (``charts.geometry.projection.tangent_part``) and orthonormalised
    (``charts.solvers.gram_schmidt.orthonormal_rows``); shape (S, 2, 3)."""
    theta = np.ascontiguousarray(theta, dtype=float)
    chart = np.asarray(system.best_chart(theta), dtype=np.int64).reshape(-1)
    keep = np.array([[q for q in range(3) if q != k] for k in range(3)], dtype=np.int64)[chart]
    P = np.empty((theta.shape[0], 2, 3))
    _frames(theta, keep, system.minv, system.weights, system.masses, P)
    return P


@njit(cache=True)
def _frames(theta, keep, minv, a, m, P):
    for i in range(theta.shape[0]):
        for r in range(2):
            e = np.zeros(3)
            e[keep[i, r]] = 1.0
            P[i, r] = tangent_part(theta[i], e, minv, a)
        orthonormal_rows(P[i], m)


def surface_plan(system, n_grid=256, route="chart"):
    """(n_grid, route) of `surface_integrals` checked before any work: N = 3, ``n_grid`` an
    integer in 8..16384 whose n_grid² cells fit the memory budget (`BYTES_PER_CELL` each),
    ``route`` "chart" or "gauss"; ValueError naming the argument otherwise."""
    _surface_system(system)
    n_grid = integer("n_grid", n_grid, 8, 1 << 14)
    check_memory(BYTES_PER_CELL * n_grid ** 2, f"the quadrature on {n_grid}² cells would",
                 f"use n_grid <= {math.isqrt(memory_budget() // BYTES_PER_CELL)} (n_grid = 512 "
                 "already gives ∫K dA to 1e-9, docs/hyperbolicity.md)")
    route = option("route", route, ("chart", "gauss"))
    return n_grid, route


@mechanism_route("mechanism_surface", "mechanism_surface_integrals")
def surface_integrals(system, n_grid=256, route="chart") -> SurfaceIntegrals:
    """Area, total curvature, χ and the entropy bracket of the surface of ``system`` (N = 3,
    any masses, weights and smooth level), by the quadrature of `surface_nodes` with the
    curvature from ``route`` (``"chart"``: the generated Riemann tensor; ``"gauss"``: the
    Gauss equation, ``charts.analyses.exact_curvature``).  Every argument is checked before
    any work (`surface_plan`).  Another ``charts.Mechanism`` of dimension 2 goes to
    ``charts.mechanism.surface.surface_integrals`` (χ read from ∫K dA / 2π there)."""
    rotor_system(system)
    n_grid, route = surface_plan(system, n_grid, route)
    chi = euler_characteristic(system.weights, system.level)
    theta, dA, _ = surface_nodes(system, n_grid)
    K = exact_curvatures(system, theta, tangent_frames(system, theta), route)[:, 0, 0]
    return integrals_from_nodes(K, dA, chi, n_grid, route, system.describe())
