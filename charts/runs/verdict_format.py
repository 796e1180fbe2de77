"""The reports of ``charts verdict`` as text (charts.runs.verdict's reports and their verdict
line): the rotors' surface and torus cases, the triple linkage's and a 2-dimensional mechanism's
measured surfaces, each ending with its verdict, evidence and reason."""
from __future__ import annotations

import numpy as np

from .verdict import report_kind, verdict_line

__all__ = ["format_verdict"]


def _num(x, fmt=".6f"):
    return "—" if x is None else format(x, fmt)


def _format_torus(rep: dict) -> str:
    s, t = rep["system"], rep["torus"]
    lines = [f"N = {s['n']}: masses {s['masses']}, weights {s['weights']}, level {s['level']:g}",
             f"antipodal torus: {t['verdict']}"]
    if t["pairs"]:
        lines.append(f"  pairs (theta_j = theta_i + pi) {t['pairs']}, at pi/2: {t['lone']}; "
                     f"a flat torus of dimension {t['dimension']}")
    for step in t["proof"]:
        lines.append(f"  [{'proved' if step['holds'] else 'FAILED'}] {step['statement']}")
    m = t["monodromy"]
    if m:
        lines.append(f"  closed geodesic: period {m['period']:.6f}, {m['steps']} RK4 steps; stays "
                     f"on the torus to {m['max_distance_from_torus']:.1e}, returns to "
                     f"{m['return_error']:.1e}")
        if "jordan_residual" in m:
            lines.append(f"  monodromy: the in-torus Jacobi field t*w (linear growth) to "
                         f"{m['jordan_residual']:.1e}; transverse exponents "
                         + ", ".join(f"{x:+.4f}" for x in m["transverse_exponents"]))
    lines.append(verdict_line(rep))
    lines.append(f"({rep['seconds']:.1f} s of wall time)")
    return "\n".join(lines)


def _gauss_bonnet_lines(rep: dict) -> list:
    """The Gauss–Bonnet line of each curvature route of a surface report."""
    return [f"Gauss-Bonnet, {route} route: int K dA = {r['total_curvature']:.12f}, "
            f"2 pi chi = {2 * np.pi * r['euler_characteristic']:.12f}, "
            f"difference {r['gauss_bonnet_error']:.1e}" for route, r in rep["routes"].items()]


def _exponent_lines(rep: dict) -> list:
    """The entropy bracket of a surface report and each λ₁ run against it."""
    lo, hi = rep["bracket"]
    lines = [f"entropy bracket at unit speed: mean sqrt(-K) = {_num(lo)} <= lambda1 <= "
             f"sqrt(2 pi |chi| / A) = {_num(hi)}"]
    for e in rep["exponents"]:
        lines.append(f"  lambda1 (seed {e['seed']}, T = {e['t_final']:g}) = {e['lambda1']:.4f} "
                     f"± {e['stderr']:.4f}: "
                     + ("no bracket (chi >= 0)" if lo is None and hi is None else
                        "inside the bracket by 3 standard errors" if e["resolved_inside"] else
                        "consistent with the bracket (within 3 standard errors)"
                        if e["consistent"] else "VIOLATES the bracket by over 3 standard errors"))
    return lines


def format_verdict(rep: dict) -> str:
    """A report of `surface_verdict`, `torus_verdict`, `linkage_verdict` or
    `mechanism_verdict` as text."""
    if "torus" in rep:
        return _format_torus(rep)
    if report_kind(rep) == "triple_linkage":
        return _format_linkage(rep)
    if report_kind(rep) == "mechanism":
        return _format_mechanism(rep)
    s = rep["system"]
    c = rep["routes"]["chart"]
    lines = [f"N = 3 surface: masses {s['masses']}, weights {s['weights']}, level {s['level']:g}",
             f"Euler characteristic (Morse count): {c['euler_characteristic']}",
             f"area A = {c['area']:.10f} (n_grid = {rep['n_grid']})"]
    lines += _gauss_bonnet_lines(rep)
    lines.append(f"K > 0 on {100 * c['positive_area']:.2f} % of the area; largest K at the "
                 f"nodes {c['max_curvature']:.3g}")
    lines += _exponent_lines(rep)
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
    lines.append(verdict_line(rep))
    lines.append(f"({rep['seconds']:.1f} s of wall time)")
    return "\n".join(lines)


def _linkage_head(s: dict) -> str:
    return (f"triple linkage r = {s['r']:g}, l = {s['l']:g}, R = {s['R']:g} (delta = "
            f"{s['delta']:g}; inertia {s['inertia']:g}, joint mass {s['joint_mass']:g}, rod "
            f"mass {s['rod_mass']:g})")


def _format_linkage(rep: dict) -> str:
    lim = rep["limit"]
    morse = "a critical level" if lim["euler_characteristic"] is None else \
        f"chi = {lim['euler_characteristic']} by the Morse count"
    return _format_measured(rep, [
        _linkage_head(rep["system"]),
        f"limit r -> 0: the rotor surface sum cos theta = {lim['level']:g} ({morse}; "
        f"its verdict: {lim['command']})"])


def _format_mechanism(rep: dict) -> str:
    s = rep["system"]
    params = ", ".join(f"{k} = {v:g}" for k, v in s["parameters"].items())
    return _format_measured(rep, [f"mechanism {s['name']}: q = ({', '.join(s['coordinates'])}), "
                                  f"dimension {s['dimension']}"
                                  + (f"; parameters {params}" if params else "")])


def _format_measured(rep: dict, head: list) -> str:
    """A report whose χ the quadrature reads (the triple linkage's, a mechanism's) as text,
    after its ``head`` lines."""
    c = rep["routes"]["chart"]
    lines = head + [
        f"Euler characteristic (nearest integer to int K dA / 2 pi; measured, not "
        f"certified): {c['euler_characteristic']}",
        f"area A = {c['area']:.10f} (n_grid = {rep['n_grid']})"]
    lines += _gauss_bonnet_lines(rep)
    for route, r in rep["routes"].items():
        lines.append(f"K at the nodes ({route} route) in [{r['min_curvature']:.4g}, "
                     f"{r['max_curvature']:.4g}]; K > 0 on {100 * r['positive_area']:.3f} % of "
                     "the area")
    lines += _exponent_lines(rep)
    for a in rep.get("angles", []):
        lines.append(f"  restricted angles (seed {a['seed']}, T = {a['t_final']:g}): min "
                     f"{a['min']:.4g} rad, median {a['median']:.4g}, "
                     f"{100 * a['frac_small']:.3g} % below {a['small']:g} rad, {a['n']} samples")
    lines.append(verdict_line(rep))
    lines.append(f"({rep['seconds']:.1f} s of wall time)")
    return "\n".join(lines)
