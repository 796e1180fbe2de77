"""Sweeps: validation of sweep files, the points and their scenes, and a
sweep on a local Dask cluster (2 workers) that is killed midway (SIGKILL to the whole
process group), resumed without recomputing finished points, and ends with the same table
as an uninterrupted run on an existing cluster (``--scheduler``)."""
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from process_events import read_until
from charts.runs.sweep.execute import POINTS
from charts.runs.sweep import (LOG, SUMMARY, TABLE, SweepError, load_sweep, parse_sweep,
                          point_columns, read_table, run_sweep, sweep_points)

BASE = {"system": {"n": 4}, "integrator": {"dt": 0.01}, "run": {"t_final": 30.0, "t_transient": 5.0},
        "effects": {"lyapunov": {"n_batches": 3}, "curvature": {"route": "exact"},
                    "angles": {"variant": "both"}}}
SMALL = """\
name = "tiny"
description = "four masses x two seeds, N = 4, short runs"
[scene.integrator]
dt = 0.01
[scene.run]
t_final = 30.0
t_transient = 5.0
[scene.effects.lyapunov]
n_batches = 3
[scene.effects.curvature]
route = "exact"
[scene.effects.angles]
variant = "both"
[sweep]
seeds = [1, 2]
[sweep.parameters]
n = [4]
m = [0.5, 1.0, 2.0, 4.0]
[sweep.masses]
"1,1,1,m" = [1, 1, 1, "m"]
"""
#: a polling guard only (the test fails instead of hanging if the sweep never writes)
WAIT_S = 600


def _sweep(**over):
    data = {"name": "t", "scene": BASE, "sweep": {"seeds": [1], "parameters": {"m": [0.5, 2.0]},
                                                   "masses": {"p": [1, 1, "m", 1]}}}
    data["sweep"].update(over)
    return parse_sweep(data, source="t.toml")


@pytest.mark.parametrize("change, message", [
    ({"seed": [1]}, "unknown key 'seed' in [sweep] — did you mean 'seeds'?"),
    ({"parameters": {"m": [0.5], "k": [1.0]}}, "k is not used"),
    ({"parameters": {"m": {"min": 0.25, "max": 4.0}}}, "needs mode = \"random\""),
    ({"masses": {"p": [1, 1, "m", "q"]}}, "uses q, which is not a parameter"),
    ({"masses": {"p": [1, 1, "m", "import os"]}}, "is not an arithmetic expression"),
    ({"mode": "latin"}, "mode = 'latin' is not allowed"),
    ({"seeds": [1, 1]}, "repeats a seed"),
    ({"seeds": 10**9}, "seeds = 1000000000 is more than the 100000 points"),
    ({"seeds": 5000, "parameters": {"m": [float(i + 1) for i in range(30)]}},
     "the sweep has 150000 points = 1 ([sweep.masses]) × 30 (m) × 5000 (seeds), more than"),
    ({"mode": "random", "n_points": 10**12, "parameters": {"m": {"min": 0.5, "max": 2.0}}},
     "1000000000000 points = 1 ([sweep.masses]) × 1000000000000 (n_points) × 1 (seeds)"),
    ({"mode": "random", "n_points": 10**400, "parameters": {"m": {"min": 0.5, "max": 2.0}}},
     "1.00e+400 points = 1 ([sweep.masses]) × 1.00e+400 (n_points) × 1 (seeds), more than"),
    ({"parameters": {"m": [float(i + 1) for i in range(200_000)]}},
     "the sweep has 200000 points = 1 ([sweep.masses]) × 200000 (m) × 1 (seeds), more than"),
])
def test_malformed_sweeps_are_named(change, message):
    with pytest.raises(SweepError) as exc:
        _sweep(**change)
    assert message in str(exc.value) and len(str(exc.value)) < 400     # values shown in brief


def test_each_point_scene_is_validated_before_running():
    sw = _sweep(masses={"p": [1, 1, "m"]})           # three masses for N = 4
    with pytest.raises(SweepError, match=r"point 0 \(masses=p, m=0.5, seed=1\): \[system\] "
                                         r"masses = \[1.0, 1.0, 0.5\] is not allowed"):
        sweep_points(sw)


