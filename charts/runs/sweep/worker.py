"""What a Dask worker does for one point, or for the seeds of one point together: run the
scenes quietly in a temporary folder and return one row of statistics per point (a point
that fails to integrate is a row too)."""
from __future__ import annotations

import contextlib
import json
import math
import os
import socket
import tempfile
import time
from pathlib import Path

import numpy as np

from ...analyses.lyapunov_members import MIN_LANES
from .. import runner
from ..outdir import OutputError
from ..scene import parse_scene
from ..seed_lanes import lane_angles, lane_flows, run_seed_lanes, seed_family
from .statistics import result_statistics

__all__ = ["evaluate_point", "evaluate_points", "seeds_pay", "tiny_version", "prime_points"]

#: The simulated time of a point's tiny version (`tiny_version`): enough for one chunk of
#: every effect, a few hundred steps at the usual dt.
PRIME_T = 1.0


def evaluate_point(raw: dict, keep=None) -> dict:
    """Run one point (on a Dask worker) quietly, in the folder ``keep`` if given and
    writable (the sweep's ``points/<point id>``: its checkpoints survive an interrupted sweep,
    and a point found there half done is resumed, with the same numbers), else in a
    temporary folder.  Returns {'status', 'error', 'stats', 'wall_s', 'worker', 't_final',
    'resumed_from'} ('resumed_from': the simulated time and chunks of the checkpoint the
    point continued, None if it ran from the start); never raises for a point that fails to
    integrate (status 'failed' with the message).  A checkpoint there that cannot be
    trusted (empty, torn, inconsistent: `runner.CheckpointError`) is taken as torn: the
    point is computed again from the start, and 'notice' says so in one line (the sweep
    prints it and logs it)."""
    scene = parse_scene(raw, source=raw.get("name", "<point>"))
    t0 = time.perf_counter()
    folder = _kept_folder(keep)
    if folder is None:
        with tempfile.TemporaryDirectory(prefix="charts-sweep-") as td:
            return _point_outcome(_run(scene, td, False), Path(td), time.perf_counter() - t0)
    resume = (folder / runner.CHECKPOINT).exists()
    notices = []
    try:
        outcome = _run(scene, folder, resume, notices)
    except OutputError:
        # the folder is held by another live run of this point (Dask may run a task twice,
        # e.g. on a worker it took for lost): compute it here from the start instead
        with tempfile.TemporaryDirectory(prefix="charts-sweep-") as td:
            return _point_outcome(_run(scene, td, False), Path(td), time.perf_counter() - t0)
    out = _point_outcome(outcome, folder, time.perf_counter() - t0)
    if notices:
        out["notice"] = notices[0]
    return out


def _kept_folder(keep):
    """``keep`` as a created folder, or None (not given, or not writable on this worker)."""
    if keep is None:
        return None
    try:
        folder = Path(keep)
        folder.mkdir(parents=True, exist_ok=True)
        return folder
    except OSError:
        return None


def _run(scene, folder, resume, notices=None):
    """`runner.run_scene` into ``folder``: resumed from its checkpoint if ``resume`` (started
    over when that checkpoint belongs to another scene, or cannot be trusted: then with a
    line in ``notices``); the result dict, or the `RunError` of a run that failed."""
    try:
        if resume:
            try:
                return runner.run_scene(scene, folder, quiet=True, resume=True)
            except OutputError:                             # held by a live run: the caller's
                raise
            except (runner.CheckpointError, OSError, ValueError, KeyError) as exc:   # torn
                text = str(exc).removeprefix("--resume: ").split("; its run cannot")[0]
                if notices is not None:
                    notices.append(f"charts: {text}; computing the point again")
            except runner.RunError as exc:
                if "--resume" not in str(exc):
                    raise
            return runner.run_scene(scene, folder, quiet=True, force=True)
        return runner.run_scene(scene, folder, quiet=True)
    except runner.RunError as exc:
        return exc


def evaluate_points(raws: list, keep=None, device="cpu", lanes=None) -> list:
    """`evaluate_point` of each of ``raws`` (in the folders ``keep``, one per point, if
    given); points of one seed family
    (``charts.runs.seed_lanes``), at least `MIN_LANES` of them, run together in the lanes of
    one kernel where the lanes pay (``lanes``: None asks `seeds_pay`; the same rows, bit for
    bit; each point's wall time is the block's share), or
    with ``device="cuda"`` in one GPU thread each (``charts.runs.seed_lanes.lane_flows``; their
    angle tests too, `lane_angles`).

    The points run with Dask's synchronous scheduler: a point never talks to the cluster
    it runs on."""
    with _own_scheduler():
        return _evaluate_points(raws, keep, device, lanes)


