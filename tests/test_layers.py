"""The layers of the package (README, Layout): data flows down, nothing imports from above.

Every module of ``charts/`` and ``generated/`` is parsed (``ast``, nothing is imported) and
each of its imports, at the top or inside a function (the lazy ones count), is checked
against `LAYERS`.  Imports by name (``importlib.import_module``) are not seen: the loaders of
generated code (``charts.codegen.shipped``, ``charts.codegen.mechanism``) and of result
types (``charts.io.archive.KINDS``) use them.  The generated modules import nothing written by
hand (`GENERATED_MAY_IMPORT`), as the code generator's output for an unshipped N (the
on-demand cache) does.
"""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: The layers, lowest first (the folders of ``charts/``; a top-level module by its name): a
#: module may import from its own layer and from the layers below it.
LAYERS = (
    ("generated",),                         # the generated kernels: see GENERATED_MAY_IMPORT
    ("version",),                           # the package's version
    ("jit",),                               # the compile machinery (numba: adaptations, calls)
    ("io",),                                # results on disk (result types by name)
    ("codegen",),                           # the symbolic derivation and its emitter
    ("geometry",),                          # the manifold, the atlas, projections, kernels
    ("flows",),                             # the equations (8), (14), (16), (17), (19)
    ("plotting",),                          # figures; the results' plot() import it lazily
    ("solvers",),                           # steppers, the loop, formulations, integrate
    ("mechanism",),                         # symbolic holonomic mechanisms (charts.mechanism)
    ("analyses",),                          # Lyapunov, curvature, CLVs, spectra, ...
    ("runs", "data"),                       # scenes, sweeps, benchmarks; the bundled TOML files
    ("cli", "__main__"),                    # the ``charts`` command, ``python -m charts``
    ("__init__",),                          # the public surface, charts/__init__.py
)
RANK = {name: i for i, names in enumerate(LAYERS) for name in names}

#: What a generated module may import: the standard library's math and numpy, nothing of
#: charts and no numba (the loader makes its kernels callable from compiled code).
GENERATED_MAY_IMPORT = {"math", "numpy"}


def modules(root: Path) -> dict[str, Path]:
    """Dotted name -> file of every module of ``charts/`` and ``generated/`` (installed as
    ``charts.generated``) under ``root``."""
    out = {}
    for package, folder in (("charts", root / "charts"), ("charts.generated", root / "generated")):
        for path in sorted(folder.rglob("*.py")):
            parts = list(path.relative_to(folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            out[".".join([package, *parts])] = path
    return out


def layer(module: str) -> str:
    """The layer of a dotted ``charts`` module name."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def imports(module: str, path: Path, known) -> list[tuple[str, int]]:
    """(imported module, line) of every import in the file, relative ones resolved; for
    ``from P import x`` the module P.x when it is one, else P."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            out += [(alias.name, node.lineno) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                parts = parts[:len(parts) - node.level + 1] + ([node.module] if node.module else [])
                base = ".".join(parts)
            else:
                base = node.module
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                out.append((sub if sub in known else base, node.lineno))
    return list(dict.fromkeys(out))


def violations(root: Path) -> list[str]:
    """Every import in ``root``'s package that breaks the layers, one line each."""
    known = modules(root)
    bad = []
    for module, path in known.items():
        for target, line in imports(module, path, known):
            top = target.split(".")[0]
            where = f"{path.relative_to(root)}:{line}"
            if layer(module) == "generated":
                if top not in GENERATED_MAY_IMPORT:
                    bad.append(f"{where}: generated code imports {target} (only "
                               f"{sorted(GENERATED_MAY_IMPORT)}: regenerate without it)")
            elif top == "charts" and RANK[layer(target)] > RANK[layer(module)]:
                bad.append(f"{where}: {module} (layer {layer(module)}) imports {target} "
                           f"(layer {layer(target)}, above it)")
    return bad


def test_every_module_has_a_layer():
    assert {layer(m) for m in modules(ROOT)} <= set(RANK)


def test_nothing_imports_from_above_and_generated_code_imports_nothing_hand_written():
    assert violations(ROOT) == []


def test_the_emitter_writes_modules_that_import_math_only():
    """The on-demand cache (N >= 7) writes `module_source`'s output: the same rule."""
    from charts.codegen.emit import module_source

    for paper in (False, True):
        tree = ast.parse(module_source(3, paper))
        names = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import)
                 for alias in node.names}
        names |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
        assert names == {"math"}


def test_the_chart_right_hand_side_bound_by_hand_stays_cached_on_disk():
    """Binding a generated module's kernels in ``charts.flows.chart`` keeps numba's on-disk
    cache: a second process loads the compiled right-hand side without compiling it."""
    code = ("from charts.jit.compilation import compile_timer\n"
            "from charts.solvers.chart_formulation import chart_rhs\n"
            "spent = []\n"
            "with compile_timer(spent.append):\n"
            "    chart_rhs(3, True)\n"
            "print(sum(spent))\n")
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
            for _ in range(2)]
    assert all(r.returncode == 0 for r in runs), runs[-1].stderr
    assert float(runs[1].stdout) == 0.0


@pytest.mark.parametrize("source, expect", [
    ("from charts.flows.chart import rates\n", "generated code imports charts.flows.chart"),
    ("from numba.extending import register_jitable\n", "generated code imports numba.extending"),
])
def test_the_check_sees_what_it_forbids(tmp_path, source, expect):
    """A layer broken on purpose in a copy of the layout is reported."""
    for name in ("charts/__init__.py", "charts/geometry/__init__.py", "charts/geometry/low.py",
                 "charts/flows/__init__.py", "charts/flows/high.py", "generated/__init__.py"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("")
    (tmp_path / "charts/geometry/low.py").write_text("def f():\n    from ..flows.high import g\n")
    (tmp_path / "generated/rotor_n3.py").write_text("import math\n" + source)
    bad = violations(tmp_path)
    assert any("low.py:2: charts.geometry.low (layer geometry) imports charts.flows.high" in b
               for b in bad)
    assert any(expect in b for b in bad)
    assert len(bad) == 2
