"""What a result file must hold before `charts.io.archive.load` builds a result from it: its
first bytes (NetCDF-4, `check_netcdf4`), its header read without its data (`layout`, through
`read`, which turns HDF5's errors on damaged bytes into one line naming the file), and the
header checked against the kind's schema (`SCHEMAS`, `check_layout`): variables, dimensions,
numbers, sizes against the file's own size, attributes, bounded JSON."""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np

__all__ = ["SCHEMAS", "COMPRESSION_BOUND", "check_layout", "check_netcdf4", "layout", "read",
           "refused", "one_line", "unreadable", "path", "shown"]

#: What the file of each kind holds, from what its ``to_xarray`` gives `dataset`: variables
#: (data and coordinates) as name → their dimensions, numbers all (a name starting ``?`` is
#: optional, checked where present); attributes as name → "integer", "number" or "text".  An
#: ensemble's file holds its members' variables (`SCHEMAS` of ``member_kind``), each with or
#: without a leading ``member`` dimension.  `check_layout` refuses a file that differs.  A
#: tally's ``seed``: its ``state_seed`` in files written before the rename
#: (``charts.io.renamed_settings``).
SCHEMAS = {
    "trajectory": ({"t": "t", "theta": "t rotor", "u": "t rotor", "switch_t": "switch",
                    "switch_from": "switch", "switch_to": "switch", "?transported": "t vector rotor",
                    "?event_t": "event", "?event_index": "event", "?event_y": "event state"},
                   {"n_steps": "integer", "n_rejected": "integer", "n_rhs": "integer",
                    "?n_events": "integer", "status": "text", "formulation": "text",
                    "method": "text"}),
    "lyapunov": ({"exponents": "exponent", "stderr": "exponent", "history": "record exponent",
                  "history_t": "record", "batches": "batch exponent",
                  "?full_spectrum": "spectrum_index", "?energy_share_counts": "share_bin"}, {}),
    "curvature": ({"t": "t", "theta": "t rotor", "u": "t rotor", "frames": "t frame rotor",
                   "K_numeric": "t direction direction2", "?K_exact": "t direction direction2"},
                  {}),
    "angles": ({"t": "t", "phi_full": "t", "phi_restricted": "t", "forward_exponents": "vector",
                "adjoint_exponents": "vector"}, {}),
    "angle_tally": ({"n": "member", "min": "variant member", "argmin": "variant member",
                     "zeros": "variant member", "below": "variant member edge",
                     "law_count": "variant member x0", "law_logsum": "variant member x0",
                     "ladder_count": "variant member size", "ladder_sum": "variant member size",
                     "ladder_sumsq": "variant member size", "episodes": "variant member",
                     "?state_seed": "member", "?seed": "member"}, {}),
    "covariant": ({"t": "t", "phi": "t", "phi_vectors": "t", "growth": "t clv",
                   "gs_rates": "t clv", "states": "t component", "?vectors": "t clv component"},
                  {"variant": "text"}),
    "waveform": ({"t": "t", "theta": "t rotor", "u": "t rotor"}, {"dt_sample": "number"}),
    "spectrum": ({"omega": "omega", "density": "omega"}, {}),
    "ensemble": ({"?ensemble_exponents": "exponent", "?ensemble_stderr": "exponent",
                  "?batch_error_ratio": "exponent"}, {"member_kind": "text"}),
    "linkage": ({"exponents": "exponent", "stderr": "exponent", "batches": "batch exponent",
                 "K": "sample exponent", "states": "sample component", "t": "sample"},
                {"min_sin2": "number", "min_health": "number"}),
    "mechanism_lyapunov": ({"exponents": "exponent", "stderr": "exponent",
                            "batches": "batch exponent", "batch_t": "batch"},
                           {"energy_error": "number"}),
    "mechanism_curvature": ({"t": "t", "q": "t coordinate", "v": "t coordinate",
                             "frames": "t frame coordinate",
                             "K_numeric": "t direction direction2",
                             "?K_exact": "t direction direction2"}, {}),
    "mechanism_angles": ({"t": "t", "phi_restricted": "t", "forward_exponents": "vector",
                          "adjoint_exponents": "vector"}, {}),
    "scene": ({}, {"result": "json", "scene_text": "text"}),
    "sweep": ({}, {"column_order": "any"}),
}
#: A variable may declare at most this many times the file's size in bytes (the most that
#: deflate, HDF5's compression, packs into a byte is about 1032); more is a damaged or
#: hostile header, which would otherwise be allocated on loading.
COMPRESSION_BOUND = 1024


