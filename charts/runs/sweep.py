"""Parameter sweeps: many scenes on a Dask cluster, one table, resumable (issue 7).

Design note.  A sweep file (TOML) is a *base scene* plus the parameters to vary.  Every
parameter point becomes an ordinary scene (``charts.scene``), validated before anything
runs, and is evaluated by :func:`evaluate_point` — :func:`charts.runner.run_scene` in a
temporary folder on a Dask worker — which returns one row of statistics.  The main
process appends each row to ``DIR/sweep.csv`` as soon as its point finishes (one line,
flushed and fsync'ed), so an interrupted sweep keeps every finished point and
``--resume`` computes only the others.  When the last point is in, the table is rewritten
in point order: it is then byte-identical to the table of an uninterrupted run (rows hold
only deterministic numbers; who computed what and when goes to ``DIR/log.jsonl``).

Layout of a sweep file::

    name = "masses-n4"
    description = "..."
    [scene]                       # the base scene: any key of a scene file (docs/scenes.md)
    [scene.run]                   #   except [initial] theta/u (points are seeded)
    t_final = 2000.0
    [scene.effects.lyapunov]
    [sweep]
    mode = "grid"                 # "grid": every combination; "random": n_points draws
    seeds = [1, 2]                # initial-state seeds (or a count k: seeds 0..k-1)
    n_points = 20                 # random mode only
    sample_seed = 0               # random mode only
    [sweep.parameters]            # the axes
    n = [4]                       # -> [system] n
    speed = [1.0]                 # -> [system] speed
    m = [0.25, 1.0, 4.0]          # a free symbol, used by the mass patterns
    "run.t_final" = [500.0, 1000.0]   # a dotted key overrides that scene key
    # random mode: a list is drawn uniformly, {min, max, log} a (log-)uniform number
    [sweep.masses]                # named mass patterns: numbers or expressions in symbols
    "1,1,1,m" = [1, 1, 1, "m"]
    "1,m,1,1/m" = [1, "m", 1, "1/m"]

With ``[sweep.masses]`` the pattern name is one more axis, ``masses``.  The table has one
row per point (parameters, seed, the resolved mass vector, the statistics, the full scene as
run in JSON) — see :func:`point_columns`.  ``DIR/summary.csv`` averages over seeds and
``DIR/figures/`` holds one curve or heat map per statistic over the swept parameters
(``charts.sweep_report``).
"""
from __future__ import annotations

import ast
import csv
import hashlib
import io
import json
import math
import operator
import os
import socket
import tempfile
import time
import uuid
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib

from .scene import Scene, SceneError, parse_scene, scene_to_dict

__all__ = ["Sweep", "SweepError", "SweepPoint", "load_sweep", "parse_sweep", "sweep_points",
           "evaluate_point", "point_columns", "run_sweep", "read_table", "bundled_sweeps",
           "TABLE", "SUMMARY", "LOG"]

TABLE, SUMMARY, LOG, META = "sweep.csv", "summary.csv", "log.jsonl", "sweep.json"
MODES = ("grid", "random")
#: Parameter names with a fixed meaning; any other plain name is a symbol of the patterns.
SYSTEM_AXES = {"n": "n", "speed": "speed"}
#: Columns before the statistics (after them come the parameter columns).
HEAD = ["index", "point_id", "status"]
TAIL = ["mass_vector", "t_final", "error", "scene"]


class SweepError(ValueError):
    """A sweep that cannot run.  The message names the key, the value and what is allowed."""


@dataclass(frozen=True)
class SweepPoint:
    """One point: its parameters (axis name -> value, ``seed`` last), the raw scene dict
    sent to the worker, the validated :class:`Scene` and a content hash ``point_id``."""
    index: int
    params: dict
    raw: dict
    scene: Scene
    point_id: str


@dataclass(frozen=True)
class Sweep:
    name: str
    description: str
    base: dict
    mode: str
    seeds: tuple
    axes: dict                      # name -> list (grid) or list / {min, max, log} (random)
    masses: dict = field(default_factory=dict)   # pattern name -> list of numbers/exprs
    n_points: int = 0
    sample_seed: int = 0
    source: str = "<sweep>"
    data: dict = field(default_factory=dict)     # the file as read


