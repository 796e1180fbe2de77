"""The paper's claims that ``charts reproduce`` checks, each with our number, its sample size
and error and the verdict of ``charts.runs.claim_rule.verdict`` (`claims`); what a preset
cannot show, from its numbers (`cannot_show`); where and why the two curvature routes differ
most (`curvature_gap_lines`).  Every function reads ``results.json`` as written by
``charts.runs.reproduce`` (with ``charts.runs.reproduce_report.add_measurements``' numbers),
keys as JSON has them (N a string)."""
from __future__ import annotations

import math

from .claim_rule import ZERO_COUNT_SIGMA, fraction_error, paper_rounding_se, verdict
from .paper import EQ22_DIGITS, EQ22_DT, EXPONENT_DECIMALS

__all__ = ["claims", "cannot_show", "curvature_gap_lines", "eq22_bound", "big", "ANGLE_BATCHES",
           "COUNT_TARGET", "ORDER"]

#: The batches of the angle fractions' errors: those of ``angle_statistics``' small-value law
#: (``charts.analyses.hyperbolicity``: 10 contiguous blocks of the angles of one N).
ANGLE_BATCHES = 10
#: Samples below the near-tangency threshold for a counting error of 1/√100 = 10 %: the
#: length a run needs to measure the fraction of small angles (`cannot_show`).
COUNT_TARGET = 100
#: The largest route (a)–(b) difference counts as the truncation of a large |K| when it is
#: within this many Δt²K²: an order of magnitude, since c⁗/12 is of order K² wherever K's
#: own size sets its rate of change (near a singular point every term of c⁗ grows like K²).
ORDER = 10.0
#: Figure 4's panels by (N, i) of K_ii (its caption).
FIG4 = {(4, 1): "4b", (4, 2): "4c", (5, 1): "4d", (5, 2): "4e", (5, 3): "4f"}
#: Figure 5's panels by N.
FIG5 = {3: "5a", 4: "5b", 5: "5c"}


def eq22_bound():
    """The relative difference below which route (a) and eq (22) agree "up to the fifth
    significant digit" (section 3): half a unit of that digit, for a leading digit 1 (the
    loosest reading)."""
    return 0.5 * 10.0 ** (1 - EQ22_DIGITS)


def big(x):
    """``x`` to two significant digits, powers of ten written out: 2·10⁶, 2.5·10⁵."""
    m, e = f"{x:.1e}".split("e")
    e = int(e)
    if -2 <= e <= 3:
        return f"{float(f'{x:.2g}'):g}"
    sup = str(e).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"{m.rstrip('0').rstrip('.')}·10{sup}"


def _ns(results):
    return sorted(results["lyapunov"], key=int)


def _row(claim, where, paper, ours, n, v, context=""):
    return dict(claim=claim, where=where, paper=paper, ours=ours, n=n, verdict=v["verdict"],
                z=v["z"], reason=v["reason"] + (f"; {context}" if context else ""))


def _fraction_text(f, k, n, se):
    if k == 0:
        return f"0 of {n} (s.e. {se:.1e}: 1σ limit)"
    if se is None:
        return f"{f:.3g} ({k} of {n}; no s.e.)"
    return f"{f:.4g} ± {se:.2g}"


def _lyapunov_claims(results):
    ly = results["run"]["lyapunov"]
    B = ly["members"] * ly["batches"]
    n_text = f"{ly['members']} × t = {ly['t_final']:g}: {B} batch means"
    dec = EXPONENT_DECIMALS
    rows = []
    for n in _ns(results):
        r = results["lyapunov"][n]
        for k, (e, se, p) in enumerate(zip(r["exponents"], r["stderr"], r["paper"])):
            rows.append(_row(f"N = {n}: λ{k + 1}", "§2, the printed spectrum", f"{p:.{dec}f}",
                             f"{e:.4f} ± {se:.4f}", n_text,
                             verdict(e, se, p, paper_rounding_se(dec), relation="=", batches=B)))
        m = len(r["exponents"])
        e, se = r["exponents"][-1], r["stderr"][-1]
        rows.append(_row(f"N = {n}: {m} positive exponent{'s' * (m > 1)} (λ{m} > 0)",
                         "abstract; §2", f"λ{m} = {r['paper'][-1]:.{dec}f} > 0",
                         f"λ{m} = {e:.4f} ± {se:.4f}", n_text,
                         verdict(e, se, 0.0, relation=">", batches=B)))
    return rows


