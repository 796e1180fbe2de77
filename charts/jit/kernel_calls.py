"""A large compiled kernel called from compiled code through its address, not as a copy.

numba compiles a function that calls another compiled function by linking a copy of the
callee's code into its own and having LLVM optimise and translate the whole again: every
analysis that drives the tangent kernel from its own kernel (the angle test's forward pass,
the curvature's sampler, the CLVs' forward pass) compiled the tangent kernel's code a second
time in its first call, 0.7–0.9 s each (docs/performance.md).  `CallsKernel` compiles such a
driver with the kernel as an argument, a numba first-class function (`KernelAddressType`,
numba's ``FunctionType`` with its ``FunctionModel``): the driver calls the kernel's one
compiled code through its address, in numba's own calling convention (its exceptions
propagate as from a direct call), and its own compilation holds only itself.  The same
machine code runs either way, so the numbers are the same bit for bit; a call costs an
indirect jump, once per chunk of steps.

This is the ``kernel_address`` adaptation (`charts.jit.adaptations`): it relies on numba's
experimental first-class function model and on the dispatcher's hook for new argument types
(``_compile_for_args``).  Where they differ from what it expects, or under
``CHARTS_NUMBA_PLAIN=1``, a `CallsKernel` is numba's plain way: the driver compiled with the
kernel dispatchers as arguments (linked in; not cached on disk, since numba keys such an
entry on the process's own dispatcher objects).
"""
from __future__ import annotations

import threading

from numba import typeof, types
from numba.core import cgutils
from numba.extending import NativeValue, register_model, typeof_impl, unbox

from . import adaptations
from .cache_lock import adopt

__all__ = ["CallsKernel", "KernelAddress", "KernelAddressType", "usable"]


def _check():
    """None, or what differs in numba's first-class functions and dispatchers from what
    `CallsKernel` expects."""
    import inspect

    from numba.core.dispatcher import Dispatcher
    from numba.experimental import function_type

    model = getattr(function_type, "FunctionModel", None)
    if model is None:
        return "numba.experimental.function_type.FunctionModel is missing"
    source = inspect.getsource(model)
    missing = [f for f in ("'c_addr'", "'py_addr'", "'jit_addr'") if f not in source]
    if missing:
        return f"FunctionModel has no field {', '.join(missing)}"
    if not callable(getattr(Dispatcher, "_compile_for_args", None)):
        return "Dispatcher._compile_for_args is missing"
    if list(inspect.signature(Dispatcher._compile_for_args).parameters) != ["self", "args", "kws"]:
        return "Dispatcher._compile_for_args has other parameters"
    return None


def usable() -> bool:
    """Whether drivers call their kernels by address in this process."""
    return adaptations.active("kernel_address", _check)


class KernelAddressType(types.FunctionType):
    """numba's first-class function type of one compiled kernel, for a `KernelAddress`: its
    two addresses are read from the Python object when a call passes it (numba's own
    dispatcher argument looks its compiled code up anew at each call: 40 µs with the tangent
    kernel's signature of named tuples)."""


def _register_model():
    from numba.experimental.function_type import FunctionModel

    register_model(KernelAddressType)(FunctionModel)


if usable():
    _register_model()


class KernelAddress:
    """The compiled code of the numba dispatcher ``kernel`` for the argument types ``argtypes``
    (compiled or loaded from the cache here), as a driver receives it."""

    def __init__(self, kernel, argtypes):
        kernel.compile(argtypes)                # (loaded from the cache where it is there)
        cres = kernel.overloads[tuple(argtypes)]
        self.numba_type = KernelAddressType(cres.signature)
        self.jit_addr = cres.library.get_pointer_to_function(cres.fndesc.llvm_func_name)
        self.c_addr = cres.library.get_pointer_to_function(cres.fndesc.llvm_cfunc_wrapper_name)
        self.cres = cres                    # (its code and environment live as long as this)


@typeof_impl.register(KernelAddress)
def _typeof_kernel_address(val, c):
    return val.numba_type


@unbox(KernelAddressType)
def _unbox_kernel_address(typ, obj, c):
    fn = cgutils.create_struct_proxy(typ)(c.context, c.builder)
    for field in ("c_addr", "jit_addr"):
        addr = c.pyapi.object_getattr_string(obj, field)
        setattr(fn, field, c.pyapi.long_as_voidptr(addr))
        c.pyapi.decref(addr)
    fn.py_addr = c.builder.ptrtoint(obj, c.context.get_value_type(types.voidptr))
    return NativeValue(fn._getvalue())