# --------------------------------------------------------------------------- parsing
_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
        ast.Div: operator.truediv, ast.Pow: operator.pow, ast.USub: operator.neg,
        ast.UAdd: operator.pos}


def _expr_symbols(expr: str, where: str) -> set:
    try:
        tree = ast.parse(expr, mode="eval")
    except SyntaxError:
        raise SweepError(f"{where}: {expr!r} is not an arithmetic expression "
                         "(numbers, parameter names, + - * / **)") from None
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            names.add(node.id)
        elif not isinstance(node, (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Constant,
                                   ast.Load, *_OPS)):
            raise SweepError(f"{where}: {expr!r} uses {type(node).__name__}; allowed: numbers, "
                             "parameter names, + - * / **")
    return names


def _eval(expr: str, env: dict) -> float:
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.Name):
            return float(env[node.id])
        if isinstance(node, ast.BinOp):
            return _OPS[type(node.op)](ev(node.left), ev(node.right))
        return _OPS[type(node.op)](ev(node.operand))
    return ev(ast.parse(expr, mode="eval"))


def _unknown(source, section, key, allowed):
    import difflib
    hint = difflib.get_close_matches(key, list(allowed), n=1, cutoff=0.6)
    did = f" — did you mean {hint[0]!r}?" if hint else ""
    return SweepError(f"{source}: unknown key {key!r} in {section}{did} "
                      f"(allowed: {', '.join(sorted(allowed))})")


