"""The generated modules shipped in ``generated/`` (``charts.generated``): written, compared
and imported here.

`write_all` is the one writer (``scripts/generate.py`` and ``charts generate`` call it);
`stale_files` compares a folder with a fresh derivation; `import_shipped` imports one module
and, when the installed file is damaged (truncated, edited, not Python), says which file and
the command that repairs it instead of a traceback from inside it.  Light at import: SymPy
is loaded only to derive.
"""
from __future__ import annotations

import difflib
import importlib
import importlib.util
import sys
import tempfile
import time
from pathlib import Path

from ..io.atomic import atomic_write

__all__ = ["write_all", "compare", "stale_files", "import_shipped", "DamagedModuleError",
           "REPAIR"]

#: What repairs a damaged or stale shipped module (rewrites charts.generated in place).
REPAIR = "`charts generate` (or reinstall charts)"


class DamagedModuleError(ImportError):
    """A shipped generated module that does not import; the message names the file and
    `REPAIR`."""


def write_all(outdir: Path, ns=None, verbose=True) -> dict:
    """Write every shipped module into ``outdir``: ``__init__.py``, ``rotor_nN.py`` and
    ``rotor_nN_paper.py`` for N in ``ns`` (default `SHIPPED_N`) and the mechanisms' jets
    (``charts.codegen.mechanism.write_shipped``: the rotors, the triple linkage, the Appendix
    linkage); returns the seconds each N (each mechanism) took."""
    from .emit import SHIPPED_N, init_source, module_name, module_source
    from .symbolic import ChartGeometry

    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    timings = {}
    atomic_write(outdir / "__init__.py", init_source().encode("utf-8"))
    for n in SHIPPED_N if ns is None else ns:
        t0 = time.perf_counter()
        G = ChartGeometry(n, n - 1)  # one derivation, two modules (the family, its paper member)
        for paper in (False, True):
            atomic_write(outdir / f"{module_name(n, paper)}.py",
                         module_source(n, paper, G).encode("utf-8"))
        timings[f"N={n}"] = time.perf_counter() - t0
        if verbose:
            print(f"  N={n}: {timings[f'N={n}']:.1f} s", flush=True)
    from .mechanism import write_shipped

    timings.update(write_shipped(outdir, verbose))
    return timings


def compare(new: Path, old: Path) -> list:
    """Unified diff lines between two generated folders (empty when equal)."""
    diff = []
    names = sorted({p.name for p in Path(new).glob("*.py")} | {p.name for p in Path(old).glob("*.py")})
    for name in names:
        a, b = (_lines(Path(old) / name), _lines(Path(new) / name))
        diff += list(difflib.unified_diff(a, b, f"generated/{name}", f"regenerated/{name}"))
    return diff


def _lines(path: Path) -> list:
    try:
        return path.read_text(encoding="utf-8").splitlines(keepends=True)
    except FileNotFoundError:
        return []
    except (OSError, UnicodeDecodeError) as exc:       # a damaged file differs everywhere
        return [f"<unreadable: {exc}>\n"]


def stale_files(folder: Path) -> tuple:
    """(names of the modules in ``folder`` that differ from a fresh derivation, the diff)."""
    with tempfile.TemporaryDirectory() as tmp:
        write_all(Path(tmp), verbose=False)
        diff = compare(Path(tmp), folder)
    names = sorted({line[len("--- generated/"):].split("\t")[0].strip()
                    for line in diff if line.startswith("--- generated/")})
    return names, diff


def _origin(full: str) -> str:
    """The file a module would be imported from (found without executing it)."""
    try:
        spec = importlib.util.find_spec(full)
    except Exception:               # noqa: BLE001 - the message must not fail in turn
        spec = None
    return spec.origin if spec is not None and spec.origin else full


def import_shipped(name: str):
    """``charts.generated.<name>``; `DamagedModuleError` naming the file and `REPAIR` when it
    exists but does not import, or imports without its last line (``COMPLETE``: cut short)."""
    full = f"charts.generated.{name}"
    try:
        mod = importlib.import_module(full)
        if getattr(mod, "COMPLETE", False) is not True:
            sys.modules.pop(full, None)
            raise ImportError("the file ends before its last line (COMPLETE = True): cut short")
        return mod
    except ModuleNotFoundError as exc:
        if exc.name in (full, "charts.generated"):
            raise DamagedModuleError(f"{full} is missing from this installation; repair it "
                                     f"with {REPAIR}") from None
        raise
    except Exception as exc:        # noqa: BLE001 - whatever a damaged file raises
        raise DamagedModuleError(
            f"{_origin(full)}: the shipped generated module is damaged and does not "
            f"import ({type(exc).__name__}: {' '.join(str(exc).split())[:200]}); repair it "
            f"with {REPAIR}") from None
