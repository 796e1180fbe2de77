"""Key-level checks of a scene: each value's type, range and choices against the schema
(``charts.runs.scene_schema``), unknown keys with a did-you-mean hint, whole multiples of a
time grid, and `Problems`, which gathers the problems of a scene so that they are reported
together as one `SceneError`."""
from __future__ import annotations

import difflib
import math
from contextlib import contextmanager

from ..geometry.checks import shown
from .scene_schema import GRID_RTOL, Key, SceneError

__all__ = ["Problems", "where", "unknown_key", "is_number", "is_finite_number", "coerce", "section_values",
           "table_values", "multiple_of"]


def where(source, section, key):
    loc = f"[{section}] {key}" if section else key
    return f"{source}: {loc}"


def source_names(source, default_name, error=SceneError):
    """``error`` naming ``source`` or ``default_name`` unless each is a str (the label of
    the data in messages, and the name a nameless scene or sweep takes)."""
    for name, value in (("source", source), ("default_name", default_name)):
        if not isinstance(value, str):
            raise error(f"{name} must be a str, got {shown(value)}")


def unknown_key(source, section, key, allowed, error=SceneError):
    """The error (`SceneError` unless ``error`` says otherwise) for an unknown key, with the
    closest allowed key as a hint."""
    hint = difflib.get_close_matches(key, list(allowed), n=1, cutoff=0.6)
    did = f" — did you mean {shown(hint[0])}?" if hint else ""
    sect = f"[{section}]" if section else "the top level"
    return error(f"{source}: unknown key {shown(key)} in {sect}{did} "
                      f"(allowed: {', '.join(sorted(allowed)) or 'none'})")


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def is_finite_number(v):
    return is_number(v) and _finite(v)


def _finite(v) -> bool:
    """v finite as a float (an integer beyond a float's range is not)."""
    try:
        return math.isfinite(v)
    except OverflowError:
        return False


def coerce(source, section, key, spec: Key, value):
    """Type-check one value; return it converted (int → float where a float is wanted)."""
    loc = where(source, section, key)
    kind = spec.kind
    bad = None
    if kind == "int":
        if not isinstance(value, int) or isinstance(value, bool):
            bad = "an integer"
    elif kind == "float":
        if not is_number(value):
            bad = "a number"
        elif not _finite(value):
            bad = "a finite number (an integer beyond a float's range is not)"
        else:
            value = float(value)
    elif kind == "duration":                # a time, or the name of a transient rule
        if isinstance(value, str):
            from ..analyses.transients import TRANSIENT_RULES
            if value in TRANSIENT_RULES:
                return value
            hint = difflib.get_close_matches(value, TRANSIENT_RULES, n=1, cutoff=0.5)
            did = f" — did you mean {shown(hint[0])}?" if hint else ""
            raise SceneError(f"{loc} = {shown(value)} is not allowed{did} (expected a number "
                             f"of time units, or one of {', '.join(map(repr, TRANSIENT_RULES))})")
        if not is_number(value):
            bad = "a number, 'scaled' or 'auto'"
        elif not _finite(value):
            bad = "a finite number (an integer beyond a float's range is not)"
        else:
            value = float(value)
    elif kind == "str":
        if not isinstance(value, str):
            bad = "a string"
    elif kind == "bool":
        if not isinstance(value, bool):
            bad = "true or false"
    elif kind == "floats":
        if not isinstance(value, list) or not all(is_number(x) for x in value):
            bad = "a list of numbers"
        elif not all(_finite(x) for x in value):
            bad = "a list of finite numbers (no nan or inf)"
        else:
            value = [float(x) for x in value]
    elif kind == "ints":
        if not isinstance(value, list) or not all(isinstance(x, int) and not isinstance(x, bool)
                                                  for x in value):
            bad = "a list of integers"
    if bad is None and spec.choices and value not in spec.choices:
        hint = difflib.get_close_matches(str(value), spec.choices, n=1, cutoff=0.6)
        did = f" — did you mean {shown(hint[0])}?" if hint else ""
        raise SceneError(f"{loc} = {shown(value)} is not allowed{did} "
                         f"(allowed: {', '.join(repr(c) for c in spec.choices)})")
    if bad is None and spec.check is not None:
        bad = spec.check(value)
    if bad is not None:
        raise SceneError(f"{loc} = {shown(value)} is not allowed: expected {bad}")
    return value


class Problems:
    """The problems of one scene, gathered so that they are reported together: ``check``
    runs a check and keeps its `SceneError`; ``raise_all`` raises one error naming them all."""

    def __init__(self, source):
        self.source = source
        self.messages = []

    @contextmanager
    def check(self):
        try:
            yield
        except SceneError as exc:
            self.messages.append(str(exc))

    def raise_all(self):
        if len(self.messages) == 1:
            raise SceneError(self.messages[0])
        if self.messages:
            prefix = f"{self.source}: "
            parts = [m[len(prefix):] if m.startswith(prefix) else m for m in self.messages]
            raise SceneError(f"{self.source}: {len(parts)} problems: " + "; ".join(parts))


def section_values(source, data, section, schema, problems, label=None):
    """The validated keys of one section (defaults filled in) and its raw table; every
    problem of the section goes to ``problems``."""
    raw = data.get(section, {})
    section = label or section
    if not isinstance(raw, dict):
        problems.messages.append(f"{source}: [{section}] must be a table, got {shown(raw)}")
        raw = {}
    return table_values(source, raw, section, schema, problems), raw


def table_values(source, raw, section, schema, problems, allowed=None):
    """The keys of ``schema`` in the table ``raw`` (``section`` None: the top level),
    validated, defaults filled in; keys outside ``allowed`` (default: the schema's) and
    every other problem go to ``problems``."""
    allowed = schema if allowed is None else allowed
    for key in raw:
        if key not in allowed:
            problems.messages.append(str(unknown_key(source, section, key, allowed)))
    out = {}
    for key, spec in schema.items():
        out[key] = spec.value
        if key in raw:
            with problems.check():
                out[key] = coerce(source, section, key, spec, raw[key])
        elif spec.required:
            problems.messages.append(f"{where(source, section, key)} is required ({spec.doc})")
    return out


def multiple_of(source, section, key, value, base, base_name):
    """Require value to be an integer multiple of base; return the integer ratio."""
    k = value / base
    r = round(k)
    if r < 1 or abs(k - r) > GRID_RTOL * max(1.0, k):
        near = max(1, r) * base
        raise SceneError(f"{where(source, section, key)} = {shown(value)} is not allowed: expected "
                         f"a positive multiple of {base_name} = {shown(base)} (nearest: {near:.10g})")
    return int(r)
