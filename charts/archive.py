"""Results that save and load themselves: NetCDF-4 files through xarray (the optional extra
``charts[io]``: xarray + h5netcdf).  The one home of the mechanism; no imports from the
package's layers (any layer may use it), and ``xarray`` is imported only when used.

The contract of a result type (a class with ``Archivable`` among its bases):

* ``KIND`` — the name stored in the file (attribute ``charts_kind``);
* ``to_xarray()`` — an ``xarray.Dataset`` built with :func:`dataset`: named dimensions,
  coordinates, a ``units`` attribute on every variable, and the settings as attributes;
* ``from_xarray(ds)`` (classmethod) — the inverse, given the dataset of a file.

``save(path)`` and :func:`load` come with it.  A new result type adds its class to
:data:`KINDS` — one line — so that ``charts.load`` returns it.

Attributes: the settings as NetCDF holds them natively, so that a reader without this
package (``ncdump -h``, plain xarray) reads every number as a number; the same attributes
are what `load` reads back, equal to the settings saved (an int stays an int, a list a list):

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

Every file also carries the CF global attributes (``Conventions``, ``title``, ``history``,
``source``, ``references``, and ``comment``: the units of the settings, `COMMENT`).  Files
written before this encoding hold each settings dict also as one JSON text
(``params = "json:{...}"``, its entries beside it with booleans as 1 or 0 and no lists of
names): where that text is present, `attributes` reads it.
"""
from __future__ import annotations

import dataclasses
import importlib
import json
import os
from pathlib import Path

import numpy as np

from .atomic import atomic_write

__all__ = ["Archivable", "KINDS", "dataset", "exponent_coordinate", "attributes", "save",
           "load", "require_xarray", "ENGINE", "RATE", "ANGULAR_VELOCITY", "TITLES",
           "ENSEMBLE_TITLES", "GLOBALS", "COMMENT", "FLATTENED", "MARKS", "MEMBER", "encode",
           "member_settings", "member_attributes", "index_coordinate", "same_value",
           "one_line", "system_label", "counted", "span_words", "exponent_words",
           "smallest_words", "REPR_WIDTH"]

#: kind → "module:Class" of every result type ``load`` knows (imported when a file needs it).
KINDS = {
    "trajectory": "charts.solvers.integrate:IntegrationResult",
    "lyapunov": "charts.analyses.lyapunov:LyapunovResult",
    "curvature": "charts.analyses.curvature:CurvatureResult",
    "angles": "charts.analyses.hyperbolicity:AngleResult",
    "covariant": "charts.analyses.covariant:CovariantResult",
    "waveform": "charts.analyses.spectra:Waveform",
    "spectrum": "charts.analyses.spectra:PowerSpectrum",
    "ensemble": "charts.analyses.ensemble:EnsembleResult",
    "linkage": "charts.analyses.linkage:LinkageResult",
    "scene": "charts.runs.netcdf_results:SceneResult",
    "sweep": "charts.runs.netcdf_results:SweepTable",
}

#: The NetCDF engine (NetCDF-4/HDF5: 64-bit integers, unicode strings, compression).
ENGINE = "h5netcdf"
_JSON = "json:"


def require_xarray():
    """``xarray``, or an ImportError that names the extra to install."""
    try:
        import xarray
        import h5netcdf  # noqa: F401
        import h5py  # noqa: F401  (h5netcdf's backend, optional in its own requirements)
    except ImportError as err:
        raise ImportError(f"saving and loading results needs xarray and h5netcdf ({err.name} is "
                          "missing): pip install 'charts[io]'") from None
    return xarray


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


def _decode(v):
    """An attribute's value as Python: JSON text decoded, numpy numbers and arrays as Python
    numbers and lists."""
    if isinstance(v, str) and v.startswith(_JSON):
        return json.loads(v[len(_JSON):])
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return v


#: Units as the files write them and the figures' labels say them, one spelling (time in time
#: units of the flow): exponents and growth rates, and angular velocities and frequencies.
RATE = "1 / time"
ANGULAR_VELOCITY = "rad / time"

