"""Fixtures shared by the tests, built on tests/scenarios.py.

* ``CHARTS_CACHE_DIR`` points at a session temporary folder for the whole session (autouse), so
  geometry derived on demand (N >= 7) never lands in the user's ~/.cache/charts;
* ``derived_n7``: N = 7 derived once per session (per xdist worker) in a fresh process with its
  own hash seed, into that folder.  Every test that uses N >= 7 requests it (directly or
  through ``system7``), so the derivation in that process is the first one of the session
  (tests/test_ondemand.py checks its cost report);
* ``members(result)``: the members of an ensemble result, whatever its container.
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys

import pytest

N_LARGE = 7


@pytest.fixture(scope="session", autouse=True)
def charts_cache_dir(tmp_path_factory):
    """A fresh CHARTS_CACHE_DIR for the session."""
    cache = tmp_path_factory.mktemp("charts-cache")
    old = os.environ.get("CHARTS_CACHE_DIR")
    os.environ["CHARTS_CACHE_DIR"] = str(cache)
    yield cache
    if old is None:
        os.environ.pop("CHARTS_CACHE_DIR", None)
    else:
        os.environ["CHARTS_CACHE_DIR"] = old


@pytest.fixture
def python_sigint():
    """SIGINT raising KeyboardInterrupt in this process for the test (Python's own handler),
    whatever the disposition the test run inherited: a shell starts a background job with
    SIGINT ignored, and Python then leaves it ignored."""
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)


@pytest.fixture(scope="session")
def derived_n7(charts_cache_dir):
    """Derive N = 7 in a fresh process (own hash seed) into the session cache.
    Returns (cache folder, path of the derived module, the process's stderr)."""
    env = dict(os.environ, CHARTS_CACHE_DIR=str(charts_cache_dir), PYTHONHASHSEED="12345")
    code = ("from charts.codegen.cache import load_or_generate; "
            f"m = load_or_generate({N_LARGE}); print(m.__file__)")
    p = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return charts_cache_dir, p.stdout.strip(), p.stderr


@pytest.fixture(scope="session")
def system7(derived_n7):
    """RotorSystem(7) with the "n7" masses, from the session's derivation."""
    from charts import RotorSystem

    from scenarios import masses
    return RotorSystem(N_LARGE, masses("n7", N_LARGE))


def members(result):
    """The member results of ``lyapunov_ensemble`` / ``hyperbolicity_ensemble``, whatever
    their container: an object with ``.members`` (charts.EnsembleResult), the tuple
    (mean, stderr, members) or a plain list."""
    if hasattr(result, "members"):
        return list(result.members)
    if isinstance(result, tuple) and len(result) == 3 and isinstance(result[2], list):
        return list(result[2])
    return list(result)