def test_grid_and_random_points():
    sw = _sweep(seeds=[3, 4], parameters={"m": [0.5, 2.0], "run.t_final": [10.0, 20.0]},
                masses={"p": [1, 1, "m", 1], "q": [1, "m", 1, "1/m"]})
    pts = sweep_points(sw)
    assert len(pts) == 2 * 2 * 2 * 2
    p = pts[-1]
    assert p.params == {"masses": "q", "m": 2.0, "run.t_final": 20.0, "seed": 4}
    assert p.scene.system["masses"] == [1.0, 2.0, 1.0, 0.5]
    assert p.scene.run["t_final"] == 20.0 and p.scene.initial["seed"] == 4
    assert len({q.point_id for q in pts}) == len(pts)
    assert point_columns(pts)[:8] == ["index", "point_id", "status", "masses", "m",
                                      "run.t_final", "seed", "lambda_1"]
    # random sample: reproducible, inside the ranges, log-uniform when asked
    data = {"name": "r", "scene": BASE,
            "sweep": {"mode": "random", "n_points": 50, "sample_seed": 9,
                      "parameters": {"m": {"min": 0.25, "max": 4.0, "log": True},
                                     "speed": [0.5, 2.0]},
                      "masses": {"p": [1, "m", 1, "m"]}}}
    a, b = sweep_points(parse_sweep(data)), sweep_points(parse_sweep(data))
    assert [x.params for x in a] == [x.params for x in b]
    ms = [x.params["m"] for x in a]
    assert min(ms) >= 0.25 and max(ms) <= 4.0
    assert sum(m < 1.0 for m in ms) > 10 and sum(m > 1.0 for m in ms) > 10   # log-uniform
    assert {x.params["speed"] for x in a} == {0.5, 2.0}


def test_bundled_sweeps_validate():
    from charts.runs.sweep import bundled_sweeps
    sweeps = bundled_sweeps()
    assert "masses-n4" in sweeps
    for path in sweeps.values():
        assert len(sweep_points(load_sweep(path))) > 0


def _rows(path):
    return read_table(path)[1] if path.exists() else []


#: ``python -c HOOKED_SWEEP ARGS``: ``charts ARGS`` whose ``charts sweep`` prints a line when
#: its second row is written and then writes no more (its workers go on), until it is killed.
HOOKED_SWEEP = """
import sys, time
import charts.cli.sweep as command
run_sweep = command.run_sweep
def hooked(*args, **kwargs):
    def on_point(done, total):
        if done == 2:
            print("2 rows written", flush=True)
            while True:
                time.sleep(0.01)
    return run_sweep(*args, on_point=on_point, **kwargs)
command.run_sweep = hooked
from charts.cli.main import main
sys.exit(main(sys.argv[1:]))
"""