def _curvature_claims(results):
    cv = results["run"]["curvature"]
    rows = []
    for n in _ns(results):
        c = results["curvature"][n]
        S, B = c["samples"], c["batches"]
        n_text = f"{S} samples of 1 × t = {cv['t_final']:g}, {B} batches"
        if int(n) == 3:
            m, se, bound = c["eq22_median_rel"], c["eq22_median_rel_se"], eq22_bound()
            note = f"max abs. difference {c['eq22_max_abs']:.1e}"
            if cv["dt"] != EQ22_DT:
                note += f"; our Δt = {cv['dt']:g}, the paper's {EQ22_DT:g}"
            rows.append(_row("N = 3: route (a) = eq (22) to 5 significant digits (median "
                             "relative difference)", "§3, after eq (22)",
                             f"< {bound:.0e} at Δt = {EQ22_DT:g}", f"{m:.2e} ± {se:.1e}",
                             n_text, verdict(m, se, bound, relation="<", batches=B), note))
        for i, f in enumerate(c["fraction_positive"]):
            k = c["positive_count"][i]
            se = fraction_error(k, S, c["fraction_positive_se"][i])
            ours = _fraction_text(f, k, S, se)
            if int(n) == 3:
                rows.append(_row("N = 3: K < 0 everywhere but at 8 points (fraction K > 0)",
                                 "§3, eq (22); Fig. 4a", "0", ours, n_text,
                                 verdict(f, se, 0.0, relation="=", batches=B)))
            else:
                rows.append(_row(f"N = {n}: K_{i + 1}{i + 1} > 0 occurs (fraction K > 0)",
                                 f"§3, Fig. {FIG4.get((int(n), i + 1), '4')}", "> 0", ours,
                                 n_text, verdict(f, se, 0.0, relation=">", batches=B)))
    return rows


def _angle_claims(results):
    an = results["run"]["angles"]
    rows = []
    for n in _ns(results):
        for var in ("full", "restricted"):
            s = results["angles"][n][var]
            k, N, x0 = s["law_count"], s["n"], s["small"]
            batch_se = None if s["law_coef2_se"] is None else s["law_coef2_se"] * x0 ** 2
            se = fraction_error(k, N, batch_se)
            n_text = (f"{N} samples of {an['members']} × t = {an['t_final']:g}, "
                      f"{ANGLE_BATCHES} batches")
            context = f"smallest φ {s['min']:.3g} rad"
            if k and se is None:
                context = (f"{k} samples below {x0:g} rad, in fewer than two of the "
                           f"{ANGLE_BATCHES} batches; " + context)
            where = f"§4, Fig. {FIG5.get(int(n), '5')}"
            ours = _fraction_text(s["frac_small"], k, N, se)
            if int(n) == 3:
                rows.append(_row(f"N = 3 ({var}): no angle near 0 (fraction φ < {x0:g} rad)",
                                 where, "0", ours, n_text,
                                 verdict(s["frac_small"], se, 0.0, relation="=",
                                         batches=ANGLE_BATCHES), context))
            else:
                rows.append(_row(f"N = {n} ({var}): angles near 0 occur (fraction φ < "
                                 f"{x0:g} rad)", where, "> 0", ours, n_text,
                                 verdict(s["frac_small"], se, 0.0, relation=">",
                                         batches=ANGLE_BATCHES), context))
    return rows


def claims(results) -> list:
    """Every claim the preset checks, in the paper's order (sections 2, 3, 4), each a dict:
    claim, where (in the paper), paper (its number), ours (± s.e.), n (samples and the
    batches of the error), verdict, z, reason."""
    return _lyapunov_claims(results) + _curvature_claims(results) + _angle_claims(results)


