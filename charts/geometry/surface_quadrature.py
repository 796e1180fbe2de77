"""The quadrature shared by the surface integrals of three rotors
(``charts.analyses.surface_integrals``) and of a mechanism's configuration surface
(``charts.mechanism.surface``): the periodic trapezoidal grid of an angle chart, the smooth
partition of unity between charts, and the reduction of curvatures at weighted nodes to
`SurfaceIntegrals` (area, ∫K dA, mean √(−K), max K, share of area with K > 0).

Each chart c is a square [−π, π)² of two angles with the trapezoidal rule on n_grid² nodes;
its score s_c at a point vanishes where the chart ends, and the partition of unity
ψ_c = s_cᵖ / Σ s_lᵖ (p = `POU_POWER`) makes ψ_c dA vanish there like s_cᵖ⁻¹, smooth enough
for the trapezoidal rule to converge fast.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

__all__ = ["POU_POWER", "SurfaceIntegrals", "torus_grid", "partition_of_unity",
           "integrals_from_nodes"]

#: Power p of the partition of unity s_kᵖ / Σ s_lᵖ between the charts (for the rotors
#: s_k = |aₖ sin θₖ|).
POU_POWER = 8


def torus_grid(n_grid):
    """The nodes of the periodic trapezoidal rule on a chart's square [−π, π)²: (ti, tj, h),
    ti and tj shape (n_grid²,) the two angles of each node, h the grid step."""
    h = 2.0 * np.pi / n_grid
    x = -np.pi + h * np.arange(n_grid)
    ti, tj = (g.ravel() for g in np.meshgrid(x, x, indexing="ij"))
    return ti, tj, h


def partition_of_unity(s, k):
    """The share of chart k at each node: s[:, k]ᵖ / Σ_l s[:, l]ᵖ (p = `POU_POWER`), s shape
    (S, C) the scores of the C charts at S nodes."""
    return s[:, k] ** POU_POWER / np.sum(s ** POU_POWER, axis=1)


def integrals_from_nodes(K, dA, euler_characteristic, n_grid, route, params):
    """`SurfaceIntegrals` from the curvature K (S,) at quadrature nodes of weights dA (S,)."""
    area = float(np.sum(dA))
    return SurfaceIntegrals(
        area=area, total_curvature=float(np.sum(K * dA)),
        euler_characteristic=int(euler_characteristic),
        mean_sqrt_neg_curvature=float(np.sum(np.sqrt(np.maximum(-K, 0.0)) * dA) / area),
        max_curvature=float(K.max()), positive_area=float(np.sum(dA[K > 0.0]) / area),
        n_grid=int(n_grid), route=route, params=params)


@dataclass(frozen=True)
class SurfaceIntegrals:
    """The integrals over a closed surface of ``charts.analyses.surface_integrals`` (three
    rotors; lengths in rad of the metric Σ m dθ²) and ``charts.mechanism.surface`` (a
    mechanism's configuration surface).

    area : A = ∫ dA;  total_curvature : ∫ K dA;  euler_characteristic : χ (for the rotors by the Morse count
    of ``charts.geometry.topology``);  mean_sqrt_neg_curvature : (1/A) ∫ √max(−K, 0) dA;
    max_curvature : the largest K at the nodes;  positive_area : the fraction of the area
    where K > 0;  n_grid, route, params : how they were computed.
    """
    area: float
    total_curvature: float
    euler_characteristic: int
    mean_sqrt_neg_curvature: float
    max_curvature: float
    positive_area: float
    n_grid: int
    route: str
    params: dict

    @property
    def gauss_bonnet_error(self) -> float:
        """∫ K dA − 2πχ: zero by the Gauss–Bonnet theorem, up to the quadrature's error."""
        return self.total_curvature - 2.0 * np.pi * self.euler_characteristic

    def entropy_bracket(self):
        """(lower, upper) bounds of the leading exponent λ₁ at unit speed
        (the docstring of ``charts.analyses.surface_integrals``):
        Osserman–Sarnak's mean √(−K), None unless K ≤ 0 at every node, and Katok's
        √(2π|χ|/A), None unless χ < 0."""
        upper = float(np.sqrt(2.0 * np.pi * abs(self.euler_characteristic) / self.area)) \
            if self.euler_characteristic < 0 else None
        lower = self.mean_sqrt_neg_curvature if self.max_curvature <= 0.0 else None
        return lower, upper

    def to_dict(self) -> dict:
        out = asdict(self)
        out["gauss_bonnet_error"] = self.gauss_bonnet_error
        out["entropy_bracket"] = list(self.entropy_bracket())
        return out
