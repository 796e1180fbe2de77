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
integers, so settings come back equal.
"""
from __future__ import annotations

import importlib
import json
import os
from pathlib import Path

import numpy as np

from .atomic import atomic_write

__all__ = ["Archivable", "KINDS", "dataset", "attributes", "save", "load", "require_xarray",
           "ENGINE"]

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


def dataset(kind: str, data_vars: dict, coords: dict | None = None, attrs: dict | None = None):
    """An ``xarray.Dataset`` stamped with ``charts_kind`` and ``charts_version``.

    ``data_vars`` and ``coords``: name → ``(dims, array, units)`` or
    ``(dims, array, units, description)``; ``attrs``: settings (encoded as above)."""
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
    ds.attrs.update({k: _encode(v) for k, v in (attrs or {}).items()})
    ds.attrs["charts_kind"] = kind
    ds.attrs["charts_version"] = __version__
    return ds


def attributes(ds) -> dict:
    """The dataset's attributes, decoded (without the ``charts_*`` stamps)."""
    return {k: _decode(v) for k, v in ds.attrs.items() if not k.startswith("charts_")}


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
    ds = xr.load_dataset(path, engine=ENGINE)
    kind = ds.attrs.get("charts_kind")
    if kind not in KINDS:
        raise ValueError(f"{path} is not a charts result (charts_kind = {kind!r}; known: "
                         f"{', '.join(KINDS)})")
    module, name = KINDS[kind].split(":")
    return getattr(importlib.import_module(module), name).from_xarray(ds)


class Archivable:
    """Base of the result types: ``save(path)`` from their ``to_xarray()`` (module docstring)."""

    KIND = "abstract"

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
