"""Integrals over the configuration surface of a Mechanism of dimension 2: area, ∫K dA (the
Gauss–Bonnet theorem), the mean √(−K), the largest K and the share of area where K > 0.

**Quadrature** (that of the rotors, ``charts.analyses.surface_integrals``: the grid, the
partition of unity and the reductions are the shared ones of
``charts.geometry.surface_quadrature``).  The surface C is covered by its *angle charts*: the pairs
(θ_a, θ_b) of periodic coordinates, each a square [−π, π)² with the periodic trapezoidal rule
(``torus_grid``).  Above a node lie the points of C with those two angles, one per *sheet*,
given by the mechanism's ``sheets`` function (closed forms for ``rotors`` and
``triple_linkage``; for a mechanism of one's own found by Newton's method from a grid of seeds,
``charts.mechanism.sheets``; a node may have none).  With T an M-orthonormal frame of the tangent plane
(n, 2) and ρ_c = |det T[c]| for each angle chart c (the Jacobian of the projection of the
tangent plane onto chart c; ρ_c = 0 where chart c ends), the area element of chart c is
dA = dθ_a dθ_b / ρ_c and the partition of unity ψ_c = ρ_cᵖ / Σ ρᵖ (``partition_of_unity``),
so that ψ_c dA = ρ_cᵖ⁻¹ / Σ ρᵖ dθ_a dθ_b is smooth where the chart ends.  For three rotors of
equal masses ρ_k ∝ |a_k sin θ_k| and the weights are the rotor module's exactly.

**Curvature.**  ``route="chart"``: the intrinsic K (``Mechanism.gaussian_curvatures``) in the
best-conditioned chart of every node (``Mechanism.best_chart``'s rule, over all charts of the
atlas); ``route="gauss"``: the Gauss equation (``Mechanism.gauss_equation_curvatures``,
constant metric only).

**Topology.**  χ is not derived here: give ``euler_characteristic`` when it is known (then
``gauss_bonnet_error`` is a test), or it is read as the integer nearest ∫K dA / 2π (then
``gauss_bonnet_error`` only measures how far the quadrature is from an integer);
``params["euler_characteristic_from"]`` says which.
"""
from __future__ import annotations

import itertools

import numpy as np

from ..geometry.surface_quadrature import (SurfaceIntegrals, integrals_from_nodes,
                                           partition_of_unity, torus_grid)
from ..geometry.checks import integer, option
from .atlas import chart_scores
from .errors import MechanismError
from .model import Mechanism
from .sheets import newton_sheets

__all__ = ["surface_integrals", "surface_nodes", "angle_charts"]

#: Largest |F| accepted at a point given by a ``sheets`` function (closed forms are exact to
#: rounding, ~1e-15 for lengths of order 1; anything larger is a wrong sheet).
SHEET_TOL = 1e-9
#: Points per batch of the curvature (the jets of ∂²M take n⁴ floats a point).
CHUNK = 4096


def angle_charts(mech):
    """The angle charts of ``mech``: the pairs of its periodic coordinates (indices), in
    ``itertools.combinations`` order."""
    angles = [i for i, s in enumerate(mech.q) if s.name in mech.periodic]
    return list(itertools.combinations(angles, 2))


def _check(mech, sheets):
    if not isinstance(mech, Mechanism):
        raise MechanismError(f"mech must be a charts.Mechanism, got {type(mech).__name__}")
    if mech.dim != 2:
        raise MechanismError(f"surface integrals are over a 2-dimensional configuration space; "
                             f"{mech.name} has dimension {mech.dim}")
    if sheets is not None and not callable(sheets):
        raise MechanismError(f"sheets must be a function f(mech, chart, ta, tb) -> list of "
                             f"(S, n) arrays, got {type(sheets).__name__}")
    sheets = sheets if sheets is not None else getattr(mech, "sheets", None)
    if sheets is None:                      # a mechanism of one's own: found by Newton
        sheets = newton_sheets
    charts_ = angle_charts(mech)
    if not charts_:
        raise MechanismError(f"{mech.name} has fewer than two periodic coordinates: no angle "
                             "charts to integrate over")
    return sheets, charts_


