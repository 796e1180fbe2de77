"""Sphinx configuration of the documentation site: the README, the guide pages of docs/ (Markdown,
read by MyST) and the API reference, every public name of ``charts`` (``charts.__all__``)
documented from its docstring by autodoc (NumPy-style sections read by napoleon).

    python -m sphinx -W -b html docs docs/_build     # warnings fail

The page ``api.rst`` is written here at each build from ``charts._HOMES`` (the names grouped by
the module they live in), so a new public name appears without an edit; tests/test_api_docs.py
builds the whole site with warnings as errors.
"""
from __future__ import annotations

import inspect
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))          # the checkout's charts, also uninstalled

import charts  # noqa: E402
from charts.io.archive import Archivable  # noqa: E402

project = "charts"
author = "the charts developers"
release = charts.__version__
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "myst_parser"]
napoleon_google_docstring = False
napoleon_numpy_docstring = True
autodoc_member_order = "bysource"
autodoc_typehints = "none"
exclude_patterns = ["_build", "figures"]   # figures/: run outputs (report.md), not pages
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_heading_anchors = 4        # links to a section (page.md#first-use) resolve as on GitHub
html_theme = "alabaster"
suppress_warnings = ["ref.python"]  # bare type words in prose ("ndarray") are not links


def api_page() -> str:
    """The reST of every public name, grouped by its home module."""
    groups: dict[str, list[str]] = {}
    for name, home in charts._HOMES.items():
        groups.setdefault(f"charts{home}", []).append(name)
    lines = ["API reference", "=============", "",
             "Every name below is importable as ``charts.NAME``; each section is the module it",
             "lives in.  The narrative is in the other pages of docs/; the equations cited are",
             "the paper's.", ""]
    for module, names in groups.items():
        lines += [f"``{module}``", "-" * (len(module) + 4), ""]
        for name in names:
            obj = getattr(charts, name)
            if inspect.isclass(obj):
                lines += [f".. autoclass:: charts.{name}", "   :members:"]
                if issubclass(obj, Archivable):        # save, ==, the entropy and dimension
                    lines += ["   :inherited-members: tuple"]
                lines += [""]
            elif callable(obj):
                lines += [f".. autofunction:: charts.{name}", ""]
            else:
                lines += [f".. autodata:: charts.{name}", "   :annotation:", ""]
    lines += ["Every result", "------------", "",
              "Each result class above is an ``Archivable``: ``save(path)`` writes it as NetCDF,",
              "``charts.load(path)`` reads it back, and ``==`` compares two results by value.", "",
              ".. autoclass:: charts.io.archive.Archivable", "   :members: save",
              "   :special-members: __eq__", "",
              "``charts.runs.netcdf_results``", "-" * 34, "",
              ".. autoclass:: charts.runs.netcdf_results.SceneResult", "   :members:",
              "   :inherited-members:", "",
              ".. autoclass:: charts.runs.netcdf_results.SweepTable", "   :members:",
              "   :inherited-members:", "",
              "``charts.plotting``", "-" * 22, "",
              ".. automodule:: charts.plotting", "   :members:", ""]
    return "\n".join(lines) + "\n"


def literal_bars(app, what, name, obj, options, lines) -> None:
    """|x| in the docstrings is an absolute value or a norm, not a reST substitution."""
    for i, line in enumerate(lines):
        lines[i] = line.replace("|", "\\|")


def setup(app):
    app.connect("autodoc-process-docstring", literal_bars, priority=400)


(HERE / "api.rst").write_text(api_page(), encoding="utf-8")
