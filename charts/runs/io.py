"""Result files: atomic writes (never a half-written file, even on a crash), NPZ and JSON
encoding, and the version stamp every result carries."""
from __future__ import annotations

import io
import platform

import numpy as np

from ..io.atomic import atomic_write

__all__ = ["atomic_write", "atomic_text", "npz_bytes", "json_default", "versions"]


def atomic_text(path, text: str) -> None:
    """`atomic_write` of UTF-8 text."""
    atomic_write(path, text.encode("utf-8"))


def npz_bytes(arrays: dict) -> bytes:
    """The bytes of ``np.savez(**arrays)``."""
    buf = io.BytesIO()
    np.savez(buf, **arrays)
    return buf.getvalue()


def json_default(o):
    """``json.dumps(default=...)`` for NumPy arrays and scalars."""
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.bool_):
        return bool(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def versions() -> dict:
    """Versions of charts and the libraries that decide its numbers."""
    import numba
    import scipy

    from ..version import source_version
    return {"charts": source_version(), "python": platform.python_version(), "numpy": np.__version__,
            "scipy": scipy.__version__, "numba": numba.__version__}
