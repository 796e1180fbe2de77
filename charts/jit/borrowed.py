"""Arrays read from a named loop state without reference counts (`borrowed`), and the use
that keeps their memory alive (`keep_alive`).

The loop (``charts.solvers.driver``) reads its arrays from a named tuple of the flow's state
at every step; numba counts a reference for each read (an atomic increment and decrement:
where the code branches, numba's pruning leaves them in the loop).  `borrowed` builds a view
that holds no reference to its memory (a null meminfo), valid while the array it views lives;
a function that builds a named state of borrowed views of arrays it allocated itself passes
them to `keep_alive` after the loop (numba frees an array right after its variable's last
use).  Both are numba intrinsics (``numba.extending.intrinsic``, numba's documented API) that
write numba's array structure by field.

This is the ``borrowed_views`` adaptation (`charts.jit.adaptations`): where numba's array
model has other fields, or under ``CHARTS_NUMBA_PLAIN=1``, `borrowed` returns the array
itself (counted as numba counts it; the same numbers).
"""
from __future__ import annotations

from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic

from . import adaptations

__all__ = ["borrowed", "keep_alive", "usable"]

#: The fields of numba's array structure that `borrowed` writes.
FIELDS = ("meminfo", "parent", "nitems", "itemsize", "data", "shape", "strides")


def _check():
    """None, or what differs in numba's array model from what `borrowed` writes."""
    import inspect

    from numba.core.datamodel import models

    source = inspect.getsource(models.ArrayModel)
    missing = [f for f in FIELDS if f"'{f}'" not in source and f'"{f}"' not in source]
    if missing:
        return f"numba's ArrayModel has no field {', '.join(missing)}"
    if not callable(getattr(cgutils, "get_null_value", None)):
        return "numba.core.cgutils.get_null_value is missing"
    return None


def usable() -> bool:
    """Whether `borrowed` makes views without a reference in this process."""
    return adaptations.active("borrowed_views", _check)


@intrinsic
def _borrowed_view(typingctx, a):
    """A view of the array ``a`` that holds no reference to its memory (no meminfo)."""
    def codegen(context, builder, sig, args):
        src = context.make_array(a)(context, builder, value=args[0])
        out = context.make_array(a)(context, builder)
        out.meminfo = cgutils.get_null_value(out.meminfo.type)
        out.parent = cgutils.get_null_value(out.parent.type)
        out.nitems = src.nitems
        out.itemsize = src.itemsize
        out.data = src.data
        out.shape = src.shape
        out.strides = src.strides
        return out._getvalue()
    return a(a), codegen


@njit(inline="always")
def _the_array(a):
    """The array itself (numba's own reference counting)."""
    return a


#: ``borrowed(a)``: a view of ``a`` without a reference, or ``a`` itself (see the module).
borrowed = _borrowed_view if usable() else _the_array


@intrinsic
def keep_alive(typingctx, owners):
    """A use of ``owners`` (an array or a tuple of them) that compiles to nothing: placed
    after a loop over `borrowed` views, it keeps their memory allocated until then."""
    def codegen(context, builder, sig, args):
        return context.get_dummy_value()
    return types.none(owners), codegen
