"""Generated geometry for N not shipped in ``generated/``: derived once, cached on disk.

The same generator (``charts.codegen.emit.module_source``) writes the same bytes that
``scripts/generate.py`` would; the module is stored under the cache folder
(``$CHARTS_CACHE_DIR``, default ``~/.cache/charts``) keyed by N, the SymPy version and a
hash of the generator's source,
and imported from there.  The first derivation's cost is reported on stderr.

What is loaded is checked: beside each module ``rotor_nN.py`` lies ``rotor_nN.py.sha256``,
the SHA-256 of its bytes, written after the module.  A module whose hash is missing or does
not match (half-written by a full disk, edited, or left by an interrupted derivation), or
that does not import, is derived again with a message on stderr.  Derivation is serialised
by a file lock (``rotor_nN.lock``, ``fcntl.flock``; released by the kernel if the process
dies): two processes that need the same N at once derive it once, the second waits and
loads the first one's file.  `load_or_write` is that machinery for any generated module: a
mechanism's jets (``charts.codegen.mechanism``) are cached through it, keyed by their model.
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import os
import shutil
import sys
import time
from pathlib import Path

import sympy

from ..io.atomic import atomic_write
from .emit import module_name, module_source

__all__ = ["cache_dir", "load_or_generate", "load_or_write"]


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


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _say(msg: str) -> None:
    print(f"charts: {msg}", file=sys.stderr, flush=True)


@contextlib.contextmanager
def _derivation_lock(path: Path, what: str):
    """An exclusive ``flock`` on ``path`` (waits, saying so, while another process holds it)."""
    try:
        import fcntl
    except ImportError:                 # no flock on this platform: atomic writes only
        yield
        return
    with open(path, "a") as fh:
        try:
            fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            _say(f"waiting for another process deriving the {what} ({path})")
            fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def _problem(path: Path) -> str | None:
    """Why the cached module at ``path`` cannot be used (None if its hash matches)."""
    sidecar = path.with_name(path.name + ".sha256")
    if not path.exists() and not path.is_symlink():
        return "missing"
    if not path.is_file():
        return "it is not a file"
    if not sidecar.exists():
        return "its hash file is missing (an interrupted derivation?)"
    if not sidecar.is_file():
        return "its hash file is not a file"
    try:
        if sidecar.read_text().strip() != _digest(path.read_bytes()):
            return "its contents do not match the stored hash (corrupt or stale)"
    except (OSError, UnicodeDecodeError) as exc:
        return f"it cannot be read ({exc})"
    return None


def _clear(path: Path) -> None:
    """Remove whatever occupies one of the cache's own names (a file, a link or a folder)."""
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    elif path.exists() or path.is_symlink():
        path.unlink()


def _folder() -> Path:
    """The cache folder, created; a file in its place (a damaged cache) is replaced, with a
    message; a ``CHARTS_CACHE_DIR`` that is not a folder is a ValueError naming it."""
    folder = cache_dir()
    root = folder.parent                              # CHARTS_CACHE_DIR (or ~/.cache/charts)
    if root.exists() and not root.is_dir():
        raise ValueError(f"the geometry cache {root} is not a folder: remove it or set "
                         "CHARTS_CACHE_DIR to a folder")
    if (folder.exists() or folder.is_symlink()) and not folder.is_dir():
        _say(f"the geometry cache {folder} is not a folder; replacing it")
        _clear(folder)
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def _derive(what: str, label: str, path: Path, reason: str, source) -> None:
    if reason != "missing":
        _say(f"the cached {what} at {path} is unusable: {reason}; deriving it again")
        for stale in (path, path.with_name(path.name + ".sha256")):
            if stale.is_dir() and not stale.is_symlink():
                _clear(stale)
    t0 = time.perf_counter()
    _say(f"deriving {what} (not shipped); cached at {path}")
    data = source().encode("utf-8")
    atomic_write(path, data)            # concurrent readers never see half a file
    atomic_write(path.with_name(path.name + ".sha256"), (_digest(data) + "\n").encode())
    _say(f"{label} derived in {time.perf_counter() - t0:.1f} s")


def _import(stem: str, path: Path):
    name = f"charts_ondemand_{stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    sys.modules[name] = mod
    return mod


def load_or_generate(n: int, paper: bool = False):
    """The generated module for N rotors (``paper``: its specialisation to a = 1, c = 0) from
    the cache, derived (once, under a file lock) when missing, corrupt or stale."""
    return load_or_write(module_name(n, paper), f"geometry for N={n}",
                         lambda: module_source(n, paper), f"N={n}")


def load_or_write(name: str, what: str, source, label: str | None = None):
    """The cached module ``name`` (``name.py`` in `cache_dir`), written from ``source()`` (its
    text; once, under a file lock) when missing, corrupt or stale.  ``what`` names it in the
    messages ("geometry for N=7"), ``label`` in the timing line (default ``what``)."""
    label = what if label is None else label
    folder = _folder()
    path = folder / f"{name}.py"
    lock = folder / f"{name}.lock"
    if lock.is_dir() and not lock.is_symlink():
        _say(f"the geometry cache's lock {lock} is a folder; replacing it")
        _clear(lock)
    with _derivation_lock(lock, what):
        reason = _problem(path)
        if reason is not None:
            _derive(what, label, path, reason, source)
        try:
            return _import(name, path)
        except Exception as exc:        # noqa: BLE001 - a hash-valid file that fails to import
            if reason is not None:      # freshly derived: a real error, not a corrupt cache
                raise
            _derive(what, label, path, f"it does not import ({type(exc).__name__}: {exc})",
                    source)
            return _import(name, path)
