"""Interrupted work resumes identically, and a real Dask cluster that loses a worker gives
the local table.

* ``charts run`` killed with SIGKILL twice, each time after a seeded random number of its
  checkpoints (at whatever point of the next chunk the kill lands), then ``--resume``: every
  number of result.json equals the uninterrupted run's (the killed run's lock is stale and
  taken over);
* a resume into a folder written by another sweep refuses;
* ``charts reproduce``'s pieces: a second run reuses the finished ones and computes only the
  missing ones; a piece computed with other arguments is not reused;
* a real ``dask scheduler`` and two ``dask worker`` processes: one worker is killed with
  SIGKILL mid-sweep; the sweep finishes with the same table, byte for byte, as a local run
  (skipped when the processes cannot start, e.g. no free port)."""
from __future__ import annotations

import json
import os
import random
import shlex
import signal
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from process_events import wait_for
from charts.runs.runner import run_scene
from charts.runs.scene import load_scene
from charts.runs.sweep import (SweepError, TABLE, csv_line, load_sweep, point_columns,
                               read_table, run_sweep, sweep_points)

CHARTS = [sys.executable, "-m", "charts.cli.main"]
#: a polling guard only (the test fails instead of hanging)
WAIT_S = 600

SCENE = """name = "killed"
[system]
n = 4
[initial]
seed = 5
[run]
t_final = 60000.0
t_transient = 10.0
sample_dt = 1.0
checkpoint_every = 4000.0
[effects.lyapunov]
n_batches = 5
[effects.drift]
sample_every = 50.0
"""


def _wait_for(predicate, proc):
    """Poll for an event of the child ``proc`` (a file it writes); fails if it ends first."""
    wait_for(predicate, proc)


def _checkpoints(ck):
    """Which checkpoint ``ck`` is: its mtime and inode (a new one replaces it: another
    inode), or None (not written yet)."""
    try:
        st = ck.stat()
    except FileNotFoundError:
        return None
    return st.st_mtime_ns, st.st_ino


