"""Generated geometry for N not shipped in ``generated/``: derived once, cached on disk.

The same generator (``charts.codegen.emit.module_source``) writes the same bytes that
``scripts/generate.py`` would; the module is stored under the cache folder
(``$CHARTS_CACHE_DIR``, default ``~/.cache/charts``) keyed by N, the SymPy version and a
hash of the generator's source,
and imported from there.  The first derivation's cost is reported on stderr.
"""
from __future__ import annotations

import importlib.util
import os
import sys
import time
from pathlib import Path

import sympy

from ..atomic import atomic_write
from .emit import module_name, module_source

__all__ = ["cache_dir", "load_or_generate"]


def _generator_digest() -> str:
    """Hash of the generator's source: a changed derivation never reuses a stale cache."""
    import hashlib

    here = Path(__file__).resolve().parent
    h = hashlib.sha256()
    for name in ("symbolic.py", "emit.py", "names.py"):
        h.update((here / name).read_bytes())
    return h.hexdigest()[:12]


def cache_dir() -> Path:
    root = os.environ.get("CHARTS_CACHE_DIR") or Path.home() / ".cache" / "charts"
    return Path(root) / f"generated-sympy{sympy.__version__}-{_generator_digest()}"


def load_or_generate(n: int):
    path = cache_dir() / f"{module_name(n)}.py"
    if not path.exists():
        path.parent.mkdir(parents=True, exist_ok=True)
        t0 = time.perf_counter()
        print(f"charts: deriving geometry for N={n} (not shipped); cached at {path}",
              file=sys.stderr, flush=True)
        src = module_source(n)
        atomic_write(path, src.encode("utf-8"))  # concurrent workers never see half a file
        print(f"charts: N={n} derived in {time.perf_counter() - t0:.1f} s", file=sys.stderr, flush=True)
    name = f"charts_ondemand_{module_name(n)}"
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod
