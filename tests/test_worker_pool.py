"""The package's process pools name their workers (``charts.analyses.worker_pool``): an
interrupt stops those and nothing else this process started."""
from __future__ import annotations

import multiprocessing
import os

from charts.analyses.worker_pool import pool_workers, worker_pool, workers_of
from charts.runs.interrupts import stop_pool_workers


def _pid(_):
    return os.getpid()


def _wait(conn):
    conn.recv()                       # until the test says so


def _ended(p) -> bool:
    """``p`` (joined) has ended: its exit code is known, or its pid is gone (the executor's own
    thread may reap a stopped worker first, and then ``join`` cannot read the exit code and
    ``is_alive`` stays True although the process is gone)."""
    if p.exitcode is not None:
        return True
    try:
        os.kill(p.pid, 0)
    except ProcessLookupError:
        return True
    return False


def test_a_pool_names_its_workers_and_no_other_child():
    parent, child = multiprocessing.Pipe()
    other = multiprocessing.Process(target=_wait, args=(child,))
    other.start()
    try:
        with worker_pool(2) as pool:
            pids = set(pool.map(_pid, range(8)))           # the workers are up
            mine = workers_of(pool)
            assert {p.pid for p in mine} >= pids and len(mine) == 2
            assert {p.pid for p in mine} <= {p.pid for p in pool_workers()}
            assert other.pid not in {p.pid for p in pool_workers()}
            stopped = stop_pool_workers()
            assert {p.pid for p in stopped} >= {p.pid for p in mine}
            for p in mine:
                p.join()
                assert _ended(p)
            assert other.is_alive()                          # not a pool's: left alone
            assert workers_of(pool) == []
    finally:
        parent.send(None)
        other.join()
    assert workers_of(object()) == []                      # not a pool of the package
