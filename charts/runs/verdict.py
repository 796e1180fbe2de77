"""The verdicts on hyperbolicity from exact invariants and certificates (docs/hyperbolicity.md;
``charts verdict``): for N = 3 the Gauss–Bonnet theorem by both curvature routes, the leading
exponent against the bracket of Katok's and Osserman–Sarnak's inequalities and the certified
sign of the curvature; for N ≥ 4 the flat totally geodesic torus that rules out the Anosov
property, with the monodromy of its closed geodesic.  Where neither applies, the statistics
of the angle test at scale (``charts.runs.verdict_statistics``, ``charts verdict
--statistics``).  For the triple linkage (``charts.runs.verdict_linkage``, ``charts verdict
--triple-linkage``) the surface integrals and λ₁ at each r, where no theorem is certified at
a given r; for any 2-dimensional mechanism (``charts.runs.verdict_mechanism``, ``charts
verdict --mechanism``) the same measurements, where only χ > 0 decides.  This module holds the reports of the rotors' exact verdicts and the rule that
turns any report into its verdict.  Each
report carries its verdict (`case_verdict`: "hyperbolic (Anosov)", "not hyperbolic" or
"open", the class of its evidence and one sentence why), derived from the certificates'
outcomes, never from N alone.
"""
from __future__ import annotations

import time

import numpy as np

from ..analyses.curvature_certificate import certify_curvature_sign
from ..analyses.flat_tori import certify_flat_torus
from ..analyses.lyapunov import lyapunov_spectrum
from ..analyses.surface_integrals import surface_integrals

__all__ = ["surface_verdict", "torus_verdict", "verdict_passed", "case_verdict",
           "verdict_line", "report_kind", "exponent_report", "VERDICTS", "EVIDENCE",
           "CHI_TOLERANCE"]

#: The largest distance of ∫K dA / 2π from the integer χ it is read as, for a surface whose χ
#: the quadrature reads (the triple linkage): Gauss–Bonnet makes it an integer; the default
#: grid (96²) meets it by 3·10⁻⁵ or better up to r = 0.3, r = 0.4 needs 192²
#: (docs/triple-linkage.md); a larger distance means the grid does not resolve the
#: curvature, or the surface is singular.
CHI_TOLERANCE = 1e-3
#: Hopf's and Klingenberg's argument on a closed surface with χ > 0 (the end of a sentence).
_HOPF = ("a closed surface without conjugate points has int K dA <= 0 (Hopf 1948): there are "
         "conjugate points, which an Anosov geodesic flow never has (Klingenberg 1974)")

#: The verdicts a case can get (`case_verdict`).
VERDICTS = ("hyperbolic (Anosov)", "not hyperbolic", "open")
#: The classes of evidence behind a verdict: a theorem whose hypotheses a certificate of the
#: library proves; a theorem whose hypotheses are exact (topology, a symbolic proof); sampled
#: statistics only (the angles of the angle test, or a leading exponent resolved above 0 on
#: sampled trajectories; always "open"); nothing that decides.
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
    exponents = [exponent_report(lyapunov_spectrum(system, *system.random_state(seed=seed,
                                                                                speed=1.0),
                                                   t_final), seed, t_final, (lower, upper))
                 for seed in seeds]
    cert = certify_curvature_sign(system).to_dict()
    rep = dict(system=system.describe(),
               n_grid=int(n_grid), routes=routes, bracket=[lower, upper],
               exponents=exponents, certificate=cert,
               seconds=time.perf_counter() - t0)
    return dict(rep, **case_verdict(rep))


def exponent_report(result, seed, t_final, bracket) -> dict:
    """The JSON entry of one λ₁ run (a result with ``exponents`` and ``stderr``) against the
    entropy bracket (lower, upper; None where a bound does not apply): consistent when no
    bound is violated by more than 3 standard errors, resolved inside when the whole ±3 s.e.
    interval lies inside."""
    lower, upper = bracket
    lam, se = float(result.exponents[0]), float(result.stderr[0])
    consistent = (lower is None or lam + 3 * se > lower) and \
        (upper is None or lam - 3 * se < upper)
    resolved = (lower is None or lam - 3 * se > lower) and \
        (upper is None or lam + 3 * se < upper)
    return dict(seed=int(seed), t_final=float(t_final), lambda1=lam, stderr=se,
                consistent=bool(consistent), resolved_inside=bool(resolved))


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
                f"chi = {chi} (Morse count), so int K dA = 2 pi chi > 0 (Gauss-Bonnet), and "
                + _HOPF)
    if outcome == "positive somewhere" and chi == 0:
        return ("not hyperbolic", "theorem with certificate",
                "chi = 0 (Morse count), so int K dA = 0 (Gauss-Bonnet), and K > 0 is certified "
                "on a box, so K is not identically 0; a closed surface without conjugate points "
                "has int K dA <= 0 on each component, with equality only where it is flat (Hopf "
                "1948), so there are conjugate points, which an Anosov geodesic flow never has "
                "(Klingenberg 1974)")
    if outcome == "positive somewhere":
        evidence, exponents = _exponent_evidence(rep)
        return ("open", evidence,
                f"K > 0 is certified on a box (chi = {chi}), so no curvature theorem applies, "
                "and a surface with some positive curvature can still be Anosov; "
                + exponents)
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


