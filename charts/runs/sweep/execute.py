"""Running a sweep: the points on a Dask cluster (local or existing), each row appended as
its point finishes, a progress bar, and at the end the table in point order, the summary
and the figures."""
from __future__ import annotations

import json
import logging
import os
import shutil
import sys
import time
import uuid

from ...analyses.cluster import SCHEDULER_TIMEOUT_S
from ...analyses.cluster import check_scheduler_address as cluster_address
from ...analyses.cluster import dask_client as cluster_client
from ...analyses.arguments import MAX_WORKERS, flag
from ...geometry.checks import callback, instance, integer, shown
from ...io.result_words import counted
from ..io import atomic_text
from ..outdir import OutputLock, prepare_output
from ..scene import scene_to_dict
from .points import digest, sweep_points
from .report import SUMMARY, plot_sweep, summarize, write_summary
from .spec import Sweep, SweepError
from .table import (TABLE, TableAppender, finish_table, point_columns, point_row,
                    prepare_table)
from ...analyses.lyapunov_members import LANE_BLOCK, MIN_LANES
from ..seed_lanes import seed_family
from .worker import evaluate_points, seeds_pay

__all__ = ["run_sweep", "dask_client", "same_scene_groups", "lane_blocks",
           "check_scheduler_address", "META", "POINTS", "SCHEDULER_TIMEOUT_S"]

META = "sweep.json"
#: Folder of the points in progress (one per point computed alone: its run's checkpoints),
#: each removed once its row is written, the folder once the table is complete.
POINTS = "points"


def check_scheduler_address(scheduler) -> str:
    """``scheduler`` if it is a well-formed Dask address (``tcp://host:port``, ``host:port``);
    :class:`SweepError` naming it otherwise.  Called before any work
    (``charts.analyses.cluster.check_scheduler_address``)."""
    return cluster_address(scheduler, SweepError)


def run_sweep(sweep: Sweep, outdir, *, scheduler=None, workers=None, resume=False,
              quiet=False, plots=True, on_point=None, device="cpu") -> dict:
    """Evaluate every point of ``sweep`` on Dask into ``outdir`` (see
    :mod:`charts.runs.sweep`).

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
    device : {"cpu", "cuda", "auto"}
        Where the seeds of a point advance together (``charts.runs.seed_lanes.lane_flows``):
        the CPU's vector lanes, or one GPU thread per seed ("auto": the GPU when there is
        one).  Checked here for a local cluster (``SweepError`` naming what is missing);
        the rows are the same up to the GPU's rounding (docs/gpu.md).

    Returns
    -------
    dict with 'points', 'skipped' (finished before), 'computed', 'failed', 'lost' (worker
    errors, not in the table), 'run_id', 'table', 'summary', 'figures'.
    An interrupt leaves the table valid and re-raises ``KeyboardInterrupt``.  ``outdir`` is
    checked before any work and locked while the sweep writes into it (a second sweep or run
    into it refuses, :mod:`charts.runs.outdir`).
    """
    instance("sweep", sweep, Sweep, "charts.Sweep (load_sweep, parse_sweep)")
    resume, quiet, plots = flag("resume", resume), flag("quiet", quiet), flag("plots", plots)
    callback("on_point", on_point)
    if scheduler is not None and not isinstance(scheduler, str):
        raise ValueError(f"scheduler must be a Dask scheduler address (a str) or None, got "
                         f"{shown(scheduler)}")
    if scheduler:
        check_scheduler_address(scheduler)
    if workers is not None:
        integer("workers", workers, 1, MAX_WORKERS)
    device = _sweep_device(device, scheduler)
    points = sweep_points(sweep)          # every point's scene validated before any file
    outdir = prepare_output(outdir, "outdir")
    with OutputLock(outdir, f"charts sweep {sweep.name}"):
        return _run_locked(sweep, points, outdir, scheduler, workers, resume, quiet, plots,
                           on_point, device)


def _sweep_device(device, scheduler) -> str:
    """``device`` checked: "cpu" or "cuda" ("auto" resolved here for a local cluster; with
    ``scheduler`` the workers' machines decide, so "auto" and "cuda" are passed on)."""
    from ...solvers.device import DeviceUnavailable, resolve_device

    if not isinstance(device, str) or device not in ("cpu", "cuda", "auto"):
        raise SweepError(f"--device must be cpu, cuda or auto, got {shown(device)}")
    if scheduler:
        return device
    try:
        return resolve_device(device)
    except DeviceUnavailable as exc:
        raise SweepError(str(exc).replace("device='cuda'", "--device cuda")
                         .replace("device='cpu' (or 'auto')", "--device cpu (or auto)")) from None