def test_run_killed_at_random_moments_resumes_identically(tmp_path):
    """Each kill follows a seeded random number (1 to 3) of new checkpoints, events of the
    run, with 10 or more of its 16 chunks still to run: the kill never finds it finished."""
    scene_file = tmp_path / "killed.toml"
    scene_file.write_text(SCENE)
    whole = run_scene(load_scene(scene_file), tmp_path / "whole", quiet=True)
    out = tmp_path / "out"
    rng = random.Random(20261123)
    for attempt in range(2):                    # kill, resume and kill again, then finish
        args = ["run", str(scene_file), "-o", str(out), "--quiet"] + (["--resume"] if attempt
                                                                       else [])
        proc = subprocess.Popen(CHARTS + args, stderr=subprocess.PIPE, text=True)
        ck = out / "checkpoint.npz"
        for _ in range(rng.randint(1, 3)):      # the next checkpoints, one after the other
            seen = _checkpoints(ck)
            _wait_for(lambda: _checkpoints(ck) not in (None, seen), proc)
        assert proc.poll() is None, "the run ended before the kill"
        proc.send_signal(signal.SIGKILL)
        proc.communicate()
        assert (out / ".charts.lock").exists()   # the killed run's lock is left behind
    p = subprocess.run(CHARTS + ["run", str(scene_file), "-o", str(out), "--resume", "--quiet"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "removing a stale lock" in p.stderr
    resumed = json.loads((out / "result.json").read_text())
    assert resumed["status"] == "complete"
    assert resumed["results"] == json.loads(json.dumps(whole["results"]))
    assert resumed["drift"] == json.loads(json.dumps(whole["drift"]))
    with np.load(out / "arrays.npz") as a, np.load(tmp_path / "whole" / "arrays.npz") as b:
        assert sorted(a.files) == sorted(b.files)
        for k in a.files:
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)


SWEEP = """name = "{name}"
[scene.system]
n = 4
[scene.integrator]
dt = 0.01
[scene.run]
t_final = 20.0
t_transient = 2.0
[scene.effects.lyapunov]
n_batches = 2
[sweep]
seeds = [1, 2]
[sweep.parameters]
m = [{masses}]
[sweep.masses]
"1,1,1,m" = [1, 1, 1, "m"]
"""


def test_a_resume_into_another_sweeps_folder_refuses(tmp_path):
    (tmp_path / "a.toml").write_text(SWEEP.format(name="a", masses="0.5, 2.0"))
    (tmp_path / "b.toml").write_text(SWEEP.format(name="b", masses="0.5, 3.0"))
    a, b = load_sweep(tmp_path / "a.toml"), load_sweep(tmp_path / "b.toml")
    pa = sweep_points(a)
    cols = point_columns(pa)
    out = tmp_path / "out"
    out.mkdir()
    row = ["" for _ in cols]
    row[cols.index("index")], row[cols.index("point_id")] = "3", pa[3].point_id
    (out / TABLE).write_text(csv_line(cols) + csv_line(row))    # a's last point (m = 2)
    with pytest.raises(SweepError, match="not in .*b.toml"):
        run_sweep(b, out, resume=True, quiet=True)


def test_reproduce_reuses_finished_pieces_and_only_those(tmp_path, capsys):
    from charts.runs import reproduce as rp

    cfg = dict(lyap_members=1, lyap_t=20.0, lyap_batches=2, angle_members=1, angle_t=150.0,
               curv_t=5.0, wave_t=800.0, angle_transient=2.0)
    pieces = tmp_path / "pieces"
    pieces.mkdir()
    first = rp._run_all(cfg, 1, True, pieces)
    files = sorted(pieces.glob("*.npz"))
    assert len(files) == len(first) == 15
    for f in files[::3]:                        # as if interrupted before these finished
        f.unlink()
    (pieces / "lyap-n3-0.npz").unlink(missing_ok=True)
    stamp = {f.name: f.stat().st_mtime_ns for f in pieces.glob("*.npz")}
    capsys.readouterr()
    second = rp._run_all(cfg, 1, False, pieces)
    assert f"reusing {len(stamp)} of 15 finished pieces" in capsys.readouterr().err
    assert {f.name: f.stat().st_mtime_ns for f in pieces.glob("*.npz")
            if f.name in stamp} == stamp          # reused pieces were not rewritten
    for key, res in first.items():              # recomputed or reused: the same numbers
        if key[0] == "clv":                     # nested per variant; its own tests compare it
            continue
        for name, value in res.items():
            np.testing.assert_array_equal(np.asarray(second[key][name]), np.asarray(value))
    longer = dict(cfg, lyap_t=40.0)             # another preset: lyap pieces are recomputed
    assert rp.load_piece(pieces, ("lyap", 3, 0), rp._tasks(longer)[("lyap", 3, 0)][1]) is None
    assert rp.load_piece(pieces, ("wave", 3, 0), rp._tasks(longer)[("wave", 3, 0)][1]) is not None


def _start(cmd, log):
    return subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)


def _address(sched_file):
    """The scheduler's address from its file, once the file is there and whole; else None."""
    try:
        return json.loads(sched_file.read_text())["address"]
    except (OSError, ValueError, KeyError):
        return None