#: Titles of the files of each kind (CF ``title``).
TITLES = {
    "trajectory": "geodesic of the rotor constraint manifold (charts.integrate)",
    "lyapunov": "Lyapunov spectrum (charts.lyapunov_spectrum)",
    "curvature": "sectional curvatures along a trajectory (charts.curvature_along_trajectory)",
    "angles": "angles between the expanding and the zero-and-contracting subspaces "
              "(charts.hyperbolicity_angles)",
    "covariant": "covariant Lyapunov vectors (charts.covariant_lyapunov_vectors)",
    "waveform": "waveforms theta(t), u(t) (charts.waveform)",
    "spectrum": "power spectrum (charts.power_spectrum)",
    "ensemble": "ensemble of independent trajectories (an EnsembleResult)",
    "linkage": "Lyapunov exponents and curvature of the Appendix's linkage (charts.linkage_run)",
    "scene": "scene results (charts run)",
    "sweep": "sweep table (charts sweep)",
}
#: Titles of the ensembles' files by the kind of their members: what each member holds and the
#: function that runs them (`TITLES` ``"ensemble"`` for members of any other kind).
ENSEMBLE_TITLES = {
    "lyapunov": "ensemble of Lyapunov spectra of independent trajectories "
                "(charts.lyapunov_ensemble)",
    "angles": "ensemble of hyperbolicity angle tests of independent trajectories "
              "(charts.hyperbolicity_ensemble)",
    "linkage": "ensemble of runs of the Appendix's linkage, Lyapunov exponents and curvature "
               "(charts.linkage_ensemble)",
}
#: CF global attributes every file carries (not settings: `attributes` leaves them out).
GLOBALS = ("Conventions", "title", "history", "source", "references", "institution", "comment")
#: CF ``comment`` of every file: the units of the settings, which NetCDF attributes cannot
#: carry themselves (every variable has its own ``units``), and what ``params_seed`` seeds.
COMMENT = ("Units of the settings (params_*, options_*, member.params.*): times (t_final, "
           "t_transient, dt, t_span, every *_every) in time units of the flow; angles (theta0) "
           "in rad; velocities (u0) and speed in rad / time (the linkage's q0, v0: see "
           "q_component_units).  params_seed seeds the random tangent vectors; in an ensemble, "
           "member i has seed + i for its initial state and its tangent vectors.  Every "
           "variable carries its own units.")
