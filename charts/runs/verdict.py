"""The verdicts on hyperbolicity from exact invariants and certificates (docs/hyperbolicity.md;
``charts verdict``): for N = 3 the Gauss–Bonnet theorem by both curvature routes, the leading
exponent against the bracket of Katok's and Osserman–Sarnak's inequalities and the certified
sign of the curvature; for N ≥ 4 the flat totally geodesic torus that rules out the Anosov
property, with the monodromy of its closed geodesic.  Where neither applies, the statistics
of the angle test at scale (`statistics_verdict`, ``charts verdict --statistics``).  Each
report carries its verdict (`case_verdict`: "hyperbolic (Anosov)", "not hyperbolic" or
"open", the class of its evidence and one sentence why), derived from the certificates'
outcomes, never from N alone.
"""
from __future__ import annotations

import json
import time
import warnings

import numpy as np

from ..analyses.curvature_certificate import certify_curvature_sign
from ..analyses.flat_tori import certify_flat_torus
from ..analyses.lyapunov import lyapunov_spectrum
from ..analyses.surface_integrals import surface_integrals

__all__ = ["surface_verdict", "torus_verdict", "format_verdict", "verdict_passed",
           "statistics_verdict", "tally_report", "family_systems", "format_statistics",
           "members_window", "case_verdict", "verdict_line", "VERDICTS", "EVIDENCE"]

#: The verdicts a case can get (`case_verdict`).
VERDICTS = ("hyperbolic (Anosov)", "not hyperbolic", "open")
#: The classes of evidence behind a verdict: a theorem whose hypotheses a certificate of the
#: library proves; a theorem whose hypotheses are exact (topology, a symbolic proof); the angle
#: statistics only; nothing that decides.
EVIDENCE = ("theorem with certificate", "theorem", "statistics", "no proof")


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
    rep = dict(system=system.describe(),
               n_grid=int(n_grid), routes=routes, bracket=[lower, upper],
               exponents=exponents, certificate=cert,
               seconds=time.perf_counter() - t0)
    return dict(rep, **case_verdict(rep))


def torus_verdict(system) -> dict:
    """The flat-torus certificate of ``system`` (N ≥ 4; ``charts.analyses.flat_tori``) as one
    JSON-ready dict."""
    t0 = time.perf_counter()
    cert = certify_flat_torus(system).to_dict()
    rep = dict(system=system.describe(),
               torus=cert, seconds=time.perf_counter() - t0)
    return dict(rep, **case_verdict(rep))


def _surface_case(rep: dict) -> tuple:
    """(verdict, evidence, reason) of a `surface_verdict` report: from χ (the Morse count,
    exact) and the curvature certificate's outcome only; Gauss–Bonnet and the exponents are
    checks of consistency (`verdict_passed`), not hypotheses of a theorem."""
    chi = rep["routes"]["chart"]["euler_characteristic"]
    cert = rep["certificate"]
    outcome = cert["verdict"]
    if chi > 0:
        return ("not hyperbolic", "theorem",
                f"chi = {chi} (Morse count), so int K dA = 2 pi chi > 0 (Gauss-Bonnet), and a "
                "closed surface without conjugate points has int K dA <= 0 (Hopf 1948): there "
                "are conjugate points, which an Anosov geodesic flow never has (Klingenberg "
                "1974)")
    if outcome == "positive somewhere" and chi == 0:
        return ("not hyperbolic", "theorem with certificate",
                "chi = 0 (Morse count), so int K dA = 0 (Gauss-Bonnet), and K > 0 is certified "
                "on a box, so K is not identically 0; a closed surface without conjugate points "
                "has int K dA <= 0 on each component, with equality only where it is flat (Hopf "
                "1948), so there are conjugate points, which an Anosov geodesic flow never has "
                "(Klingenberg 1974)")
    if outcome == "positive somewhere":
        return ("open", "no proof",
                f"K > 0 is certified on a box (chi = {chi}), so no curvature theorem applies, "
                "and a surface with some positive curvature can still be Anosov: nothing run "
                "here decides (the exponent inside the entropy bracket is consistency, not "
                "proof)")
    if outcome == "nonpositive" and chi < 0:
        if cert["zeros"]:
            return ("hyperbolic (Anosov)", "theorem with certificate",
                    f"K <= 0 is certified on the whole closed surface, with K = 0 only at "
                    f"{len(cert['zeros'])} isolated points, so no geodesic has K = 0 all along "
                    "it, which on a closed surface with K <= 0 is Eberlein's condition for an "
                    "Anosov geodesic flow (1973: no geodesic carries a parallel perpendicular "
                    "Jacobi field)")
        return ("hyperbolic (Anosov)", "theorem with certificate",
                "K < 0 is certified on the whole closed surface, and the geodesic flow of a "
                "closed manifold of negative curvature is Anosov (Anosov 1967)")
    if outcome == "nonpositive":
        return ("open", "no proof",
                f"the certificate's K <= 0 contradicts chi = {chi} >= 0 with K not "
                "identically 0 (Gauss-Bonnet): the evidence is inconsistent")
    why = (f"{cert['open_boxes']} boxes left open" if cert.get("open_boxes") else
           "its cover of the surface was not proved" if not cert.get("charts") else
           f"its outcome is {outcome!r}")
    return ("open", "no proof",
            f"the curvature certificate is undecided ({why}), so the sign of K is not proved "
            "and no theorem applies")


