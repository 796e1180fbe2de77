"""Atomic file writes, the one helper every layer uses (generated-code cache, result files,
checkpoints, tables, figures): a temporary file in the same folder, flushed to disk, then
``os.replace`` — readers and concurrent workers see the old file or the new one, never a part.
No imports from the package: any layer may use it."""
from __future__ import annotations

import contextlib
import os
import signal
import threading
from pathlib import Path

__all__ = ["atomic_write", "signals_deferred"]


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


@contextlib.contextmanager
def signals_deferred():
    """Ctrl-C (SIGINT) and SIGTERM taken only once the block is done (in the main thread,
    where Python runs its signal handlers; elsewhere nothing changes): a file being written
    is finished first.  The handlers in place are noted and put back, and a signal received
    meanwhile is raised again then, to them.  For writers whose library leaves noise behind
    when interrupted halfway (h5netcdf's ``Exception ignored in: <function File.close …>``
    from a file object whose construction a KeyboardInterrupt cut short)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught, old = [], {}
    try:
        for signum in (signal.SIGINT, signal.SIGTERM):
            old[signum] = signal.signal(signum, lambda s, frame: caught.append(s))
    except (ValueError, OSError):
        for signum, h in old.items():
            signal.signal(signum, h)
        yield
        return
    try:
        yield
    finally:
        for signum, h in old.items():
            if h is not None:                   # None: a handler not set from Python
                signal.signal(signum, h)
        if caught:
            signal.raise_signal(caught[0])