def load_sweep(path) -> Sweep:
    """Read and validate a sweep file (TOML).  Raises :class:`SweepError`."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_bytes().decode("utf-8"))
    except FileNotFoundError:
        raise SweepError(f"{path}: no such sweep file (bundled sweeps: `charts sweep --list`)") \
            from None
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise SweepError(f"{path}: cannot read the sweep: {exc}") from None
    return parse_sweep(data, source=str(path), default_name=path.stem)


def _is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def parse_sweep(data: dict, *, source="<sweep>", default_name="sweep") -> Sweep:
    """Validate a sweep given as a dict (as read from TOML); every point's scene is
    validated by :func:`sweep_points` too."""
    top = {"name", "description", "scene", "sweep"}
    for key in data:
        if key not in top:
            raise _unknown(source, "the top level", key, top)
    base = data.get("scene", {})
    if not isinstance(base, dict):
        raise SweepError(f"{source}: [scene] must be a table (the base scene)")
    if any(k in base.get("initial", {}) for k in ("theta", "u")):
        raise SweepError(f"{source}: [scene.initial] theta/u are not allowed in a sweep: "
                         "points are seeded (use [sweep] seeds)")
    if "name" in base:
        raise SweepError(f"{source}: [scene] name is not allowed: points are named "
                         "<sweep name>-<index>")
    sw = data.get("sweep")
    if not isinstance(sw, dict):
        raise SweepError(f"{source}: [sweep] is required: the parameters to vary")
    allowed = {"mode", "seeds", "n_points", "sample_seed", "parameters", "masses"}
    for key in sw:
        if key not in allowed:
            raise _unknown(source, "[sweep]", key, allowed)
    mode = sw.get("mode", "grid")
    if mode not in MODES:
        raise SweepError(f"{source}: [sweep] mode = {mode!r} is not allowed "
                         f"(allowed: {', '.join(map(repr, MODES))})")
    seeds = sw.get("seeds", [0])
    if isinstance(seeds, int) and not isinstance(seeds, bool) and seeds >= 1:
        seeds = list(range(seeds))
    if not (isinstance(seeds, list) and seeds and all(isinstance(s, int) and not isinstance(s, bool)
                                                     and s >= 0 for s in seeds)):
        raise SweepError(f"{source}: [sweep] seeds = {seeds!r} is not allowed: expected a "
                         "non-empty list of integers >= 0, or a count >= 1")
    if len(set(seeds)) != len(seeds):
        raise SweepError(f"{source}: [sweep] seeds = {seeds!r} repeats a seed")
    n_points, sample_seed = sw.get("n_points"), sw.get("sample_seed", 0)
    if mode == "random":
        if not (isinstance(n_points, int) and not isinstance(n_points, bool) and n_points >= 1):
            raise SweepError(f"{source}: [sweep] n_points = {n_points!r}: random mode needs "
                             "an integer >= 1 (the number of parameter draws)")
        if not (isinstance(sample_seed, int) and not isinstance(sample_seed, bool)):
            raise SweepError(f"{source}: [sweep] sample_seed = {sample_seed!r}: expected an integer")
    elif n_points is not None or "sample_seed" in sw:
        raise SweepError(f"{source}: [sweep] n_points/sample_seed are for mode = \"random\" "
                         "only")

    axes = sw.get("parameters", {})
    masses = sw.get("masses", {})
    if not isinstance(axes, dict) or not isinstance(masses, dict):
        raise SweepError(f"{source}: [sweep.parameters] and [sweep.masses] must be tables")
    if "seed" in axes or "masses" in axes:
        raise SweepError(f"{source}: [sweep.parameters] seed/masses are reserved: use "
                         "[sweep] seeds and the [sweep.masses] patterns")
    for name, vals in axes.items():
        where = f"{source}: [sweep.parameters] {name}"
        if isinstance(vals, dict):
            if mode != "random":
                raise SweepError(f"{where} = {vals!r}: a range {{min, max, log}} needs mode = "
                                 "\"random\"; a grid takes a list of values")
            extra = set(vals) - {"min", "max", "log"}
            if extra or not (_is_num(vals.get("min")) and _is_num(vals.get("max"))
                             and vals["min"] < vals["max"]):
                raise SweepError(f"{where} = {vals!r} is not allowed: expected {{min = a, "
                                 "max = b, log = true|false}} with a < b")
            if vals.get("log", False) and vals["min"] <= 0:
                raise SweepError(f"{where}: log = true needs min > 0")
        elif not (isinstance(vals, list) and vals):
            raise SweepError(f"{where} = {vals!r} is not allowed: expected a non-empty list "
                             "of values" + (" or {min, max, log}" if mode == "random" else ""))
        elif len({json.dumps(v) for v in vals}) != len(vals):
            raise SweepError(f"{where} = {vals!r} repeats a value")
        if "." in name:
            section = name.split(".")[0]
            if section not in ("system", "initial", "integrator", "run", "effects"):
                raise SweepError(f"{where}: a dotted key must start with system., integrator., "
                                 "run. or effects. (e.g. \"run.t_final\")")
            if name in ("system.masses", "system.n", "system.speed", "initial.seed"):
                raise SweepError(f"{where}: use the parameter name "
                                 f"{name.split('.')[-1]!r} (or seeds / [sweep.masses])")
    symbols = {k for k in axes if "." not in k and k not in SYSTEM_AXES}
    used = set()
    for pname, pat in masses.items():
        where = f"{source}: [sweep.masses] {pname!r}"
        if not (isinstance(pat, list) and pat):
            raise SweepError(f"{where} = {pat!r}: expected a list of numbers or expressions")
        for x in pat:
            if isinstance(x, str):
                names = _expr_symbols(x, where)
                missing = names - symbols
                if missing:
                    raise SweepError(f"{where}: {x!r} uses {', '.join(sorted(missing))}, which is "
                                     "not a parameter; add it to [sweep.parameters]")
                used |= names
            elif not (_is_num(x) and x > 0):
                raise SweepError(f"{where}: {x!r} is not allowed: entries are numbers > 0 or "
                                 "expressions in the parameters")
    unused = symbols - used
    if unused:
        raise SweepError(f"{source}: [sweep.parameters] {', '.join(sorted(unused))} is not used: "
                         "reference it in a [sweep.masses] pattern, or use n, speed or a dotted "
                         "scene key such as \"run.t_final\"")
    return Sweep(name=data.get("name", default_name), description=data.get("description", ""),
                 base=base, mode=mode, seeds=tuple(seeds), axes=dict(axes), masses=dict(masses),
                 n_points=n_points or 0, sample_seed=sample_seed, source=source, data=data)


# --------------------------------------------------------------------------- points
def _draw(rng, spec):
    if isinstance(spec, dict):
        lo, hi = spec["min"], spec["max"]
        if spec.get("log", False):
            return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))
        return float(rng.uniform(lo, hi))
    return spec[int(rng.integers(len(spec)))]


def _combinations(sweep: Sweep) -> list[dict]:
    names = (["masses"] if sweep.masses else []) + list(sweep.axes)
    values = ([list(sweep.masses)] if sweep.masses else []) + list(sweep.axes.values())
    if sweep.mode == "grid":
        import itertools
        return [dict(zip(names, combo)) for combo in itertools.product(*values)]
    rng = np.random.default_rng(sweep.sample_seed)
    return [{k: _draw(rng, v) for k, v in zip(names, values)} for _ in range(sweep.n_points)]


def _point_scene(sweep: Sweep, params: dict) -> dict:
    raw = json.loads(json.dumps(sweep.base))          # deep copy, TOML types only
    system = raw.setdefault("system", {})
    for key, val in params.items():
        if key in SYSTEM_AXES:
            system[SYSTEM_AXES[key]] = val
        elif "." in key:
            *path, leaf = key.split(".")
            node = raw
            for p in path:
                node = node.setdefault(p, {})
            node[leaf] = val
    if "masses" in params:
        env = {k: v for k, v in params.items() if k not in ("masses", "seed") and "." not in k}
        system["masses"] = [float(_eval(x, env)) if isinstance(x, str) else float(x)
                            for x in sweep.masses[params["masses"]]]
    raw.setdefault("initial", {})["seed"] = params["seed"]
    return raw


def _digest(obj) -> str:
    return hashlib.sha256(json.dumps(obj, sort_keys=True).encode()).hexdigest()[:12]


def sweep_points(sweep: Sweep) -> list[SweepPoint]:
    """Every point of the sweep, in a deterministic order (parameter combinations, then
    seeds), each with its validated scene.  Raises :class:`SweepError` naming the point."""
    points = []
    for combo in _combinations(sweep):
        for seed in sweep.seeds:
            params = dict(combo, seed=seed)
            index = len(points)
            raw = _point_scene(sweep, params)
            raw["name"] = f"{sweep.name}-{index:04d}"
            if sweep.description:
                raw.setdefault("description", sweep.description)
            desc = ", ".join(f"{k}={v}" for k, v in params.items())
            try:
                scene = parse_scene(raw, source=f"{sweep.source} point {index} ({desc})")
            except SceneError as exc:
                raise SweepError(str(exc)) from None
            d = scene_to_dict(scene)
            # the parameters are part of the identity: two families that meet (e.g. equal
            # masses in both) are two points, each with its own row
            pid = _digest([params, {k: v for k, v in d.items()
                                    if k not in ("name", "description")}])
            points.append(SweepPoint(index, params, raw, scene, pid))
    if not points:
        raise SweepError(f"{sweep.source}: the sweep has no points")
    return points


# --------------------------------------------------------------------------- statistics
def _stat_columns(scene: Scene) -> list[str]:
    eff, cols = scene.effects, []
    if "lyapunov" in eff:
        k = eff["lyapunov"]["n_exponents"]
        cols += [f"lambda_{i}" for i in range(1, k + 1)]
        cols += [f"lambda_{i}_se" for i in range(1, k + 1)]
    if "curvature" in eff:
        c = eff["curvature"]
        routes = ["numerical", "exact"] if c["route"] == "both" else [c["route"]]
        for r in routes:
            cols += [f"Kpos_{r}_{i}" for i in range(1, c["n_directions"] + 1)]
            cols += [f"Kpos_{r}_any"]
            cols += [f"Kmean_{r}_{i}" for i in range(1, c["n_directions"] + 1)]
    if "angles" in eff:
        v = eff["angles"]["variant"]
        for var in (["full", "restricted"] if v == "both" else [v]):
            cols += [f"phi_{var}_{s}" for s in ("min", "p001", "median", "frac_small")]
    return cols


def point_columns(points: list[SweepPoint]) -> list[str]:
    """Columns of the table: index, point_id, status, the parameters, the statistics
    (union over points, in first-seen order), then mass_vector, t_final, error, scene."""
    params, stats = [], []
    for p in points:
        params += [k for k in p.params if k not in params]
        stats += [c for c in _stat_columns(p.scene) if c not in stats]
    return HEAD + params + stats + TAIL


def _statistics(result: dict, arrays) -> dict:
    res, out = result.get("results", {}), {}
    ly = res.get("lyapunov", {})
    for i, (e, s) in enumerate(zip(ly.get("exponents", []),
                                   ly.get("stderr", [None] * len(ly.get("exponents", [])))), 1):
        out[f"lambda_{i}"], out[f"lambda_{i}_se"] = e, s
    cv = res.get("curvature", {})
    for route in ("numerical", "exact"):
        if route in cv:
            for i, (f, m) in enumerate(zip(cv[route]["fraction_positive"], cv[route]["mean"]), 1):
                out[f"Kpos_{route}_{i}"], out[f"Kmean_{route}_{i}"] = f, m
            K = arrays.get(f"curvature_{route}") if arrays is not None else None
            if K is not None and len(K):
                out[f"Kpos_{route}_any"] = float((K > 0).any(axis=1).mean())
    an = res.get("angles", {})
    for var in ("full", "restricted"):
        if var in an:
            for s in ("min", "p001", "median", "frac_small"):
                out[f"phi_{var}_{s}"] = an[var][s]
    return out


def evaluate_point(raw: dict) -> dict:
    """Run one point (on a Dask worker): the scene in a temporary folder, quietly.
    Returns {'status', 'error', 'stats', 'wall_s', 'worker', 't_final'}; never raises for
    a point that fails to integrate (status 'failed' with the message)."""
    from .runner import RunError, run_scene

    scene = parse_scene(raw, source=raw.get("name", "<point>"))
    t0 = time.perf_counter()
    status, error, arrays = "complete", "", None
    with tempfile.TemporaryDirectory(prefix="charts-sweep-") as td:
        try:
            result = run_scene(scene, td, quiet=True)
        except RunError as exc:
            status, error = "failed", str(exc).replace(td, "<point>")
            try:
                result = json.loads((Path(td) / "result.json").read_text())
            except (OSError, ValueError):
                result = {}
        if (Path(td) / "arrays.npz").exists():
            with np.load(Path(td) / "arrays.npz") as a:
                arrays = {k: a[k] for k in a.files if k.startswith("curvature_")}
    stats = _statistics(result, arrays)
    bad = sorted(k for k, v in stats.items() if v is not None and not math.isfinite(v))
    drift = result.get("drift", {})
    if status == "complete" and (bad or not all(math.isfinite(v) for v in drift.values())):
        # the runner's ambient kernel does not stop on a non-finite state (e.g. N = 4 close
        # to a singular point without projection): such a point failed
        status = "failed"
        error = (f"non-finite results ({', '.join(bad) or 'drift'}): the trajectory left the "
                 "manifold; set [scene.integrator] project = true or a smaller dt")
    return {"status": status, "error": error, "stats": stats,
            "t_final": result.get("progress", {}).get("t_done"),
            "wall_s": round(time.perf_counter() - t0, 3),
            "worker": f"{socket.gethostname()}:{os.getpid()}"}


# --------------------------------------------------------------------------- table
def _fmt(v) -> str:
    if v is None:
        return ""
    if isinstance(v, float):
        return repr(v)
    return str(v)


def _row(point: SweepPoint, out: dict, columns: list[str]) -> list[str]:
    vals = {"index": point.index, "point_id": point.point_id, "status": out["status"],
            **point.params, **out["stats"],
            "mass_vector": json.dumps(point.scene.system["masses"]),
            "t_final": out.get("t_final"), "error": out.get("error", ""),
            "scene": json.dumps(scene_to_dict(point.scene), sort_keys=True)}
    return [_fmt(vals.get(c)) for c in columns]


def _line(cells: list[str]) -> str:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(cells)
    return buf.getvalue()


def read_table(path) -> tuple[list[str], list[dict]]:
    """Header and rows (dicts of strings) of a sweep table; a trailing partial line (a
    sweep killed while writing) is ignored."""
    text = Path(path).read_text()
    if text and not text.endswith("\n"):
        text = text[: text.rfind("\n") + 1]
    reader = csv.reader(io.StringIO(text))
    rows = list(reader)
    if not rows:
        return [], []
    header = rows[0]
    return header, [dict(zip(header, r)) for r in rows[1:] if len(r) == len(header)]


def _atomic_text(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp{os.getpid()}")
    tmp.write_text(text)
    os.replace(tmp, path)


def _prepare_table(outdir: Path, columns, points, resume: bool, source: str) -> dict:
    """Create (or, with resume, check and repair) the table; return point_id -> row of the
    finished points."""
    table = outdir / TABLE
    if not table.exists() or table.stat().st_size == 0:
        _atomic_text(table, _line(columns))
        return {}
    header, rows = read_table(table)
    if not rows:                      # only a header (a sweep that never got a point in)
        _atomic_text(table, _line(columns))
        return {}
    if not resume:
        raise SweepError(f"{table} already holds a sweep ({len(rows)} points): continue it with "
                         "--resume, or choose another output folder")
    if header != columns:
        raise SweepError(f"{table} has different columns than {source} would write (the sweep "
                         "file changed its effects or parameters); use another output folder")
    ids = {p.point_id for p in points}
    foreign = [r["point_id"] for r in rows if r["point_id"] not in ids]
    if foreign:
        raise SweepError(f"{table} holds {len(foreign)} points that are not in {source} (the "
                         "sweep file changed); use another output folder")
    # drop a partial last line, keep one row per point
    done = {r["point_id"]: r for r in rows}
    text = table.read_text()
    if text and not text.endswith("\n"):
        _atomic_text(table, text[: text.rfind("\n") + 1])
    return done


class _Appender:
    """Append rows and log records as points finish (flush + fsync each)."""

    def __init__(self, outdir: Path):
        self.table = open(outdir / TABLE, "a", newline="")
        self.log = open(outdir / LOG, "a")

    def add(self, cells, record):
        for f, text in ((self.table, _line(cells)), (self.log, json.dumps(record) + "\n")):
            f.write(text)
            f.flush()
            os.fsync(f.fileno())

    def close(self):
        self.table.close()
        self.log.close()


# --------------------------------------------------------------------------- engine
def _client(scheduler, workers):
    """A Dask client: the cluster at ``scheduler``, or a LocalCluster of ``workers``
    single-threaded processes (default: every core)."""
    import logging

    from dask.distributed import Client, LocalCluster

    if scheduler:
        if workers:
            raise SweepError("--workers applies to the local cluster only; an existing cluster "
                             "(--scheduler) has its own workers")
        try:
            return Client(scheduler, timeout="20s"), None
        except (OSError, TimeoutError) as exc:
            raise SweepError(f"cannot reach the Dask scheduler at {scheduler!r}: {exc} (start "
                             "one with `dask scheduler`, workers with `dask worker ADDRESS`)") \
                from None
    n = int(workers or os.cpu_count() or 1)
    if n < 1:
        raise SweepError(f"--workers must be >= 1, got {n}")
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def run_sweep(sweep: Sweep, outdir, *, scheduler=None, workers=None, resume=False,
              quiet=False, plots=True, on_point=None) -> dict:
    """Evaluate every point of ``sweep`` on Dask into ``outdir`` (see the module note).

    Parameters
    ----------
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``); its workers must be
        able to import ``charts``.  Default: a LocalCluster.
    workers : int, optional
        Processes of the LocalCluster (default: every core).
    resume : bool
        Continue the table in ``outdir``: finished points are not recomputed.
    on_point : callable(done, total), optional
        Called after each row is written (tests raise KeyboardInterrupt from it).

    Returns
    -------
    dict with 'points', 'skipped' (finished before), 'computed', 'failed', 'lost' (worker
    errors, not in the table), 'run_id', 'table', 'summary', 'figures'.
    An interrupt leaves the table valid and re-raises ``KeyboardInterrupt``.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    points = sweep_points(sweep)
    columns = point_columns(points)
    done = _prepare_table(outdir, columns, points, resume, sweep.source)
    todo = [p for p in points if p.point_id not in done]
    run_id = uuid.uuid4().hex[:8]
    meta = {"name": sweep.name, "source": sweep.source, "sweep": sweep.data,
            "points": len(points), "columns": columns}
    _atomic_text(outdir / META, json.dumps(meta, indent=2, default=str) + "\n")
    info = {"points": len(points), "skipped": len(done), "computed": [], "failed": [],
            "lost": [], "run_id": run_id, "table": str(outdir / TABLE)}
    from ..geometry.kernels import chart_module
    from ..codegen.emit import SHIPPED_N
    for n in sorted({p.scene.system["n"] for p in todo} - set(SHIPPED_N)):
        chart_module(n)     # derive a non-shipped N once, here (cost on stderr): local
                            # workers then read it from the on-disk cache
    if todo:
        _compute(sweep, todo, len(points), len(done), columns, outdir, info, scheduler,
                 workers, quiet, on_point)
    header, rows = read_table(outdir / TABLE)
    if len(rows) == len(points) and len({r["point_id"] for r in rows}) == len(points):
        rows.sort(key=lambda r: int(r["index"]))
        _atomic_text(outdir / TABLE, _line(header) + "".join(_line([r[c] for c in header])
                                                            for r in rows))
        from .sweep_report import plot_sweep, summarize, write_summary
        summary = summarize(header, rows, points)
        write_summary(outdir / SUMMARY, summary)
        info["summary"] = str(outdir / SUMMARY)
        info["figures"] = plot_sweep(summary, outdir / "figures", sweep.name) if plots else []
    return info