def _torus_case(rep: dict) -> tuple:
    """(verdict, evidence, reason) of a `torus_verdict` report: from the flat-torus
    certificate's outcome (every symbolic step proved, a torus of dimension ≥ 2)."""
    t = rep["torus"]
    failed = [s["statement"] for s in t["proof"] if not s["holds"]]
    if failed or t["verdict"] == "proof failed":
        return ("open", "no proof",
                "a step of the flat-torus proof failed (" + "; ".join(failed) + "), so "
                "nothing is proved")
    if t["verdict"] == "not hyperbolic" and t["dimension"] >= 2:
        i, j = t["pairs"][0]
        return ("not hyperbolic", "theorem",
                f"a flat, totally geodesic {t['dimension']}-torus of antipodal pairs is proved "
                f"symbolically, and its closed geodesic on which rotors {i} and {j} turn "
                "(antipodal) and "
                "the others stay at +-pi/2 (off every singular point) carries a parallel Jacobi "
                "field inside the torus (multiplier 1, zero exponent): a closed orbit that is "
                "not hyperbolic, which an Anosov flow cannot have")
    if t["verdict"] == "no conclusion":
        return ("open", "no proof",
                "the antipodal torus is only a closed geodesic here (one pair of equal "
                "rotors), which contradicts nothing, and no other proof is run; angle "
                "statistics (--statistics) cannot decide")
    return ("open", "no proof",
            "there is no flat torus of antipodal pairs (it needs level 0 and rotors of equal "
            "mass and weight), and no other proof is run; angle statistics (--statistics) "
            "cannot decide")


def _statistics_case(rep: dict) -> tuple:
    """(verdict, evidence, reason) of a `tally_report`: the angles decide nothing."""
    st = rep.get("statistics", {}).get("restricted") or {}
    seen = ""
    if st.get("min") is not None and st.get("n") is not None:
        seen = f" (smallest restricted angle {st['min']:.3g} rad in {st['n']:.3g} samples)"
    return ("open", "statistics",
            f"angle statistics only{seen}: sampled angles can neither prove nor rule out "
            "uniform hyperbolicity, and this mode runs no theorem (without --statistics the "
            "command runs the curvature certificate for N = 3 and the flat torus for N >= 4)")


