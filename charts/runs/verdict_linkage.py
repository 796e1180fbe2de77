"""The triple linkage's verdict at each rim radius r (``charts verdict --triple-linkage``;
docs/triple-linkage.md): the configuration surface's integrals by the chart and Gauss routes,
χ read from Gauss–Bonnet, the limit r → 0 (the rotor surface Σ cos θ = 3δ), λ₁ and optionally
the restricted angles, judged by `charts.runs.verdict.case_verdict` (no theorem is certified at
a given r)."""
from __future__ import annotations

import time
import warnings

import numpy as np

from .verdict import case_verdict, exponent_report

__all__ = ["linkage_plan", "linkage_verdict", "format_linkage_table", "PLAN_GRID"]


#: Nodes per axis of each angle chart in `linkage_plan`'s check that the linkage assembles.
PLAN_GRID = 16


def linkage_plan(r, *, l=1.0, joint_mass=0.0, rod_mass=0.0):
    """The triple linkage (R = 1, inertia 1) of rim radius ``r``, rod length ``l``, masses of
    the joint and of each rod, checked before any long work: its parameters
    (``charts.mechanism.triple_linkage``), that it assembles (points of its configuration
    surface above a `PLAN_GRID`² grid of each angle chart) and that the surface is regular
    there (finite area elements and curvatures: r = R = l is not, two hinges meet at the
    centre); MechanismError (a ValueError) naming what fails otherwise."""
    from ..mechanism import MechanismError, triple_linkage
    from ..mechanism.surface import curvatures, surface_nodes
    mech = triple_linkage(r, l=l, joint_mass=joint_mass, rod_mass=rod_mass)
    where = f"r = {mech.parameter_values['r']:g}, l = {mech.parameter_values['l']:g}, R = 1"
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")       # NaN at singular nodes: refused below
        try:
            q, dA = surface_nodes(mech, PLAN_GRID)
        except MechanismError as exc:
            if "no point of the surface" not in str(exc):
                raise
            raise MechanismError(
                f"the triple linkage does not assemble at {where}: no configuration above a "
                f"{PLAN_GRID}^2 grid of each pair of disc angles (the three rods must reach "
                "one joint: never where l + r < R; always where l, r, R satisfy the strict "
                "triangle inequalities, with the joint at the centre)") from None
        K = curvatures(mech, q, "chart")
    if not (np.all(np.isfinite(dA)) and np.all(np.isfinite(K))):
        raise MechanismError(
            f"the triple linkage is singular at {where}: area elements or curvatures are not "
            f"finite at points above the {PLAN_GRID}^2 grid (the constraints lose rank there, "
            "or the kinetic metric degenerates: with a massless joint, the joint moving while "
            "the discs stand still), so it is not a closed smooth Riemannian surface and no "
            "verdict applies")
    return mech


