"""The verdict on a claim of the paper from our number and its error: one rule for every
line of ``charts reproduce``'s report (`verdict`), with the error of a counted fraction
(`fraction_error`) and of a printed, rounded number (`paper_rounding_se`); `RULE` states it
in words for the report."""
from __future__ import annotations

import math

__all__ = ["verdict", "fraction_error", "paper_rounding_se", "VERDICTS", "AGREE", "DISAGREE",
           "MIN_BATCHES", "ZERO_COUNT_SIGMA", "RULE"]

#: The verdicts, in the order of the rule.
VERDICTS = ("confirmed", "not confirmed", "inconclusive")
#: |z| at or below which our number agrees with a value the paper claims (a bound: the
#: margin by which ours must lie on the claimed side): two combined standard errors.
AGREE = 2.0
#: |z| beyond which our number contradicts the claim: three combined standard errors.
DISAGREE = 3.0
#: Fewest independent batches (or trajectories) behind an error bar: the standard error of
#: a standard error from m batch means is 1/√(2(m − 1)) of it, over 24 % below 10.
MIN_BATCHES = 10
#: Gehrels (1986, ApJ 303, 336, table 1): the 1σ (84.13 %) upper limit of a Poisson mean
#: when no event is seen; the error of a fraction 0/n is taken as this over n.
ZERO_COUNT_SIGMA = 1.841


def verdict(ours, se, claim, claim_se=0.0, *, relation="=", batches=None,
            min_batches=MIN_BATCHES) -> dict:
    """The verdict on one claim: ``dict(verdict, z, reason)``.

    z = (ours − claim) / √(se² + claim_se²).  ``relation`` "=" (the paper claims the value
    ``claim``): confirmed if |z| ≤ `AGREE`, not confirmed if |z| > `DISAGREE`.  ">" or "<"
    (the paper claims a bound: ours > claim, ours < claim): confirmed if ours lies on the
    claimed side by more than `AGREE` combined standard errors, not confirmed if on the
    other side by more than `DISAGREE`.  Inconclusive in between, and whatever z where
    ``se`` is None or not finite (no error bar: too few samples) or ``batches`` (the
    independent batches behind ``se``) is below ``min_batches``.  ``reason``: one line
    with the numbers."""
    if relation not in ("=", ">", "<"):
        raise ValueError(f"relation must be '=', '>' or '<', got {relation!r}")
    if se is None or not math.isfinite(se) or se < 0:
        return dict(verdict="inconclusive", z=None, reason="no standard error (too few samples)")
    if batches is not None and batches < min_batches:
        return dict(verdict="inconclusive", z=None,
                    reason=f"the error rests on {batches} batches (fewer than {min_batches})")
    d = float(ours) - float(claim)
    s = math.hypot(se, claim_se)
    z = 0.0 if d == 0 else (math.copysign(math.inf, d) if s == 0 else d / s)
    if relation == "=":
        a = abs(z)
        word = ("confirmed" if a <= AGREE else "not confirmed" if a > DISAGREE
                else "inconclusive")
        cmp = (f"≤ {AGREE:g}" if word == "confirmed" else f"> {DISAGREE:g}"
               if word == "not confirmed" else f"between {AGREE:g} and {DISAGREE:g}")
        return dict(verdict=word, z=z, reason=f"|ours − paper| = {abs(d):.2g} = {a:.1f} "
                                             f"combined s.e., {cmp}")
    side = z if relation == ">" else -z        # > 0: on the claimed side
    word = ("confirmed" if side > AGREE else "not confirmed" if side < -DISAGREE
            else "inconclusive")
    where = "above" if relation == ">" else "below"
    if word == "confirmed":
        why = f"{abs(z):.1f} combined s.e. {where} {claim:g} (more than {AGREE:g})"
    elif word == "not confirmed":
        why = f"{abs(z):.1f} combined s.e. on the wrong side of {claim:g} (more than {DISAGREE:g})"
    else:
        why = (f"{side:+.1f} combined s.e. {where} {claim:g}: neither more than {AGREE:g} "
               f"{where} nor {DISAGREE:g} on the wrong side")
    return dict(verdict=word, z=z, reason=why)


def fraction_error(count, n, batch_se):
    """Standard error of the fraction ``count``/``n``: ``batch_se`` (the batch means; None
    where fewer than two batches hold a count) when ``count`` > 0; with no count,
    `ZERO_COUNT_SIGMA`/n (the samples counted as independent: optimistic for correlated
    samples)."""
    if count == 0:
        return ZERO_COUNT_SIGMA / n
    return batch_se


def paper_rounding_se(decimals):
    """Standard error of a number printed to ``decimals`` decimals: half a unit of the last,
    uniform, over √3."""
    return 0.5 * 10.0 ** -decimals / math.sqrt(3)


#: The rule in words, as the report states it once.
RULE = (
    "**The rule** (`charts.runs.claim_rule.verdict`, the same for every line): z = "
    "(ours − paper) / √(s.e.² + s.e.paper²), with s.e. our two-sided standard error (its "
    "source in the line's n column) and s.e.paper the paper's rounding (half a unit of the last "
    "printed digit, uniform: / √3; 0 for a bound).  A value claimed: **confirmed** if |z| ≤ "
    f"{AGREE:g}, **not confirmed** if |z| > {DISAGREE:g}.  A bound claimed (ours > b or ours < "
    f"b): **confirmed** if ours lies on the claimed side by more than {AGREE:g} combined s.e., "
    f"**not confirmed** if on the other side by more than {DISAGREE:g}.  **Inconclusive** in "
    "between, and always where the error bar is undefined (too few samples) or rests on fewer "
    f"than {MIN_BATCHES} independent batches.  A fraction k/n has the s.e. of its batch means "
    "where at least two batches hold a count, none where fewer do, and for k = 0 "
    f"{ZERO_COUNT_SIGMA}/n, the 1σ Poisson upper limit (Gehrels 1986; the samples counted as "
    "independent, so optimistic).")
