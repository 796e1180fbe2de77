"""The sweep table ``sweep.csv``: its columns, one row per point appended (and fsync'ed)
as the point finishes, reading it back (a half-written last line is ignored), checking it
before a resume, and the final rewrite in point order."""
from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path

from ..io import atomic_text
from ..scene import scene_to_dict
from .points import SweepPoint
from .spec import SweepError
from .statistics import stat_columns

__all__ = ["TABLE", "LOG", "HEAD", "TAIL", "WEIGHT_VECTOR", "point_columns", "point_row", "format_cell",
           "csv_line", "csv_text", "read_table", "prepare_table", "finish_table",
           "TableAppender"]

TABLE, LOG = "sweep.csv", "log.jsonl"
#: Columns before the parameters (after them come the statistics).
HEAD = ["index", "point_id", "status"]
#: Columns after the statistics.
TAIL = ["mass_vector", "t_final", "error", "scene"]
#: A column after ``mass_vector`` in sweeps with [sweep.weights] patterns only (the resolved
#: weights of the point), so that the tables of other sweeps keep their columns.
WEIGHT_VECTOR = "weight_vector"


def point_columns(points: list[SweepPoint]) -> list[str]:
    """Columns of the table: index, point_id, status, the parameters, the statistics
    (union over points, in first-seen order), then mass_vector, (weight_vector when the
    sweep has weight patterns), t_final, error, scene."""
    params, stats = [], []
    for p in points:
        params += [k for k in p.params if k not in params]
        stats += [c for c in stat_columns(p.scene) if c not in stats]
    tail = TAIL[:1] + [WEIGHT_VECTOR] + TAIL[1:] if "weights" in params else TAIL
    return HEAD + params + stats + tail


def format_cell(v) -> str:
    """A value as a table cell: '' for None, ``repr`` for floats (exact round trip)."""
    if v is None:
        return ""
    if isinstance(v, float):
        return repr(v)
    return str(v)


def point_row(point: SweepPoint, out: dict, columns: list[str]) -> list[str]:
    """The cells of one point given the worker's output ``out`` (see evaluate_point)."""
    vals = {"index": point.index, "point_id": point.point_id, "status": out["status"],
            **point.params, **out["stats"],
            "mass_vector": json.dumps(point.scene.system.get("masses")),   # (a mechanism's:
            # null; its parameters are in its columns and its scene)
            WEIGHT_VECTOR: json.dumps(point.scene.system.get("weights")),
            "t_final": out.get("t_final"), "error": out.get("error", ""),
            "scene": json.dumps(scene_to_dict(point.scene), sort_keys=True)}
    return [format_cell(vals.get(c)) for c in columns]


def csv_line(cells: list[str]) -> str:
    """One CSV line (``\\n`` terminated)."""
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(cells)
    return buf.getvalue()


def csv_text(header: list[str], rows) -> str:
    """A whole CSV file: the header line, then one line per row of cells."""
    return csv_line(header) + "".join(csv_line(r) for r in rows)


def read_table(path) -> tuple[list[str], list[dict]]:
    """Header and rows (dicts of strings) of a sweep table; a trailing partial line (a
    sweep killed while writing) is ignored."""
    text = Path(path).read_text()
    if text and not text.endswith("\n"):
        text = text[: text.rfind("\n") + 1]
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return [], []
    header = rows[0]
    return header, [dict(zip(header, r)) for r in rows[1:] if len(r) == len(header)]


def prepare_table(outdir: Path, columns, points, resume: bool, source: str) -> dict:
    """Create (or, with resume, check and repair) the table; return point_id -> row of the
    finished points."""
    table = outdir / TABLE
    if not table.exists() or table.stat().st_size == 0:
        atomic_text(table, csv_line(columns))
        return {}
    header, rows = read_table(table)
    if not rows:                      # only a header (a sweep that never got a point in)
        atomic_text(table, csv_line(columns))
        return {}
    if not resume:
        raise SweepError(f"{table} already holds a sweep ({len(rows)} points): continue it with "
                         "--resume, or choose another output folder")
    if header != columns:
        missing = [c for c in columns if c not in header]
        extra = [c for c in header if c not in columns]
        diff = "; ".join(part for part in (
            f"missing {', '.join(missing)}" if missing else "",
            f"not written now {', '.join(extra)}" if extra else "") if part) or "their order"
        raise SweepError(f"{table} has different columns than {source} would write ({diff}: "
                         "the sweep file changed its effects or parameters, or an earlier "
                         "version of charts wrote the table); use another output folder")
    ids = {p.point_id for p in points}
    foreign = [r["point_id"] for r in rows if r["point_id"] not in ids]
    if foreign:
        raise SweepError(f"{table} holds {len(foreign)} points that are not in {source} (the "
                         "sweep file changed); use another output folder")
    # drop a partial last line, keep one row per point
    done = {r["point_id"]: r for r in rows}
    text = table.read_text()
    if text and not text.endswith("\n"):
        atomic_text(table, text[: text.rfind("\n") + 1])
    return done


def finish_table(path, n_points: int):
    """When the table at ``path`` holds every one of the ``n_points`` points once, rewrite
    it in point order (then it equals an uninterrupted run's) and return ``(header, rows)``;
    otherwise None."""
    header, rows = read_table(path)
    if len(rows) != n_points or len({r["point_id"] for r in rows}) != n_points:
        return None
    rows.sort(key=lambda r: int(r["index"]))
    atomic_text(path, csv_text(header, ([r[c] for c in header] for r in rows)))
    return header, rows


class TableAppender:
    """Append rows to the table and records to the log as points finish (flush + fsync
    each)."""

    def __init__(self, outdir: Path):
        self.table = open(outdir / TABLE, "a", newline="")
        self.log = open(outdir / LOG, "a")

    def add(self, cells, record):
        for f, text in ((self.table, csv_line(cells)), (self.log, json.dumps(record) + "\n")):
            f.write(text)
            f.flush()
            os.fsync(f.fileno())

    def close(self):
        self.table.close()
        self.log.close()
