"""The public surface of ``charts`` is imported lazily (charts/__init__.py); every name must
still be there, be the object of its home module, and ``import charts`` must not import the
heavy modules (numba, scipy.optimize, xarray, matplotlib) before a name is used."""
import importlib
import subprocess
import sys

import pytest

import charts


@pytest.mark.parametrize("name", charts.__all__)
def test_every_public_name_resolves_to_its_home(name):
    value = getattr(charts, name)
    home = importlib.import_module(charts._HOMES[name], "charts")
    assert value is getattr(home, name)
    assert name in dir(charts)


def test_star_import_and_unknown_names():
    ns = {}
    exec("from charts import *", ns)
    assert set(charts.__all__) <= set(ns)
    assert len(set(charts.__all__)) == len(charts.__all__)
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        charts.no_such_name
    with pytest.raises(AttributeError):
        charts.__wrapped__
    assert charts.runs.runner.run_scene is charts.run_scene   # subpackages by attribute


def test_import_charts_imports_nothing_heavy():
    code = ("import sys, charts\n"
            "heavy = ('numba', 'scipy', 'xarray', 'matplotlib', 'sympy')\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in heavy))\n"
            "charts.lyapunov_spectrum\n"
            "print('scipy.optimize' in sys.modules, 'numba' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    assert out == ["[]", "False True"]