def _exponent_evidence(rep: dict) -> tuple:
    """(evidence, clause) for a surface where no theorem applies: "statistics" when every λ₁
    run of the report lies above 0 by 3 standard errors or the report holds sampled angles,
    "no proof" otherwise; the clause ends the reason."""
    runs, angles = rep.get("exponents") or [], rep.get("angles") or []
    said = []
    if runs and all(e["lambda1"] - 3 * e["stderr"] > 0 for e in runs):
        lams = ", ".join(f"{e['lambda1']:.3f} +- {e['stderr']:.3f}" for e in runs)
        said.append(f"lambda1 = {lams} at unit speed (T = {runs[0]['t_final']:g})")
    if angles:
        said.append(f"the smallest restricted angle is {min(a['min'] for a in angles):.3g} rad "
                    f"in {sum(a['n'] for a in angles)} samples")
    if said:
        k = max(len(runs), len(angles))
        return ("statistics",
                " and ".join(said) + f" on {k} sampled trajector{'y' if k == 1 else 'ies'} "
                "are statistics: they can be consistent with the Anosov property but do not "
                "prove a uniform splitting on the whole unit tangent bundle")
    return ("no proof", "no exponent run here is resolved above 0, and none would decide: "
            "nothing run here decides")


#: What Hunt and MacKay's theorem gives at a finite r (a clause of the linkage's reasons).
_HUNT_MACKAY = ("Hunt and MacKay (Nonlinearity 16, 2003) prove the Anosov property for some "
                "non-empty open set of lengths and masses, by structural stability from the "
                "limit r -> 0 with l = R (the N = 3 rotor surface, K <= 0 certified: charts "
                "verdict --n 3), with no explicit bound on r, so it certifies no given r")


def report_kind(rep: dict):
    """The kind of system a report is of: "triple_linkage" (``linkage_verdict``), "mechanism"
    (``charts.runs.verdict_mechanism``: a 2-dimensional mechanism of one's own, or an instance
    given by ``--mechanism``), or None (the rotors' reports)."""
    system = rep.get("system")
    return system.get("kind") if isinstance(system, dict) else None


def _chi_settled(rep: dict) -> bool:
    """Every route reads the same χ, each ∫K dA / 2π within `CHI_TOLERANCE` of it."""
    routes = rep["routes"].values()
    return len({r["euler_characteristic"] for r in routes}) == 1 and all(
        abs(r["total_curvature"] / (2 * np.pi) - r["euler_characteristic"]) <= CHI_TOLERANCE
        for r in routes)


def _measured_case(rep: dict, at: str, morse: str, no_sign: str, known: str,
                   flat: str) -> tuple:
    """(verdict, evidence, reason) of a surface whose χ the quadrature reads (Gauss–Bonnet;
    measured, not certified) and whose curvature is known at the nodes only (floating
    point): the triple linkage's and a generic 2-dimensional mechanism's.  ``at`` names the
    surface, ``morse`` ends the sentence on χ, ``no_sign`` says why K ≤ 0 at the nodes
    proves nothing, ``known`` is what is known beyond the nodes, ``flat`` the clause for
    χ = 0 (None: the exponents' evidence, as for χ < 0)."""
    routes = rep["routes"]
    names = " and ".join(routes)
    totals = ", ".join(f"{r['total_curvature'] / (2 * np.pi):.6f} ({route})"
                       for route, r in routes.items())
    if not _chi_settled(rep):
        return ("open", "no proof",
                f"the quadrature does not settle chi at {at}: int K "
                f"dA / 2 pi = {totals} on {rep['n_grid']}^2 nodes per chart, not within "
                f"{CHI_TOLERANCE:g} of one integer (a finer --grid, or a singular surface), so "
                "no theorem can be applied")
    chi = next(iter(routes.values()))["euler_characteristic"]
    off = max(abs(r["total_curvature"] / (2 * np.pi) - chi) for r in routes.values())
    measured = (f"chi = {chi} read from Gauss-Bonnet (int K dA / 2 pi within {off:.1g} of it "
                f"by the {names} route{'s' if len(routes) > 1 else ''}; measured, not "
                f"certified{morse})")
    if chi > 0:
        return ("not hyperbolic", "theorem",
                f"{measured}, so some component is a sphere, and " + _HOPF)
    if chi == 0 and flat is not None:
        return ("open", "no proof", f"{measured}, {flat}")
    c = routes["chart"]
    kmax = max(r["max_curvature"] for r in routes.values())
    if kmax > 0:
        curv = (f"K > 0 on {100 * c['positive_area']:.2g} % of the area (largest K "
                f"{kmax:.2g} at the nodes, in floating point by the {names} "
                f"route{'s' if len(routes) > 1 else ''}, no interval certificate), so neither "
                "Anosov's theorem (K < 0) nor Eberlein's condition (K <= 0) applies, and a "
                "surface with some positive curvature can still be Anosov")
    else:
        curv = f"K <= 0 at every node, but nodes prove no sign ({no_sign}), so no " \
            "curvature theorem applies"
    evidence, exponents = _exponent_evidence(rep)
    return ("open", evidence, f"{measured}; {curv}; {known}; {exponents}")


