"""The scripts in examples/ run as a researcher would copy them (shortened by their time
argument) and write what they say."""
import runpy
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("script, T, files", [
    ("poincare_section.py", "300", ["poincare.png", "poincare.nc"]),
    ("lyapunov_convergence.py", "100", ["lyapunov.png", "lyapunov.nc"]),
    ("trajectory_figures.py", "4", ["angles.png", "surface.png", "rotors.gif"]),
])
def test_example_runs(script, T, files, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(sys, "argv", [script, T])
    runpy.run_path(str(EXAMPLES / script), run_name="__main__")
    for f in files:
        assert (tmp_path / f).stat().st_size > 0, f