def test_dask_sweep_killed_and_resumed_equals_uninterrupted(tmp_path):
    from dask.distributed import LocalCluster

    spec = tmp_path / "tiny.toml"
    spec.write_text(SMALL)
    sweep = load_sweep(spec)
    ids = [p.point_id for p in sweep_points(sweep)]

    # 1. uninterrupted, on an existing cluster (the --scheduler route)
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster:
        ref = run_sweep(sweep, tmp_path / "ref", scheduler=cluster.scheduler_address,
                        quiet=True)
    assert ref["skipped"] == 0 and sorted(ref["computed"]) == sorted(ids)
    assert not ref["failed"] and not ref["lost"]
    header, rows = read_table(tmp_path / "ref" / TABLE)
    assert [r["point_id"] for r in rows] == ids               # point order at the end
    assert all(float(r["lambda_1"]) > 0 for r in rows)
    assert {r["mass_vector"] for r in rows} >= {"[1.0, 1.0, 1.0, 0.5]", "[1.0, 1.0, 1.0, 4.0]"}
    assert json.loads(rows[0]["scene"])["system"]["masses"] == [1.0, 1.0, 1.0, 0.5]
    assert len(read_table(tmp_path / "ref" / SUMMARY)[1]) == 4   # mean over the 2 seeds
    assert (tmp_path / "ref" / "figures" / "lambda_1.png").exists()
    assert (tmp_path / "ref" / "figures" / "overview.png").exists()
    assert "| masses | n | m | seeds | lambda_1 |" in (tmp_path / "ref" / "summary.md").read_text()

    # 2. the command line on a local cluster of 2 workers, killed after two points: the
    # sweep says when its second row is written and writes no more (HOOKED_SWEEP), so the
    # kill never finds it finished, however busy the machine
    out = tmp_path / "cut"
    proc = subprocess.Popen([sys.executable, "-c", HOOKED_SWEEP, "sweep", str(spec), "-o",
                             str(out), "--workers", "2", "--quiet", "--no-plots"],
                            start_new_session=True, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    read_until(proc.stdout, "2 rows written", proc)
    os.killpg(proc.pid, signal.SIGKILL)                      # the sweep and its workers
    proc.wait()
    before = {r["point_id"] for r in _rows(out / TABLE)}
    assert len(before) == 2, "the sweep was not killed midway"

    # 3. resume: only the missing points are computed; the table equals the uninterrupted one
    with pytest.raises(SweepError, match="--resume"):
        run_sweep(sweep, out, workers=2, quiet=True)
    res = run_sweep(sweep, out, workers=2, resume=True, quiet=True, plots=False)
    assert res["skipped"] == len(before)
    assert set(res["computed"]).isdisjoint(before)
    assert set(res["computed"]) | before == set(ids)
    assert (out / TABLE).read_bytes() == (tmp_path / "ref" / TABLE).read_bytes()
    log = [json.loads(x) for x in (out / LOG).read_text().splitlines()]
    resumed = [x["point_id"] for x in log if x["run_id"] == res["run_id"]]
    assert sorted(resumed) == sorted(res["computed"])
    assert not (out / POINTS).exists() and not (tmp_path / "ref" / POINTS).exists()
    # 4. a finished sweep resumed again computes nothing
    again = run_sweep(sweep, out, resume=True, quiet=True, plots=False)
    assert again["computed"] == [] and again["skipped"] == len(ids)


def test_a_point_with_non_finite_results_is_failed(monkeypatch):
    """The ambient kernel can run off the manifold without stopping (N = 4 near a singular
    point, no projection); the sweep must not record such numbers as a finished point."""
    import charts.runs.runner
    from charts.runs.sweep import evaluate_point

    def fake(scene, outdir, **kw):
        return {"results": {"lyapunov": {"exponents": [float("nan"), 0.2],
                                         "stderr": [0.01, 0.01]}},
                "drift": {"constraint": float("nan")}, "progress": {"t_done": 30.0}}

    monkeypatch.setattr(charts.runs.runner, "run_scene", fake)
    raw = sweep_points(_sweep())[0].raw
    out = evaluate_point(raw)
    assert out["status"] == "failed" and "lambda_1" in out["error"] and "project" in out["error"]


def _light_point(m=0.5):
    """One short point (N = 3, t = 4, the Lyapunov effect, a checkpoint every time unit)."""
    base = {"system": {"n": 3}, "integrator": {"dt": 0.01},
            "run": {"t_final": 4.0, "t_transient": 0.0, "checkpoint_every": 1.0},
            "effects": {"lyapunov": {"n_batches": 2}}}
    sweep = parse_sweep({"name": "light", "scene": base,
                         "sweep": {"seeds": [1], "parameters": {"m": [m]},
                                   "masses": {"p": [1, "m", 1]}}}, source="light.toml")
    return sweep_points(sweep)[0]


def test_a_long_point_interrupted_resumes_from_its_checkpoint(tmp_path, monkeypatch):
    """A point computed alone runs in the sweep's points/<id>: a sweep stopped in the middle
    of it leaves its checkpoints there, and the resumed sweep's worker continues the run
    (resume=True) to the same row as a point computed in one go."""
    from charts.runs import runner
    from charts.runs.sweep.worker import evaluate_point
    point = _light_point()
    keep = tmp_path / POINTS / point.point_id

    def stop(idx, total):
        if idx == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        runner.run_scene(point.scene, keep, quiet=True, on_chunk=stop)
    calls, real = [], runner.run_scene
    monkeypatch.setattr(runner, "run_scene",
                        lambda *a, **k: calls.append(k.get("resume", False)) or real(*a, **k))
    resumed = evaluate_point(point.raw, str(keep))
    assert calls == [True] and resumed["status"] == "complete"
    # it says from where it continued: the checkpoint after the third of four chunks
    assert resumed["resumed_from"] == {"t_done": 3.0, "chunks_done": 3}
    fresh = evaluate_point(point.raw)
    assert calls == [True, False] and fresh["resumed_from"] is None
    assert resumed["stats"] == fresh["stats"] and resumed["t_final"] == fresh["t_final"]
    # a checkpoint of another scene there is not resumed: the point starts over
    other = _light_point(3.0)
    resumed_other = evaluate_point(other.raw, str(keep))
    assert calls[2:] == [True, False] and resumed_other["status"] == "complete"


LIGHT = """name = "light"
[scene.system]
n = 3
[scene.integrator]
dt = 0.01
[scene.run]
t_final = 4.0
t_transient = 0.0
checkpoint_every = 1.0
[scene.effects.lyapunov]
n_batches = 2
[sweep]
seeds = [1]
[sweep.parameters]
m = [0.5]
[sweep.masses]
p = [1, "m", 1]
"""


def test_a_sweep_says_where_it_runs_before_its_bar_and_logs_a_resumed_point(tmp_path):
    """The command line's first line says where the points run ("1 worker", singular),
    before the progress bar draws (stdout and stderr in one pipe); a point that continues
    the checkpoint of an interrupted sweep is recorded in log.jsonl with where it resumed."""
    import re

    from charts.runs import runner
    spec = tmp_path / "light.toml"
    spec.write_text(LIGHT)
    point = sweep_points(load_sweep(spec))[0]
    out = tmp_path / "out"

    def stop(idx, total):
        if idx == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):      # what a sweep killed in this point leaves
        runner.run_scene(point.scene, out / POINTS / point.point_id, quiet=True, on_chunk=stop)
    proc = subprocess.run([sys.executable, "-m", "charts.cli.main", "sweep", str(spec), "-o",
                           str(out), "--workers", "1", "--no-plots"], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=WAIT_S)
    assert proc.returncode == 0, proc.stdout
    lines = [x.strip() for x in re.split(r"[\r\n]+", proc.stdout) if x.strip()]
    said = [i for i, x in enumerate(lines) if "(0 finished before" in x]
    bars = [i for i, x in enumerate(lines) if x.startswith("light:") and "%|" in x]
    assert said and bars and said[0] < bars[0], lines
    assert lines[said[0]] == ("light: 1 point (0 finished before, 1 to compute) on a local "
                              "cluster of 1 worker")
    log = [json.loads(x) for x in (out / LOG).read_text().splitlines()]
    assert [x["point_id"] for x in log] == [point.point_id]
    assert log[0]["resumed_from"] == {"t_done": 2.0, "chunks_done": 2}


