"""How long a Lyapunov run discards first: the rules a ``t_transient`` may name instead of a
duration, and the duration each gives.

* ``"scaled"`` (the default of `lyapunov_spectrum`, `lyapunov_ensemble` and
  `curvature_along_trajectory`, whose frames are the Lyapunov vectors): `SCALED_PER_N2`
  · N² / speed time units, at least `SCALED_MIN`, with no upper bound; no pilot, its cost
  grows with the N that needs it.
* ``"auto"``: `AUTO_EFOLDINGS` over the smallest positive exponent of a pilot run
  (`charts.analyses.lyapunov.auto_transient`), for systems far from the measured ones
  (masses, weights, levels).

Why: the last tangent vector aligns with its Oseledets direction after many e-foldings of the
smallest positive exponent λ_{N−2}, and a shorter transient biases it in short runs: with the
old default of 50, by −11 % at N = 5 (T = 50) and −22 % at N = 8 (T = 100), 2.6 and 5.0
combined standard errors (docs/large-n.md, "Transients"; ``python scripts/transient_bias.py``).
Measured at unit speed, λ_{N−2} ≈ 3 / N²: 0.1212 at N = 5 (3.03 / N²), 0.0455 at N = 8
(2.91 / N²), 0.0215 at N = 12 (3.10 / N²), 1/280 at N = 32 (3.66 / N²); 15 e-foldings of
3 / N² is 5 N².
The rule gives 50 at N = 3 (the old default: N = 3 runs are unchanged), 80 at N = 4, 125 at
N = 5, 320 at N = 8, 720 at N = 12, 5120 at N = 32, 11520 at N = 48, 20480 at N = 64.
Measured (errors across the members, seeds 1, 2, …; ``python scripts/transient_bias.py --n N
--t-final T --members M --transients ...``; 2026-12-04, the 2-core VM), the smallest exponent against a long reference (T =
2000; 64 members, 32 at N = 12, after 100, 500, 1500):

====  =====  =======  ===============  ==================  ==================  ===========
N     T      members  transient        λ_{N−2}             reference           off by
====  =====  =======  ===============  ==================  ==================  ===========
5     50     512      50 (old)         0.1155 ± 0.0023     0.1212 ± 0.0009     2.3 σ
5     50     512      125 (scaled)     0.1197 ± 0.0024     0.1212 ± 0.0009     0.6 σ
8     100    128      50 (old)         0.0354 ± 0.0018     0.0455 ± 0.0006     5.3 σ
8     100    512      320 (scaled)     0.0451 ± 0.0011     0.0455 ± 0.0006     0.3 σ
12    100    256      50 (old)         0.0231 ± 0.0007     0.0215 ± 0.0005     1.9 σ high
12    100    256      720 (scaled)     0.0209 ± 0.0013     0.0215 ± 0.0005     0.4 σ
====  =====  =======  ===============  ==================  ==================  ===========

(σ: the combined standard error.)  Exponents scale with the speed, so the times scale as
1/speed.  There is no upper bound: up to N = 64 the measured λ_{N−2} (docs/large-n.md: 3.66/N²
at N = 32, 4.4/N² at N = 48, 4.1/N² at N = 64) makes 5 N² at least 15 e-foldings, where an
upper bound of 5000 (this rule until 2026-12-05) left 8000 and 15000 needed at N = 48 and 64,
so a short run's smallest exponent came out biased.  Its cost is the transient alone, no
pilot, and grows as N² like the alignment it waits for: at N = 5 and T = 50 the run integrates
175 time units where the old default integrated 100; at N = 64 the transient is 20480 (a
written ``t_transient`` or ``n_exponents`` small with a duration of one's own is cheaper where
only the leading exponents matter).
"""
from __future__ import annotations

import difflib

import numpy as np

from ..geometry.checks import shown
from .arguments import Documented

__all__ = ["TRANSIENT_RULES", "transient_rule", "scaled_transient", "SCALED_PER_N2",
           "SCALED_MIN", "SCALED_RULE", "AUTO_EFOLDINGS", "AUTO_TRANSIENT_RANGE", "PILOT_TIMES",
           "AUTO_RULE",
           "resolve_transient", "kinetic_speed", "auto_duration"]

