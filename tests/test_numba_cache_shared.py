"""Processes that share numba's cache and add entries to one index at once keep each entry's
key with its own code (charts.jit.cache_lock's lock): two processes compile the chart
right-hand side of N = 3 and of N = 4 — two entries of one function's index — with numba's
save slowed down so that without the lock both take the same object file and the index
names one entry's key with the other's code; a third process then loads both from the shared cache and must
get what a process with a cache of its own computes."""
import os
import subprocess
import sys

import pytest

pytest.importorskip("fcntl")

# numba's save slowed down where a race can slip in: after reading the index (each process
# finds no entry for its N and chooses the first free object file) and, in the first process,
# between writing the index and writing the object file; the second process reads the index
# before the first writes it, and writes its own index after it: without the lock, the index
# names the second process's key and the file holds the first one's code
SLOW = """
import time
from numba.core import caching
_read, _write = caching.IndexDataCacheFile._load_index, caching.IndexDataCacheFile._save_index
def _slow_read(self):
    out = _read(self)
    if "generated_rates" in self._index_path:
        time.sleep({read})
    return out
def _slow_write(self, overloads):
    _write(self, overloads)
    if "generated_rates" in self._index_path:
        time.sleep({write})
caching.IndexDataCacheFile._load_index = _slow_read
caching.IndexDataCacheFile._save_index = _slow_write
"""

EVALUATE = """
import sys
import numpy as np
from charts import RotorSystem
from charts.flows.chart import local_parameters
from charts.solvers.chart_formulation import chart_rhs
for n in map(int, sys.argv[1:]):
    rhs = chart_rhs(n, True)
    system = RotorSystem(n)
    theta, u = system.random_state(seed=1)
    k = system.best_chart(theta)
    y = np.concatenate([np.delete(theta, k), np.delete(u, k)])
    par = local_parameters(system.masses, system.weights, system.level, k)
    dy = np.empty_like(y)
    rhs(y, par, dy)
    print(n, [float(v).hex() for v in dy])
"""


def _start(cache, code, *ns):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    return subprocess.Popen([sys.executable, "-c", code, *map(str, ns)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _output(proc):
    out, err = proc.communicate(timeout=600)
    assert proc.returncode == 0, err
    return out


def test_two_processes_adding_entries_to_one_index_keep_each_its_own_code(tmp_path):
    shared = tmp_path / "shared"
    first = _start(shared, SLOW.format(read=1.5, write=3.0) + EVALUATE, 3)
    second = _start(shared, SLOW.format(read=2.5, write=0.0) + EVALUATE, 4)
    own = _start(tmp_path / "own", EVALUATE, 3, 4)
    computed = _output(first) + _output(second)
    expected = _output(own)
    assert sorted(computed.splitlines()) == sorted(expected.splitlines())
    loaded = _output(_start(shared, EVALUATE, 3, 4))      # both from the shared cache
    assert loaded == expected


STEP_WITH_OWN_RHS = """
import numpy as np
from numba import njit
from charts.solvers.rk import RHS_SIG, rk4_step
@njit(RHS_SIG)
def decay(y, par, dy):
    dy[0] = -y[0]
    return 1.0
y = np.ones(1)
rk4_step(decay, y, 0.1, np.zeros(1), np.zeros((4, 1)), np.zeros(1), np.zeros(1))
print(y[0].hex())
"""


def test_a_kernel_given_a_function_of_its_caller_leaves_no_cache_entry(tmp_path):
    """``rk4_step(f, …)`` from Python with the caller's own compiled ``f``: numba keys such an
    entry on that process's function, which no other process finds, so it is not saved (each
    run added one to the step's index, and numba rebuilds them all to save the next)."""
    out = {_output(_start(tmp_path, STEP_WITH_OWN_RHS)) for _ in range(2)}
    assert len(out) == 1
    assert not list(tmp_path.rglob("rk.rk4_step*.nbc"))
