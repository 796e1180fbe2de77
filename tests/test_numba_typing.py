"""numba's typing of calls remembered (``charts.jit.typing_memo``): in numba's class only while
numba compiles a charts function, off under ``CHARTS_NUMBA_PLAIN=1``, and the compiled code
the same with and without it."""
import operator
import os
import subprocess
import sys
from contextlib import contextmanager
from types import ModuleType, SimpleNamespace

import numpy as np
import pytest
from numba import njit
from numba.core import types
from numba.extending import overload

from charts.jit import typing_memo

#: Compiles a generated chart kernel afresh (no cache) in a new process and prints whether
#: the memo is on and a digest of the optimised LLVM IR of what numba compiled.
_PROBE = """
import hashlib, numpy as np
from numba import njit
from numba.core.types.functions import BaseFunction
import charts.jit
from charts.jit import typing_memo
from charts.generated import rotor_n4 as g
f = njit(error_model="numpy")(g.transport_rate_sc)
d = g.DIM
x = np.linspace(0.2, 0.9, d)
f(x, x + 1.0, x, x, np.ones(d + 1), np.ones(d + 1), 0.0, np.empty(d))
ir = "".join(f.inspect_llvm().values())
own = BaseFunction.get_call_type.__module__ == "numba.core.types.functions"
print(len(typing_memo._HELD) > 0, own, hashlib.sha1(ir.encode()).hexdigest())
"""


def _probe(memo: bool):
    env = dict(os.environ, CHARTS_NUMBA_PLAIN="0" if memo else "1")
    r = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, text=True,
                       timeout=300, env=env)
    assert r.returncode == 0, r.stderr
    used, own, digest = r.stdout.split()
    assert own == "True"                # numba's own function once the compilation ended
    return used == "True", digest


def test_used_while_a_charts_function_compiles_and_off_when_plain():
    """A process that imports charts' compile machinery types a charts kernel's calls with
    the memo, and numba has its own function back afterwards; ``CHARTS_NUMBA_PLAIN=1``
    leaves numba's own function throughout.  Either way the generated kernel compiles to
    the same LLVM IR, byte for byte."""
    on, with_memo = _probe(True)
    off, without = _probe(False)
    assert on and not off
    assert with_memo == without


def test_install_is_idempotent_and_restore_gives_numbas_function_back():
    from numba.core.types.functions import BaseFunction

    own = BaseFunction.get_call_type
    assert typing_memo.usable()
    typing_memo.install()
    typing_memo.install()
    try:
        patched = BaseFunction.get_call_type
        assert patched._charts_memo
        assert patched.__wrapped__ is own
    finally:
        typing_memo.restore()
    assert BaseFunction.get_call_type is own


@contextmanager
def _typing_in(ctx, modname):
    """``ctx``'s type inference as if inside a function of module ``modname`` (a frame on
    its call stack, as numba pushes while typing a function)."""
    from numba.core.target_extension import CPU
    frame = SimpleNamespace(func_id=SimpleNamespace(modname=modname), target=CPU)
    ctx.callstack._stack.append(frame)
    try:
        yield
    finally:
        ctx.callstack._stack.pop()


def test_a_hit_returns_the_signature_and_implementation_numba_found():
    """Typing a charts function, the memo answers the second question with the first answer:
    the same signature object, and the implementation key numba recorded for it; typing
    anyone else's function, it remembers nothing."""
    typing_memo.install()                        # (as while a charts function compiles)
    try:
        _hit_and_miss(mul_args=(types.int16, types.float32))
    finally:
        typing_memo.restore()


def _hit_and_miss(mul_args):
    from numba.core.registry import cpu_target

    ctx = cpu_target.typing_context
    ctx.refresh()                                # numba's registries, loaded lazily
    mul = ctx.resolve_value_type(operator.mul)
    assert isinstance(mul, types.Function)
    args = mul_args                              # a pair nothing in charts multiplies
    before = typing_memo.memo_size(mul)
    with _typing_in(ctx, "users_own.module"):
        mul.get_call_type(ctx, args, {})
    assert typing_memo.memo_size(mul) == before
    with _typing_in(ctx, "charts.probe"):
        first = mul.get_call_type(ctx, args, {})
        assert typing_memo.memo_size(mul) == before + 1
        key = mul._impl_keys[first.args]
        mul._impl_keys[first.args] = None        # a later resolution wrote another key
        again = mul.get_call_type(ctx, args, {})
    assert again is first
    assert mul._impl_keys[first.args] == key     # the hit records it again, as numba's does
    assert again.return_type == first.return_type == types.float32