class _Plain(Exception):
    """The kernel's address could not be read: the driver goes numba's plain way."""


class CallsKernel:
    """``fn(*kernels, *args)`` as ``driver(*args)``, compiled (cached on disk) for the types of
    ``args`` with each kernel, a numba dispatcher, given by address (`KernelAddress`).  Each
    of ``calls`` is a pair (kernel, kernel_types): ``kernel_types(*types of args)`` gives the
    argument types the driver calls that kernel with, and the kernel is compiled (or loaded
    from the cache) for them before the driver.  ``options``: numba's (``cache=False`` for a
    driver whose code is to be inspected).

    A call goes straight to numba's dispatcher with the last kernel addresses, and numba
    matches the arguments to the signatures compiled so far (in C: typing them here in
    Python cost 85 µs a call) — exactly or by a safe conversion, never a lossy one, as
    numba does while it may compile.  Arguments that match no signature reach numba's hook
    for compiling (``_compile_for_args``), which is `_new_types` here: the kernels' addresses
    and the driver's signature for their types, compiled under a lock (numba compiles none
    of its own: it would link the kernels in).

    Without the ``kernel_address`` adaptation (`usable`), ``driver(*args)`` is numba's
    ``fn(*kernels, *args)`` with the kernel dispatchers themselves (`plain`)."""

    def __init__(self, fn, *calls, **options):
        from numba import njit

        self.py_func = fn
        self.calls = calls
        self.options = options
        self.plain = None                   # numba's own driver, where not by address
        if usable():
            self.dispatcher = adopt(njit(**dict({"cache": True}, **options))(fn))
            self.dispatcher._compile_for_args = self._new_types
        else:
            self._go_plain()
        self._kernels = None                # the kernel addresses of the last call
        self._addresses = {}                # (kernel, its argument types) -> its address
        self._lock = threading.Lock()       # (threads meeting new types compile in turn)
        self.__doc__ = fn.__doc__
        self.__name__ = fn.__name__

    def _go_plain(self):
        """Use numba's plain driver from now on."""
        from numba import njit

        self.dispatcher = njit(**dict(self.options, cache=False))(self.py_func)
        self.plain = tuple(kernel for kernel, _ in self.calls)

    def __call__(self, *args):
        if self.plain is not None:
            return self.dispatcher(*self.plain, *args)
        kernels = self._kernels
        if kernels is None:
            try:
                kernels, _ = self._prepare(args)
            except _Plain:
                return self.dispatcher(*self.plain, *args)
        return self.dispatcher(*kernels, *args)

    def _new_types(self, *args, **kws):
        """numba's hook for arguments (the kernels first) that match no compiled signature:
        the driver compiled for their types, and what numba then calls with them — the
        compiled driver itself, with the kernels' addresses for these types, not the ones
        given (no second matching: numba may miss one while another thread compiles)."""
        args = args[len(self.calls):]
        try:
            kernels, entry = self._prepare(args)
        except _Plain:
            return lambda *_given: self.dispatcher(*self.plain, *args)
        return lambda *_given: entry(*kernels, *args)

    def _prepare(self, args):
        """(the kernels' addresses for ``args``, the driver's compiled entry point for their
        types), compiling it where it is new."""
        with self._lock:
            kernels, signature = self._resolve(args)
            if signature not in self.dispatcher.overloads:
                self.dispatcher.compile(signature)
            self._kernels = kernels
            return kernels, self.dispatcher.overloads[signature].entry_point

    def _resolve(self, args):
        """(the kernels' addresses, the driver's signature) for ``args``."""
        argtypes = tuple(typeof(a) for a in args)
        kernels = []
        for kernel, kernel_types in self.calls:
            key = (kernel, tuple(kernel_types(*argtypes)))
            if key not in self._addresses:
                try:
                    self._addresses[key] = KernelAddress(*key)
                except AttributeError as exc:   # numba's compile result is not as expected
                    adaptations.step_aside("kernel_address", f"{type(exc).__name__}: {exc}")
                    self._go_plain()
                    raise _Plain from exc
            kernels.append(self._addresses[key])
        kernels = tuple(kernels)
        return kernels, tuple(k.numba_type for k in kernels) + argtypes
