"""How the ``charts`` command stops on Ctrl-C (SIGINT) and SIGTERM (docs/reliability.md).

SIGTERM, what ``kill`` and job schedulers send, is taken as Ctrl-C is: the command stops,
keeps what it finished, says so and how to continue, and exits with 143 (128 + 15) where
Ctrl-C gives 130 (128 + 2).  `handled` installs the handlers for the command's duration:

* in the command's process, a signal stops this process's process-pool workers at once
  (`stop_pool_workers`: the work in flight is lost, what was kept stays) and raises
  `KeyboardInterrupt` (Ctrl-C) or `Terminated`, a `KeyboardInterrupt` too, so every handler
  of an interrupt (the run's checkpoint, the sweep's table, the reproduction's pieces) takes
  both alike;
* in a pool worker forked from it (the handlers are inherited), the signal is ignored: a
  Ctrl-C reaches the whole process group, and a worker that died of it, or printed a
  ``KeyboardInterrupt`` traceback, would break its pool under the main process
  (``BrokenProcessPool``) before the main process had taken the interrupt;
* on Linux a worker forked by the command's main thread is killed by the kernel when the
  command ends in any way, SIGKILL included (``PR_SET_PDEATHSIG``): no worker outlives it.

`interrupt_for` turns a ``BrokenProcessPool`` that surfaces after an interrupt into the
interrupt; `exit_status` gives 143 for SIGTERM.
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading

__all__ = ["handled", "received", "exit_status", "interrupt_for", "stop_pool_workers",
           "workers_stopped", "quiet_worker", "Terminated", "EXIT_INTERRUPTED",
           "EXIT_TERMINATED"]

#: Exit status of a command stopped by Ctrl-C (128 + SIGINT).
EXIT_INTERRUPTED = 130
#: Exit status of a command stopped by SIGTERM (128 + SIGTERM).
EXIT_TERMINATED = 143

SIGNALS = (signal.SIGINT, signal.SIGTERM)
#: prctl's option that asks for a signal when the parent (the forking thread) ends.
_PR_SET_PDEATHSIG = 1

#: owner: the pid whose handlers raise (None: not installed); first: the first signal
#: received; forker: (pid, whether the main thread forks), set just before a fork
_state = {"owner": None, "first": None, "forker": None, "stopped": False}


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised in the command's process where Ctrl-C raises `KeyboardInterrupt` (of
    which it is a kind: every handler of an interrupt takes it)."""


def received():
    """The first of SIGINT, SIGTERM received while `handled` is active (its number), or None."""
    return _state["first"]


def exit_status(status: int) -> int:
    """``status``, but 143 for an interrupted command (130) that SIGTERM stopped."""
    if status == EXIT_INTERRUPTED and received() == signal.SIGTERM:
        return EXIT_TERMINATED
    return status


def interrupt_for(exc):
    """The interrupt to raise instead of ``exc`` where ``exc`` is a consequence of one (a
    ``BrokenProcessPool``: its workers stopped by the interrupt), else None."""
    from concurrent.futures.process import BrokenProcessPool
    if isinstance(exc, BrokenProcessPool) and received() is not None:
        return Terminated() if received() == signal.SIGTERM else KeyboardInterrupt()
    return None


def stop_pool_workers() -> list:
    """Kill (SIGKILL) this process's process-pool workers (the pools of
    ``charts.analyses.worker_pool``, every pool of the package), none of anything else it
    started (a Dask cluster's processes are closed by their owner); their
    pools find them gone.  Returns the processes."""
    from ..analyses.worker_pool import pool_workers
    workers = pool_workers()
    for p in workers:
        with contextlib.suppress(OSError, ValueError, AttributeError):
            p.kill()
    if workers:
        _state["stopped"] = True
    return workers


def workers_stopped() -> bool:
    """Whether an interrupt killed process-pool workers in this process.  A worker killed
    while it sent a result leaves ``concurrent.futures``' manager thread waiting for the
    rest of the message, which Python's exit then joins forever: the ``charts`` command
    ends such a process at once (``charts.cli.console``)."""
    return _state["stopped"]


def quiet_worker():
    """A process pool's initializer: Ctrl-C and SIGTERM ignored in the worker (the main
    process stops it), whatever the start method (a forked worker inherits `handled`'s
    handlers, which ignore them too)."""
    for signum in SIGNALS:
        signal.signal(signum, signal.SIG_IGN)


def _handler(signum, frame):
    if os.getpid() != _state["owner"]:
        return                  # a worker forked from the command: the main process decides
    if _state["first"] is None:
        _state["first"] = signum
    stop_pool_workers()
    raise Terminated() if signum == signal.SIGTERM else KeyboardInterrupt()


@contextlib.contextmanager
def handled():
    """SIGINT and SIGTERM as the module says, while the block runs (in the main thread
    only: elsewhere, and where a handler cannot be set, nothing changes); the previous
    handlers back afterwards."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = {}
    try:
        for signum in SIGNALS:
            old[signum] = signal.signal(signum, _handler)
    except (ValueError, OSError):
        for signum, h in old.items():
            signal.signal(signum, h)
        yield
        return
    saved = dict(_state)
    _state.update(owner=os.getpid(), first=None)
    _fork_hooks()
    try:
        yield
    finally:
        for signum, h in old.items():
            signal.signal(signum, h)
        _state.update(owner=saved["owner"], forker=None)


_hooks = []


def _fork_hooks():
    """Once per process: before a fork, note who forks; in the child, ask the kernel for
    SIGKILL when the forking thread ends (the main thread of a command: the command), and
    end at once if it has ended already."""
    if _hooks or not sys.platform.startswith("linux") or not hasattr(os, "register_at_fork"):
        return
    try:
        import ctypes
        prctl = ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return
    _hooks.append(prctl)

    def before():
        if _state["owner"] == os.getpid():
            _state["forker"] = (os.getpid(),
                                threading.current_thread() is threading.main_thread())

    def after_in_child():
        forker, _state["forker"] = _state["forker"], None
        if forker is None or not forker[1]:
            return              # not a command's main thread: a thread may end before its child
        prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
        if os.getppid() != forker[0]:
            os._exit(EXIT_TERMINATED)           # the command ended while it forked

    def after_in_parent():
        _state["forker"] = None

    os.register_at_fork(before=before, after_in_child=after_in_child,
                        after_in_parent=after_in_parent)