# ------------------------------------------------------------------------ what it cannot show
def _exponent_precision(results):
    ly = results["run"]["lyapunov"]
    half = 0.5 * 10.0 ** -EXPONENT_DECIMALS
    ses = [s for n in _ns(results) for s in results["lyapunov"][n]["stderr"]]
    lo, hi = min(ses), max(ses)
    T = ly["members"] * ly["t_final"]
    if hi <= half:
        return [f"- **The exponents** are resolved to the paper's printed precision (± {half:g}):"
                f" our standard errors are {lo:.4f}–{hi:.4f}."]
    grow = (hi / half) ** 2
    return [f"- **The third decimal of the exponents.** The paper prints them to "
            f"{EXPONENT_DECIMALS} decimals (± {half:g}); our standard errors are {lo:.4f}–"
            f"{hi:.4f}, {lo / half:.1f}–{hi / half:.1f} × that, so a difference in the last "
            f"printed decimal is not resolved.  The errors fall like 1/√T: to bring the largest "
            f"to ± {half:g} the time per N would grow {grow:.0f}×, from {ly['members']} × "
            f"{ly['t_final']:g} = {big(T)} to {big(T * grow)}."]


def _zero_exponents(results):
    T = results["run"]["angles"]["t_final"]
    bias = math.log(T) / T
    parts, largest = [], 0.0
    for n in _ns(results):
        ex = results["clv"][n]["restricted"]["exponents"]
        zeros = ex[int(n) - 2:int(n)]
        largest = max(largest, *(abs(z) for z in zeros))
        parts.append(f"N = {n}: " + ", ".join(f"{z:+.4f}" for z in zeros))
    size = ("within" if largest <= bias else f"up to {largest / bias:.1f} ×")
    return [f"- **The two zero exponents and the ±λ pairs** (§2) get no error bar: only the "
            f"leading N − 2 exponents do.  The CLV route's mean growth along the two zero "
            f"directions (restricted; {'; '.join(parts)}) is {size} a finite run's bias "
            f"ln T / T = {bias:.1e} (T = {T:g}; docs/second-routes.md), so it neither confirms nor "
            "contradicts exact zeros."]


def _tangencies(results):
    an = results["run"]["angles"]
    ang = results["angles"]
    ns = _ns(results)
    away = {v: ang[n][v]["min"] for n in ns if int(n) == 3 for v in ("full", "restricted")}
    out, resolved = [], []
    for n in ns:
        if int(n) == 3:
            continue
        for var in ("full", "restricted"):
            s = ang[n][var]
            k, N, x0 = s["law_count"], s["n"], s["small"]
            if k and s["law_coef2_se"] is not None and s["law_exponent_se"] is not None:
                resolved.append(f"N = {n} {var} ({k} below {x0:g} rad, β̂ = "
                                f"{s['law_exponent']:.2f} ± {s['law_exponent_se']:.2f}, smallest "
                                f"φ {s['min']:.2g})")
                continue
            floor = ZERO_COUNT_SIGMA / N
            text = (f"- **N = {n}'s tangencies in the {var} variant.** {k} of {N} samples fall "
                    f"below x₀ = {x0:g} rad (smallest φ {s['min']:.3g} rad, 0.1 % quantile "
                    f"{s['p001']:.3g}), too few for an error bar on their fraction or on the law "
                    f"P(φ < x) = A x^β.  With {N} samples a fraction below about "
                    f"{floor:.1e} (the 1σ limit of a zero count) cannot be told from 0")
            if k:
                text += f"; N = {n}'s is {k / N:.1e}, {k / N / floor:.1f} × that"
            text += (f".  The run has seen nothing below {s['min']:.3g} rad, so it cannot tell "
                     "angles that come arbitrarily close to 0 from a gap below that")
            if var in away:
                text += (f"; what it does show is that they come {away[var] / s['min']:.0f}× "
                         f"closer than N = 3's (smallest {away[var]:.3g} rad)")
            if k:
                need = COUNT_TARGET * N / k
                t_need = an["members"] * an["t_final"] * COUNT_TARGET / k
                text += (f".  At the rate seen, {COUNT_TARGET} samples below x₀ (a 10 % counting "
                         f"error) need about {big(need)} samples, t ≈ {big(t_need)} per N, "
                         f"{COUNT_TARGET / k:.0f}× this preset's {an['members']} × "
                         f"{an['t_final']:g}.")
            else:
                text += ": with no sample below x₀ there is no rate to extrapolate."
            out.append(text)
    if resolved:
        out.append("- **Tangencies, where resolved** (" + "; ".join(resolved) + "): samples "
                   "below x₀ fall in several batches and their law P(φ < x) = A x^β continues "
                   "toward 0 down to the smallest angle seen; no finite sample shows P(φ < x) > 0 "
                   "for every x > 0, so \"reaches φ = 0\" rests on that law's continuation.")
    return out