def case_verdict(rep: dict) -> dict:
    """The verdict of one report of ``charts verdict`` (`surface_verdict`, `torus_verdict`
    or `tally_report`) as ``dict(verdict, evidence, reason)``: ``verdict`` one of `VERDICTS`,
    ``evidence`` one of `EVIDENCE`, ``reason`` one sentence.  Derived from what the report
    holds — the curvature certificate's outcome and χ (N = 3), the flat-torus proof (N ≥ 4);
    a certificate that is undecided or fails gives "open", and angle statistics alone give
    "open"."""
    if "torus" in rep:
        verdict, evidence, reason = _torus_case(rep)
    elif "certificate" in rep:
        verdict, evidence, reason = _surface_case(rep)
    else:
        verdict, evidence, reason = _statistics_case(rep)
    return dict(verdict=verdict, evidence=evidence, reason=reason)


def verdict_line(rep: dict) -> str:
    """The one line of a report's verdict: ``verdict: …; evidence: …; why: …``."""
    v = case_verdict(rep)
    return f"verdict: {v['verdict']}; evidence: {v['evidence']}; why: {v['reason']}"


def verdict_passed(rep: dict) -> bool:
    """Every check of a report holds: Gauss–Bonnet to 1e-6 relative, no exponent outside
    the bracket by over 3 standard errors, a curvature certificate that decided (N = 3); a
    torus proof with every step true (N ≥ 4)."""
    if "torus" in rep:
        return all(s["holds"] for s in rep["torus"]["proof"])
    chi = rep["routes"]["chart"]["euler_characteristic"]
    scale = 2 * np.pi * max(abs(chi), 1)
    return (all(abs(r["gauss_bonnet_error"]) <= 1e-6 * scale for r in rep["routes"].values())
            and all(e["consistent"] for e in rep["exponents"])
            and rep["certificate"]["verdict"] != "undecided")


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
    lines.append(f"({rep['seconds']:.1f} s)")
    return "\n".join(lines)


