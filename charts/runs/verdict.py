"""The N = 3 surface's verdict from exact invariants: the Gauss–Bonnet theorem by both
curvature routes, the leading exponent against the bracket of Katok's and Osserman–Sarnak's
inequalities, and the certified sign of the curvature (docs/verdict.md; ``charts verdict``).
"""
from __future__ import annotations

import time

import numpy as np

from ..analyses.curvature_certificate import certify_curvature_sign
from ..analyses.lyapunov import lyapunov_spectrum
from ..analyses.surface_integrals import surface_integrals

__all__ = ["surface_verdict", "format_verdict"]


def surface_verdict(system, *, n_grid=256, t_final=3000.0, seeds=(1, 2)) -> dict:
    """Every piece of the verdict for ``system`` (N = 3) as one JSON-ready dict: the surface
    integrals by the chart and the Gauss routes (``n_grid``), λ₁ at unit speed from
    `lyapunov_spectrum` over ``t_final`` for each seed with its standard error and whether
    it lies in the entropy bracket, and the curvature certificate."""
    t0 = time.perf_counter()
    routes = {route: surface_integrals(system, n_grid, route).to_dict()
              for route in ("chart", "gauss")}
    lower, upper = routes["chart"]["entropy_bracket"]
    exponents = []
    for seed in seeds:
        r = lyapunov_spectrum(system, *system.random_state(seed=seed, speed=1.0), t_final)
        lam, se = float(r.exponents[0]), float(r.stderr[0])
        # consistent: no bound violated by more than 3 standard errors; resolved: the whole
        # ±3 s.e. interval inside the bracket
        consistent = (lower is None or lam + 3 * se > lower) and \
            (upper is None or lam - 3 * se < upper)
        resolved = (lower is None or lam - 3 * se > lower) and \
            (upper is None or lam + 3 * se < upper)
        exponents.append(dict(seed=int(seed), t_final=float(t_final), lambda1=lam, stderr=se,
                              consistent=bool(consistent), resolved_inside=bool(resolved)))
    cert = certify_curvature_sign(system).to_dict()
    return dict(system=dict(n=3, masses=system.masses.tolist(), weights=system.weights.tolist(),
                            level=float(system.level)),
                n_grid=int(n_grid), routes=routes, bracket=[lower, upper],
                exponents=exponents, certificate=cert,
                seconds=time.perf_counter() - t0)


def _num(x, fmt=".6f"):
    return "—" if x is None else format(x, fmt)


def format_verdict(rep: dict) -> str:
    """The report of `surface_verdict` as text."""
    s = rep["system"]
    c = rep["routes"]["chart"]
    lines = [f"N = 3 surface: masses {s['masses']}, weights {s['weights']}, level {s['level']:g}",
             f"Euler characteristic (Morse count): {c['euler_characteristic']}",
             f"area A = {c['area']:.10f} (n_grid = {rep['n_grid']})"]
    for route, r in rep["routes"].items():
        lines.append(f"Gauss-Bonnet, {route} route: int K dA = {r['total_curvature']:.12f}, "
                     f"2 pi chi = {2 * np.pi * r['euler_characteristic']:.12f}, "
                     f"difference {r['gauss_bonnet_error']:.1e}")
    lines.append(f"K > 0 on {100 * c['positive_area']:.2f} % of the area; largest K at the "
                 f"nodes {c['max_curvature']:.3g}")
    lo, hi = rep["bracket"]
    lines.append(f"entropy bracket at unit speed: mean sqrt(-K) = {_num(lo)} <= lambda1 <= "
                 f"sqrt(2 pi |chi| / A) = {_num(hi)}")
    for e in rep["exponents"]:
        lines.append(f"  lambda1 (seed {e['seed']}, T = {e['t_final']:g}) = {e['lambda1']:.4f} "
                     f"± {e['stderr']:.4f}: "
                     + ("inside the bracket by 3 standard errors" if e["resolved_inside"] else
                        "consistent with the bracket (within 3 standard errors)"
                        if e["consistent"] else "VIOLATES the bracket by over 3 standard errors"))
    cert = rep["certificate"]
    lines.append(f"curvature certificate: {cert['verdict']} ({cert['seconds']:.1f} s of CPU)")
    lines.append(f"  cover: {cert['cover']}")
    for ch in cert["charts"]:
        lines.append(f"  chart {ch['chart']}: sign K = sign P (Q > 0 proved), P = {ch['P_approx']} ({ch['variables'][0]}"
                     f", {ch['variables'][1]}); of {ch['boxes']} boxes examined: {ch['negative']} P < 0, "
                     f"{ch['mean_value']} by the mean-value form, {ch['zero']} around a zero, "
                     f"{ch['outside']} outside the chart's part")
    if cert["zeros"]:
        lines.append("  K = 0 exactly at: " + ", ".join("(" + ", ".join(z["theta"]) + ")"
                                                      for z in cert["zeros"]))
    if cert["positive_box"]:
        b = cert["positive_box"]
        lines.append(f"  K > 0 proved on the box x in {b['x']}, y in {b['y']} of chart "
                     f"{b['chart']} ({b['note']})")
    if cert["open_boxes"] and cert["verdict"] == "undecided":
        lines.append(f"  {cert['open_boxes']} boxes left open")
    lines.append(f"({rep['seconds']:.1f} s)")
    return "\n".join(lines)