def linkage_verdict(r, *, l=1.0, joint_mass=0.0, rod_mass=0.0, n_grid=96, t_final=3000.0,
                    seeds=(1, 2), angles_window=None, progress=None) -> dict:
    """Every piece of the triple linkage's verdict at rim radius ``r`` (`linkage_plan`'s
    linkage) as one JSON-ready dict, with the keys of `surface_verdict`'s and without a
    certificate: the surface integrals on ``n_grid``² nodes per angle chart
    (``charts.mechanism.surface``) by the chart and, for a constant metric, the Gauss route,
    with χ read as the integer nearest ∫K dA / 2π and the smallest K at the nodes; the
    limit r → 0 (the rotor surface Σ cos θ = 3δ, δ = (l − R)/r, its χ by the Morse count);
    λ₁ at unit speed over ``t_final`` from each seed's random state
    (``charts.analyses.mechanism_lyapunov``) against the entropy bracket; with
    ``angles_window``, the restricted-angle test of section 4 over that window from each
    seed's state (``charts.analyses.mechanism_angles``: the smallest angle, the share below
    0.05 rad, the samples).  ``progress``: a callable given a line before each step."""
    from dataclasses import replace

    from ..analyses.mechanism_lyapunov import lyapunov_spectrum as mechanism_lyapunov
    from ..geometry.surface_quadrature import integrals_from_nodes
    from ..geometry.topology import euler_characteristic
    from ..mechanism.surface import curvatures, surface_nodes
    say = progress or (lambda line: None)
    t0 = time.perf_counter()
    mech = linkage_plan(r, l=l, joint_mass=joint_mass, rod_mass=rod_mass)
    p = mech.parameter_values
    system = dict(kind="triple_linkage", name=mech.name, r=p["r"], l=p["l"], R=p["R"],
                  inertia=p["I"], joint_mass=p["m"], rod_mass=p["mu"],
                  delta=(p["l"] - p["R"]) / p["r"])
    route_names = ("chart", "gauss") if mech.constant_metric else ("chart",)
    say(f"surface integrals on {n_grid}^2 nodes per angle chart (the "
        f"{' and '.join(route_names)} route{'s' if len(route_names) > 1 else ''})")
    q, dA = surface_nodes(mech, n_grid)
    routes = {}
    for route in route_names:
        K = curvatures(mech, q, route)
        s = integrals_from_nodes(K, dA, 0, n_grid, route, dict(p, mechanism=mech.name))
        s = replace(s, euler_characteristic=int(round(s.total_curvature / (2 * np.pi))))
        routes[route] = dict(s.to_dict(), min_curvature=float(K.min()),
                             euler_characteristic_from="nearest integer to int K dA / 2 pi")
    level = 3.0 * system["delta"]
    try:
        limit_chi = euler_characteristic((1.0, 1.0, 1.0), level)
    except ValueError:                        # a critical level: cone points, no χ
        limit_chi = None
    limit = dict(level=level, euler_characteristic=limit_chi,
                 command=f"charts verdict --n 3 --level {level:g}")
    bracket = routes["chart"]["entropy_bracket"]
    exponents = []
    for seed in seeds:
        say(f"lambda1 at unit speed, seed {seed}, T = {t_final:g}")
        exponents.append(exponent_report(mechanism_lyapunov(mech, *mech.random_state(seed), t_final,
                                                      seed=seed), seed, t_final, bracket))
    rep = dict(system=system, n_grid=int(n_grid), routes=routes, bracket=bracket, limit=limit,
               exponents=exponents)
    if angles_window is not None:
        from ..analyses.mechanism_angles import mechanism_angles
        rep["angles"] = []
        for seed in seeds:
            say(f"restricted angles, seed {seed}, T = {angles_window:g}")
            a = mechanism_angles(mech, *mech.random_state(seed), angles_window, seed=seed)
            st = a.statistics()
            rep["angles"].append(dict(seed=int(seed), t_final=float(angles_window),
                                      **{k: st[k] for k in ("min", "median", "frac_small",
                                                            "small", "n")}))
    rep["seconds"] = time.perf_counter() - t0
    return dict(rep, **case_verdict(rep))


def format_linkage_table(reports) -> str:
    """The triple linkage's reports as one Markdown table: r, l, χ, area, K's range, the share
    of K > 0, λ₁ (mean of the seeds ± the standard error of their mean, from the batch errors),
    the smallest restricted angle (— where the angle test did not run), verdict and
    evidence."""
    lines = ["| r | l | chi | area | K at the nodes | K > 0 | lambda1 | min angle | verdict "
             "| evidence |", "|---|---|---|---|---|---|---|---|---|---|"]
    for rep in reports:
        s, c, ex = rep["system"], rep["routes"]["chart"], rep["exponents"]
        lam = "—"
        if ex:
            se = np.sqrt(sum(e["stderr"] ** 2 for e in ex)) / len(ex)
            lam = f"{np.mean([e['lambda1'] for e in ex]):.4f} ± {se:.4f}"
        angle = "—" if not rep.get("angles") else \
            f"{min(a['min'] for a in rep['angles']):.3g} rad"
        lines.append(f"| {s['r']:g} | {s['l']:g} | {c['euler_characteristic']} | "
                     f"{c['area']:.4f} | [{c['min_curvature']:.3g}, {c['max_curvature']:.3g}] "
                     f"| {100 * c['positive_area']:.3f} % | {lam} | {angle} | "
                     f"{rep['verdict']} | {rep['evidence']} |")
    return "\n".join(lines)