def format_verdict(rep: dict) -> str:
    """A report of `surface_verdict` or `torus_verdict` as text."""
    if "torus" in rep:
        return _format_torus(rep)
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
                     + ("no bracket (chi >= 0)" if lo is None and hi is None else
                        "inside the bracket by 3 standard errors" if e["resolved_inside"] else
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
    lines.append(verdict_line(rep))
    lines.append(f"({rep['seconds']:.1f} s)")
    return "\n".join(lines)


def members_window(samples, members, sample_every=0.1, unit=1.0) -> float:
    """The window T per member for at least ``samples`` angles over ``members`` members
    sampled every ``sample_every``: a whole number of ``unit`` (the checkpoint segment)."""
    return float(unit * np.ceil(samples / members * sample_every / unit))


def statistics_verdict(system, samples, *, members, device="auto", t_transient=100.0,
                       sample_every=0.1, workers=None, out=None, label="",
                       progress=False, checkpoint=None, client=None) -> dict:
    """The angle test at scale: ``members`` trajectories (seeds 0, 1, …) with at least
    ``samples`` angles together, tallied (``charts.analyses.angle_tally``), as one JSON-ready
    dict: the run (members, window, device, seconds) and `AngleTally.statistics` of both
    variants; the tally saved as ``out`` (a path) when given; ``checkpoint``: the path of
    the partial tally of a run on the CPU (`hyperbolicity_tally`); ``client``: its chunks on
    a Dask cluster (`hyperbolicity_tally`'s; the device is then the workers' CPUs)."""
    from ..analyses.hyperbolicity import hyperbolicity_tally
    t_final = members_window(samples, members, sample_every)
    t0 = time.perf_counter()
    tally = hyperbolicity_tally(system, members, t_final, device=device, workers=workers,
                                t_transient=t_transient, sample_every=sample_every,
                                progress=progress, checkpoint=checkpoint, client=client)
    rep = tally_report(tally, label, time.perf_counter() - t0)
    if out is not None:
        rep["file"] = str(tally.save(out))
    return rep


def tally_report(tally, label="", seconds=None) -> dict:
    """The report of an `AngleTally` as `statistics_verdict` writes it: the run (system,
    members, window, transient, sample step, device, ``seconds`` or None for a tally read
    from a file) and `AngleTally.statistics` of both variants."""
    from ..analyses.angle_tally import VARIANTS
    p = tally.params
    system = {k: p[k] for k in ("n", "masses", "weights", "level") if k in p}
    rep = dict(label=label, system=system, members=tally.n_members, t_final=p["t_final"],
               t_transient=p["t_transient"], sample_every=p["sample_every"],
               device=p["device"], seconds=seconds,
               statistics={v: tally.statistics(v) for v in VARIANTS})
    return dict(rep, **case_verdict(rep))


def family_systems(name) -> list:
    """[(label, RotorSystem)] of the distinct systems (N, masses, weights, level) of the
    bundled sweep ``name``, in the sweep's order; the test runs them at unit speed.
    ValueError for a sweep of the linkage."""
    from ..geometry.system import RotorSystem
    from .sweep.points import sweep_points
    from .sweep.spec import bundled_sweeps, load_sweep
    sweeps = bundled_sweeps()
    if name not in sweeps:
        raise ValueError(f"unknown sweep {name!r}; bundled: {', '.join(sorted(sweeps))}")
    out, seen = [], set()
    for point in sweep_points(load_sweep(sweeps[name])):
        sysd = point.scene.system
        if sysd.get("kind", "rotors") != "rotors":
            raise ValueError(f"the sweep {name!r} runs the {sysd['kind']}: the angle test at "
                             "scale is the rotors' (charts.linkage_angles for the linkage)")
        key = json.dumps([sysd["n"], sysd.get("masses"), sysd.get("weights"),
                          sysd.get("level", 0.0)])
        if key in seen:                     # points that differ only in seed, speed, …
            continue
        seen.add(key)
        params = {k: v for k, v in point.params.items() if k not in ("seed", "speed")}
        with warnings.catch_warnings():       # critical levels: a stopped member is reported
            warnings.simplefilter("ignore")
            system = RotorSystem(sysd["n"], masses=sysd.get("masses"),
                                 weights=sysd.get("weights"), level=sysd.get("level", 0.0))
        out.append((", ".join(f"{k} {v}" for k, v in params.items()), system))
    return out


def format_statistics(rep: dict) -> str:
    """A report of `statistics_verdict` as text: the restricted angles first ("?" for a
    number the report leaves undefined)."""
    def f(x, fmt):
        return "?" if x is None else format(x, fmt)
    s = rep["system"]
    took = "read from its saved tally" if rep.get("seconds") is None else f"{rep['seconds']:.0f} s"
    head = (f"{rep['label'] or 'N = ' + str(s['n'])}: masses {s['masses']}, weights "
            f"{s['weights']}, level {s['level']:g}; {rep['members']} members x T = "
            f"{rep['t_final']:g} (transient {rep['t_transient']:g}) on the {rep['device']}, "
            f"{took}")
    lines = [head]
    for variant in ("restricted", "full"):
        st = rep["statistics"][variant]
        lines.append(f"  {variant}: {st['n']:.3g} angles, min {st['min']:.3g} rad (seed "
                     f"{st['min_seed']}, t = {f(st['min_t'], 'g')}); {st['episodes']} episodes "
                     f"below {st['small']:g} rad ({f(st['episode_rate'], '.3g')} per time unit)")
        laws = [f"x0 {d['x0']:g}: beta {f(d['exponent'], '.3f')} ± "
                f"{f(d['exponent_se'], '.3f')} (n {d['count']})" for d in st["law"] if d["count"]]
        if laws:
            lines.append("    law P(phi < x) = A x^beta: " + "; ".join(laws))
        lines.append("    mean block minima: " + ", ".join(
            f"{size:g}: {f(m, '.3g')} ± {f(se, '.1g')}" for size, m, se in st["block_minima"]))
        lines.append("    slopes d ln min / d ln size: " + ", ".join(
            f"{a:g}-{b:g}: {f(x, '.3f')} ± {f(se, '.3f')}" for a, b, x, se in st["slopes"]))
    lines.append(verdict_line(rep))
    return "\n".join(lines)