def _charts_module(name, source, **names):
    """A module named as charts' on-demand modules are (``charts_ondemand_…``), holding
    ``names`` and the functions of ``source``: their typing takes the memo."""
    mod = ModuleType(name)
    mod.__dict__.update(names)
    sys.modules[name] = mod
    exec(compile(source, f"<{name}>", "exec"), mod.__dict__)
    return mod


def _divide(a, b):
    pass


@overload(_divide)
def _divide_impl(a, b):
    def impl(a, b):
        return a / b
    return impl


def test_an_overload_keeps_each_callers_error_model():
    """An ``@overload``'s implementation inherits its caller's compiler flags (numba builds
    one per set): a caller with numba's default error model raises at a zero divisor, one
    with numpy's returns inf, in either order of compilation (the flags are in the key)."""
    for i, order in enumerate((("python_model", "numpy_model"), ("numpy_model", "python_model"))):
        mod = _charts_module(f"charts_ondemand_typing_divide{i}", """
def python_model(a, b):
    return _divide(a, b)
def numpy_model(a, b):
    return _divide(a, b)
""", _divide=_divide)
        compiled = {name: (njit(error_model="numpy") if name == "numpy_model" else njit)(
            getattr(mod, name)) for name in order}
        for name in order:
            if name == "numpy_model":
                assert compiled[name](1.0, 0.0) == np.inf
            else:
                with pytest.raises(ZeroDivisionError):
                    compiled[name](1.0, 0.0)


_OFFSET = 1


def _plus_offset(x):
    pass


@overload(_plus_offset, inline="always")
def _plus_offset_impl(x):
    def impl(x):
        return x + _OFFSET
    return impl


def test_inlined_overloads_are_left_to_numba():
    """numba rebuilds an inlined overload's IR at each typing (the inliner reads it): such
    answers are not kept, and a function compiled after the global it reads changed sees
    the new value, as without the memo."""
    global _OFFSET
    source = """
def first(x):
    return _plus_offset(x)
def second(x):
    return _plus_offset(x)
"""
    mod = _charts_module("charts_ondemand_typing_inline", source, _plus_offset=_plus_offset)
    first = njit(mod.first)
    assert first(0) == 1
    _OFFSET = 2
    try:
        second = njit(mod.second)
        assert second(0) == 2
        from numba.core.registry import cpu_target
        fnty = cpu_target.typing_context.resolve_value_type(_plus_offset)
        assert typing_memo.memo_size(fnty) == 0
    finally:
        _OFFSET = 1


_POINTER_PROBE = """
import ctypes, ctypes.util
from numba import njit
import charts.jit
libm = ctypes.CDLL(ctypes.util.find_library("m"))
cos = libm.cos
cos.restype, cos.argtypes = ctypes.c_double, (ctypes.c_double,)

@njit(cache=True)
def call(fn, x):
    return fn(x)

print(call(cos, 0.0))
"""


def test_a_cached_function_of_a_function_pointer_still_saves(tmp_path):
    """numba's disk cache pickles the argument types with their attributes; the memo is held
    beside the function types (a ctypes pointer's type is one), so they still pickle."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), CHARTS_NUMBA_PLAIN="0")
    # numba caches only functions in files; a module named as charts' on-demand ones
    (tmp_path / "charts_ondemand_pointer_probe.py").write_text(_POINTER_PROBE)
    r = subprocess.run([sys.executable, "-c", "import charts_ondemand_pointer_probe"],
                       capture_output=True, text=True,
                       timeout=300, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "1.0"
    assert list(tmp_path.rglob("*.nbi")), "nothing was cached"