def _linkage_case(rep: dict) -> tuple:
    """(verdict, evidence, reason) of a `linkage_verdict` report by `_measured_case`, with
    the limit's Morse count and Hunt–MacKay's theorem: no theorem is certified at a finite
    r, so χ < 0 gives "open" at best."""
    s, lim = rep["system"], rep["limit"]
    morse = ("" if lim["euler_characteristic"] is None else
             f"; the limit r -> 0, sum cos theta = {lim['level']:g}, has chi = "
             f"{lim['euler_characteristic']} by the Morse count")
    return _measured_case(
        rep, f"r = {s['r']:g}, l = {s['l']:g}", morse,
        "near the limit's 8 zeros K > 0 on regions of order r^2 that a grid can miss: "
        "docs/triple-linkage.md", _HUNT_MACKAY,
        "which does not fix the components (a torus, or a sphere with a surface of genus 2), "
        "and no certificate of K is run on the linkage")


def _mechanism_case(rep: dict) -> tuple:
    """(verdict, evidence, reason) of a `mechanism_verdict` report by `_measured_case`: χ > 0
    is "not hyperbolic" (Hopf), anything else "open" — no certificate of K's sign exists
    for a general mechanism, so never "hyperbolic"."""
    return _measured_case(
        rep, rep["system"]["name"], "",
        "a region of positive curvature smaller than a cell can lie between them",
        "no certificate of the sign of K exists for a general mechanism (the rotors' interval "
        "certificate is theirs), so no curvature theorem can prove the Anosov property here",
        None)


def case_verdict(rep: dict) -> dict:
    """The verdict of one report of ``charts verdict`` (`surface_verdict`, `torus_verdict`,
    `linkage_verdict`, `mechanism_verdict` or `tally_report`) as ``dict(verdict, evidence,
    reason)``: ``verdict`` one of `VERDICTS`, ``evidence`` one of `EVIDENCE`, ``reason`` one
    sentence.  Derived from what the report holds — the curvature certificate's outcome and χ
    (N = 3), the flat-torus proof (N ≥ 4), the measured χ and curvature of the triple linkage
    or of a 2-dimensional mechanism; a certificate that is
    undecided or fails gives "open", and sampled statistics alone give "open"."""
    if "torus" in rep:
        verdict, evidence, reason = _torus_case(rep)
    elif report_kind(rep) == "triple_linkage":
        verdict, evidence, reason = _linkage_case(rep)
    elif report_kind(rep) == "mechanism":
        verdict, evidence, reason = _mechanism_case(rep)
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
    torus proof with every step true (N ≥ 4); for the triple linkage and a mechanism, χ read
    alike by every route within `CHI_TOLERANCE` and no exponent above Katok's bound by over 3
    standard errors."""
    if "torus" in rep:
        return all(s["holds"] for s in rep["torus"]["proof"])
    if report_kind(rep) == "triple_linkage" or report_kind(rep) == "mechanism":
        return _chi_settled(rep) and all(e["consistent"] for e in rep["exponents"])
    chi = rep["routes"]["chart"]["euler_characteristic"]
    scale = 2 * np.pi * max(abs(chi), 1)
    return (all(abs(r["gauss_bonnet_error"]) <= 1e-6 * scale for r in rep["routes"].values())
            and all(e["consistent"] for e in rep["exponents"])
            and rep["certificate"]["verdict"] != "undecided")