def _own_scheduler():
    """Dask's synchronous scheduler for what runs inside (a no-op where Dask is not
    installed).  Without it, asking Dask for a scheduler on a worker -- xarray does, to write
    a point's NetCDF file -- connects a new client of the worker to the scheduler; when the
    cluster then shuts down under that client (an interrupted sweep), the client's
    finalizer finds its event loop closed and prints ``Exception ignored in: <function
    Client.__del__ ...> RuntimeError: IOLoop is closed`` from the worker process."""
    try:
        import dask
    except ImportError:
        return contextlib.nullcontext()
    return dask.config.set(scheduler="synchronous")


def _evaluate_points(raws: list, keep=None, device="cpu", lanes=None) -> list:
    scenes = [parse_scene(raw, source=raw.get("name", "<point>")) for raw in raws]
    families = {seed_family(sc) for sc in scenes}
    if (len(scenes) < MIN_LANES or None in families or len(families) != 1
            or not (seeds_pay(scenes[0], len(scenes), device) if lanes is None else lanes)):
        keep = keep if keep is not None else [None] * len(raws)
        return [evaluate_point(raw, k) for raw, k in zip(raws, keep)]
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="charts-sweep-") as td:
        dirs = [Path(td) / f"point-{i}" for i in range(len(scenes))]
        outcomes = run_seed_lanes(scenes, dirs, lane_flows(device), lane_angles(device))
        share = (time.perf_counter() - t0) / len(scenes)
        return [_point_outcome(o, d, share) for o, d in zip(outcomes, dirs)]


def tiny_version(raw: dict):
    """The point ``raw`` (a scene's dict) run for `PRIME_T` after a transient of half that
    (a run with a transient calls kernels one without does not): the same kernels (N,
    integrator, effects), compiled by a run of a second or less; None where that is not a
    valid scene (then nothing is primed for it)."""
    tiny = dict(raw, run=dict(raw.get("run", {}), t_final=PRIME_T, t_transient=PRIME_T / 2))
    tiny["run"].pop("checkpoint_every", None)
    try:
        parse_scene(tiny, source=raw.get("name", "<point>"))
    except Exception:                   # any rule of a scene the tiny run breaks
        return None
    return tiny


def prime_points(raws: list, device="cpu", lanes=None) -> float:
    """Run the tiny versions ``raws`` (`tiny_version`) as `evaluate_points` would run the
    points (on a Dask worker, before the points): the seconds numba spent compiling in
    them (its compile events: wall time; 0 when every kernel came from the cache)."""
    from ...jit.compilation import timed_call

    return timed_call(evaluate_points, raws, None, device, lanes)[1]


def seeds_pay(scene, lanes, device="cpu", runs=None) -> bool:
    """Whether ``lanes`` seeds of ``scene`` (one `seed_family`; ``runs`` of them in all that
    share one compilation: default ``lanes``) run their main passes together: on a GPU
    always, on the CPU where the lanes pay (``charts.solvers.lanes.lanes_pay`` with their N,
    tangent vectors and steps of transient and run), else each point alone (the same
    rows)."""
    from ...solvers.device import resolve_device
    from ...solvers.lanes import lanes_pay
    from ..plan import plan_scene, ticks

    if resolve_device(device) == "cuda":
        return True
    dt = scene.integrator["dt"]
    steps = ticks(scene.run["t_transient"], dt) + ticks(scene.run["t_final"], dt)
    return lanes_pay(scene.system["n"], plan_scene(scene).tangent_vectors, lanes, steps, runs)


def _point_outcome(outcome, folder: Path, wall_s: float) -> dict:
    """The row data of a point from its run's result dict or `RunError` ``outcome`` and its
    output folder (the scene's arrays); a point with non-finite results failed."""
    status, error, arrays = "complete", "", None
    result = outcome
    if isinstance(outcome, runner.RunError):
        status, error = "failed", str(outcome).replace(str(folder), "<point>")
        try:
            result = json.loads((folder / "result.json").read_text())
        except (OSError, ValueError):
            result = {}
    if (folder / "arrays.npz").exists():
        with np.load(folder / "arrays.npz") as a:
            arrays = {k: a[k] for k in a.files if k.startswith("curvature_")}
    stats = result_statistics(result, arrays)
    bad = sorted(k for k, v in stats.items() if v is not None and not math.isfinite(v))
    drift = result.get("drift", {})
    if status == "complete" and (bad or not all(math.isfinite(v) for v in drift.values())):
        # the runner's ambient kernel does not stop on a non-finite state (e.g. N = 4 close
        # to a singular point without projection): such a point failed
        status = "failed"
        error = (f"non-finite results ({', '.join(bad) or 'drift'}): the trajectory left the "
                 "manifold; set [scene.integrator] project = true or a smaller dt")
    progress = result.get("progress", {})
    return {"status": status, "error": error, "stats": stats,
            "t_final": progress.get("t_done"), "resumed_from": progress.get("resumed_from"),
            "wall_s": round(wall_s, 3),
            "compile_s": round(result.get("timings", {}).get("compile_wall_s", 0.0), 3),
            "worker": f"{socket.gethostname()}:{os.getpid()}"}
