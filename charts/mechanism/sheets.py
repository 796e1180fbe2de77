"""The sheets of a 2-dimensional mechanism found numerically: every point of the configuration
surface above a node of an angle chart, for a mechanism of one's own that has no closed form
(``charts.mechanism.surface``; the rotors and the triple linkage carry closed forms).

Above the node (θ_a, θ_b) = (ta, tb) of the angle chart (a, b) the other n − 2 coordinates
solve the k = n − 2 constraints F = 0.  `newton_sheets` starts Newton's method on that square
system from every seed of a grid (each dependent angle at `ANGLE_SEEDS` values in [−π, π),
each other coordinate at `LENGTH_SEEDS` values across its ``bounds``), all nodes of the chart
at once, keeps the solutions with |F| ≤ `SOLVED` and an invertible dependent block of J, and
merges them per node: two solutions are one point when their coordinates agree within
`SAME_POINT` (angles modulo 2π).

A branch that no seed reaches is missed, and the area and ∫K dA come out short.  The
Gauss–Bonnet theorem makes ∫K dA / 2π an integer on a closed surface, so a quadrature far
from one is the sign of a missed branch (``SurfaceIntegrals.gauss_bonnet_error``, read by
``charts verdict``); the tests compare this route with the closed forms of the rotors, the
triple linkage and the arm of docs/mechanisms.md.
"""
from __future__ import annotations

import itertools

import numpy as np

from .errors import MechanismError

__all__ = ["newton_sheets", "ANGLE_SEEDS", "LENGTH_SEEDS", "SOLVED", "SAME_POINT",
           "MAX_SEEDS"]

#: Starting values of each dependent angle (equally spaced in [−π, π)).
ANGLE_SEEDS = 8
#: Starting values of each other dependent coordinate (equally spaced across its bounds).
LENGTH_SEEDS = 5
#: At most this many seeds (the grid's product, thinned evenly beyond).
MAX_SEEDS = 400
#: Newton steps from each seed (quadratic convergence: a seed in a basin needs a handful).
ITERATIONS = 40
#: |F| below which a point solves the constraints (closed forms give ~1e-15 at lengths of
#: order 1; ``surface.SHEET_TOL`` refuses 1e-9).
SOLVED = 1e-12
#: Coordinates closer than this are one point (solutions converge to ~1e-14; distinct
#: branches at a node are a finite distance apart unless the node is on a fold).
SAME_POINT = 1e-7


def _seeds(mech, dep):
    """The starting values of the dependent coordinates ``dep``: (P, len(dep))."""
    axes = []
    for i in dep:
        if mech._periodic_mask[i]:
            axes.append(np.linspace(-np.pi, np.pi, ANGLE_SEEDS, endpoint=False))
        else:
            lo, hi = mech.bounds[mech.q[i].name]
            axes.append(np.linspace(lo, hi, LENGTH_SEEDS))
    grid = np.array(list(itertools.product(*axes)), dtype=float)
    if len(grid) > MAX_SEEDS:
        grid = grid[np.linspace(0, len(grid) - 1, MAX_SEEDS).round().astype(int)]
    return grid


def _newton(mech, q, dep):
    """Newton's method on F(q) = 0 in the coordinates ``dep`` at every row of q (S, n), in
    place; returns the rows that converged (|F| ≤ `SOLVED`, the dependent block invertible)."""
    alive = np.ones(len(q), bool)
    for _ in range(ITERATIONS):
        F = mech._eval("F", q)
        with np.errstate(invalid="ignore", over="ignore"):
            done = np.max(np.abs(F), axis=1) <= SOLVED
        JD = mech._eval("J", q)[:, :, dep]
        ok = alive & ~done & np.all(np.isfinite(F), axis=1) & \
            np.all(np.isfinite(JD), axis=(1, 2))
        if not np.any(ok):
            break
        det = np.linalg.det(JD[ok])
        good = np.isfinite(det) & (np.abs(det) > 1e-14)
        rows = np.flatnonzero(ok)
        alive[rows[~good]] = False
        rows = rows[good]
        if rows.size:
            step = np.linalg.solve(JD[rows], F[rows][..., None])[..., 0]
            q[np.ix_(rows, dep)] -= step
    F = mech._eval("F", q)
    with np.errstate(invalid="ignore"):
        solved = np.max(np.abs(F), axis=1) <= SOLVED
    JD = mech._eval("J", q)[:, :, dep]
    s = np.full(len(q), np.nan)
    fin = solved & np.all(np.isfinite(JD), axis=(1, 2))
    if np.any(fin):
        s[fin] = np.linalg.svd(JD[fin], compute_uv=False)[:, -1]
    return alive & solved & (s > 1e-10)


def newton_sheets(mech, chart, ta, tb):
    """The points of ``mech``'s configuration surface (d = 2) with q[a] = ta, q[b] = tb for the
    angle chart ``chart`` = (a, b) and node angles ta, tb (S,): a list of (S, n) arrays, one
    per sheet, NaN rows where a sheet has no point at that node (the ``sheets`` protocol of
    ``charts.mechanism.surface``), found by Newton's method from a grid of seeds (module
    docstring)."""
    if mech.dim != 2:
        raise MechanismError(f"sheets are points of a 2-dimensional configuration space; "
                             f"{mech.name} has dimension {mech.dim}")
    a, b = chart
    ta, tb = np.asarray(ta, dtype=float), np.asarray(tb, dtype=float)
    dep = [i for i in range(mech.n) if i not in (a, b)]
    periodic = mech._periodic_mask
    S = ta.size
    sheets = []
    for seed in _seeds(mech, dep):
        q = np.empty((S, mech.n))
        q[:, a], q[:, b] = ta, tb
        q[:, dep] = seed
        with np.errstate(all="ignore"):
            found = _newton(mech, q, dep)
        if not np.any(found):
            continue
        q = mech.wrap_angles(q)
        new = found.copy()
        for sheet in sheets:
            d = q - sheet
            d[:, periodic] = np.angle(np.exp(1j * d[:, periodic]))
            with np.errstate(invalid="ignore"):
                same = np.max(np.abs(d), axis=1) <= SAME_POINT
            new &= ~same
        for sheet in sheets:
            free = new & np.isnan(sheet[:, 0])
            sheet[free] = q[free]
            new &= ~free
        if np.any(new):
            sheet = np.full((S, mech.n), np.nan)
            sheet[new] = q[new]
            sheets.append(sheet)
    return sheets
