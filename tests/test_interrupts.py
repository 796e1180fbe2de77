"""Ctrl-C and SIGTERM of the long commands while their process pools are busy
(``charts.runs.interrupts``, docs/reliability.md): the interrupted result with its message,
exit 130 (Ctrl-C) or 143 (SIGTERM), no traceback, no process left behind.

Each test waits for an event of the child -- a piece written, a progress line -- before it
signals, with work left that the child cannot finish meanwhile (`process_events`)."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from concurrent.futures.process import BrokenProcessPool

import pytest

from charts.runs import interrupts

from process_events import (descendants, pool_workers, read_until, wait_for, wait_gone)

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="the children are found in /proc")

CHARTS = [sys.executable, "-m", "charts"]


# ------------------------------------------------------------------------- the module
def test_sigterm_is_an_interrupt_with_its_own_status():
    """Inside `handled`, SIGTERM raises `Terminated` (a KeyboardInterrupt), the status of an
    interrupted command becomes 143, and a BrokenProcessPool after it is the interrupt; the
    handlers before are back afterwards."""
    before = {s: signal.getsignal(s) for s in interrupts.SIGNALS}
    with interrupts.handled():
        assert interrupts.received() is None
        assert interrupts.interrupt_for(BrokenProcessPool("a worker died")) is None
        with pytest.raises(interrupts.Terminated):
            signal.raise_signal(signal.SIGTERM)
        assert interrupts.received() == signal.SIGTERM
        assert interrupts.exit_status(130) == 143 and interrupts.exit_status(1) == 1
        assert isinstance(interrupts.interrupt_for(BrokenProcessPool("x")),
                          interrupts.Terminated)
        assert interrupts.interrupt_for(ValueError("x")) is None
    assert {s: signal.getsignal(s) for s in interrupts.SIGNALS} == before
    with interrupts.handled():
        with pytest.raises(KeyboardInterrupt) as caught:
            signal.raise_signal(signal.SIGINT)
        assert type(caught.value) is KeyboardInterrupt
        assert interrupts.exit_status(130) == 130


def test_a_save_finishes_before_the_interrupt_is_taken(tmp_path, python_sigint):
    """A Ctrl-C while a result is written (``charts.io.archive.save``, the tally's
    checkpoint) is taken once the file is whole: no half-built file object, whose
    finalizer printed ``Exception ignored in: <function File.close …>``."""
    from charts.io.atomic import signals_deferred
    with pytest.raises(KeyboardInterrupt):
        with signals_deferred():
            signal.raise_signal(signal.SIGINT)
            written = True
    assert written


# ------------------------------------------------------------------------- reproduce
def _reproduce(out, *extra):
    """``charts reproduce --quick`` into ``out`` on 2 workers, in a session of its own (a
    process group, as a terminal's job), its stderr a pipe."""
    return subprocess.Popen(CHARTS + ["reproduce", "--quick", "--workers", "2", "-o", str(out),
                                      *extra], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)


def _pieces(out):
    return sorted((out / "pieces").glob("*.npz")) if (out / "pieces").is_dir() else []


def _interrupted_reproduction(out, proc, status, kept_before):
    """The checks of an interrupted reproduction: its status, the one message naming the
    pieces kept (those of the folder, each usable), no traceback, no process left."""
    from charts.runs import reproduce as rp
    from charts.runs.pieces import load_piece
    _, err = proc.communicate()
    assert proc.returncode == status, err
    assert "Traceback" not in err and "BrokenProcessPool" not in err, err
    kept = _pieces(out)
    assert len(kept) >= kept_before
    tasks = rp._tasks(rp.PRESETS["quick"])
    assert f"{len(kept)} of {len(tasks)} pieces kept in {out / 'pieces'}" in err, err
    assert f"charts reproduce --quick -o {out}" in err
    usable = [k for k, (f, a) in tasks.items() if load_piece(out / "pieces", k, a) is not None]
    assert len(usable) == len(kept)


@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)],
                         ids=["ctrl-c", "sigterm"])
def test_reproduce_interrupted_while_its_pool_is_busy(tmp_path, signum, status):
    """The signal to the process group (a terminal's Ctrl-C, a scheduler's SIGTERM) once the
    first piece is written, the workers busy with the next ones: the workers take no part
    (before, a Ctrl-C made them exit, and the main process could find its pool broken
    first: ``charts: error: BrokenProcessPool …``, exit 1)."""
    out = tmp_path / "rp"
    proc = _reproduce(out)
    wait_for(lambda: _pieces(out), proc, "the first piece")
    workers = pool_workers(proc.pid)
    assert workers
    os.killpg(proc.pid, signum)
    _interrupted_reproduction(out, proc, status, 1)
    assert wait_gone(workers) == []


