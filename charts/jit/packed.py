"""Named fields of a packed parameter array: the one place a formulation's layout is written.

The integration loop hands every formulation one float array ``par`` (so that the loop has
one compiled signature for every formulation).  A formulation declares its fields once, in
order, with their lengths a·N + b (:func:`layout`); each field becomes a tuple of four ints
(offset a, offset b, length a, length b), a compile-time constant in the compiled hooks, and
:func:`view` / :func:`value` read it by name — the same index arithmetic as written-out
offsets, after constant folding, without a number in the formulation's code.
"""
from __future__ import annotations

import numpy as np
from . import njit

__all__ = ["layout", "view", "value", "put", "pack", "size"]


def layout(*fields):
    """The fields ``(name, a, b)`` (length a·N + b), in order, as a dict name → (offset a,
    offset b, length a, length b); the last entry, ``"end"``, is the whole array's."""
    out = {}
    oa = ob = 0
    for name, a, b in fields:
        out[name] = (oa, ob, a, b)
        oa, ob = oa + a, ob + b
    out["end"] = (oa, ob, 0, 0)
    return out


@njit(cache=True, inline="always")
def view(par, n, f):
    """The field f of par (a view), for N = n."""
    o = f[0] * n + f[1]
    return par[o:o + f[2] * n + f[3]]


@njit(cache=True, inline="always")
def value(par, n, f):
    """The first (or only) element of the field f."""
    return par[f[0] * n + f[1]]


@njit(cache=True, inline="always")
def put(par, n, f, x):
    """Set the first (or only) element of the field f to x."""
    par[f[0] * n + f[1]] = x


def size(fields, n: int) -> int:
    """The length of a packed array of ``fields`` (`layout`) for N = n."""
    a, b, _, _ = fields["end"]
    return a * n + b


def pack(fields, n_rotors: int, **values) -> np.ndarray:
    """A packed array of ``fields`` for N = n_rotors: each named field set from ``values`` (a number
    or an array of the field's length), the others zero."""
    n = n_rotors
    par = np.zeros(size(fields, n))
    for name, x in values.items():
        oa, ob, la, lb = fields[name]
        o, m = oa * n + ob, la * n + lb
        x = np.broadcast_to(np.asarray(x, dtype=float), (m,))
        par[o:o + m] = x
    return par
