"""Reading the TOML input files (scenes, sweeps): bounded before anything is parsed.

A scene or sweep file must be a regular file of at most `MAX_BYTES`, valid UTF-8 TOML,
nested at most `MAX_DEPTH` tables or arrays deep.  Anything else — a FIFO nobody writes,
``/dev/zero``, a folder, a file of 3000 nested tables — is refused at once in one line
naming the file, never hangs, eats memory or ends in a ``RecursionError`` (docs/reliability.md).
"""
from __future__ import annotations

import os
import stat
from pathlib import Path

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["read_toml", "MAX_BYTES", "MAX_DEPTH"]

#: Largest scene or sweep file read (the bundled ones are under 4 KiB).
MAX_BYTES = 1 << 20
#: Deepest nesting of tables and arrays accepted (a scene uses 3: [effects.name] lists).
MAX_DEPTH = 16


def read_toml(path, what: str, error, missing_hint: str = "") -> dict:
    """The TOML table of the ``what`` file at ``path``; ``error`` (an exception class) with
    one line naming the file for a missing, non-regular, oversized, unreadable, non-UTF-8,
    invalid or too deeply nested file."""
    path = Path(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise error(f"{path}: no such {what} file{missing_hint}") from None
    except OSError as exc:
        raise error(f"{path}: cannot read the {what}: {exc.strerror or exc}") from None
    if not stat.S_ISREG(st.st_mode):
        raise error(f"{path}: the {what} is not a regular file (it is {_kind(st.st_mode)}); "
                    "give the path of a .toml file")
    if st.st_size > MAX_BYTES:
        raise error(f"{path}: the {what} file has {st.st_size} bytes, more than the "
                    f"{MAX_BYTES} a {what} may have")
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
        if len(raw) > MAX_BYTES:
            raise error(f"{path}: the {what} file has more than the {MAX_BYTES} bytes a "
                        f"{what} may have")
        data = tomllib.loads(raw.decode("utf-8"))
    except (OSError, UnicodeDecodeError) as exc:
        raise error(f"{path}: cannot read the {what}: {exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: not valid TOML: {exc}") from None
    except (RecursionError, MemoryError):
        raise error(f"{path}: the {what} nests its tables or arrays too deeply to read "
                    f"(at most {MAX_DEPTH} levels)") from None
    depth = nesting_depth(data)
    if depth > MAX_DEPTH:
        raise error(f"{path}: the {what} nests its tables or arrays {depth} levels deep; at "
                    f"most {MAX_DEPTH} are allowed")
    return data


def nesting_depth(value) -> int:
    """How many tables and arrays deep ``value`` goes (0 for a number or string), without
    recursion."""
    deepest, stack = 0, [(value, 0)]
    while stack:
        v, d = stack.pop()
        if isinstance(v, dict):
            stack.extend((x, d + 1) for x in v.values())
            deepest = max(deepest, d + 1)
        elif isinstance(v, list):
            stack.extend((x, d + 1) for x in v)
            deepest = max(deepest, d + 1)
    return deepest


def _kind(mode: int) -> str:
    return ("a folder" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
            else "a character device" if stat.S_ISCHR(mode)
            else "a block device" if stat.S_ISBLK(mode)
            else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