def _run_locked(sweep, points, outdir, scheduler, workers, resume, quiet, plots,
                on_point, device) -> dict:
    columns = point_columns(points)
    done = prepare_table(outdir, columns, points, resume, sweep.source)
    todo = [p for p in points if p.point_id not in done]
    run_id = uuid.uuid4().hex[:8]
    meta = {"name": sweep.name, "source": sweep.source, "sweep": sweep.data,
            "points": len(points), "columns": columns}
    atomic_text(outdir / META, json.dumps(meta, indent=2, default=str) + "\n")
    info = {"points": len(points), "skipped": len(done), "computed": [], "failed": [],
            "lost": [], "run_id": run_id, "table": str(outdir / TABLE)}
    if todo:
        _compute(sweep, todo, len(points), len(done), columns, outdir, info, scheduler,
                 workers, quiet, on_point, device)
    table = finish_table(outdir / TABLE, len(points))
    if table is not None:           # every row written: no point in progress is left
        shutil.rmtree(outdir / POINTS, ignore_errors=True)
        summary = summarize(*table, points)
        write_summary(outdir / SUMMARY, summary)
        info["summary"] = str(outdir / SUMMARY)
        info["figures"] = plot_sweep(summary, outdir / "figures", sweep.name) if plots else []
    return info


def same_scene_groups(points) -> list[list]:
    """The points grouped by identical scene (everything but name and description; the
    seed is part of the scene), in first-seen order: two families that meet (e.g. equal
    masses in both) keep a row each but are computed once."""
    groups = {}
    for p in points:
        d = scene_to_dict(p.scene)
        key = digest({k: v for k, v in d.items() if k not in ("name", "description")})
        groups.setdefault(key, []).append(p)
    return list(groups.values())


def dask_client(scheduler, workers):
    """``(client, cluster)``: a client of the cluster at ``scheduler`` (cluster None), or of
    a new LocalCluster of ``workers`` single-threaded processes (default: every core); what
    goes wrong is a :class:`SweepError` (``charts.analyses.cluster.dask_client``, shared
    with the ensembles' and the angle tally's ``client=``)."""
    return cluster_client(scheduler, workers, SweepError)


def _silence_dask_logs():
    """Only critical reports from Dask's loggers in this process from now on: its own
    configuration gives some of them (e.g. ``distributed.client``) levels of their own, so
    the parent ``distributed`` alone does not reach them."""
    names = [n for n in list(logging.root.manager.loggerDict) if n.split(".")[0] in
             ("distributed", "tornado", "asyncio")]
    for name in ["distributed", *names]:
        logging.getLogger(name).setLevel(logging.CRITICAL)


def _compute(sweep, todo, total, n_done, columns, outdir, info, scheduler, workers, quiet,
             on_point, device):
    """Submit ``todo`` and write each row as its point finishes (with a progress bar)."""
    from dask.distributed import as_completed
    from tqdm.auto import tqdm

    groups = same_scene_groups(todo)
    if scheduler is None:       # a local cluster: never more processes than point groups
        workers = min(workers or os.cpu_count() or 1, max(1, len(groups)))
    client, cluster = dask_client(scheduler, workers)
    app = TableAppender(outdir)
    futures, bar = {}, None
    try:
        nw = len(client.scheduler_info().get("workers", {}))
        if not quiet:               # said (and flushed) before the bar draws its first line
            where = scheduler or f"a local cluster of {counted(nw, 'worker')}"
            print(f"{sweep.name}: {counted(total, 'point')} ({n_done} finished before, "
                  f"{len(todo)} to compute) on {where}", flush=True)
        # identical scenes are computed once; the seeds of a point together, in lanes
        blocks = lane_blocks(groups, max(nw, 1), device)
        _compile_first(client, blocks, device, quiet, sweep.name, nw)
        bar = tqdm(total=total, initial=n_done, unit="pt", desc=sweep.name, disable=quiet)
        for block in blocks:
            # a point computed alone keeps its checkpoints in points/<id> until its row is
            # written, so that a resumed sweep continues a long point where it stopped
            keep = [str(outdir / POINTS / g[0].point_id) for g in block] if len(block) == 1 \
                else None
            fut = client.submit(evaluate_points, [group[0].raw for group in block], keep,
                                device, len(block) >= MIN_LANES,
                                key=f"charts-sweep-{block[0][0].point_id}", pure=False)
            futures[fut] = block
        for fut in as_completed(list(futures)):
            block = futures[fut]
            try:
                outs = fut.result()
            except Exception as exc:        # the worker died or could not run it
                info["lost"] += [(p.index, f"{type(exc).__name__}: {exc}")
                                 for group in block for p in group]
                bar.update(sum(len(group) for group in block))
                continue
            for group, out in zip(block, outs):
                _add_rows(group, out, columns, app, info, bar, on_point, n_done, total)
                shutil.rmtree(outdir / POINTS / group[0].point_id, ignore_errors=True)
            lead = outs[-1]["stats"].get("lambda_1")
            bar.set_postfix_str(f"#{block[-1][0].index}"
                                + (f" λ1={lead:.3f}" if lead is not None else ""))
    except BaseException as exc:
        if isinstance(exc, KeyboardInterrupt):
            # the teardown of an interrupted client logs its cancelled tasks' errors with
            # tracebacks; the user is told what was kept and how to resume instead
            _silence_dask_logs()
        client.cancel(list(futures))
        raise
    finally:
        if bar is not None:
            bar.close()
        app.close()
        client.close()
        if cluster is not None:
            cluster.close()


