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

Attributes: numbers and strings are stored as they are; anything else (dicts, lists, None,
booleans) as JSON text prefixed ``json:`` — exact for floats (shortest round-trip repr) and
integers, so settings come back equal.  For readers without this package every file also
carries the CF global attributes (``Conventions``, ``title``, ``history``, ``source``,
``references``) and the entries of its ``params``, ``options`` and ``drift`` as native
attributes (``params_masses = [1.0, 2.0, 3.0]``, ``params_level = 0.0``, ...; a boolean as
the integer 1 or 0, ``options_project = 0``; an entry that is None is left out).
"""
from __future__ import annotations

import dataclasses
import importlib
import json
import os
from pathlib import Path

import numpy as np

from .atomic import atomic_write

__all__ = ["Archivable", "KINDS", "dataset", "exponent_coordinate", "attributes", "save", "load", "require_xarray",
           "ENGINE", "TITLES", "GLOBALS", "FLATTENED", "MEMBER", "member_settings",
           "member_attributes", "index_coordinate", "same_value"]

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


def _encode(v):
    if isinstance(v, (str, int, float, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_)):
        return v
    return _JSON + json.dumps(v, default=_json_default)


def _decode(v):
    if isinstance(v, str) and v.startswith(_JSON):
        return json.loads(v[len(_JSON):])
    if isinstance(v, np.generic):
        return v.item()
    return v


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
    "ensemble": "ensemble of independent trajectories (charts ensembles)",
    "linkage": "Lyapunov exponents and curvature of the Appendix's linkage (charts.linkage_run)",
    "scene": "scene results (charts run)",
    "sweep": "sweep table (charts sweep)",
}
#: CF global attributes every file carries (not settings: `attributes` leaves them out).
GLOBALS = ("Conventions", "title", "history", "source", "references", "institution")
#: Settings dicts (and the trajectory's ``drift``) that are also written entry by entry as
#: native NetCDF attributes (``params_masses = [1, 2, 3]``, ``drift_energy = 1e-13``), for
#: readers without this package; the JSON copy stays the exact one that ``load`` reads.
FLATTENED = ("params", "options", "drift")
REFERENCE = ("S. P. Kuznetsov, Chaos and hyperchaos of geodesic flows on curved manifolds "
             "corresponding to mechanically coupled rotators")


def _native(v):
    """v as a native NetCDF attribute value (a number, a string, a 1-D numeric array), or None;
    a boolean as the integer 1 or 0 (NetCDF attributes have no booleans)."""
    if isinstance(v, (bool, np.bool_)):
        return int(v)
    if v is None:
        return None
    if isinstance(v, (str, int, float, np.integer, np.floating)):
        return v
    if isinstance(v, (list, tuple, np.ndarray)):
        a = np.asarray(v)
        if a.ndim == 1 and a.size and a.dtype.kind in "if":
            return a
    return None


def _global_attributes(kind: str) -> dict:
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
    return {"Conventions": "CF-1.10", "title": f"charts: {TITLES.get(kind, kind)}",
            "history": f"{now}: written by charts {__version__}",
            "source": ", ".join(versions), "references": REFERENCE}


def dataset(kind: str, data_vars: dict, coords: dict | None = None, attrs: dict | None = None):
    """An ``xarray.Dataset`` stamped with ``charts_kind`` and ``charts_version`` and the CF
    global attributes (`GLOBALS`: conventions, title, history, source, references).

    ``data_vars`` and ``coords``: name → ``(dims, array, units)`` or
    ``(dims, array, units, description)``; ``attrs``: settings (encoded as above; the entries
    of the `FLATTENED` dicts also as native attributes ``params_<key>``)."""
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
    ds.attrs.update(_global_attributes(kind))
    ds.attrs.update({k: _encode(v) for k, v in (attrs or {}).items()})
    for name in FLATTENED:
        for key, value in ((attrs or {}).get(name) or {}).items():
            native = _native(value)
            if native is not None:
                ds.attrs[f"{name}_{key}"] = native
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
#: every member shares is one attribute ``member.params.n``; one that differs is a variable
#: along ``member`` (``member.params.seed``), native where the values are numbers or strings,
#: and a 2-D array where they are lists of numbers (``member.params.theta0`` over
#: (member, rotor)).
MEMBER = "member."


def _flat(settings: dict) -> dict:
    """{path: value}: the entries of dict-valued settings one level down."""
    out = {}
    for key, value in settings.items():
        if isinstance(value, dict) and value:
            for sub, v in value.items():
                out[(key, sub)] = v
        else:
            out[(key,)] = value
    return out


def _scalar(v) -> bool:
    return isinstance(v, (str, int, float, np.integer, np.floating)) and not isinstance(
        v, (bool, np.bool_))


def member_settings(settings: list) -> tuple[dict, dict]:
    """(attributes, data variables) that hold the members' decoded settings (a list of dicts,
    one per member): the shared ones once, encoded as attributes are, the differing ones
    along ``member`` (`MEMBER`)."""
    flats = [_flat(a) for a in settings]
    paths = list(dict.fromkeys(p for f in flats for p in f))
    attrs, data = {}, {}
    for path in paths:
        name = MEMBER + ".".join(path)
        values = [f.get(path) for f in flats]
        first = _encode(values[0])
        if all(_encode(v) == first for v in values[1:]):
            attrs[name] = _native_list(values[0]) if isinstance(values[0], list) else first
        elif all(_scalar(v) for v in values) and len({type(v) for v in values}) == 1:
            data[name] = (("member",), np.asarray(values), MEMBER_UNITS.get(path[-1], "1"),
                          f"each member's {'.'.join(path)}")
        elif _number_rows(values):
            data[name] = (("member", MEMBER_DIMS.get(path[-1], f"{path[-1]}_entry")),
                          np.asarray(values), MEMBER_UNITS.get(path[-1], "1"),
                          f"each member's {'.'.join(path)}")
        else:
            data[name] = (("member",), np.asarray([_encode(v) for v in values], dtype=str), "1",
                          f"each member's {'.'.join(path)} (JSON after 'json:')")
    return attrs, data


#: The second dimension of a setting that is a list of numbers per member (the initial
#: state: one number per rotor), and its units; other lists: ``<name>_entry``, units "1".
MEMBER_DIMS = {"theta0": "rotor", "u0": "rotor", "masses": "rotor", "weights": "rotor",
               "q0": "q_component", "v0": "q_component"}
MEMBER_UNITS = {"theta0": "rad", "u0": "rad / time", "speed": "rad / time",
                "q0": "rad (θ₀…θ₃, α), length (x, y): component_units[:7]",
                "v0": "rad / time, length / time (x, y): component_units[7:]"}


def _number_rows(values) -> bool:
    """Whether ``values`` (one per member) are lists of one length whose entries are all
    floats or all integers (a 2-D native array that `member_attributes` reads back as the
    same lists)."""
    if not all(isinstance(v, list) and v for v in values) or len({len(v) for v in values}) != 1:
        return False
    kinds = {type(x) for v in values for x in v}
    return kinds == {float} or kinds == {int}


def _native_list(v):
    """A list of numbers of one type as a native 1-D attribute (`_native`; read back by
    `member_attributes` as the same list), else its JSON encoding."""
    kinds = {type(x) for x in v}
    native = _native(v) if kinds == {int} or kinds == {float} else None
    return _encode(v) if native is None else native


def member_attributes(ds, i) -> dict:
    """Member ``i``'s settings from a file written with `member_settings`, encoded as a
    member's own file would hold them (``attributes`` decodes them)."""
    flat = {}
    for key, value in ds.attrs.items():
        if key.startswith(MEMBER):
            value = value.tolist() if isinstance(value, np.ndarray) else _decode(value)
            flat[tuple(key[len(MEMBER):].split("."))] = value
    for key in ds.data_vars:
        if key.startswith(MEMBER):
            value = ds[key].values[i]
            value = value.tolist() if ds[key].ndim == 2 else _decode(value)
            flat[tuple(key[len(MEMBER):].split("."))] = value
    nested = {}
    for path, value in flat.items():
        if len(path) == 1:
            nested[path[0]] = value
        else:
            nested.setdefault(path[0], {})[path[1]] = value
    return {k: _encode(v) for k, v in nested.items()}


def attributes(ds) -> dict:
    """The dataset's settings, decoded (without the ``charts_*`` stamps, the CF globals and
    the native copies of the `FLATTENED` dicts)."""
    return {k: _decode(v) for k, v in ds.attrs.items() if _setting(k)}


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


class Archivable:
    """Base of the result types: ``save(path)`` from their ``to_xarray()`` (module docstring).

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
