"""The triple linkage's verdict at each rim radius r (``charts verdict --triple-linkage``;
docs/triple-linkage.md): the configuration surface's integrals by the chart and Gauss routes,
χ read from Gauss–Bonnet, the limit r → 0 (the rotor surface Σ cos θ = 3δ), λ₁ and optionally
the restricted angles, judged by `charts.runs.verdict.case_verdict` (no theorem is certified at
a given r): the verdict of a 2-dimensional mechanism (``charts.runs.verdict_mechanism``) with
the limit and Hunt–MacKay's theorem."""
from __future__ import annotations

import time

import numpy as np

from .verdict import case_verdict
from .verdict_mechanism import PLAN_GRID, measure_surface, surface_plan

__all__ = ["linkage_plan", "linkage_verdict", "format_linkage_table", "PLAN_GRID"]


def linkage_plan(r, *, l=1.0, joint_mass=0.0, rod_mass=0.0):
    """The triple linkage (R = 1, inertia 1) of rim radius ``r``, rod length ``l``, masses of
    the joint and of each rod, checked before any long work: its parameters
    (``charts.mechanism.triple_linkage``), that it assembles and that its surface is regular
    (`charts.runs.verdict_mechanism.surface_plan`: points above a `PLAN_GRID`² grid of each
    angle chart, finite area elements and curvatures there; r = R = l is not regular, two
    hinges meet at the centre); MechanismError (a ValueError) naming what fails otherwise."""
    from ..mechanism import MechanismError, triple_linkage
    mech = triple_linkage(r, l=l, joint_mass=joint_mass, rod_mass=rod_mass)
    where = f"r = {mech.parameter_values['r']:g}, l = {mech.parameter_values['l']:g}, R = 1"
    try:
        return surface_plan(mech, "the triple linkage", f" at {where}")
    except MechanismError as exc:
        if "no point of the surface" not in str(exc):
            raise
        raise MechanismError(
            f"the triple linkage does not assemble at {where}: no configuration above a "
            f"{PLAN_GRID}^2 grid of each pair of disc angles (the three rods must reach "
            "one joint: never where l + r < R; always where l, r, R satisfy the strict "
            "triangle inequalities, with the joint at the centre)") from None


def linkage_verdict(r, *, l=1.0, joint_mass=0.0, rod_mass=0.0, n_grid=96, t_final=3000.0,
                    seeds=(1, 2), angles_window=None, progress=None) -> dict:
    """Every piece of the triple linkage's verdict at rim radius ``r`` (`linkage_plan`'s
    linkage) as one JSON-ready dict, with the keys of `surface_verdict`'s and without a
    certificate: a 2-dimensional mechanism's measurements
    (`charts.runs.verdict_mechanism.measure_surface`: the surface integrals on ``n_grid``²
    nodes per angle chart by the chart and, for a constant metric, the Gauss route, χ read
    as the integer nearest ∫K dA / 2π, the smallest K at the nodes; λ₁ at unit speed over
    ``t_final`` from each seed's random state against the entropy bracket; with
    ``angles_window``, the restricted-angle test from each seed's state) and the limit
    r → 0 (the rotor surface Σ cos θ = 3δ, δ = (l − R)/r, its χ by the Morse count).
    ``progress``: a callable given a line before each step."""
    from ..geometry.topology import euler_characteristic
    say = progress or (lambda line: None)
    t0 = time.perf_counter()
    mech = linkage_plan(r, l=l, joint_mass=joint_mass, rod_mass=rod_mass)
    p = mech.parameter_values
    system = dict(kind="triple_linkage", name=mech.name, r=p["r"], l=p["l"], R=p["R"],
                  inertia=p["I"], joint_mass=p["m"], rod_mass=p["mu"],
                  delta=(p["l"] - p["R"]) / p["r"])
    measured = measure_surface(mech, n_grid=n_grid, t_final=t_final, seeds=seeds,
                               angles_window=angles_window, say=say)
    level = 3.0 * system["delta"]
    try:
        limit_chi = euler_characteristic((1.0, 1.0, 1.0), level)
    except ValueError:                        # a critical level: cone points, no χ
        limit_chi = None
    limit = dict(level=level, euler_characteristic=limit_chi,
                 command=f"charts verdict --n 3 --level {level:g}")
    rep = dict(system=system, n_grid=int(n_grid), routes=measured.pop("routes"),
               bracket=measured.pop("bracket"), limit=limit, **measured)
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