def test_a_point_asks_dask_for_no_client_of_the_cluster(monkeypatch):
    """A point runs with Dask's synchronous scheduler.  Writing its NetCDF file, xarray asks
    Dask for a scheduler; without that setting the question reaches distributed's
    ``get_client``, which on a worker connects a new client of the worker to the scheduler,
    and that client's finalizer reports ``Exception ignored in: <function Client.__del__>``
    when an interrupted sweep shuts the cluster down."""
    from charts.io.archive import require_xarray
    try:
        require_xarray()
    except ImportError:
        pytest.skip("no NetCDF file without charts[io]")
    import distributed
    from charts.runs.sweep.worker import evaluate_points
    calls, real = [], distributed.get_client
    monkeypatch.setattr(distributed, "get_client",
                        lambda *a, **k: calls.append(a) or real(*a, **k))
    out = evaluate_points([_light_point().raw])
    assert out[0]["status"] == "complete"
    assert calls == []


@pytest.mark.skipif(not hasattr(signal, "pthread_sigmask"), reason="POSIX signal masks")
def test_a_ctrl_c_while_the_local_cluster_starts_interrupts_once_it_has(monkeypatch,
                                                                        python_sigint):
    """The worker processes start with Ctrl-C held back from them; a Ctrl-C that reaches
    the sweep meanwhile is not lost: once the cluster has started it is raised, and the
    cluster and its client are closed.  The handler and the signal mask are as before."""
    import dask.distributed
    from charts.runs.sweep.execute import dask_client
    closed = []

    class Cluster:
        def __init__(self, **kwargs):
            # Ctrl-C while the workers start, to the main thread: sent to the process, under
            # pytest-xdist a thread of its own took it and ended the worker
            signal.pthread_kill(threading.main_thread().ident, signal.SIGINT)

        def close(self):
            closed.append("cluster")

    class Client:
        def __init__(self, cluster):
            pass

        def close(self):
            closed.append("client")

    monkeypatch.setattr(dask.distributed, "LocalCluster", Cluster)
    monkeypatch.setattr(dask.distributed, "Client", Client)
    handler = signal.getsignal(signal.SIGINT)
    with pytest.raises(KeyboardInterrupt):
        dask_client(None, 1)
    assert closed == ["client", "cluster"]
    assert signal.getsignal(signal.SIGINT) is handler
    assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])


