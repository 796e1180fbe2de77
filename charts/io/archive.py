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

Attributes: the settings, as NetCDF holds them natively (a number as a number, a list as an
array; ``ncdump -h`` and plain xarray read them), by the encoding of `charts.io.file_settings`
(its docstring gives the rules and a trajectory's attributes); `attributes` reads them back,
equal to the settings saved.  Every file also carries the CF global attributes
(``Conventions``, ``title``, ``history``, ``source``, ``references``, and ``comment``: the
units of the settings, `COMMENT`).  A result prints as one line, in the words of
`charts.io.result_words`.
"""
from __future__ import annotations

import importlib
import os
from pathlib import Path

import numpy as np

from .atomic import atomic_write, signals_deferred
from .file_settings import FLATTENED, MEMBER, decode_attributes, encode
from .renamed_settings import renamed
from .file_checks import path as file_path
from .file_checks import (COMPRESSION_BOUND, SCHEMAS, check_layout, check_netcdf4, layout,
                          read, refused)
from .file_checks import one_line as short
from .result_words import one_line, result_fields

__all__ = ["Archivable", "KINDS", "dataset", "exponent_coordinate", "index_coordinate",
           "attributes", "save", "load", "require_xarray", "ENGINE", "TITLES",
           "ENSEMBLE_TITLES", "GLOBALS", "COMMENT", "REFERENCE", "same_value", "SCHEMAS",
           "COMPRESSION_BOUND", "check_layout", "checksummed"]

#: kind → "module:Class" of every result type ``load`` knows (imported when a file needs it).
KINDS = {
    "trajectory": "charts.solvers.integrate:IntegrationResult",
    "lyapunov": "charts.analyses.lyapunov_result:LyapunovResult",
    "curvature": "charts.analyses.curvature:CurvatureResult",
    "angles": "charts.analyses.hyperbolicity:AngleResult",
    "angle_tally": "charts.analyses.angle_tally:AngleTally",
    "covariant": "charts.analyses.covariant:CovariantResult",
    "waveform": "charts.analyses.spectra:Waveform",
    "spectrum": "charts.analyses.spectra:PowerSpectrum",
    "ensemble": "charts.analyses.ensemble:EnsembleResult",
    "linkage": "charts.analyses.linkage:LinkageResult",
    "mechanism_lyapunov": "charts.analyses.mechanism_lyapunov:MechanismLyapunov",
    "mechanism_curvature": "charts.analyses.curvature:CurvatureResult",
    "mechanism_angles": "charts.analyses.mechanism_angles:MechanismAngles",
    "scene": "charts.runs.netcdf_results:SceneResult",
    "sweep": "charts.runs.netcdf_results:SweepTable",
}

#: The NetCDF engine (NetCDF-4/HDF5: 64-bit integers, unicode strings, compression).
ENGINE = "h5netcdf"


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

#: Titles of the files of each kind (CF ``title``).
TITLES = {
    "trajectory": "geodesic of the rotor constraint manifold (charts.integrate)",
    "lyapunov": "Lyapunov spectrum (charts.lyapunov_spectrum)",
    "curvature": "sectional curvatures along a trajectory (charts.curvature_along_trajectory)",
    "angles": "angles between the expanding and the zero-and-contracting subspaces "
              "(charts.hyperbolicity_angles)",
    "angle_tally": "statistics of the angles between the expanding and the zero-and-"
                   "contracting subspaces of an ensemble (charts.hyperbolicity_tally)",
    "covariant": "covariant Lyapunov vectors (charts.covariant_lyapunov_vectors)",
    "waveform": "waveforms theta(t), u(t) (charts.waveform)",
    "spectrum": "power spectrum (charts.power_spectrum)",
    "ensemble": "ensemble of independent trajectories (an EnsembleResult)",
    "linkage": "Lyapunov exponents and curvature of the Appendix's linkage (charts.linkage_run)",
    "mechanism_lyapunov": "Lyapunov spectrum of a mechanism "
                          "(charts.analyses.mechanism_lyapunov.lyapunov_spectrum)",
    "mechanism_curvature": "sectional curvatures along a trajectory of a mechanism "
                           "(charts.curvature_along_trajectory of a charts.Mechanism)",
    "mechanism_angles": "angles between the expanding and the zero-and-contracting subspaces "
                        "of a mechanism (charts.hyperbolicity_angles of a charts.Mechanism)",
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
#: carry themselves (every variable has its own ``units``), and what each seed seeds.
COMMENT = ("Units of the settings (params_*, options_*, member.params.*): times (t_final, "
           "t_transient, dt, t_span, every *_every) in time units of the flow; angles (theta0) "
           "in rad; velocities (u0) and speed in rad / time (the linkage's q0, v0: see "
           "q_component_units).  Seeds: vectors_seed seeds the random tangent vectors; "
           "state_seed the initial state (RotorSystem.random_state), or 'given' where the "
           "caller gave it; members_seed is an ensemble's first member's seed, member i "
           "having members_seed + i for its state and its vectors (files written before "
           "these names: params_seed, params_m, read as the new names).  n_unstable is the "
           "dimension of the expanding subspace E_u.  Every variable carries its own units.")
#: CF ``references`` of every file: the paper.
REFERENCE = ("S. P. Kuznetsov, Chaos and hyperchaos of geodesic flows on curved manifolds "
             "corresponding to mechanically coupled rotators")


def _global_attributes(kind: str, title: str | None = None) -> dict:
    import datetime
    import platform

    from ..version import source_version
    versions = [f"charts {source_version()}", f"python {platform.python_version()}",
                f"numpy {np.__version__}"]
    try:
        import numba
        versions.append(f"numba {numba.__version__}")
    except ImportError:                      # pragma: no cover - numba is a dependency
        pass
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    return {"Conventions": "CF-1.10", "title": f"charts: {title or TITLES.get(kind, kind)}",
            "history": f"{now}: written by charts {source_version()}",
            "source": ", ".join(versions), "references": REFERENCE, "comment": COMMENT}


def dataset(kind: str, data_vars: dict, coords: dict | None = None, attrs: dict | None = None,
            title: str | None = None):
    """An ``xarray.Dataset`` stamped with ``charts_kind`` and ``charts_version`` (the release
    and the commit or source digest that made it, ``charts.version.source_version``) and the CF
    global attributes (`GLOBALS`: conventions, title, history, source, references, and the
    ``comment`` `COMMENT` on the settings' units).  ``title``: the CF title where the kind's
    (`TITLES`) says too little (an ensemble's names its members, `ENSEMBLE_TITLES`).

    ``data_vars`` and ``coords``: name → ``(dims, array, units)`` or
    ``(dims, array, units, description)``; ``attrs``: settings (name → value, written by
    `encode`: the entries of the `FLATTENED` dicts as ``params_<key>``)."""
    xr = require_xarray()
    from ..version import source_version

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
    ds.attrs["charts_version"] = source_version()     # changes whenever the code does
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
    """Whether the attribute ``key`` is a setting of its own: not a ``charts_*`` stamp, a CF
    global, a member's setting or an entry of a `FLATTENED` dict."""
    return not (key.startswith("charts_") or key in GLOBALS or key.startswith(MEMBER)
                or any(key.startswith(f"{name}_") for name in FLATTENED))


def attributes(ds) -> dict:
    """The dataset's settings as they were saved (the inverse of `encode`): the `FLATTENED`
    dicts gathered from their entries (or, in a file written before, read from their JSON
    text); without the ``charts_*`` stamps, the CF globals and the members' settings.  A
    file written before settings were renamed has its ``params`` under the new names, with
    a note (`charts.io.renamed_settings`)."""
    out = {k: v for k, v in decode_attributes(ds.attrs).items() if _setting(k)}
    if "params" in out:
        out["params"] = renamed(out["params"], ds.attrs.get("charts_kind"))
    return out


def checksummed(ds) -> dict:
    """The encoding that gives every array of numbers of ``ds`` (its variables with at least
    one axis; HDF5 filters need chunks, which a scalar has not) HDF5's Fletcher-32 checksum:
    a damaged byte of its data is then an error on reading (`load` names the variable), not
    a wrong number."""
    return {name: {"fletcher32": True} for name, v in ds.variables.items()
            if v.ndim > 0 and v.size > 0 and v.dtype.kind in "biuf"}


def save(ds, path) -> Path:
    """Write the dataset to ``path`` (NetCDF-4), atomically, each array of numbers with its
    checksum (`checksummed`); a Ctrl-C or SIGTERM meanwhile is taken once the file is
    written (`signals_deferred`)."""
    require_xarray()
    path = file_path("path", path)
    tmp = path.with_name(f".{path.name}.nc-tmp{os.getpid()}")
    with signals_deferred():            # a Ctrl-C meanwhile: taken once the file is written
        try:
            ds.to_netcdf(tmp, engine=ENGINE, encoding=checksummed(ds))
            atomic_write(path, tmp.read_bytes())
        finally:
            if tmp.exists():
                tmp.unlink()
    return path


def load(path):
    """The result saved in ``path`` (by any ``save``), as an object of its own type.

    A file from elsewhere is checked before its data is read (`check_layout`: the kind, its
    variables, dimensions, numbers and sizes, its attributes); a file that differs, or whose
    bytes are damaged, is refused with a ValueError of one line naming the file and the
    variable or attribute."""
    xr = require_xarray()
    path = file_path("path", path)
    if not path.exists():
        raise FileNotFoundError(f"no such file: {path}")
    check_netcdf4(path)
    variables, attrs = read(path, layout)
    kind = check_layout(path, variables, attrs)
    ds = read(path, lambda p: xr.load_dataset(p, engine=ENGINE), variables)
    from .file_settings import parse_json
    for name in ds.data_vars:                # the members' settings held as JSON text
        v = ds[name]
        if v.dtype.kind in "OU" and name.startswith(MEMBER):
            for text in v.values.ravel():
                if isinstance(text, str) and text.startswith("json:"):
                    try:
                        parse_json(text[5:])
                    except ValueError as err:
                        raise refused(path, f"variable {name!r}: {err}") from None
    module, name = KINDS[kind].split(":")
    cls = getattr(importlib.import_module(module), name)
    try:
        return cls.from_xarray(ds)
    except (KeyError, IndexError, TypeError, ValueError, AttributeError) as err:
        raise refused(path, f"its {kind} could not be rebuilt ({type(err).__name__}: "
                             f"{short(err)})") from None


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
        return same_value(result_fields(self), result_fields(other))

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