#: Settings dicts (and the trajectory's ``drift``) written entry by entry as native NetCDF
#: attributes, ``params_masses = [1, 2, 3]``, ``drift_energy = 1e-13`` (module docstring).
FLATTENED = ("params", "options", "drift")
#: Plain-text attributes naming (space-separated) the attributes whose values NetCDF has no
#: type for: lists (written as 1-D arrays), booleans (written 1 or 0), None (left out).
LISTS, BOOLEANS, NONE = "charts_lists", "charts_booleans", "charts_none"
MARKS = (LISTS, BOOLEANS, NONE)
_INT64 = (-2 ** 63, 2 ** 63 - 1)
REFERENCE = ("S. P. Kuznetsov, Chaos and hyperchaos of geodesic flows on curved manifolds "
             "corresponding to mechanically coupled rotators")


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
    entry, with the lists of names `MARKS` (module docstring); `attributes` reads them back."""
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


def _global_attributes(kind: str, title: str | None = None) -> dict:
    import datetime
    import platform

    from .version import __version__
    versions = [f"charts {__version__}", f"python {platform.python_version()}",
                f"numpy {np.__version__}"]
    try:
        import numba
        versions.append(f"numba {numba.__version__}")
    except ImportError:                      # pragma: no cover - numba is a dependency
        pass
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    return {"Conventions": "CF-1.10", "title": f"charts: {title or TITLES.get(kind, kind)}",
            "history": f"{now}: written by charts {__version__}",
            "source": ", ".join(versions), "references": REFERENCE, "comment": COMMENT}


def dataset(kind: str, data_vars: dict, coords: dict | None = None, attrs: dict | None = None,
            title: str | None = None):
    """An ``xarray.Dataset`` stamped with ``charts_kind`` and ``charts_version`` and the CF
    global attributes (`GLOBALS`: conventions, title, history, source, references, and the
    ``comment`` `COMMENT` on the settings' units).  ``title``: the CF title where the kind's
    (`TITLES`) says too little (an ensemble's names its members, `ENSEMBLE_TITLES`).

    ``data_vars`` and ``coords``: name → ``(dims, array, units)`` or
    ``(dims, array, units, description)``; ``attrs``: settings (name → value, written by
    `encode`: the entries of the `FLATTENED` dicts as ``params_<key>``)."""
    xr = require_xarray()
    from .version import __version__

    def var(spec):
        dims, values, units = spec[:3]
        a = {"units": units}
        if len(spec) > 3:
            a["long_name"] = spec[3]
        return xr.Variable(dims, np.asarray(values), a)

    ds = xr.Dataset({k: var(v) for k, v in data_vars.items()},
                    coords={k: var(v) for k, v in (coords or {}).items()})
    for dim, size in ds.sizes.items():          # every dimension labelled: an index where
        if dim not in ds.coords:                   # the result has no coordinate of its own
            ds = ds.assign_coords({dim: xr.Variable((dim,), np.arange(size, dtype=np.int64),
                                                    {"units": "1", "long_name": f"{dim} index, from 0"})})
    ds.attrs.update(_global_attributes(kind, title))
    ds.attrs.update(encode(attrs or {}))
    ds.attrs["charts_kind"] = kind
    ds.attrs["charts_version"] = __version__
    return ds


def exponent_coordinate(k: int):
    """The coordinate of an ``exponent`` dimension of k Lyapunov exponents, for `dataset`'s
    ``coords``: i of λᵢ, 1…k (λ₁ the largest), as in the paper and the field, where the
    other dimensions count from 0."""
    return index_coordinate("exponent", k, "i of λᵢ, from 1 as in the paper")


def index_coordinate(dim: str, k: int, long_name: str):
    """A coordinate 1…k of dimension ``dim`` for `dataset`'s ``coords``: the indices that the
    paper and the field count from 1 (exponents, the frame vectors of K₁₁, K₂₂, tangent and
    covariant vectors); rotors count from 0."""
    return ((dim,), np.arange(1, int(k) + 1, dtype=np.int64), "1", long_name)


def _setting(key) -> bool:
    return not (key.startswith("charts_") or key in GLOBALS or key.startswith(MEMBER)
                or any(key.startswith(f"{name}_") for name in FLATTENED))


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
    one per member): the shared ones once, as settings for `dataset`'s ``attrs``
    (``member.params.n`` → 4), the differing ones as data variables along ``member``
    (`MEMBER`)."""
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
    file holds them (`encode`; ``attributes`` decodes them)."""
    flat = {tuple(k[len(MEMBER):].split(".")): v for k, v in _values(ds.attrs).items()
            if k.startswith(MEMBER)}
    for key in ds.data_vars:
        if key.startswith(MEMBER):
            value = ds[key].values[i]
            flat[tuple(key[len(MEMBER):].split("."))] = _decode(value)
    return encode(_nest(flat))


def attributes(ds) -> dict:
    """The dataset's settings as they were saved (the inverse of `encode`): the `FLATTENED`
    dicts gathered from their entries (or, in a file written before, read from their JSON
    text); without the ``charts_*`` stamps, the CF globals and the members' settings."""
    values = _values(ds.attrs)
    out = {k: v for k, v in values.items() if _setting(k)}
    for name in FLATTENED:
        entries = {tuple(k[len(name) + 1:].split(".")): v for k, v in values.items()
                   if k.startswith(f"{name}_")}
        if name not in out and entries:
            out[name] = _nest(entries)
    return out


def save(ds, path) -> Path:
    """Write the dataset to ``path`` (NetCDF-4), atomically."""
    require_xarray()
    path = Path(path)
    tmp = path.with_name(f".{path.name}.nc-tmp{os.getpid()}")
    try:
        ds.to_netcdf(tmp, engine=ENGINE)
        atomic_write(path, tmp.read_bytes())
    finally:
        if tmp.exists():
            tmp.unlink()
    return path


def load(path):
    """The result saved in ``path`` (by any ``save``), as an object of its own type."""
    xr = require_xarray()
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"no such file: {path}")
    _check_netcdf4(path)
    try:
        ds = xr.load_dataset(path, engine=ENGINE)
    except (OSError, ValueError) as err:       # a damaged file behind a valid signature
        raise ValueError(f"{path} could not be read as NetCDF-4 (is it truncated?): {err}") from None
    kind = ds.attrs.get("charts_kind")
    if kind not in KINDS:
        raise ValueError(f"{path} is not a charts result (charts_kind = {kind!r}; known: "
                         f"{', '.join(KINDS)})")
    module, name = KINDS[kind].split(":")
    return getattr(importlib.import_module(module), name).from_xarray(ds)


#: The first bytes of an HDF5 file (NetCDF-4, what ``save`` writes), and of NetCDF-3.
_HDF5 = b"\x89HDF\r\n\x1a\n"
_NETCDF3 = (b"CDF\x01", b"CDF\x02", b"CDF\x05")


def _check_netcdf4(path: Path) -> None:
    """ValueError naming ``path`` and what it is, unless it is a regular file that starts as
    NetCDF-4 (HDF5) does: a folder, a device or FIFO, an empty file, NetCDF-3, text."""
    if not path.is_file():
        raise ValueError(f"{path} is not a regular file (a folder, a device or a pipe): charts.load "
                         "reads the NetCDF-4 files that results save")
    with open(path, "rb") as f:
        head = f.read(8)
    if not head:
        raise ValueError(f"{path} is empty: not a charts result")
    if head[:4] in _NETCDF3:
        raise ValueError(f"{path} is NetCDF-3 (classic): charts results are NetCDF-4; convert it "
                         "with `nccopy -k nc4` or save the result again")
    if head != _HDF5:
        raise ValueError(f"{path} is not a NetCDF-4 file (its first bytes are {head!r}): not a "
                         "charts result")


def same_value(a, b) -> bool:
    """Whether two result fields hold the same values: arrays by shape and elements (NaN
    equal to NaN, as a saved and reloaded result must equal itself), mappings by keys and
    values, sequences element by element, anything else by ``==``."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        if a.shape != b.shape:
            return False
        if a.dtype.kind in "biufc" and b.dtype.kind in "biufc":
            return bool(np.array_equal(a, b, equal_nan=a.dtype.kind in "fc" and b.dtype.kind in "fc"))
        return all(same_value(x, y) for x, y in zip(a.flat, b.flat))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same_value(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float) and a != a and b != b:
        return True
    try:
        return bool(a == b)
    except (TypeError, ValueError):
        return False


def _fields(result) -> dict:
    """A result's fields: its dataclass fields, else its instance attributes (and its items,
    for a result that is also a tuple)."""
    if dataclasses.is_dataclass(result):
        return {f.name: getattr(result, f.name) for f in dataclasses.fields(result)}
    out = dict(vars(result))
    if isinstance(result, tuple):
        out["items"] = tuple(result)
    return out


#: Longest one-line repr of a result (`one_line`): a longer one is cut with "…".
REPR_WIDTH = 240
#: Most exponents a repr lists (`exponent_words`); the others are counted.
REPR_EXPONENTS = 4


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
    fields = _fields(result)
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


class Archivable:
    """Base of the result types: ``save(path)`` from their ``to_xarray()`` (module docstring).

    Every result prints as one line (`one_line`): the system, the samples' time span and
    ``summary_parts()``, the kind's main numbers, which a result type supplies (its
    dataclass declared with ``repr=False``, so that the generated repr does not replace
    this one).

    Two results are equal (``==``) when they are of one type and every field holds the same
    values (`same_value`: arrays element by element, NaN equal to NaN); results are mutable
    and so not hashable.  The result dataclasses are declared with ``eq=False`` so that this
    comparison is theirs (a dataclass's own ``==`` raises on array fields)."""

    KIND = "abstract"

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return same_value(_fields(self), _fields(other))

    def __ne__(self, other):        # its own: a tuple base would compare its arrays itself
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    __hash__ = None

    def summary_parts(self) -> list:
        """The kind's main numbers as short phrases ("λ = 0.3842±0.0009", "min φ 0.02
        rad") for the one-line repr, after the system and the time span (`one_line`)."""
        return []

    def __repr__(self):
        return one_line(self)

    def to_xarray(self):  # pragma: no cover - contract
        raise NotImplementedError

    @classmethod
    def from_xarray(cls, ds):  # pragma: no cover - contract
        raise NotImplementedError

    def save(self, path) -> Path:
        """Write this result to ``path`` as NetCDF (read it back with ``charts.load``)."""
        return save(self.to_xarray(), path)

    def _repr_html_(self):
        """Jupyter: the result's one-line repr above its dataset (dimensions, units,
        settings); None (plain repr) without the extra ``charts[io]``."""
        try:
            require_xarray()
        except ImportError:
            return None
        import html
        return f"<pre>{html.escape(repr(self))}</pre>" + self.to_xarray()._repr_html_()
