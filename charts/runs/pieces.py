"""The finished pieces of ``charts reproduce`` on disk, in a format that holds data only.

A piece is one task's result (a tree of dicts, lists and tuples whose leaves are NumPy
arrays, NumPy scalars, floats, ints, bools, strings or None) with the arguments that produced
it.  It is one ``.npz`` file: the arrays (and NumPy scalars, as 0-d arrays) under the names
``a0``, ``a1``, …, and under ``piece`` a JSON text that holds the format version, the task's
key and arguments and the tree, each array leaf a reference to its name.  Reading uses
``np.load(allow_pickle=False)`` and ``json.loads``: no file in the folder, whatever its
content, is ever executed, and object arrays are refused when written and when read.

A file that cannot be read as a piece (torn, written by something else, a pickle left by an
older version or planted there) is not used: its task is computed again, with a one-line
notice naming the file, and the new piece replaces it.
"""
from __future__ import annotations

import io
import json
import sys
import zipfile
from pathlib import Path

import numpy as np

from .io import atomic_write, npz_bytes

__all__ = ["SUFFIX", "FORMAT", "piece_path", "save_piece", "load_piece", "kept_pieces",
           "encode_piece", "decode_piece", "PieceError"]

SUFFIX = ".npz"
#: Written into every piece; a piece of another format version is recomputed.
FORMAT = "charts-piece-1"
_META = "piece"


class PieceError(ValueError):
    """A file that is not a readable piece of this task (the message says why)."""


def piece_path(folder, key) -> Path:
    """DIR/pieces/<kind>-n<N>-<index>.npz for the task key (kind, N, index)."""
    return Path(folder) / f"{key[0]}-n{key[1]}-{key[2]}{SUFFIX}"


def kept_pieces(folder) -> list:
    """The piece files in ``folder`` (for the count of what an interrupted run kept)."""
    return sorted(Path(folder).glob(f"*{SUFFIX}"))


def _args_text(args) -> str:
    return json.dumps(list(args))


def _key_text(key) -> str:
    return json.dumps(list(key))


# ------------------------------------------------------------------------ the tree
def _encode(x, arrays):
    if isinstance(x, (np.ndarray, np.generic)):
        a = np.asarray(x)
        if a.dtype.hasobject:
            raise TypeError("a piece cannot hold object arrays")
        name = f"a{len(arrays)}"
        arrays[name] = a
        return {"array": name, "scalar": isinstance(x, np.generic)}
    if x is None or isinstance(x, (bool, int, float, str)):
        return {"value": x, "type": type(x).__name__}
    if isinstance(x, (list, tuple)):
        return {"seq": [_encode(v, arrays) for v in x], "tuple": isinstance(x, tuple)}
    if isinstance(x, dict):
        items = []
        for k, v in x.items():
            if not (isinstance(k, (str, float, int)) and not isinstance(k, bool)):
                raise TypeError(f"a piece's dict keys must be str, int or float, got {k!r}")
            items.append([k, type(k).__name__, _encode(v, arrays)])
        return {"dict": items}
    raise TypeError(f"a piece cannot hold a {type(x).__name__}")


_SCALARS = {"NoneType": lambda v: None, "bool": bool, "int": int, "float": float, "str": str}


def _decode(node, arrays):
    if not isinstance(node, dict):
        raise PieceError("malformed tree")
    if "array" in node:
        a = arrays[node["array"]]
        return a[()] if node.get("scalar") else a
    if "value" in node:
        conv = _SCALARS.get(node.get("type"))
        if conv is None:
            raise PieceError(f"unknown leaf type {node.get('type')!r}")
        return conv(node["value"])
    if "seq" in node:
        seq = [_decode(v, arrays) for v in node["seq"]]
        return tuple(seq) if node.get("tuple") else seq
    if "dict" in node:
        out = {}
        for k, kind, v in node["dict"]:
            if kind not in ("str", "int", "float"):
                raise PieceError(f"unknown key type {kind!r}")
            out[_SCALARS[kind](k)] = _decode(v, arrays)
        return out
    raise PieceError("malformed tree")


def encode_piece(key, args, result) -> bytes:
    """The bytes of the ``.npz`` file of one piece (module doc).  TypeError for a result
    that holds anything but the data types of the module doc."""
    arrays = {}
    tree = _encode(result, arrays)
    meta = json.dumps({"format": FORMAT, "key": _key_text(key), "args": _args_text(args),
                       "tree": tree})
    return npz_bytes({_META: np.array(meta), **arrays})     # (no object arrays: `_encode`)


def decode_piece(data: bytes, key):
    """(args text, result) of the piece in ``data``; PieceError if it is not a piece of task
    ``key`` in this format.  Never unpickles: object arrays raise."""
    try:
        with np.load(io.BytesIO(data), allow_pickle=False) as z:
            names = set(z.files)
            if _META not in names:
                raise PieceError("no piece description in it")
            meta = json.loads(str(z[_META][()]))
            if not isinstance(meta, dict) or meta.get("format") != FORMAT:
                raise PieceError(f"not a piece of format {FORMAT}")
            if meta.get("key") != _key_text(key):
                raise PieceError(f"it holds task {meta.get('key')}, not {_key_text(key)}")
            arrays = {n: z[n] for n in names - {_META}}
        return meta["args"], _decode(meta["tree"], arrays)
    except PieceError:
        raise
    except (OSError, ValueError, KeyError, TypeError, EOFError, zipfile.BadZipFile,
            json.JSONDecodeError) as exc:
        raise PieceError(f"{type(exc).__name__}: {exc}") from None


# ------------------------------------------------------------------------ the folder
def save_piece(folder, key, args, result) -> None:
    """Keep one task's result with the arguments that produced it (atomic write)."""
    atomic_write(piece_path(folder, key), encode_piece(key, args, result))


def load_piece(folder, key, args, notice=None):
    """The kept result of task ``key`` if it was computed with ``args``; None otherwise:
    missing, computed with other arguments (another preset), or not readable as a piece —
    then one line naming the file goes to ``notice`` (default: stderr) and the task is
    computed again.  A pickle of an older version beside it is named the same way and never
    read."""
    say = notice or (lambda line: print(line, file=sys.stderr))
    path = piece_path(folder, key)
    legacy = path.with_suffix(".pkl")
    if legacy.exists():
        say(f"charts: ignoring {legacy}: pieces are no longer read from pickle files "
            f"(they could run code); the piece is computed again as {path.name}")
    if not path.exists():
        return None
    try:
        kept_args, result = decode_piece(path.read_bytes(), key)
    except PieceError as exc:
        say(f"charts: {path} is not a usable piece ({exc}); computing it again")
        return None
    except OSError as exc:
        say(f"charts: cannot read {path} ({exc.strerror or exc}); computing it again")
        return None
    return result if kept_args == _args_text(args) else None
