"""A large compiled kernel called from compiled code through its address, not as a copy.

numba compiles a function that calls another compiled function by linking a copy of the
callee's code into its own and having LLVM optimise and translate the whole again: every
analysis that drives the tangent kernel from its own kernel (the angle test's forward pass,
the curvature's sampler, the CLVs' forward pass) compiled the tangent kernel's code a second
time in its first call, 0.7–0.9 s each (docs/performance.md).  `CallsKernel` compiles such a
driver with the kernel as an argument typed as a numba first-class function: the driver calls
the kernel's one compiled code through its address, in numba's own calling convention (its
exceptions propagate as from a direct call), and its own compilation holds only itself.  The
same machine code runs either way, so the numbers are the same bit for bit; a call costs an
indirect jump, once per chunk of steps.  Any layer may use it (no package imports).
"""
from __future__ import annotations

from numba import njit, typeof, types

__all__ = ["CallsKernel"]


class CallsKernel:
    """``fn(kernel, *args)`` as ``driver(*args)``, compiled (cached on disk) for the types of
    ``args`` with ``kernel``, a numba dispatcher, given as a first-class function of the
    signature it is called with: ``kernel_types(*types of args)`` gives its argument types,
    and it is compiled (or loaded from the cache) for them before the driver.  ``options``:
    numba's (``cache=False`` for a driver whose code is to be inspected)."""

    def __init__(self, fn, kernel, kernel_types, **options):
        self.py_func = fn
        self.kernel = kernel
        self.kernel_types = kernel_types
        self.options = options
        self._compiled = {}
        self.__doc__ = fn.__doc__
        self.__name__ = fn.__name__

    def __call__(self, *args):
        argtypes = tuple(typeof(a) for a in args)
        compiled = self._compiled.get(argtypes)
        if compiled is None:
            compiled = self._compile(argtypes)
        return compiled(self.kernel, *args)

    def _compile(self, argtypes):
        ktypes = tuple(self.kernel_types(*argtypes))
        self.kernel.compile(ktypes)
        ftype = types.FunctionType(self.kernel.overloads[ktypes].signature)
        options = dict({"cache": True}, **self.options)
        compiled = njit((ftype,) + argtypes, **options)(self.py_func)
        self._compiled[argtypes] = compiled
        return compiled
