"""Settings as NetCDF attributes: the settings of a result (name → value) as NetCDF holds them
natively, so that a reader without this package (``ncdump -h``, plain xarray) reads every
number as a number; the same attributes are what ``charts.load`` reads back
(``charts.io.archive.attributes``), equal to the settings saved (an int stays an int, a list a
list).  No imports from the package's layers but the units' spelling (`result_words`).

`encode` writes them:

* a number or a string: itself (``method = "rk4"``, ``min_sin2 = 0.93``);
* a list of numbers all integers or all floats, or a list of strings: a 1-D array
  (``params_masses = 1., 2., 3.``), its name listed in ``charts_lists`` (NetCDF reads a
  list of one entry as that entry);
* a boolean: the integer 1 or 0, its name listed in ``charts_booleans``;
* None: no attribute, its name listed in ``charts_none``;
* the dicts of `FLATTENED` (``params``, ``options``, ``drift``): one attribute per entry,
  ``params_<key>`` (``params_t_final = 20.``), each written by these rules; an entry that
  is itself a dict one level further, joined by ``.`` (``params_curvature.sample_every``);
* anything else, which NetCDF has no native form for (an empty list or dict, a list of
  lists or of mixed types, a dict with a key holding ``.`` or a space, a dict outside
  `FLATTENED` such as a scene's ``result``, a string that itself starts with ``json:``):
  JSON text prefixed ``json:`` — exact for floats (shortest round-trip repr) and integers.

``charts_lists``, ``charts_booleans`` and ``charts_none`` are plain text, the names
separated by spaces, present only when they name something.  A trajectory's file
(``ncdump -h``)::

    :method = "dop853" ;  :n_steps = 10 ;  :drift_energy = 1.04e-10 ;
    :options_rtol = 1.e-10 ;  :options_project = 0 ;  :options_t_span = 0., 2. ;
    :options_output = "steps" ;  :options_tau = 0.9 ;
    :params_n = 3 ;  :params_masses = 1., 1., 1. ;  :params_theta0 = 0.786, 2.496, 1.479 ;
    :charts_lists = "options_t_span params_masses params_weights params_theta0 params_u0" ;
    :charts_booleans = "options_project" ;  :charts_none = "options_chart" ;

Files written before this encoding hold each settings dict also as one JSON text
(``params = "json:{...}"``, its entries beside it with booleans as 1 or 0 and no lists of
names): where that text is present, `decode_attributes` keeps it (and
``charts.io.archive.attributes`` reads it).

The members of an ensemble, in one file: `member_settings` (their settings, shared or along
``member``, `MEMBER`) and `member_attributes` (one member's, as its own file holds them).
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

from .result_words import ANGULAR_VELOCITY

__all__ = ["FLATTENED", "MARKS", "LISTS", "BOOLEANS", "NONE", "encode", "decode_attributes",
           "MEMBER", "member_settings", "member_attributes", "MEMBER_DIMS", "MEMBER_UNITS",
           "MAX_JSON_DEPTH", "json_depth", "parse_json"]

_JSON = "json:"


def _json_default(o):
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, Path):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def _json(v) -> str:
    """v as JSON text prefixed ``json:`` (the form of a value NetCDF cannot hold natively)."""
    return _JSON + json.dumps(v, default=_json_default)


#: The deepest nesting of lists and dicts a ``json:`` value may hold (`parse_json`): the
#: settings nest a few levels; a file from elsewhere with 100,000 levels would exhaust the
#: recursion of ``json.loads``.
MAX_JSON_DEPTH = 64
_JSON_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]')


def json_depth(text: str) -> int:
    """The deepest nesting of brackets (``[``, ``{``) in the JSON ``text``, brackets inside
    strings not counted; found by a scan, without parsing (no recursion)."""
    depth = deepest = 0
    for m in _JSON_TOKENS.finditer(text):
        c = m.group()
        if c in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif c in "]}":
            depth -= 1
    return deepest


def parse_json(text: str):
    """The value of the JSON ``text`` (after ``json:``); ValueError, one line, where it nests
    deeper than `MAX_JSON_DEPTH` (checked before parsing) or is not JSON."""
    depth = json_depth(text)
    if depth > MAX_JSON_DEPTH:
        raise ValueError(f"JSON nested {depth} levels deep (at most {MAX_JSON_DEPTH})")
    try:
        return json.loads(text)
    except (ValueError, RecursionError) as err:
        raise ValueError(f"broken JSON ({err})") from None


def _decode(v):
    """An attribute's value as Python: JSON text decoded (`parse_json`), numpy numbers and
    arrays as Python numbers and lists."""
    if isinstance(v, str) and v.startswith(_JSON):
        return parse_json(v[len(_JSON):])
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return v


#: Settings dicts (and the trajectory's ``drift``) written entry by entry as native NetCDF
#: attributes, ``params_masses = [1, 2, 3]``, ``drift_energy = 1e-13`` (module docstring).
FLATTENED = ("params", "options", "drift")
#: Plain-text attributes naming (space-separated) the attributes whose values NetCDF has no
#: type for: lists (written as 1-D arrays), booleans (written 1 or 0), None (left out).
LISTS, BOOLEANS, NONE = "charts_lists", "charts_booleans", "charts_none"
MARKS = (LISTS, BOOLEANS, NONE)
_INT64 = (-2 ** 63, 2 ** 63 - 1)


def _kind(v):
    """'i', 'f' or 's' for a value NetCDF holds natively as it is (an integer within int64, a
    float, a string not starting ``json:``); None for any other (booleans included)."""
    if isinstance(v, (bool, np.bool_)):
        return None
    if isinstance(v, (int, np.integer)):
        return "i" if _INT64[0] <= v <= _INT64[1] else None
    if isinstance(v, (float, np.floating)):
        return "f"
    if isinstance(v, str):
        return None if v.startswith(_JSON) else "s"
    return None


def _native_list(v):
    """A list (tuple, 1-D array) of integers, of floats or of strings as a native attribute
    value (an int64 or float64 array, a list of strings); None for any other value."""
    if not isinstance(v, (list, tuple, np.ndarray)) or np.ndim(v) != 1 or not len(v):
        return None
    kinds = {_kind(x) for x in v}
    if kinds == {"i"}:
        return np.asarray(v, dtype=np.int64)
    if kinds == {"f"}:
        return np.asarray(v, dtype=np.float64)
    if kinds == {"s"}:
        return [str(x) for x in v]
    return None


def _by_entries(value) -> bool:
    """Whether ``value`` is a dict written entry by entry: not empty, its keys strings that can
    be parts of an attribute name (no ``.``, no spaces: names are joined by ``.`` and listed
    space-separated)."""
    return isinstance(value, dict) and bool(value) and all(
        isinstance(k, str) and k and "." not in k and k.split() == [k] for k in value)


def _flat(settings: dict, path: tuple = ()) -> dict:
    """{path: value}: the entries of ``settings``, those of dicts (`_by_entries`) one level
    down per level, so that no value is a dict that could be written entry by entry."""
    out = {}
    for key, value in settings.items():
        if _by_entries(value):
            out.update(_flat(value, path + (key,)))
        else:
            out[path + (key,)] = value
    return out


def _nest(flat: dict) -> dict:
    """The inverse of `_flat`."""
    out = {}
    for path, value in flat.items():
        node = out
        for part in path[:-1]:
            node = node.setdefault(part, {})
        node[path[-1]] = value
    return out


def _put(out: dict, marks: dict, name: str, value) -> None:
    """Write the setting ``value`` as the attribute ``name`` of ``out``, listing its name in
    ``marks`` where the attribute alone does not say what it was (module docstring)."""
    listable = name.split() == [name]
    native = _native_list(value)
    if _kind(value):
        out[name] = value
    elif isinstance(value, (bool, np.bool_)) and listable:
        out[name] = int(value)
        marks[BOOLEANS].append(name)
    elif value is None and listable:
        marks[NONE].append(name)
    elif native is not None and listable:
        out[name] = native
        marks[LISTS].append(name)
    else:
        out[name] = _json(value)


def encode(settings: dict) -> dict:
    """The attributes that hold ``settings`` (name → value), `FLATTENED` dicts entry by
    entry, with the lists of names `MARKS` (module docstring); `decode_attributes` reads
    them back."""
    out, marks = {}, {m: [] for m in MARKS}
    for key, value in settings.items():
        if key in FLATTENED and _by_entries(value):
            for path, v in _flat(value).items():
                _put(out, marks, f"{key}_{'.'.join(path)}", v)
        else:
            _put(out, marks, key, value)
    out.update({m: " ".join(names) for m, names in marks.items() if names})
    return out


def _values(attrs) -> dict:
    """Every attribute of ``attrs`` (the marks excepted) decoded by the marks, and the names
    in ``charts_none`` as None."""
    marks = {m: str(attrs.get(m, "")).split() for m in MARKS}
    lists, booleans = set(marks[LISTS]), set(marks[BOOLEANS])
    out = {}
    for key, value in attrs.items():
        if key in MARKS:
            continue
        if key in booleans:
            out[key] = bool(value)
        elif key in lists:
            out[key] = np.atleast_1d(value).tolist()
        else:
            out[key] = _decode(value)
    out.update(dict.fromkeys(marks[NONE]))
    return out


def decode_attributes(attrs) -> dict:
    """Every attribute of ``attrs`` as the value `encode` was given: decoded by the marks
    (`_values`; the marks themselves left out), and each `FLATTENED` dict gathered from its
    entries (``params_masses``, ``params_curvature.sample_every`` → ``params``) where the
    attributes do not hold it whole (as JSON text, in a file written before this encoding);
    the entries stay beside it."""
    values = _values(attrs)
    out = dict(values)
    for name in FLATTENED:
        entries = {tuple(k[len(name) + 1:].split(".")): v for k, v in values.items()
                   if k.startswith(f"{name}_")}
        if name not in out and entries:
            out[name] = _nest(entries)
    return out


#: Prefix of the members' settings in a file of several results (an ensemble): a setting
#: every member shares is one attribute ``member.params.n`` (written by `encode`'s rules:
#: ``member.params.masses`` native and listed in ``charts_lists``, a nested dict's entries
#: ``member.params.curvature.sample_every``); one that differs is a variable along
#: ``member`` (``member.params.seed``), native where the values are numbers or strings, and
#: a 2-D array where they are lists of numbers (``member.params.theta0`` over
#: (member, rotor)).
MEMBER = "member."


def member_settings(settings: list) -> tuple[dict, dict]:
    """(attributes, data variables) that hold the members' decoded settings (a list of dicts,
    one per member): the shared ones once, as settings for the ``attrs`` of
    ``charts.io.archive.dataset`` (``member.params.n`` → 4), the differing ones as data
    variables along ``member`` (`MEMBER`)."""
    flats = [_flat(a) for a in settings]
    paths = list(dict.fromkeys(p for f in flats for p in f))
    attrs, data = {}, {}
    for path in paths:
        name = MEMBER + ".".join(path)
        values = [f.get(path) for f in flats]
        first = _json(values[0])
        if all(_json(v) == first for v in values[1:]):
            attrs[name] = values[0]
        elif len({_kind(v) for v in values}) == 1 and _kind(values[0]):
            data[name] = (("member",), np.asarray(values), MEMBER_UNITS.get(path[-1], "1"),
                          f"each member's {'.'.join(path)}")
        elif _number_rows(values):
            data[name] = (("member", MEMBER_DIMS.get(path[-1], f"{path[-1]}_entry")),
                          np.asarray(values), MEMBER_UNITS.get(path[-1], "1"),
                          f"each member's {'.'.join(path)}")
        else:
            data[name] = (("member",), np.asarray([_json(v) for v in values], dtype=str), "1",
                          f"each member's {'.'.join(path)} (JSON after 'json:')")
    return attrs, data


#: The second dimension of a setting that is a list of numbers per member (the initial
#: state: one number per rotor), and its units; other lists: ``<name>_entry``, units "1".
MEMBER_DIMS = {"theta0": "rotor", "u0": "rotor", "masses": "rotor", "weights": "rotor",
               "q0": "q_component", "v0": "q_component"}
MEMBER_UNITS = {"theta0": "rad", "u0": ANGULAR_VELOCITY, "speed": ANGULAR_VELOCITY,
                "q0": "rad (θ₀…θ₃, α), length (x, y): q_component_units",
                "v0": "rad / time, length / time (x, y): q_component_units per time"}


def _number_rows(values) -> bool:
    """Whether ``values`` (one per member) are lists of one length whose entries are all
    floats or all integers (a 2-D native array that `member_attributes` reads back as the
    same lists)."""
    if not all(isinstance(v, list) and v for v in values) or len({len(v) for v in values}) != 1:
        return False
    kinds = {type(x) for v in values for x in v}
    return kinds == {float} or kinds == {int}


def member_attributes(ds, i) -> dict:
    """Member ``i``'s settings from a file written with `member_settings`, as a member's own
    file holds them (`encode`; ``charts.io.archive.attributes`` decodes them)."""
    flat = {tuple(k[len(MEMBER):].split(".")): v for k, v in _values(ds.attrs).items()
            if k.startswith(MEMBER)}
    for key in ds.data_vars:
        if key.startswith(MEMBER):
            value = ds[key].values[i]
            flat[tuple(key[len(MEMBER):].split("."))] = _decode(value)
    return encode(_nest(flat))

