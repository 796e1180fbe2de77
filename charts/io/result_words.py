"""Results in words: the one-line repr of every result type and the labels that reprs, figure
titles and legends share (the system, the samples and their time span, the exponents, the
smallest value), and the units' one spelling in the files and on the figures' axes.  No
imports from the package's layers (any layer may use it).

A repr reads ``Type(system, samples and time span, main numbers)`` (`one_line`)::

    AngleResult(N = 4, 4 samples, t = 100…100.3, min φ full 0.02 rad, restricted 0.12 rad)
"""
from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["RATE", "ANGULAR_VELOCITY", "REPR_WIDTH", "REPR_EXPONENTS", "result_fields",
           "system_label", "counted", "span_words", "exponent_words", "smallest_words",
           "one_line"]

#: Units as the files write them and the figures' labels say them, one spelling (time in time
#: units of the flow): exponents and growth rates, and angular velocities and frequencies.
RATE = "1 / time"
ANGULAR_VELOCITY = "rad / time"

#: Longest one-line repr of a result (`one_line`): a longer one is cut with "…".
REPR_WIDTH = 240
#: Most exponents a repr lists (`exponent_words`); the others are counted.
REPR_EXPONENTS = 4


def result_fields(result) -> dict:
    """A result's fields: its dataclass fields, else its instance attributes (and its items,
    for a result that is also a tuple)."""
    if dataclasses.is_dataclass(result):
        return {f.name: getattr(result, f.name) for f in dataclasses.fields(result)}
    out = dict(vars(result))
    if isinstance(result, tuple):
        out["items"] = tuple(result)
    return out


def system_label(params) -> str:
    """The system of a result's ``params`` in a few words, for reprs, titles and legends:
    "linkage ε = 0.1", "N = 4", with masses, weights and level where they are not the
    paper's (all 1, level 0)."""
    if params.get("eps") is not None:
        return f"linkage ε = {params['eps']:g}"
    out = f"N = {params.get('n')}"
    for key in ("masses", "weights"):
        vals = params.get(key)
        if vals is not None and any(float(x) != 1.0 for x in vals):
            out += f", {key} (" + ", ".join(f"{float(x):g}" for x in vals) + ")"
    if params.get("level"):
        out += f", level {params['level']:g}"
    return out


def counted(k: int, noun: str, plural: str | None = None) -> str:
    """"1 sample", "3 samples": ``k`` and the noun in the number it takes (``plural``: the
    noun's plural where it is not ``noun + "s"``)."""
    return f"{k} {noun if k == 1 else plural or noun + 's'}"


def span_words(t) -> str:
    """"S samples, t = t₀…t₁" of sample times ``t`` (S,)."""
    t = np.asarray(t)
    return counted(t.size, "sample") + (f", t = {t[0]:g}…{t[-1]:g}" if t.size else "")


def exponent_words(exponents, stderr=None) -> str:
    """"λ = 0.3842±0.0009, 0.2291±0.0006": the first `REPR_EXPONENTS` exponents (± their
    standard errors where given), the others counted."""
    lam = np.asarray(exponents, dtype=float).ravel()
    se = None if stderr is None else np.asarray(stderr, dtype=float).ravel()
    shown = [f"{x:.4f}" + (f"±{se[i]:.4f}" if se is not None and i < se.size else "")
             for i, x in enumerate(lam[:REPR_EXPONENTS])]
    more = lam.size - len(shown)
    return "λ = " + (", ".join(shown) or "none") + (f", … ({more} more)" if more > 0 else "")


def smallest_words(values, units="rad") -> str:
    """The smallest finite value of ``values`` to 3 digits with its ``units`` ("0.02 rad"),
    "none" if there is none."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    return f"{v.min():.3g} {units}" if v.size else "none"


def one_line(result) -> str:
    """The repr of every result type: ``Type(system, samples and time span, main numbers)`` —
    the system from ``params`` (`system_label`), the span from a field ``t`` of sample times,
    then the kind's own numbers (``Archivable.summary_parts``: exponents, minima, counts);
    never the arrays, and at most `REPR_WIDTH` characters."""
    fields = result_fields(result)
    params = fields.get("params")
    parts = []
    if isinstance(params, dict) and ("n" in params or "eps" in params):
        parts.append(system_label(params))
    t = fields.get("t")
    if isinstance(t, np.ndarray) and t.ndim == 1:
        parts.append(span_words(t))
    parts += [p for p in result.summary_parts() if p]
    text = f"{type(result).__name__}({', '.join(parts)})"
    return text if len(text) <= REPR_WIDTH else text[:REPR_WIDTH - 2] + "…)"