def shown(x) -> str:
    """``repr(x)`` for a message, at most 80 characters (a million masses are not echoed);
    NumPy arrays and scalars as the Python values they hold (``2.5``, not ``np.float64(2.5)``)."""
    text = repr(x.tolist() if isinstance(x, (np.ndarray, np.generic)) else x)
    return text if len(text) <= 80 else text[:77] + "..."


def path(name, x) -> Path:
    """``x`` as a ``Path``: a str or ``os.PathLike`` with a file name (not ``''``, ``'.'``
    nor a folder's ``'..'``); ValueError naming ``name`` otherwise (a number is not a path)."""
    if isinstance(x, bytes) or not isinstance(x, (str, os.PathLike)):
        raise ValueError(f"{name} must be a file path (a str or os.PathLike), got {shown(x)}")
    p = Path(x)
    if p.name in ("", ".", ".."):
        raise ValueError(f"{name} must name a file, got {shown(x)}")
    return p


def one_line(err) -> str:
    """An exception's text on one line, at most 200 characters."""
    text = " ".join(str(err).split()) or type(err).__name__
    return text if len(text) <= 200 else text[:197] + "..."


def refused(path, what) -> ValueError:
    return ValueError(f"{path} is not a usable charts result: {what}")


def _kind_of(dtype) -> str:
    """'number', 'text' or the dtype's name (anything else: booleans, compounds)."""
    try:
        dt = np.dtype(dtype)
    except TypeError:
        return str(dtype)
    if dt.kind in "iuf":
        return "number"
    return "text" if dt.kind in "USO" else str(dt)


def _attribute_ok(value, kind) -> bool:
    if isinstance(value, np.ndarray) and value.size == 1 and kind != "any":
        value = value.reshape(()).item()
    if isinstance(value, (bool, np.bool_)):
        return kind in ("any", "json")
    if kind == "integer":
        return isinstance(value, (int, np.integer))
    if kind == "number":
        return isinstance(value, (int, float, np.integer, np.floating))
    if kind == "text":
        return isinstance(value, str)
    if kind == "json":
        return isinstance(value, str) and value.startswith("json:")
    return True


def _size_words(n: float) -> str:
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if n < 1024 or unit == "PiB":
            return f"{n:.3g} {unit}"
        n /= 1024


