"""Waiting for what a child process does, never for time: a line it prints, a file it
writes, a process that is gone.  Each wait polls for its event and gives up only after
`GUARD_S`, a guard against a hang (the test then fails), never a delay the test relies on."""
from __future__ import annotations

import re
import time
from pathlib import Path

__all__ = ["GUARD_S", "wait_for", "read_until", "descendants", "pool_workers", "wait_gone",
           "HOOKED_RUN"]

#: How long a wait may take before the test fails instead of hanging.
GUARD_S = 600


def wait_for(event, proc=None, what="the event"):
    """Poll ``event()`` until it is true; AssertionError if ``proc`` (a Popen) ends first
    (with its stderr when it was a pipe) or after `GUARD_S`."""
    t0 = time.monotonic()
    while not event():
        if proc is not None and proc.poll() is not None:
            err = proc.stderr.read() if proc.stderr is not None else ""
            raise AssertionError(f"the child ended (status {proc.returncode}) before {what}: "
                                 f"{err}")
        assert time.monotonic() - t0 < GUARD_S, f"no {what} after {GUARD_S} s"
        time.sleep(0.01)


def read_until(stream, pattern, proc=None) -> list:
    """The lines of ``stream`` (a child's text stdout or stderr) up to the first that matches
    ``pattern`` (a regular expression); AssertionError at the end of the stream (the child
    ended without printing it)."""
    lines = []
    for line in iter(stream.readline, ""):
        lines.append(line)
        if re.search(pattern, line):
            return lines
    status = proc.wait() if proc is not None else None
    raise AssertionError(f"no line matching {pattern!r} (status {status}): {''.join(lines)}")


def _children(pid) -> list:
    try:
        tasks = list(Path(f"/proc/{pid}/task").iterdir())
    except OSError:
        return []
    out = []
    for task in tasks:
        try:
            out += [int(x) for x in (task / "children").read_text().split()]
        except OSError:
            pass
    return out


def descendants(pid) -> list:
    """The pids of every process below ``pid`` (Linux: /proc/PID/task/*/children)."""
    out, todo = [], [pid]
    while todo:
        for child in _children(todo.pop()):
            out.append(child)
            todo.append(child)
    return out


def pool_workers(pid) -> list:
    """The children of ``pid`` forked from it (its process pools' workers: the same command
    line), not the helpers it started otherwise (multiprocessing's resource tracker)."""
    def cmdline(p):
        try:
            return Path(f"/proc/{p}/cmdline").read_bytes()
        except OSError:
            return None
    own = cmdline(pid)
    return [c for c in _children(pid) if cmdline(c) == own]


def _running(pid) -> bool:
    """Whether ``pid`` is a live process (a zombie, dead and not yet reaped, is not)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] not in ("Z", "X")


def wait_gone(pids) -> list:
    """Wait until none of ``pids`` runs (each one's exit is the event); the pids still
    running after `GUARD_S` (the test then fails naming them)."""
    t0 = time.monotonic()
    while (alive := [p for p in pids if _running(p)]) and time.monotonic() - t0 < GUARD_S:
        time.sleep(0.01)
    return alive


#: ``python -c HOOKED_RUN ARGS``: ``charts ARGS`` whose ``charts run`` prints a line after its
#: first checkpoint and then waits for a signal (the test's) instead of going on, so that the
#: signal finds the run after that checkpoint however busy the machine: the run cannot end
#: before it.  It idles in short sleeps, each of which lets Python run the signal's handler.
HOOKED_RUN = """
import sys, time
from charts.runs import runner
run_scene = runner.run_scene
def hooked(*args, **kwargs):
    def after(index, n_chunks):
        if index == 0:
            print(f"checkpoint 1 of {n_chunks} written", flush=True)
            while True:
                time.sleep(0.01)
    return run_scene(*args, on_chunk=after, **kwargs)
runner.run_scene = hooked
from charts.cli.main import main
sys.exit(main(sys.argv[1:]))
"""