#: The words a ``t_transient`` may be instead of a duration.
TRANSIENT_RULES = ("scaled", "auto")
#: ``t_transient="auto"``: this many e-foldings of the smallest positive exponent, estimated
#: by a pilot run, so that the last tangent vector has aligned with its Oseledets direction
#: (its misalignment decays at the gap to the zero exponent next to it).  Measured
#: (docs/large-n.md, "Transients"): with fewer the smallest exponent comes out biased, by
#: −12 % at N = 5 (T = 50, transient 10) and −24 % at N = 8 (T = 100, transient 50).
AUTO_EFOLDINGS = 15.0
#: The pilot of the rule: (transient, averaging time), both in time units.
PILOT_TIMES = (50.0, 200.0)
#: Bounds of "auto"'s transients (time units); the exponent "auto" divides is floored at
#: 1 % of the largest, so that a pilot's near-zero estimate does not ask for an endless one.
AUTO_TRANSIENT_RANGE = (50.0, 5000.0)
AUTO_RULE = (f"auto: {AUTO_EFOLDINGS:g} / (smallest positive exponent of a pilot of "
             f"{PILOT_TIMES[1]:g} after {PILOT_TIMES[0]:g}), within {AUTO_TRANSIENT_RANGE}")
#: ``t_transient="scaled"``: time units per N² at unit speed, `AUTO_EFOLDINGS` e-foldings of
#: the measured λ_{N−2} ≈ 3 / N² (module docstring).
SCALED_PER_N2 = AUTO_EFOLDINGS / 3.0
#: The shortest transient of ``"scaled"`` (N = 3's: 25 e-foldings of λ₁ ≈ 0.5 at unit speed).
SCALED_MIN = AUTO_TRANSIENT_RANGE[0]
SCALED_RULE = f"scaled: {SCALED_PER_N2:g} N^2 / speed, at least {SCALED_MIN:g}"


def transient_rule(t_transient):
    """The rule ``t_transient`` names ("scaled" or "auto"), None for a duration; ValueError
    for another string, suggesting the nearest rule."""
    if isinstance(t_transient, str):
        if t_transient not in TRANSIENT_RULES:
            near = difflib.get_close_matches(t_transient, TRANSIENT_RULES, n=1, cutoff=0.5)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise ValueError(f"t_transient must be a duration, 'scaled' or 'auto', got "
                             f"{t_transient!r}{hint}")
        return t_transient
    return None


def scaled_transient(n: int, speed: float) -> Documented:
    """The transient of ``t_transient="scaled"`` for N rotors at kinetic speed ``speed``:
    `SCALED_PER_N2` · N² / speed, at least `SCALED_MIN`, as a `Documented` duration (the
    nearest whole number of steps at any dt)."""
    speed = float(speed)
    if not (np.isfinite(speed) and speed > 0):
        raise ValueError(f"t_transient='scaled' needs a positive speed, got {speed!r}; give "
                         "t_transient as a duration")
    return Documented(max(SCALED_MIN, SCALED_PER_N2 * n * n / speed))


def kinetic_speed(system, u0) -> float:
    """|u0| = √(Σ mᵢ u0ᵢ²), the speed the exponents scale with."""
    u = np.asarray(u0, dtype=float)
    return float(np.sqrt(np.sum(np.asarray(system.masses, dtype=float) * u * u)))


def auto_duration(exponents) -> Documented:
    """The transient "auto" gives after a pilot whose exponents are ``exponents``:
    `AUTO_EFOLDINGS` over the smallest positive one (floored at 1 % of the largest), within
    `AUTO_TRANSIENT_RANGE` (the upper bound where none is positive), as a `Documented`
    duration (the nearest whole number of steps); ValueError for a NaN exponent."""
    lam = np.asarray(exponents, dtype=float)
    low, high = AUTO_TRANSIENT_RANGE
    if np.isnan(lam).any():
        raise ValueError(f"t_transient='auto': the pilot run gave a NaN exponent ({shown(lam)}); "
                         "give t_transient as a duration")
    positive = lam[lam > 0]
    if positive.size == 0:
        return Documented(high)
    rate = max(positive.min(), positive.max() / 100.0)
    return Documented(min(high, max(low, AUTO_EFOLDINGS / rate)))


def resolve_transient(t_transient, system, theta0, u0, auto, **pilot):
    """(duration, rule text or None) of ``t_transient`` for a run from (theta0, u0): a
    duration as given; "scaled" by N and the speed of u0; "auto" by its pilot run
    ``auto(system, theta0, u0, **pilot)`` with the run's settings ``pilot`` (dt,
    n_exponents, inner, space, seed; ``charts.analyses.lyapunov.resolve_transient`` passes
    its ``auto_transient``).  Check the run's other settings before calling it: "auto" runs
    its pilot here."""
    rule = transient_rule(t_transient)
    if rule == "scaled":
        return scaled_transient(system.n, kinetic_speed(system, u0)), SCALED_RULE
    if rule == "auto":
        return auto(system, theta0, u0, **pilot), AUTO_RULE
    return t_transient, None
