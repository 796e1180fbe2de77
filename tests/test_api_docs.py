"""The API reference (docs/reference, Sphinx autodoc from the docstrings) builds without a
single warning and documents every public name of ``charts``."""
import posixpath
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_the_reference_builds_without_warnings_and_covers_every_public_name(tmp_path):
    pytest.importorskip("sphinx")          # in the test extra; skipped only where removed
    from sphinx.util.inventory import InventoryFile

    import charts
    out = tmp_path / "html"
    r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                        "-d", str(tmp_path / "doctrees"), str(ROOT / "docs" / "reference"),
                        str(out)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    with open(out / "objects.inv", "rb") as fh:
        inventory = InventoryFile.load(fh, "", posixpath.join)
    documented = {name for entries in inventory.values() for name in entries}
    missing = [n for n in charts.__all__ if f"charts.{n}" not in documented]
    assert missing == []
    assert "charts.AngleResult.statistics" in documented               # methods listed
    page = (out / "api.html").read_text(encoding="utf-8")
    assert "lyapunov_spectrum" in page and "Parameters" in page
