"""Every module of the package imports (a renamed or removed module leaves no stale import
behind, in modules that no other test happens to load)."""
from __future__ import annotations

import importlib
import pkgutil

import pytest

import charts

MODULES = sorted(m.name for m in pkgutil.walk_packages(charts.__path__, "charts."))


def test_the_package_has_its_layers():
    for layer in ("geometry", "codegen", "flows", "solvers", "analyses", "runs", "plotting", "cli"):
        assert f"charts.{layer}" in MODULES


@pytest.mark.parametrize("name", MODULES)
def test_module_imports(name):
    importlib.import_module(name)