def cannot_show(results) -> list:
    """Markdown bullets: what the preset's numbers cannot decide, each from the numbers."""
    cv = results["run"]["curvature"]
    seeds = sorted({s for v in cv["seeds"].values() for s in v})
    return (_exponent_precision(results) + _zero_exponents(results) + _tangencies(results) + [
        f"- **How often K > 0.** The paper gives no number (positive values \"with notable "
        f"statistical significance\", §3), so only K > 0 at all is tested, on one trajectory "
        f"per N (t = {cv['t_final']:g}, seed {', '.join(map(str, seeds))}); the histograms of "
        "Fig. 4 are drawn (fig4.png), not compared.",
        "- **Figures 2 and 3** (waveforms and spectra, \"chaotic ... continuous spectra\", §1) "
        "are drawn (fig2.png, fig3.png), not tested: results.json holds no number for them.",
        "- **Hyperbolicity itself.** \"Confirmed\" on the angles means our samples agree with "
        "the paper's reading of Fig. 5; sampled angles neither prove nor rule out uniform "
        "hyperbolicity (`charts verdict` runs the theorems: docs/hyperbolicity.md)."])


# ------------------------------------------------------------------------ the two curvature routes
def curvature_gap_lines(results) -> list:
    """Markdown lines: where the two curvature routes differ most for each N, and why."""
    L = ["**The two curvature routes.**  Route (a) is the paper's algorithm (eqs 19–21: a "
         "second difference over one RK4 step ±Δt), route (b) the exact Riemann tensor at the "
         "same points and frames.  Route (a)'s error is the truncation of that difference, "
         "≈ Δt²·c⁗/12 with c⁗ = (K² − K̈)c − 2K̇ċ (from c̈ = −Kc): it is large where |K| is "
         "(close to the singular points of N = 4, where Σ sin²θ → 0) or where K changes fast, "
         "and it falls 4× per halving of Δt, as measured at the very samples of the largest "
         "differences below (docs/second-routes.md, \"The two curvature routes\").  Largest "
         "difference on the diagonal per N, and its size in units of Δt²K²:", "",
         "| N | largest \\|K_a − K_b\\| | in | K there (route b) | 99.9 % of \\|K\\| below "
         "| relative | ÷ Δt²K² |",
         "|---|---|---|---|---|---|---|"]
    notes = []
    for n in _ns(results):
        g = results["curvature"][n]["route_gap"]
        K, d, r = g["K_exact"], g["max_abs"], g["per_dt2_K2"]
        rel = d / abs(K) if K else math.inf
        L.append(f"| {n} | {d:.2g} | K_{g['direction']}{g['direction']} | {K:.4g} | "
                 f"{g['abs_K_p999']:.3g} | {rel:.1e} | {'—' if r is None else f'{r:.2g}'} |")
        top = " (the run's largest)" if abs(K) >= g["abs_K_max"] else ""
        big_k = (f"above 99.9 % of the run{top}" if abs(K) >= g["abs_K_p999"] else
                 "below the run's 99.9 % quantile")
        if r is not None and r <= ORDER:
            why = (f"{r:.2g} Δt²K², within {ORDER:g} Δt²K²: the truncation of a curvature this "
                   "large")
        else:
            size = "far above Δt²K²" if r is None else f"{r:.2g} Δt²K², beyond {ORDER:g} Δt²K²"
            why = (f"{size}: not the size of K but its change along the geodesic (the K̈ and "
                   "K̇ċ terms of c⁗)")
        notes.append(f"- N = {n}: {d:.2g} (relative {rel:.1e}) at |K| = {abs(K):.3g}, "
                     f"{big_k}; it is {why}.")
        full = results["curvature"][n]["max_ab"]
        if full > d * (1 + 1e-9):
            notes[-1] += f"  Off the diagonal the largest is {full:.2g}."
    return L + [""] + notes + [""]