def test_a_point_whose_folder_is_held_runs_in_a_temporary_one(tmp_path):
    """Dask may run a point twice (a worker it took for lost still runs it): the second run
    finds points/<id> locked by a live process and computes the point in a temporary folder,
    to the same row."""
    from charts.runs.outdir import OutputLock
    from charts.runs.sweep.worker import evaluate_point
    point = _light_point()
    keep = tmp_path / POINTS / point.point_id
    keep.mkdir(parents=True)
    with OutputLock(keep, "another run of this point"):
        held = evaluate_point(point.raw, str(keep))
    assert held["status"] == "complete"
    assert held["stats"] == evaluate_point(point.raw)["stats"]


def test_a_zombie_does_not_hold_a_lock():
    """A killed process that nobody reaps (a container whose first process reaps nothing)
    stays a zombie: its lock is stale, not live."""
    from charts.runs.outdir import _alive
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    t0 = time.monotonic()
    while Path(f"/proc/{child.pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z":
        assert time.monotonic() - t0 < 30
        time.sleep(0.01)
    try:
        assert not _alive(child.pid)
    finally:
        child.wait()
    assert _alive(os.getpid())


def test_a_half_written_last_row_is_dropped_on_resume(tmp_path):
    """A kill during a write leaves a partial last line: it is not a finished point."""
    from charts.runs.sweep import csv_line, prepare_table
    pts = sweep_points(_sweep())
    cols = point_columns(pts)
    row = {c: "" for c in cols}
    row.update(index="0", point_id=pts[0].point_id, status="complete")
    text = csv_line(cols) + csv_line([row[c] for c in cols])
    (tmp_path / TABLE).write_text(text + f"1,{pts[1].point_id},compl")
    assert [r["point_id"] for r in read_table(tmp_path / TABLE)[1]] == [pts[0].point_id]
    done = prepare_table(tmp_path, cols, pts, True, "t.toml")
    assert set(done) == {pts[0].point_id}
    assert (tmp_path / TABLE).read_text() == text
    with pytest.raises(SweepError, match=f"different columns .*not written now {cols[-1]}"):
        prepare_table(tmp_path, cols[:-1], pts, True, "t.toml")
    with pytest.raises(SweepError, match="missing a_new_column: .*earlier version of charts"):
        prepare_table(tmp_path, cols + ["a_new_column"], pts, True, "t.toml")


def test_clv_columns_are_read_from_the_scene_result(tmp_path):
    """A sweep point asking for the CLV effect gives one column per variant, angle statistic
    and domination window, each filled from the run's result.json."""
    from charts.runs.runner import run_scene
    from charts.runs.scene import parse_scene
    from charts.runs.sweep.statistics import result_statistics, stat_columns

    sc = parse_scene({"system": {"n": 3}, "run": {"t_final": 10.0, "t_transient": 10.0},
                      "effects": {"clv": {"windows": [0.5, 2.0]}}})
    result = run_scene(sc, tmp_path / "p", quiet=True)
    cols = stat_columns(sc)
    assert "clv_split_full_0.5" in cols and "clv_phi_restricted_min" in cols
    stats = result_statistics(result, None)
    assert set(stats) == set(cols)
    assert stats["clv_phi_restricted_min"] == result["results"]["clv"]["restricted"]["phi"]["min"]
    assert stats["clv_split_restricted_2"] == 0.0          # N = 3: dominated over windows of 2


def test_identical_scenes_are_computed_once():
    """Two families that meet (m = 1 makes both mass vectors (1, 1, 1, 1)) keep a row each
    but share one computation."""
    from charts.runs.sweep.execute import same_scene_groups
    sw = _sweep(seeds=[1, 2], parameters={"m": [1.0, 2.0]},
                masses={"p": [1, 1, "m", 1], "q": [1, "m", 1, 1]})
    pts = sweep_points(sw)
    groups = same_scene_groups(pts)
    assert len(pts) == 8 and len(groups) == 6
    shared = [g for g in groups if len(g) == 2]
    assert len(shared) == 2 and all(g[0].params["m"] == 1.0 for g in shared)
    assert all(g[0].point_id != g[1].point_id for g in shared)


def test_summary_keeps_integers_integers():
    from charts.runs.sweep.report import _num
    assert _num("4") == 4 and isinstance(_num("4"), int)
    assert _num("0.5") == 0.5 and _num("1e-3") == 1e-3 and _num("(1,1,1,m)") == "(1,1,1,m)"


def test_the_seeds_of_a_point_run_in_lanes_with_the_rows_of_single_runs(tmp_path, monkeypatch):
    """`MIN_LANES` seeds of one point share a lane kernel on the cluster (here where the
    lanes would not pay for their compilation: told they do); every row equals the row of its
    point run alone (`evaluate_point`)."""
    from charts.analyses.lyapunov_members import MIN_LANES
    from charts.runs.sweep import execute
    from charts.runs.sweep.execute import lane_blocks, same_scene_groups

    monkeypatch.setattr(execute, "seeds_pay", lambda scene, lanes, device, runs: True)
    from charts.runs.sweep.table import point_row
    from charts.runs.sweep.worker import evaluate_point

    base = {**BASE, "run": {"t_final": 4.0, "t_transient": 1.0},
            "effects": {"lyapunov": {"n_batches": 2}, "curvature": {"route": "exact"}}}
    sweep = parse_sweep({"name": "lanes", "scene": base,
                         "sweep": {"seeds": list(range(1, MIN_LANES + 1)),
                                   "parameters": {"n": [4]}}}, source="t.toml")
    pts = sweep_points(sweep)
    assert [len(b) for b in lane_blocks(same_scene_groups(pts), 1)] == [MIN_LANES]
    res = run_sweep(sweep, tmp_path / "out", workers=1, quiet=True, plots=False)
    assert not res["failed"] and not res["lost"]
    columns = point_columns(pts)
    header, rows = read_table(tmp_path / "out" / TABLE)
    for p, row in zip(pts, rows):
        alone = dict(zip(columns, point_row(p, evaluate_point(p.raw), columns)))
        for c in columns:
            if c not in ("wall_s",):
                assert str(row[c]) == alone[c] or float(row[c]) == float(alone[c]), c