def check_layout(path, variables: dict, attrs: dict) -> str:
    """The kind of the file ``path`` once its layout is found to be a charts result's, before
    any data is read: ``variables`` name → (dimensions, shape, dtype) and ``attrs`` as the file
    declares them.  Checked: ``charts_kind`` known; each variable's shape consistent with its
    dimensions and the other variables', and its declared bytes within `COMPRESSION_BOUND`
    times the file's size; the kind's variables (`SCHEMAS`) present, with their dimensions,
    numbers; its attributes present and of their type; every ``json:`` attribute JSON of
    bounded nesting (`parse_json`).  A ValueError of one line naming the file and the variable
    or attribute otherwise."""
    from .file_settings import parse_json
    kind = attrs.get("charts_kind")
    if not isinstance(kind, str) or kind not in SCHEMAS:
        raise ValueError(f"{path} is not a charts result (charts_kind = "
                         f"{one_line(repr(kind))}; known: {', '.join(SCHEMAS)})")
    for name, value in attrs.items():
        if isinstance(value, str) and value.startswith("json:"):
            try:
                parse_json(value[5:])
            except ValueError as err:
                raise refused(path, f"attribute {name!r}: {err}") from None
    limit = COMPRESSION_BOUND * Path(path).stat().st_size
    sizes = {}
    for name, (dims, shape, dtype) in variables.items():
        if len(dims) != len(shape):
            raise refused(path, f"variable {name!r} has {len(shape)} axes but names "
                                 f"{len(dims)} dimensions {dims}")
        for dim, n in zip(dims, shape):
            if sizes.setdefault(dim, (n, name))[0] != n:
                raise refused(path, f"variable {name!r} has {n} along {dim!r}, variable "
                                     f"{sizes[dim][1]!r} {sizes[dim][0]}")
        count = int(np.prod(shape, dtype=object))
        try:
            item = max(np.dtype(dtype).itemsize, 8 if np.dtype(dtype).kind in "OUS" else 1)
        except TypeError:
            item = 8
        if count * item > limit:
            raise refused(path, f"variable {name!r} declares shape {tuple(shape)} "
                                 f"({_size_words(count * item)}), more than a file of "
                                 f"{_size_words(limit / COMPRESSION_BOUND)} can hold "
                                 f"({COMPRESSION_BOUND}× its size)")
    wanted, wanted_attrs = SCHEMAS.get(kind, ({}, {}))
    lead = ()
    if kind == "ensemble":
        member_kind = attrs.get("member_kind")
        if member_kind not in SCHEMAS or member_kind in ("ensemble", "scene", "sweep"):
            raise refused(path, f"attribute 'member_kind' = {one_line(repr(member_kind))} is "
                                 "not a kind of result an ensemble holds")
        wanted = {**SCHEMAS[member_kind][0], **wanted}
        lead = ("member",)
    for key, spec in wanted.items():
        name = key.lstrip("?")
        if name not in variables:
            if key.startswith("?"):
                continue
            raise refused(path, f"the {kind} variable {name!r} is missing")
        dims, shape, dtype = variables[name]
        expected = tuple(spec.split())
        if dims != expected and not (lead and name not in SCHEMAS["ensemble"][0]
                                     and dims == lead + expected):
            raise refused(path, f"variable {name!r} has dimensions {dims}, not {expected}")
        if _kind_of(dtype) != "number":
            raise refused(path, f"variable {name!r} holds {_kind_of(dtype)}, not numbers")
    for key, spec in wanted_attrs.items():
        name = key.lstrip("?")
        if name not in attrs:
            if key.startswith("?"):
                continue
            raise refused(path, f"the {kind} attribute {name!r} is missing")
        if not _attribute_ok(attrs[name], spec):
            raise refused(path, f"attribute {name!r} = {one_line(repr(attrs[name]))} is not "
                                 f"{'JSON text' if spec == 'json' else spec}")
    return kind


def layout(path):
    """(variables: name → (dimensions, shape, dtype), attributes) of the NetCDF-4 file
    ``path``, read from its header without its data (h5netcdf)."""
    import h5netcdf
    with h5netcdf.File(path, "r") as f:
        variables = {name: (tuple(v.dimensions), tuple(int(n) for n in v.shape), v.dtype)
                     for name, v in f.variables.items()}
        return variables, dict(f.attrs)


def read(path, read, variables=()):
    """``read(path)``; a ValueError of one line naming ``path`` where HDF5 fails on its bytes
    (errors of any type: OSError, RuntimeError, KeyError...), and the first of ``variables``
    whose data cannot be read (`unreadable`: a damaged byte under a checksum, a broken
    chunk).  The file objects that h5netcdf leaves half-opened then are collected quietly
    (their ``close`` would print a traceback)."""
    import gc
    import sys
    failure, hook = None, sys.unraisablehook
    sys.unraisablehook = lambda unraisable: None
    try:
        try:
            return read(path)
        except Exception as err:             # noqa: BLE001 - HDF5's errors are of any type
            failure = f"{type(err).__name__}: {one_line(err)}"
            name = unreadable(path, variables)
        gc.collect()
    finally:
        sys.unraisablehook = hook
    where = f": the data of variable {name!r} is damaged" if name is not None else ""
    raise ValueError(f"{path} could not be read as NetCDF-4 (is it truncated or damaged?)"
                     f"{where}: {failure}")


def unreadable(path, variables):
    """The first of ``variables`` (names) whose data h5netcdf cannot read from ``path``, or
    None (all read, or the file cannot be opened at all)."""
    import h5netcdf
    try:
        with h5netcdf.File(path, "r") as f:
            for name in variables:
                try:
                    f.variables[name][...]
                except Exception:            # noqa: BLE001 - HDF5's errors are of any type
                    return name
    except Exception:                        # noqa: BLE001
        return None
    return None


#: The first bytes of an HDF5 file (NetCDF-4, what ``save`` writes), and of NetCDF-3.
_HDF5 = b"\x89HDF\r\n\x1a\n"
_NETCDF3 = (b"CDF\x01", b"CDF\x02", b"CDF\x05")


def check_netcdf4(path: Path) -> None:
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


