"""Output folders of ``charts run``, ``charts sweep`` and ``charts reproduce``: checked before
any work starts, and locked while a process writes into them.

:func:`prepare_output` refuses, in one sentence naming the folder, a path that exists as a
file, lies under a file, has a name too long for the file system, or cannot be created or
written; it creates the folder otherwise.

:class:`OutputLock` is a lock file ``DIR/.charts.lock`` (created with ``O_EXCL``) holding
the writer's pid, host, process start time and command.  A second writer refuses with
those details.  A lock left by a process that no longer runs (killed with SIGKILL, say) is
recognised on the same host — its pid is gone, or belongs to a process started at another
time — and taken over with a message; a lock from another host is never broken silently
(the message says which file to delete).  Neither is anything at the lock's path that
charts did not write — a folder, or a file whose pid is not a process id: the refusal says
what it is and what to remove.  Whatever a command deletes or overwrites in its folder, it
deletes only after it holds the lock (``charts run --force``: ``charts.runs.runner``).
"""
from __future__ import annotations

import errno
import json
import os
import socket
import sys
import time
from pathlib import Path

from ..geometry.checks import shown

__all__ = ["OutputError", "prepare_output", "check_output", "check_writable", "OutputLock",
           "LOCK"]

LOCK = ".charts.lock"
#: A lock file still empty after this many seconds is the trace of a writer killed between
#: creating and filling it.
EMPTY_LOCK_GRACE_S = 10.0


class OutputError(ValueError):
    """The output folder cannot be used (a file, under a file, too long, not writable, or
    locked by another writer); the message names it and says what to do."""


def _name_max(folder: Path) -> int:
    try:
        return os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError):
        return 255


def _path_max() -> int:
    try:
        return os.pathconf("/", "PC_PATH_MAX")
    except (OSError, ValueError):
        return 4096


def _short(path: Path) -> str:
    text = str(path)
    return text if len(text) <= 60 else f"{text[:28]}…{text[-28:]}"


def prepare_output(path, what: str = "-o") -> Path:
    """Check ``path`` as an output folder (:func:`check_output`) and create it;
    :class:`OutputError` if unusable."""
    path = check_output(path, what)
    try:
        path.mkdir(parents=True, exist_ok=True)
        probe = path / f".charts-write-probe-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise OutputError(f"{what} {_short(path)}: cannot create or write the folder ({reason}); "
                          "choose a writable place") from None
    return path


def check_output(path, what: str = "-o") -> Path:
    """Refuse (:class:`OutputError`) an output folder that is a file, lies under a file, or
    whose name or path is too long, or that is not a path at all; creates nothing."""
    if isinstance(path, bytes) or not isinstance(path, (str, os.PathLike)) or str(path) == "":
        raise OutputError(f"{what} must be a folder path (a non-empty str or os.PathLike), got "
                          f"{shown(path)}")
    path = Path(path)
    _folder_anchor(path, what)
    return path


def _folder_anchor(path: Path, what: str) -> Path:
    """The nearest existing folder of the output folder ``path`` (itself if it exists), after
    `check_output`'s refusals."""
    _check_lengths(path, what)
    if path.exists() and not path.is_dir():
        raise OutputError(f"{what} {path}: exists and is a file, not a folder; choose a folder")
    anchor = path.absolute()
    while not anchor.exists():
        anchor = anchor.parent
    if not anchor.is_dir():
        raise OutputError(f"{what} {path}: {anchor} is a file, so no folder can be created "
                          "under it; choose another place")
    return anchor


def check_writable(path, what: str, *, folder: bool = False) -> Path:
    """Refuse (:class:`OutputError`), before any work and creating nothing, an output that
    could not be written at the end: for a folder (``folder=True``) what `check_output`
    refuses and a nearest existing folder this process may not write in (``os.access``); for
    a file (written through a temporary file beside it, ``charts.io.atomic``) a path that is
    an existing folder, whose folder does not exist, is a file, or may not be written in,
    or whose name or path is too long."""
    path = Path(path)
    if folder:
        anchor = _folder_anchor(path, what)
    else:
        _check_lengths(path, what)
        if path.is_dir():
            raise OutputError(f"{what} {path}: is a folder, not a file; give a file name")
        anchor = path.absolute().parent
        if not anchor.exists():
            raise OutputError(f"{what} {path}: the folder {anchor} does not exist; create it or "
                              "choose another place")
        if not anchor.is_dir():
            raise OutputError(f"{what} {path}: {anchor} is a file, not a folder; choose "
                              "another place")
    if not os.access(anchor, os.W_OK | os.X_OK):
        raise OutputError(f"{what} {path}: cannot write in the folder {anchor} (permission "
                          "denied or a read-only file system); choose a writable place")
    return path


