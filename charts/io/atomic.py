"""Atomic file writes, the one helper every layer uses (generated-code cache, result files,
checkpoints, tables, figures): a temporary file in the same folder, flushed to disk, then
``os.replace`` — readers and concurrent workers see the old file or the new one, never a part.
No imports from the package: any layer may use it."""
from __future__ import annotations

import os
from pathlib import Path

__all__ = ["atomic_write"]


def atomic_write(path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file in the same folder, flushed to
    disk, then ``os.replace``: readers see the old file or the new one, never a part."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.tmp{os.getpid()}")
    try:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
