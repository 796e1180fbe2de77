"""A damaged numba cache entry of a charts kernel is removed and compiled again, once, with
one notice (charts.jit.cache_lock: the cache object of charts' own dispatchers)."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

CALL = ("import charts; th, u = charts.RotorSystem(3).random_state(seed=1); "
        "print(repr(th.tolist()))")


def _run(cache: Path):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    r = subprocess.run([sys.executable, "-c", CALL], capture_output=True, text=True, env=env,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    return r.stdout, [line for line in r.stderr.splitlines() if line.startswith("charts:")]


@pytest.fixture(scope="module")
def filled(tmp_path_factory):
    cache = tmp_path_factory.mktemp("numba-cache")
    out, notes = _run(cache)
    assert notes == []
    return cache, out


@pytest.mark.parametrize("suffix, damage", [
    (".nbi", lambda p: p.write_bytes(p.read_bytes()[:10])),          # truncated index
    (".nbc", lambda p: p.write_bytes(os.urandom(4096))),              # object file overwritten
])
def test_a_damaged_entry_is_rebuilt_once_with_a_notice(filled, tmp_path, suffix, damage):
    source, expected = filled
    cache = tmp_path / "cache"
    subprocess.run(["cp", "-r", str(source), str(cache)], check=True)
    files = sorted(cache.rglob(f"*{suffix}"))
    assert files
    for path in files:
        damage(path)
    out, notes = _run(cache)
    assert out == expected
    assert notes and len(set(notes)) == len(notes)      # one notice per damaged function
    assert all("was damaged" in n and "compiling again (once)" in n for n in notes)
    out, notes = _run(cache)             # healed: loads silently
    assert out == expected and notes == []


def test_the_guard_is_charts_dispatchers_own_and_leaves_numbas_classes_alone():
    """A charts kernel with cache=True has the locked cache; numba's Cache class keeps its
    own methods, and a function of anyone else keeps numba's FunctionCache."""
    import numba
    from numba.core.caching import Cache, FunctionCache

    from charts.jit import cache_lock, njit
    from charts.solvers.status import sum_squares

    assert cache_lock.usable()
    assert type(sum_squares._cache) is not FunctionCache
    assert isinstance(sum_squares._cache, FunctionCache)
    assert Cache.load_overload.__module__ == Cache.save_overload.__module__ == "numba.core.caching"

    def users(x):
        return x
    assert type(numba.njit(cache=True)(users)._cache) is FunctionCache
    assert type(njit(cache=True)(users)._cache) is not FunctionCache   # (charts' njit)


def test_a_file_system_that_refuses_locks_caches_without_them_and_says_so_once(tmp_path):
    """flock failing (NFS without its lock daemon, some FUSE mounts): the kernels compile,
    load and give the same numbers as with the lock, and one notice says why there is none."""
    refuse = ("import errno, fcntl\n"
              "def _refuse(fd, mode):\n"
              "    raise OSError(errno.ENOLCK, 'No locks available')\n"
              "fcntl.flock = _refuse\n")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path))
    expected, _ = _run(tmp_path / "locked")
    for _ in range(2):                   # compiled and saved, then loaded
        r = subprocess.run([sys.executable, "-c", refuse + CALL], capture_output=True,
                           text=True, env=env, timeout=300)
        assert r.returncode == 0, r.stderr
        assert r.stdout == expected
        notes = [line for line in r.stderr.splitlines() if line.startswith("charts:")]
        assert len(notes) == 1 and "could not be locked" in notes[0]