def _check_lengths(path: Path, what: str) -> None:
    """Refuse a path with a name or a whole length beyond what the file system allows."""
    limit = _name_max(Path(path.anchor or "."))
    for name in path.parts:
        if len(name.encode()) > limit:
            raise OutputError(f"{what} {_short(path)}: the name {name[:20]}… has "
                              f"{len(name.encode())} bytes, more than this file system allows "
                              f"({limit}); choose a shorter name")
    full = len(str(path.absolute()).encode())
    if full >= _path_max():
        raise OutputError(f"{what} {_short(path)}: the path has {full} bytes, more than this "
                          f"system allows ({_path_max()}); choose a shorter path")


def _start_time(pid: int) -> str | None:
    """The start time of process ``pid`` (Linux /proc; None where unknown)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    return stat.rsplit(")", 1)[1].split()[19]


def _pid(value) -> int | None:
    """``value`` as a process id (an int 1 … 2²² as charts writes it), else None."""
    if isinstance(value, bool) or not isinstance(value, int) or not 0 < value < 2 ** 22:
        return None
    return value


def _alive(pid: int) -> bool:
    """Whether process ``pid`` runs (a zombie, killed but not yet reaped by its parent, does
    not: in a container whose first process reaps nothing it stays a zombie for good)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return True
    return state not in ("Z", "X")


class OutputLock:
    """``with OutputLock(folder, command):`` — the only writer of ``folder`` (see module)."""

    def __init__(self, folder, command: str = "charts"):
        self.path = Path(folder) / LOCK
        self.me = {"pid": os.getpid(), "host": socket.gethostname(),
                   "start": _start_time(os.getpid()), "command": command,
                   "since": time.strftime("%Y-%m-%d %H:%M:%S")}
        self.held = False

    def acquire(self) -> "OutputLock":
        for _ in range(3):
            self._refuse_foreign()
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                if not self._stale():
                    raise OutputError(self._refusal()) from None
                continue
            except OSError as exc:
                raise OutputError(f"-o {self.path.parent}: cannot create the lock file "
                                  f"{self.path.name} ({exc.strerror})") from None
            with os.fdopen(fd, "w") as fh:
                fh.write(json.dumps(self.me))
            self.held = True
            return self
        raise OutputError(self._refusal())

    def _holder(self) -> dict | None:
        """The lock's content: {} if it vanished, None if empty, torn or not a JSON object."""
        try:
            h = json.loads(self.path.read_text())
        except FileNotFoundError:
            return {}
        except (OSError, ValueError):
            return None
        return h if isinstance(h, dict) and h else None

    def _refuse_foreign(self) -> None:
        """OutputError (one line) for something at the lock's path that no charts process
        wrote: a folder or other non-file, or a lock whose pid is not a process id."""
        if self.path.is_symlink() or (self.path.exists() and not self.path.is_file()):
            kind = "a folder" if self.path.is_dir() else "not a regular file"
            raise OutputError(f"-o {self.path.parent}: {self.path} is {kind}, not a charts lock "
                              "file; remove it if no charts process is writing into this "
                              "folder, then run again")
        h = self._holder()
        if h and _pid(h.get("pid")) is None:
            raise OutputError(f"-o {self.path.parent}: the lock file {self.path} holds "
                              f"pid {h.get('pid')!r}, not a process id, so charts cannot tell "
                              "whether its writer still runs; delete it if no charts process is "
                              "writing into this folder, then run again")

    def _stale(self) -> bool:
        """Whether the existing lock belongs to no running process (then it is removed)."""
        h = self._holder()
        if h == {}:                                    # vanished meanwhile: try again
            return True
        if h is None:                                  # empty or torn: killed while writing it
            try:
                age = time.time() - self.path.stat().st_mtime
            except FileNotFoundError:
                return True
            if age < EMPTY_LOCK_GRACE_S:
                return False
            reason = "an empty lock file"
        elif h.get("host") != self.me["host"]:
            return False
        elif _pid(h.get("pid")) is None:               # not a process id: never broken
            return False
        elif _alive(_pid(h["pid"])) and _start_time(_pid(h["pid"])) in (None, h.get("start")):
            return False
        else:
            reason = f"pid {h['pid']} ({h.get('command', '?')}) is no longer running"
        print(f"charts: removing a stale lock in {self.path.parent}: {reason}",
              file=sys.stderr, flush=True)
        try:
            self.path.unlink()
        except FileNotFoundError:
            pass
        return True

    def _refusal(self) -> str:
        h = self._holder() or {}
        who = (f"pid {h.get('pid', '?')} on {h.get('host', '?')} ({h.get('command', '?')}, "
               f"since {h.get('since', '?')})")
        return (f"-o {self.path.parent}: another process is writing into this folder: {who}; "
                "wait for it to finish or choose another folder (if that process is gone, "
                f"delete {self.path})")

    def release(self) -> None:
        if self.held:
            self.held = False
            h = self._holder()
            if h and h.get("pid") == self.me["pid"] and h.get("host") == self.me["host"]:
                try:
                    self.path.unlink()
                except OSError as exc:
                    if exc.errno != errno.ENOENT:
                        raise

    def __enter__(self):
        return self.acquire()

    def __exit__(self, *exc):
        self.release()
