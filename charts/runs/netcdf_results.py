"""Scene results and sweep tables as NetCDF (``charts.io.archive``): ``SceneResult`` (what a
scene run writes: ``results.nc`` beside ``result.json``) and ``SweepTable`` (``sweep.csv``
as a dataset along a ``point`` dimension)."""
from __future__ import annotations

import csv
import json
import re
from pathlib import Path

import numpy as np

from ..io.archive import Archivable, attributes, dataset, exponent_coordinate
from ..io.result_words import ANGULAR_VELOCITY, RATE, counted
from .io import json_default

__all__ = ["SceneResult", "SweepTable", "SCENE_NETCDF", "ARRAY_LAYOUT", "COLUMN_UNITS",
           "COLUMN_DESCRIPTIONS", "column_units"]

#: The file a scene run writes its arrays to, beside result.json.
SCENE_NETCDF = "results.nc"

#: Dimensions and units of the arrays a scene stores (``arrays.npz`` keys).
ARRAY_LAYOUT = {
    "waveforms_t": (("waveforms_sample",), "time"),
    "waveforms_u": (("waveforms_sample", "waveforms_rotor"), ANGULAR_VELOCITY),
    "spectrum_omega": (("frequency",), ANGULAR_VELOCITY),
    "spectrum_psd": (("frequency",), f"({ANGULAR_VELOCITY})² per unit ω"),
    "drift_t": (("drift_sample",), "time"),
    "drift_constraint": (("drift_sample",), "1"),
    "drift_tangency": (("drift_sample",), ANGULAR_VELOCITY),
    "drift_energy": (("drift_sample",), "1"),
    "lyapunov_history_t": (("lyapunov_record",), "time"),
    "lyapunov_history": (("lyapunov_record", "exponent"), RATE),
    "energy_share_counts": (("share_bin",), "1"),
    "angles_t": (("angles_sample",), "time"),
    "angles_full": (("angles_sample",), "rad"),
    "angles_restricted": (("angles_sample",), "rad"),
    "curvature_t": (("curvature_sample",), "time"),
    "curvature_numerical": (("curvature_sample", "direction"), "1 / rad²"),
    "curvature_exact": (("curvature_sample", "direction"), "1 / rad²"),
    "curvature_eq22": (("curvature_sample",), "1 / rad²"),
    "switches": (("switch", "switch_field"), "time | chart | chart"),
}


class SceneResult(Archivable):
    """A scene run's results: ``result`` (the dict of result.json), ``arrays`` (name →
    array, as in arrays.npz) and ``scene_text`` (the scene file's text, when it was a file).
    ``charts.load(outdir / "results.nc")`` returns one."""

    KIND = "scene"

    def __init__(self, result: dict, arrays: dict, scene_text: str = ""):
        self.result = result
        self.arrays = dict(arrays)
        self.scene_text = scene_text

    @classmethod
    def from_run(cls, result: dict, arrays: dict, source: str):
        path = Path(source)
        text = path.read_text(encoding="utf-8") if path.is_file() else ""
        return cls(json.loads(json.dumps(result, default=json_default)), arrays, text)

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``); the exponents counted from 1, as in a
        `LyapunovResult`'s file."""
        data, coords = {}, {}
        for name, arr in self.arrays.items():
            dims, units = ARRAY_LAYOUT.get(name, (None, "1"))
            arr = np.asarray(arr)
            if dims is None or len(dims) != arr.ndim:
                dims = tuple(f"{name}_dim{i}" for i in range(arr.ndim))
            data[name] = (dims, arr, units)
            if "exponent" in dims:
                coords["exponent"] = exponent_coordinate(arr.shape[dims.index("exponent")])
        return dataset(self.KIND, data, coords=coords, attrs={"result": self.result,
                                                              "scene_text": self.scene_text})

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        return cls(a["result"], {k: v.values for k, v in ds.data_vars.items()}, a["scene_text"])

    def summary_parts(self):
        """The scene's name, the run's status and how many arrays it holds."""
        return [repr(self.result.get("scene", {}).get("name")),
                f"status={self.result.get('status')!r}", counted(len(self.arrays), "array")]


#: Units of the sweep table's known columns (``charts.runs.sweep``: the exponents and their
#: errors, the times, the mean curvatures, the angles), by pattern; every other column "1".
COLUMN_UNITS = ((r"lambda_\d+(_se)?", RATE), (r"h_ks(_se)?", RATE), (r"t_final", "time"),
                (r"Kmean_\w+", "1 / rad^2"),
                (r"(clv_)?phi_[a-z]+_(min|p001|median)", "rad"), (r"cone_distance_min", "rad"))


#: Descriptions (``long_name``) of the sweep table's columns that need saying how they were
#: obtained.
COLUMN_DESCRIPTIONS = {
    "h_ks": "Kolmogorov–Sinai entropy by Pesin's formula: the sum of the leading N−2 "
            "exponents that are positive in the point's estimate (the zeros of the flow "
            "direction and the energy shift never count)",
    "h_ks_se": "standard error of h_ks by batch means: the standard deviation over the "
               "batches of the same exponents' sums, over √(number of batches); not the "
               "exponents' errors added",
}


def column_units(name: str) -> str | None:
    """The units of the sweep column ``name`` (`COLUMN_UNITS`), None for a column of none."""
    for pattern, units in COLUMN_UNITS:
        if re.fullmatch(pattern, name):
            return units
    return None


def _column(values, name=""):
    """A table column as an array: integers, floats (empty cells NaN) or strings; a column
    of empty cells only is text (e.g. ``error`` when no point failed), unless ``name`` is a
    column of numbers with units (`column_units`)."""
    if all(v == "" for v in values) and column_units(name) is None:
        return np.array(values, dtype=str)
    for kind in (int, float):
        try:
            return np.array([kind(v) if v != "" else (np.nan if kind is float else None)
                             for v in values], dtype=kind)
        except (TypeError, ValueError):
            continue
    return np.array(values, dtype=str)


class SweepTable(Archivable):
    """A sweep's table: ``columns`` (name → array along the points, in table order) and
    ``attrs`` (the sweep's source).  ``SweepTable.from_csv(outdir / "sweep.csv")``."""

    KIND = "sweep"

    def __init__(self, columns: dict, attrs: dict | None = None):
        self.columns = dict(columns)
        self.attrs = dict(attrs or {})

    @classmethod
    def from_csv(cls, path):
        """The table of a sweep's ``sweep.csv``, one column per statistic along ``point``
        (integers stay integers): ``SweepTable.from_csv("DIR/sweep.csv").save("DIR/sweep.nc")``."""
        path = Path(path)
        with open(path, newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
        if not rows:
            raise ValueError(f"{path} is empty: not a sweep table")
        header, body = rows[0], [r for r in rows[1:] if len(r) == len(rows[0])]
        cols = {h: _column([r[i] for r in body], h) for i, h in enumerate(header)}
        return cls(cols, {"source": str(path)})

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``)."""
        data = {k: (("point",), v, column_units(k) or "1")
                + ((COLUMN_DESCRIPTIONS[k],) if k in COLUMN_DESCRIPTIONS else ())
                for k, v in self.columns.items()}
        return dataset(self.KIND, data, attrs={"table": self.attrs,
                                               "column_order": list(self.columns)})

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        return cls({k: ds[k].values for k in a["column_order"]}, a["table"])

    def summary_parts(self):
        """The points and the columns of the table."""
        n = len(next(iter(self.columns.values()))) if self.columns else 0
        return [counted(n, "point"), counted(len(self.columns), "column")]