def _compute(sweep, todo, total, n_done, columns, outdir, info, scheduler, workers, quiet,
             on_point):
    from dask.distributed import as_completed
    from tqdm.auto import tqdm

    client, cluster = _client(scheduler, workers)
    app = _Appender(outdir)
    bar = tqdm(total=total, initial=n_done, unit="pt", desc=sweep.name, disable=quiet)
    futures = {}
    try:
        if not quiet:
            nw = len(client.scheduler_info().get("workers", {}))
            where = scheduler or f"a local cluster of {nw} workers"
            bar.write(f"{sweep.name}: {total} points ({n_done} finished before, {len(todo)} to "
                      f"compute) on {where}")
        for p in todo:
            fut = client.submit(evaluate_point, p.raw, key=f"charts-sweep-{p.point_id}",
                                pure=False)
            futures[fut] = p
        for fut in as_completed(list(futures)):
            p = futures[fut]
            try:
                out = fut.result()
            except Exception as exc:        # the worker died or could not run it
                info["lost"].append((p.index, f"{type(exc).__name__}: {exc}"))
                bar.update(1)
                continue
            app.add(_row(p, out, columns),
                    {"run_id": info["run_id"], "index": p.index, "point_id": p.point_id,
                     "status": out["status"], "wall_s": out["wall_s"], "worker": out["worker"],
                     "finished": time.strftime("%Y-%m-%dT%H:%M:%S")})
            info["computed"].append(p.point_id)
            if out["status"] != "complete":
                info["failed"].append((p.index, out["error"]))
            bar.update(1)
            lead = out["stats"].get("lambda_1")
            bar.set_postfix_str(f"#{p.index}" + (f" λ1={lead:.3f}" if lead is not None else ""))
            if on_point is not None:
                on_point(n_done + len(info["computed"]), total)
    except BaseException:
        client.cancel(list(futures))
        raise
    finally:
        bar.close()
        app.close()
        client.close()
        if cluster is not None:
            cluster.close()