def test_a_real_cluster_that_loses_a_worker_gives_the_local_table(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(SWEEP.format(name="cluster", masses="0.5, 1.0, 2.0, 4.0"))
    sweep = load_sweep(spec)
    local = run_sweep(sweep, tmp_path / "local", workers=2, quiet=True, plots=False)
    assert not local["lost"] and not local["failed"]

    sched_file = tmp_path / "scheduler.json"
    log = open(tmp_path / "cluster.log", "w")
    dask = [sys.executable, "-m", "dask"]
    procs = [_start(dask + ["scheduler", "--host", "127.0.0.1", "--port", "0",
                            "--dashboard-address", ":0", "--scheduler-file", str(sched_file)],
                    log)]
    try:
        try:                                    # the scheduler's file, whole (its address)
            wait_for(lambda: _address(sched_file) is not None, procs[0], "the scheduler file")
        except AssertionError:
            pytest.skip("dask scheduler did not start: " +
                        Path(tmp_path / "cluster.log").read_text()[-300:])
        address = _address(sched_file)
        for _ in range(2):
            procs.append(_start(dask + ["worker", address, "--nworkers", "1", "--nthreads", "1",
                                        "--no-dashboard", "--death-timeout", "60"], log))
        from dask.distributed import Client
        with Client(address, timeout="30s") as c:
            c.wait_for_workers(2, timeout=120)
        out = tmp_path / "cluster"
        sweeper = subprocess.Popen(CHARTS + ["sweep", str(spec), "-o", str(out), "--scheduler",
                                             address, "--quiet", "--no-plots"],
                                   stderr=subprocess.PIPE, text=True)
        _wait_for(lambda: (out / TABLE).exists() and len(read_table(out / TABLE)[1]) >= 1,
                  sweeper)
        os.killpg(procs[1].pid, signal.SIGKILL)        # one worker (and its nanny) dies
        _, err = sweeper.communicate(timeout=WAIT_S)
        assert sweeper.returncode == 0, err
    finally:
        for p in procs:
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            p.wait()
        log.close()
    assert (out / TABLE).read_bytes() == (tmp_path / "local" / TABLE).read_bytes()


def test_reproduce_interrupted_by_ctrl_c_says_what_it_kept(tmp_path):
    """Ctrl-C (SIGINT to the process group, as a terminal sends it) once a piece is kept:
    exit 130, one message naming the kept pieces and the command, no worker traceback."""
    out = tmp_path / "rp"
    proc = subprocess.Popen(CHARTS + ["reproduce", "--quick", "--workers", "2", "-o", str(out),
                                      "--quiet"], stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    _wait_for(lambda: (out / "pieces").is_dir() and any((out / "pieces").glob("*.npz")), proc)
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=WAIT_S)
    kept = len(list((out / "pieces").glob("*.npz")))
    assert proc.returncode == 130, err
    from charts.runs import reproduce as rp
    total = len(rp._tasks(rp.PRESETS["quick"]))  # 21: the Lyapunov members of an N are one piece
    assert "Traceback" not in err, err
    assert f"{kept} of {total} pieces kept" in err, err
    assert f"charts reproduce --quick -o {out}" in err


#: two points: the short one's row is written while the long one is running
SHORT_AND_LONG = """name = "ctrlc"
[scene.system]
n = 4
[scene.integrator]
dt = 0.01
[scene.run]
t_transient = 2.0
[scene.effects.lyapunov]
n_batches = 2
[sweep.parameters]
"run.t_final" = [20.0, 20000.0]
"""


def test_sweep_interrupted_by_ctrl_c_prints_only_how_to_resume(tmp_path):
    """Ctrl-C (SIGINT to the process group, as a terminal sends it) once the short point's
    row is written, while the other point runs: exit 130, the row kept, the lock removed,
    and stderr is the sweep's own message alone -- no worker traceback, no report of Dask
    (``Exception ignored in: <function Client.__del__ ...>``, ``Port 8787 is already in
    use``) or of Python's resource tracker (``There appear to be 1 leaked semaphore
    objects``)."""
    spec = tmp_path / "s.toml"
    spec.write_text(SHORT_AND_LONG)
    out = tmp_path / "out"
    # Dask's default HTTP port taken, as by another cluster on the host (or it is already)
    held = socket.socket()
    try:
        held.bind(("127.0.0.1", 8787))
        held.listen()
    except OSError:
        pass
    try:
        # `python -m charts`, as users start it (`-m charts.cli.main` makes runpy warn, in
        # the worker processes too, which re-import the main module)
        proc = subprocess.Popen([sys.executable, "-m", "charts", "sweep", str(spec), "-o",
                                 str(out), "--workers", "2", "--quiet", "--no-plots"],
                                stderr=subprocess.PIPE, text=True, start_new_session=True)
        _wait_for(lambda: (out / TABLE).exists() and len(read_table(out / TABLE)[1]) >= 1,
                  proc)
        os.killpg(proc.pid, signal.SIGINT)
        _, err = proc.communicate(timeout=WAIT_S)
    finally:
        held.close()
    assert proc.returncode == 130, err
    assert err.strip().splitlines() == [
        f"interrupted: the finished points are in {out / TABLE} (and the checkpoints of a "
        f"long point in {out / 'points'}); continue with:",
        f"  charts sweep {shlex.quote(str(spec))} -o {shlex.quote(str(out))} --resume --workers 2"], err
    assert len(read_table(out / TABLE)[1]) == 1
    assert not (out / ".charts.lock").exists()
