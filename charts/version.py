"""The version of charts (one place; read by the package, the CLI and result files).

`__version__` is the release.  `source_version` says which code made a result: the release
with, as a PEP 440 local label, the git commit where the package runs from a git checkout
(``0.1.0+g43be42f``; ``.dirty`` where its files differ from that commit), else a digest of
the package's own source files (``0.1.0+src.3f9a1c2e``), so that it changes whenever the
code does, on every kind of install.
"""
from __future__ import annotations

import functools
import hashlib
import subprocess
from pathlib import Path

__all__ = ["__version__", "source_version", "source_digest", "source_commit"]

__version__ = "0.1.0"

_PACKAGE = Path(__file__).resolve().parent


@functools.lru_cache(maxsize=None)
def source_digest() -> str:
    """SHA-256 (first 8 hex digits) of the package's Python files and the generated kernels,
    by relative path and content."""
    h = hashlib.sha256()
    generated = _PACKAGE.parent / "generated"
    roots = [("charts", _PACKAGE)] + ([("generated", generated)] if generated.is_dir() else [])
    for name, root in roots:
        for path in sorted(root.rglob("*.py")):
            h.update(f"{name}/{path.relative_to(root).as_posix()}\0".encode())
            h.update(path.read_bytes())
    return h.hexdigest()[:8]


@functools.lru_cache(maxsize=None)
def source_commit() -> str | None:
    """The short git commit of the checkout the package runs from, with ``.dirty`` where the
    package's files differ from it; None outside a git checkout (or without git)."""
    def git(*args, where=_PACKAGE):
        return subprocess.run(["git", "-C", str(where), *args], capture_output=True,
                              text=True, timeout=10)
    try:
        top = git("rev-parse", "--show-toplevel")
        root = Path(top.stdout.strip())
        if top.returncode != 0 or not (root / "charts").resolve() == _PACKAGE:
            return None
        head = git("rev-parse", "--short=7", "HEAD")
        if head.returncode != 0:
            return None
        dirty = git("status", "--porcelain", "--untracked-files=no", "--", "charts",
                    "generated", where=root)
        return head.stdout.strip() + (".dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return None


@functools.lru_cache(maxsize=None)
def source_version() -> str:
    """The release and the code that made a result: ``0.1.0+g<commit>`` in a git checkout,
    else ``0.1.0+src.<digest>`` (`source_digest`)."""
    commit = source_commit()
    return f"{__version__}+g{commit}" if commit else f"{__version__}+src.{source_digest()}"
