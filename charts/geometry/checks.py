"""The argument checks of the public surface, written once (every layer above uses them;
``charts.analyses.arguments`` builds the time-grid rules on top).

Each check returns the value in its working type or raises ``ValueError`` whose message
names the argument, shows the value and says what is allowed.  Numbers users commonly pass
in another type keep working: NumPy scalars and 0-d arrays (``np.array(32)`` is 32), integral
floats where a count is expected (``4.0`` rotors), and a float32 or float16 read as the decimal
it prints (``np.float32(0.01)`` is 0.01, not 0.009999999776…, which no duration of whole
steps would match); ``True``, ``2.7`` and ``"2"`` are not counts.
"""
from __future__ import annotations

import math

import numpy as np

from ..io.file_checks import path, shown  # noqa: F401 - the checks' home for files, re-exported

__all__ = ["number", "integer", "finite_array", "option", "flag", "path", "instance", "callback",
           "shown"]


def _scalar(x):
    """A 0-d array as its NumPy scalar (``np.array(32)`` -> ``np.int64(32)``); anything else
    as it is."""
    return x[()] if isinstance(x, np.ndarray) and x.ndim == 0 else x


def number(name, x) -> float:
    """``x`` as a finite float; ValueError naming ``name`` otherwise (bool, strings and
    complex numbers are not numbers; an integer beyond a float's range is refused).  A
    float32 or float16 is the decimal it prints: the value its writer meant, to its
    precision."""
    x = _scalar(x)
    if isinstance(x, np.floating) and x.dtype.itemsize < 8 and np.isfinite(x):
        x = float(str(x))
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} must be a real number, got {shown(x)}")
    try:
        x = float(x)
    except OverflowError:
        raise ValueError(f"{name} must be a finite number, got an integer of {len(str(x))} "
                         "digits (beyond a float's range)") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return x


def _entries_are_real_numbers(x) -> bool:
    """Every leaf of nested lists/tuples is a real number (no bool, str, bytes, complex,
    None): NumPy would turn ``[True, 1]`` into integers and ``['1', '2']`` into strings."""
    if isinstance(x, (list, tuple)):
        return all(_entries_are_real_numbers(e) for e in x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind in "iuf" or (x.dtype.kind == "O" and all(
            _entries_are_real_numbers(e) for e in x.ravel().tolist()))
    return not isinstance(x, (bool, np.bool_)) and isinstance(
        x, (int, float, np.integer, np.floating))


def integer(name, x, minimum=None, maximum=None) -> int:
    """``x`` as an int in [minimum, maximum]; integral floats (``4.0``) and NumPy integers
    are accepted (0-d arrays of them too), bool, fractions and strings are not."""
    x = _scalar(x)
    if isinstance(x, (float, np.floating)) and not isinstance(x, bool) and math.isfinite(x) \
            and float(x).is_integer():
        x = int(x)
    if isinstance(x, bool) or not isinstance(x, (int, np.integer)):
        allowed = ("an integer" if minimum is None else f"an integer >= {minimum}"
                   if maximum is None else f"an integer in {minimum}..{maximum}")
        raise ValueError(f"{name} must be {allowed}, got {shown(x)}")
    x = int(x)
    if (minimum is not None and x < minimum) or (maximum is not None and x > maximum):
        allowed = (f"an integer >= {minimum}" if maximum is None
                   else f"an integer in {minimum}..{maximum}")
        raise ValueError(f"{name} must be {allowed}, got {x}")
    return x


def finite_array(name, x, shape=None, ndim=None) -> np.ndarray:
    """``x`` as a float array of the given ``shape`` (a tuple; None entries are free) or
    ``ndim``, every entry finite; ValueError naming ``name`` otherwise."""
    try:
        # never drop an imaginary part, read a string or count a bool silently
        if not _entries_are_real_numbers(x):
            raise TypeError
        a = np.asarray(x, dtype=float)
    except OverflowError:
        raise ValueError(f"{name} has an integer beyond a float's range") from None
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be an array of real numbers, got {shown(x)}") from None
    if ndim is not None and a.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-D array, got shape {a.shape}")
    if shape is not None and (a.ndim != len(shape) or any(
            s is not None and s != d for s, d in zip(shape, a.shape))):
        want = "(" + ", ".join("k" if s is None else str(s) for s in shape) + \
            ("," if len(shape) == 1 else "") + ")"
        raise ValueError(f"{name} must have shape {want}, got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} has non-finite entries: {shown(a)}")
    return a


def option(name, x, allowed):
    """``x`` if it is one of ``allowed`` (compared by equality, bools only to bools)."""
    if isinstance(x, np.bool_):
        x = bool(x)
    for a in allowed:
        if type(a) is bool or type(x) is bool:
            if type(x) is type(a) and x == a:
                return x
        elif isinstance(x, type(a)) and x == a:
            return x
    raise ValueError(f"{name} must be one of {', '.join(map(repr, allowed))}; got {shown(x)}")


def flag(name, x) -> bool:
    """A yes/no setting: True or False, or 1 or 0 as a saved file's plain attributes hold
    them (``charts.io.file_settings``), so that a call repeated from a file runs; ValueError for
    anything else."""
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, np.integer)) and x in (0, 1):
        return bool(x)
    raise ValueError(f"{name} must be True or False (or 1 or 0), got {x!r}")


def instance(name, x, cls, what=None):
    """``x`` if it is a ``cls``; TypeError naming ``name`` and ``what`` (default the class's
    name) otherwise."""
    if not isinstance(x, cls):
        raise TypeError(f"{name} must be a {what or cls.__name__}, got {shown(x)}")
    return x


def callback(name, x):
    """``x`` if it is None or callable; TypeError naming ``name`` otherwise."""
    if x is not None and not callable(x):
        raise TypeError(f"{name} must be a callable or None, got {shown(x)}")
    return x
