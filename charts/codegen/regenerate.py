"""Writing and comparing the generated modules shipped in ``generated/``: `write_all` is the
one writer (``scripts/generate.py`` and ``charts generate`` call it); `stale_files` compares a
folder with a fresh derivation.  SymPy is loaded only to derive.
"""
from __future__ import annotations

import difflib
import tempfile
import time
from pathlib import Path

from ..io.atomic import atomic_write

__all__ = ["write_all", "compare", "stale_files"]


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