def _orthonormal_frames(mech, q):
    """M-orthonormal frames of the tangent planes at q (S, n): shape (S, n, 2)."""
    T = np.swapaxes(np.linalg.svd(mech._eval("J", q))[2][:, mech.k:, :], 1, 2)
    G = np.swapaxes(T, 1, 2) @ mech._eval("M", q) @ T
    lam, V = np.linalg.eigh(G)                                   # G^(−1/2) = V Λ^(−1/2) Vᵀ
    return T @ (V / np.sqrt(lam)[:, None, :]) @ np.swapaxes(V, 1, 2)


def surface_nodes(mech, n_grid=64, sheets=None):
    """Quadrature nodes and weights on the configuration surface of ``mech`` (d = 2):
    (q, dA), q shape (S, n) the points, dA (S,) the weights (area element × partition of
    unity × grid cell); Σ f(q) dA ≈ ∫_C f dA.  ``sheets``: see the module docstring (default
    ``mech.sheets``)."""
    sheets, charts_ = _check(mech, sheets)
    n_grid = integer("n_grid", n_grid, 8, 1 << 12)
    ti, tj, h = torus_grid(n_grid)
    points, weights = [], []
    for c, chart in enumerate(charts_):
        for q in sheets(mech, chart, ti, tj):
            q = q[np.all(np.isfinite(q), axis=1)]
            if not q.size:
                continue
            F = np.max(np.abs(mech._eval("F", q)), axis=1)
            if np.max(F) > SHEET_TOL:
                raise MechanismError(f"the sheets function gave points off the constraint "
                                     f"(|F| = {np.max(F):.2e}) in chart {chart}")
            T = _orthonormal_frames(mech, q)
            rho = np.stack([np.abs(np.linalg.det(T[:, list(ab), :])) for ab in charts_], 1)
            if np.any(np.sum(rho, axis=1) == 0):
                raise MechanismError("the angle charts do not cover the surface (a tangent "
                                     "plane projects to a line in every angle chart)")
            points.append(q)
            weights.append(partition_of_unity(rho, c) / rho[:, c] * h * h)
    if not points:
        raise MechanismError(f"{mech.name}: no point of the surface above the grid")
    return np.concatenate(points), np.concatenate(weights)


def curvatures(mech, q, route="chart"):
    """K at the points q (S, n) of the surface by ``route`` ("chart": intrinsic, each point
    in its best chart; "gauss": the Gauss equation), in batches of `CHUNK`; shape (S,)."""
    route = option("route", route, ("chart", "gauss"))
    K = np.empty(len(q))
    every = mech.all_charts()
    for lo in range(0, len(q), CHUNK):
        p = q[lo:lo + CHUNK]
        if route == "gauss":
            K[lo:lo + CHUNK] = mech.gauss_equation_curvatures(p)
            continue
        best = np.argmax(chart_scores(mech._eval("J", p), every), axis=1)
        out = np.empty(len(p))
        for c in np.unique(best):
            out[best == c] = mech.gaussian_curvatures(p[best == c], every[c])
        K[lo:lo + CHUNK] = out
    return K


def surface_integrals(mech, n_grid=64, route="chart", euler_characteristic=None,
                      sheets=None) -> SurfaceIntegrals:
    """Area, ∫K dA, χ, mean √(−K), max K and the share of area with K > 0 of the
    configuration surface of ``mech`` (d = 2), by the quadrature of `surface_nodes` on
    n_grid² nodes per angle chart and the curvature of ``route`` (module docstring): a
    ``SurfaceIntegrals`` as the rotors' (``gauss_bonnet_error``, ``entropy_bracket``),
    ``params`` the mechanism's parameters."""
    route = option("route", route, ("chart", "gauss"))
    q, dA = surface_nodes(mech, n_grid, sheets)
    K = curvatures(mech, q, route)
    total = float(np.sum(K * dA))
    if euler_characteristic is None:
        chi, source = int(round(total / (2.0 * np.pi))), "nearest integer to ∫K dA / 2π"
    else:
        chi, source = integer("euler_characteristic", euler_characteristic, -(1 << 20)), "given"
    found = sheets if sheets is not None else getattr(mech, "sheets", None)
    params = dict(mech.parameter_values, mechanism=mech.name, euler_characteristic_from=source,
                  sheets_from="closed form" if found is not None else
                  "Newton from a grid of seeds (charts.mechanism.sheets)")
    return integrals_from_nodes(K, dA, chi, n_grid, route, params)
