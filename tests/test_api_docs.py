"""The documentation site (docs/conf.py: the README, the guide pages of docs/ read by MyST, and
the API reference written by Sphinx autodoc from the docstrings) builds without a single
warning, holds every guide page, and documents every public name of ``charts``."""
import posixpath
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def _toctree_pages():
    """The pages docs/index.md lists in its toctrees."""
    text = (DOCS / "index.md").read_text(encoding="utf-8")
    pages = []
    for block in re.findall(r"```\{toctree\}\n(.*?)```", text, flags=re.S):
        pages += [line.strip() for line in block.splitlines()
                  if line.strip() and not line.startswith(":")]
    return pages


def test_every_guide_page_is_in_the_site():
    """A page of docs/ that no toctree lists would build as an orphan (a warning) and be
    unreachable from the site's index."""
    listed = set(_toctree_pages())
    pages = {p.stem for p in DOCS.glob("*.md") if p.name != "index.md"}
    assert pages - listed == set()
    assert listed - pages <= {"api"}


def test_the_site_builds_without_warnings_and_covers_every_public_name(tmp_path):
    pytest.importorskip("sphinx")          # in the test extra; skipped only where removed
    pytest.importorskip("myst_parser")
    from sphinx.util.inventory import InventoryFile

    import charts
    out = tmp_path / "html"
    r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                        "-d", str(tmp_path / "doctrees"), str(DOCS), str(out)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    with open(out / "objects.inv", "rb") as fh:
        inventory = InventoryFile.load(fh, "", posixpath.join)
    documented = {name for entries in inventory.values() for name in entries}
    missing = [n for n in charts.__all__ if f"charts.{n}" not in documented]
    assert missing == []
    assert "charts.AngleResult.statistics" in documented               # methods listed
    page = (out / "api.html").read_text(encoding="utf-8")
    assert "lyapunov_spectrum" in page and "Parameters" in page
    # the guide pages are pages of the site, with their titles, and the README is its front page
    for page in _toctree_pages():
        assert (out / f"{page}.html").exists(), page
    titles = {"index": "Geodesic flows on the configuration manifolds",
              "reproduce": "Reproducing the paper",
              "scenes": "Scenes",
              "performance": "Performance",
              "hyperbolicity": "hyperbolicity"}
    for page, title in titles.items():
        assert title in (out / f"{page}.html").read_text(encoding="utf-8"), page
    # links between the pages resolve to pages of the site (the README's docs/X.md too)
    front = (out / "index.html").read_text(encoding="utf-8")
    assert 'href="reproduce.html"' in front and 'href="performance.html#first-use"' in front