# --------------------------------------------------------------------------- command line
def bundled_sweeps() -> dict[str, Path]:
    """Name -> path of every sweep shipped in ``charts/sweeps``."""
    from importlib import resources
    folder = resources.files("charts.sweeps")
    return {p.name[:-5]: Path(str(p)) for p in sorted(folder.iterdir(), key=lambda p: p.name)
            if p.name.endswith(".toml")}


def _resolve(arg: str) -> Path:
    p = Path(arg)
    if p.exists() or p.suffix == ".toml":
        return p
    sweeps = bundled_sweeps()
    if arg in sweeps:
        return sweeps[arg]
    raise SweepError(f"{arg!r} is neither a sweep file nor a bundled sweep (list them with "
                     "`charts sweep --list`)")


def add_parser(sub) -> None:
    """Register ``charts sweep`` on the ``charts`` subparsers (called by charts.cli)."""
    p = sub.add_parser(
        "sweep", help="evaluate a grid or random sample of scenes on Dask into one table",
        description="Run a sweep file (TOML; a base scene plus the parameters to vary: masses, "
        "N, speed, seeds, any scene key) on a Dask cluster: a local one using every core by "
        "default, or an existing one with --scheduler. Each point's statistics are appended to "
        "DIR/sweep.csv as it finishes; Ctrl-C keeps them and --resume computes only the rest. "
        "At the end: DIR/summary.csv (mean over seeds) and DIR/figures/*.png. See docs/sweeps.md.")
    p.add_argument("sweep", metavar="SWEEP", nargs="?",
                   help="path to a sweep .toml, or a bundled sweep name (see --list)")
    p.add_argument("-o", "--output", type=Path, metavar="DIR", help="output folder")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="address of an existing Dask scheduler (e.g. tcp://host:8786)")
    p.add_argument("--workers", type=int, metavar="N",
                   help="worker processes of the local cluster (default: every core)")
    p.add_argument("--resume", action="store_true",
                   help="continue the table in DIR without recomputing finished points")
    p.add_argument("--no-plots", action="store_true", help="skip DIR/figures")
    p.add_argument("--list", action="store_true", help="list the bundled sweeps and exit")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")
    p.set_defaults(func=cli_main)