@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)],
                         ids=["ctrl-c", "sigterm"])
def test_reproduce_signalled_alone_stops_its_workers(tmp_path, signum, status):
    """The signal to the main process only (``kill PID``): it stops its workers, which
    would otherwise run their pieces to the end (the command waiting for them) or, for
    SIGTERM before, outlive it."""
    out = tmp_path / "rp"
    proc = _reproduce(out)
    wait_for(lambda: _pieces(out), proc, "the first piece")
    workers = pool_workers(proc.pid)
    assert workers
    proc.send_signal(signum)
    _interrupted_reproduction(out, proc, status, 1)
    assert wait_gone(workers) == []


def test_a_ctrl_c_that_reaches_the_workers_first_does_not_break_the_pool(tmp_path):
    """Ctrl-C reaches every process of the group, and the main process may take it after
    its workers (it is busy, or the signal lands there first).  Here the workers get it
    alone: the pool must stay whole -- the next piece is written -- and the main process's
    Ctrl-C then gives the interrupted result.  Before, each worker exited at once and the
    command ended in ``charts: error: BrokenProcessPool``."""
    out = tmp_path / "rp"
    proc = _reproduce(out)
    wait_for(lambda: _pieces(out), proc, "the first piece")
    workers = pool_workers(proc.pid)
    first = len(_pieces(out))
    for pid in workers:
        os.kill(pid, signal.SIGINT)
    wait_for(lambda: len(_pieces(out)) > first, proc, "a piece after the workers' Ctrl-C")
    proc.send_signal(signal.SIGINT)
    _interrupted_reproduction(out, proc, 130, first + 1)
    assert wait_gone(workers) == []


# ------------------------------------------------------------------------- verdict
def _statistics(out):
    """``charts verdict --statistics`` at about its cheapest with several chunks of members
    on 2 workers: 64 members, 8 chunks, one progress line after the first."""
    return subprocess.Popen(
        CHARTS + ["verdict", "--statistics", "--n", "3", "--members", "64", "--samples", "128000",
                  "--t-transient", "1", "--device", "cpu", "--workers", "2", "--out", str(out)],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, start_new_session=True)


@pytest.mark.parametrize("to_group", [False, True], ids=["kill-pid", "process-group"])
def test_verdict_statistics_sigterm_leaves_no_process(tmp_path, to_group):
    """SIGTERM (``kill PID``, or a scheduler's to the whole job) after the first progress
    line: exit 143, the message, no traceback, and no process of the command left (before,
    its pool's workers ran on, orphaned, holding the pipes)."""
    out = tmp_path / "stats"
    proc = _statistics(out)
    read_until(proc.stderr, r"N = 3: \d+ % of the members' time done", proc)
    below = descendants(proc.pid)
    assert below
    if to_group:
        os.killpg(proc.pid, signal.SIGTERM)
    else:
        proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate()
    assert proc.returncode == 143, err
    assert "Traceback" not in err and "interrupted: " in err, err
    assert wait_gone(below) == []
    assert list(out.glob("*.partial.nc"))         # the members done are kept


def test_verdict_statistics_ctrl_c_prints_no_worker_traceback(tmp_path):
    """Ctrl-C to the process group after the first progress line: exit 130, only the
    message (before: a KeyboardInterrupt traceback from every idle worker), the members done
    kept in a checkpoint the same command goes on from."""
    from charts.analyses.angle_tally import AngleTally
    from charts.io.archive import load
    out = tmp_path / "stats"
    proc = _statistics(out)
    read_until(proc.stderr, r"N = 3: \d+ % of the members' time done", proc)
    below = descendants(proc.pid)
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate()
    assert proc.returncode == 130, err
    assert err.strip().splitlines()[-1].startswith("interrupted: the systems finished"), err
    assert "Traceback" not in err and "Exception ignored" not in err, err
    assert wait_gone(below) == []
    (partial,) = out.glob("*.partial.nc")
    assert isinstance(load(partial), AngleTally)


def test_verdict_statistics_killed_leaves_no_worker(tmp_path):
    """SIGKILL, which no handler sees, after the first progress line: on Linux the kernel
    ends the workers with the command (``PR_SET_PDEATHSIG``); before, they ran on."""
    out = tmp_path / "stats"
    proc = _statistics(out)
    read_until(proc.stderr, r"N = 3: \d+ % of the members' time done", proc)
    workers = pool_workers(proc.pid)
    assert workers
    proc.send_signal(signal.SIGKILL)
    proc.communicate()
    assert wait_gone(workers) == []