def _compile_first(client, blocks, device, quiet, name, nw):
    """The kernels of the points compiled before them, each kind by one worker: a tiny
    version (``charts.runs.sweep.worker.tiny_version``) of the first block of each kind (N,
    integrator, effects, lanes), instead of every worker compiling the same kernels on its
    first point at once; with the cache filled, the workers load them here (what the points
    would do anyway).  A line on stderr while it takes long (`compiling_line`), a notice
    with its wall time after (like ``charts reproduce``'s).  Workers on other machines than
    the primed ones compile on their first points."""
    from contextlib import nullcontext

    from ...jit.compilation import NOTE_SECONDS, compiling_line
    from .worker import prime_points, tiny_version

    kinds = {}
    for block in blocks:
        raws = [tiny_version(group[0].raw) for group in block]
        if None in raws:
            continue
        lanes = len(block) >= MIN_LANES
        first = raws[0]
        key = json.dumps([first["system"].get("n"), first.get("integrator"), first.get("effects"),
                          len(block) if lanes else 0, first["system"].get("kind")],
                         sort_keys=True, default=str)
        kinds.setdefault(key, (raws, lanes))
    if not kinds:
        return
    where = f" in {counted(nw, 'Dask worker')}"
    start = time.perf_counter()
    try:
        with nullcontext() if quiet else compiling_line(f"sweep {name}",
                                                        where + ", before the points"):
            futures = [client.submit(prime_points, raws, device, lanes, pure=False,
                                     key=f"charts-sweep-prime-{uuid.uuid4().hex[:8]}")
                       for raws, lanes in kinds.values()]
            spent = client.gather(futures)
    except Exception:           # a worker lost: the points compile (and report) on their own
        return
    wall = time.perf_counter() - start
    if not quiet and max(spent) > NOTE_SECONDS:
        print(f"charts: sweep {name} compiled its kernels{where} in {wall:.1f} s of wall time "
              f"({sum(spent):.1f} s: each worker's compiling wall time, summed; once: they are "
              "cached on disk for the next runs)", file=sys.stderr, flush=True)


def _add_rows(group, out, columns, app, info, bar, on_point, n_done, total):
    """The rows of ``group`` (points of one scene) from its outcome ``out``; the log's
    record of a point that continued the checkpoint of an interrupted sweep says from where
    (``resumed_from``: simulated time and chunks done then); a point whose checkpoint could
    not be trusted and was computed again says so on stderr, quiet or not, and in the log
    (``notice``)."""
    if out.get("notice"):
        bar.write(out["notice"], file=sys.stderr)
    for p in group:
        app.add(point_row(p, out, columns),
                {"run_id": info["run_id"], "index": p.index, "point_id": p.point_id,
                 "status": out["status"], "wall_s": out["wall_s"],
                 "compile_s": out.get("compile_s"),
                 "worker": out["worker"], "finished": time.strftime("%Y-%m-%dT%H:%M:%S"),
                 **({"resumed_from": out["resumed_from"]} if out.get("resumed_from") else {}),
                 **({"notice": out["notice"]} if out.get("notice") else {}),
                 **({"same_scene_as": group[0].index} if p is not group[0] else {})})
        info["computed"].append(p.point_id)
        if out["status"] != "complete":
            info["failed"].append((p.index, out["error"]))
        bar.update(1)
        if on_point is not None:
            on_point(n_done + len(info["computed"]), total)


def lane_blocks(groups, n_workers: int, device="cpu") -> list[list]:
    """The groups of identical points (`same_scene_groups`) cut into the blocks one task
    computes: the groups of one seed family (``charts.runs.seed_lanes.seed_family``) share a
    lane kernel where the lanes pay (``charts.runs.sweep.worker.seeds_pay``, the family's
    seeds counted in all), in blocks of `MIN_LANES` to `LANE_BLOCK` (as many as give the
    ``n_workers`` work where the family is large enough); every other group is a block of its
    own."""
    families = {}
    for group in groups:
        key = seed_family(group[0].scene)
        families.setdefault(key if key is not None else id(group), []).append(group)
    total = len(groups)
    blocks = []
    for fam in families.values():
        g = len(fam)
        if g < MIN_LANES:
            blocks += [[group] for group in fam]
            continue
        share = -(-n_workers * g // total)          # this family's part of the workers
        nb = max(-(-g // LANE_BLOCK), min(share, g // MIN_LANES))
        cut = [g * b // nb for b in range(nb + 1)]
        lanes = max(b - a for a, b in zip(cut, cut[1:]))
        per_worker = -(-g // min(nb, n_workers))    # seeds of one worker's compilation
        if not seeds_pay(fam[0][0].scene, lanes, device, runs=per_worker):
            blocks += [[group] for group in fam]
            continue
        blocks += [fam[a:b] for a, b in zip(cut, cut[1:])]
    return blocks