def cli_main(args) -> int:
    import sys

    def fail(msg, code=2):
        print(f"charts: error: {msg}", file=sys.stderr)
        return code

    if args.list:
        for name, path in bundled_sweeps().items():
            try:
                desc = load_sweep(path).description.strip().splitlines()[0]
            except (SweepError, IndexError):
                desc = ""
            print(f"{name}  {desc}")
        return 0
    if args.sweep is None or args.output is None:
        return fail("charts sweep needs SWEEP and -o DIR (see `charts sweep --help`)")
    try:
        path = _resolve(args.sweep)
        sweep = load_sweep(path)
        info = run_sweep(sweep, args.output, scheduler=args.scheduler, workers=args.workers,
                         resume=args.resume, quiet=args.quiet, plots=not args.no_plots)
    except SweepError as exc:
        return fail(str(exc))
    except KeyboardInterrupt:
        print(f"\ninterrupted: the finished points are in {args.output / TABLE}; continue "
              f"with:\n  charts sweep {args.sweep} -o {args.output} --resume", file=sys.stderr)
        return 130
    if not args.quiet:
        print(f"{sweep.name}: {info['points']} points, {info['skipped']} finished before, "
              f"{len(info['computed'])} computed now, {len(info['failed'])} failed -> "
              f"{info['table']}")
        for idx, err in info["failed"] + info["lost"]:
            print(f"  point {idx}: {err}")
        if "summary" in info:
            print(f"  summary: {info['summary']}; figures: {len(info.get('figures', []))} in "
                  f"{args.output / 'figures'}")
    return 1 if info["lost"] else 0
