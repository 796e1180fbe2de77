"""Scenes that differ only in their seed, run together: the main pass of every scene in the
vector lanes of one kernel (``charts.solvers.lanes``), then each scene's separate passes
(angle test, covariant vectors) and outputs as `run_scene` writes them.

Each lane does the operations of the one-trajectory kernel in the same order, and every scene
stops, records and checkpoints where `run_scene` would, so each result equals that scene's
own `run_scene` bit for bit (tests/test_seed_lanes.py); a scene whose lane stops (a singular
point, a non-finite state) fails as it would alone, the others go on.  Sweeps
(``charts.runs.sweep``) run the seeds of one parameter point this way.
"""
from __future__ import annotations

import json
import time
from contextlib import ExitStack

from ..jit.compilation import compile_timer
from ..solvers.lanes import LaneFlows
from ..solvers.status import RUNNING
from .engines import KERNEL_ROUTE, count_kernel_steps, kernel_failure, record_interval, recording_stops
from .outdir import OutputLock, prepare_output
from .run_state import RunError
from .runner import QUIET_BAR, SceneRun
from .scene import Scene, scene_to_dict
from .scene_kind import scene_kind

__all__ = ["seed_family", "run_seed_lanes", "lane_flows", "lane_angles"]


def seed_family(scene: Scene):
    """The key of the scenes that can share lanes with ``scene`` (equal keys: the same scene
    but for name, description and seed), or None if its main pass cannot run in lanes (not
    the kernel engine, a linkage, or an initial state given in full)."""
    from .plan import plan_scene

    if not scene_kind(scene).lanes or scene.initial["theta"] is not None:
        return None
    if plan_scene(scene).engine != "kernel":
        return None
    d = scene_to_dict(scene)
    d = {k: v for k, v in d.items() if k not in ("name", "description")}
    d["initial"] = {k: v for k, v in d["initial"].items() if k != "seed"}
    return json.dumps(d, sort_keys=True, default=str)


def lane_flows(device: str = "cpu"):
    """What advances the seeds' flows together: ``"cpu"`` the vector lanes of one kernel
    (``charts.solvers.lanes.LaneFlows``), ``"cuda"`` one GPU thread per seed
    (``charts.solvers.device.DeviceFlows``; `DeviceUnavailable` without a GPU or without the
    extra ``charts[gpu]``), ``"auto"`` the GPU when there is one."""
    from ..solvers.device import DeviceFlows, resolve_device

    if resolve_device(device) == "cuda":
        return lambda flows: DeviceFlows.of_flows(flows, backend="cuda")
    return LaneFlows


def lane_angles(device: str = "cpu"):
    """What runs the angle test of a point's seeds together: None on the CPU (each run's
    own pass, `hyperbolicity_angles`), with ``"cuda"`` one GPU thread per seed
    (``charts.analyses.hyperbolicity.angle_members``), ``"auto"`` the GPU when there is
    one."""
    from ..solvers.device import resolve_device

    if resolve_device(device) == "cuda":
        from ..analyses.hyperbolicity import angle_members
        return lambda system, cfg, seeds, speed: angle_members(system, cfg, seeds, speed,
                                                               backend="cuda")
    return None


def run_seed_lanes(scenes, outdirs, flows=LaneFlows, angles=None) -> list:
    """Run ``scenes`` (one `seed_family`) into ``outdirs`` (one each, checked and locked as
    `run_scene` does), quietly, their main passes advanced together by ``flows`` (a function
    of the scenes' `TangentFlow` s, `lane_flows`), their angle tests by ``angles`` where
    given (`lane_angles`: (system, settings, seeds, speed) → [`AngleResult`]).  Returns, per
    scene, its result dict or the `RunError` that `run_scene` would have raised for it (its
    finished part written)."""
    scenes = list(scenes)
    keys = {seed_family(sc) for sc in scenes}
    if not scenes or None in keys or len(keys) != 1:
        raise ValueError("run_seed_lanes takes scenes that differ only in their seed, whose "
                         "main pass is the ambient kernel (seed_family)")
    dirs = [prepare_output(d) for d in outdirs]
    with ExitStack() as stack:
        for sc, d in zip(scenes, dirs):
            stack.enter_context(OutputLock(d, f"charts run {sc.name}"))
        runs = [SceneRun(sc, d, resume=False) for sc, d in zip(scenes, dirs)]
        outcome = [("complete", None)] * len(runs)

        def add_compile_time(seconds):
            for r in runs:
                r.st.add_compile_time(seconds)

        with compile_timer(add_compile_time):
            live = _main_pass(runs, outcome, flows)
            if angles is not None and "angles" in scenes[0].effects and live:
                _angle_pass(runs, live, outcome, angles)
            for i in live:
                try:
                    runs[i].run_chunks(None, QUIET_BAR)
                except RunError as exc:
                    outcome[i] = runs[i].stop(exc)
        results = []
        for r, (status, failure) in zip(runs, outcome):
            try:
                results.append(r.finish(status, failure))
            except RunError as exc:
                results.append(exc)
        return results


def _angle_pass(runs, live, outcome, angles) -> None:
    """The angle test of the running seeds together (``angles``), each result left in its
    run's state for its own angle pass to record; where it fails, every such run stops with
    the error, as its own pass would have."""
    from ..analyses.forward_pass import angle_settings
    from .rotor_run import angle_settings_of

    lead = runs[live[0]].st
    kw = angle_settings_of(lead)
    seeds = [runs[i].st.scene.initial["seed"] or 0 for i in live]
    try:
        cfg = angle_settings(lead.system, lead.scene.run["t_final"], **kw)
        results = angles(lead.system, cfg, seeds, lead.scene.system["speed"])
    except (ValueError, RuntimeError) as exc:
        for i in list(live):
            outcome[i] = runs[i].stop(RunError(f"the angle test of the point's seeds: {exc}"))
            live.remove(i)
        return
    for i, res in zip(live, results):
        runs[i].st.angles_result = res


def _main_pass(runs, outcome, flows) -> list[int]:
    """Every main chunk of every run in one ``flows`` (`LaneFlows` or the GPU's
    ``DeviceFlows``, the same interface): the lanes advance to each recording stop, then each
    running lane's state goes back into its run's flow for its recorders, the end of chunk
    bookkeeping and its checkpoint.  Returns the runs still running."""
    lanes = flows([r.st.flow for r in runs])
    lead = runs[0]
    unit = record_interval(lead.plan) or None
    live = list(range(len(runs)))
    for idx in range(lead.n_main):
        t_wall = time.perf_counter()
        start, end = lead.chunk_start(idx), lead.ends[idx]
        pos = start
        for stop in recording_stops(start, end, unit if lead.recorders_of(idx) else None,
                                    lead.transient):
            lanes.advance(stop - pos)
            for i in list(live):
                st = runs[i].st
                if lanes.status[i] != RUNNING:
                    outcome[i] = runs[i].stop(kernel_failure(lanes.error(i, KERNEL_ROUTE)))
                    live.remove(i)
                    continue
                count_kernel_steps(st, stop - pos)
                lanes.store(i, st.flow)
                for rec in runs[i].recorders_of(idx):
                    rec(stop)
            pos = stop
        wall = (time.perf_counter() - t_wall) / max(len(live), 1)
        for i in live:
            runs[i].end_main_chunk(idx)
            lanes.logsum[i] = runs[i].st.logsum     # zeroed at the end of the transient,
            lanes.shares[i] = runs[i].st.flow.shares  # as are the shares
            runs[i].checkpoint(idx, wall)
    return live
