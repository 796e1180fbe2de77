"""A kernel called by address (`charts.jit.kernel_calls.CallsKernel`): the same numbers as a direct
call, the kernel's code not compiled into the driver, its exceptions propagated, one
compilation per argument types, and the analyses' drivers leaving the tangent kernel with the
one signature `TangentFlow.advance` gives it."""
import numpy as np
import pytest
from numba import njit

from charts.jit.kernel_calls import CallsKernel


@njit(cache=True)
def _kernel(x, scale, out):
    """Something the driver calls: a loop with a branch that raises."""
    if scale == 0.0:
        raise ValueError("scale must not be zero")
    if scale < 0.0:
        raise TypeError("a negative scale")        # a TypeError from inside the call
    acc = 0.0
    for i in range(x.size):
        acc += np.sin(x[i]) * scale
        out[i] = acc
    return acc


def _kernel_types(x, scale, out, times):
    return (x, scale, out)


def _drive(kernel, x, scale, out, times):
    total = 0.0
    for _ in range(times):
        total += kernel(x, scale, out)
    return total


@njit
def _drive_direct(x, scale, out, times):
    total = 0.0
    for _ in range(times):
        total += _kernel(x, scale, out)
    return total


drive = CallsKernel(_drive, (_kernel, _kernel_types))


def test_same_numbers_as_the_direct_call():
    x = np.linspace(0.0, 3.0, 17)
    a, b = np.empty(17), np.empty(17)
    assert drive(x, 0.7, a, 3) == _drive_direct(x, 0.7, b, 3)
    assert np.array_equal(a, b)


def test_the_kernel_is_not_compiled_into_the_driver():
    """The driver's LLVM code holds none of the kernel's work (its sines); a direct call's
    does (numba links a copy of the callee's code into its caller, where LLVM inlines this
    small one).  Neither is cached: numba inspects only code it compiled in this process."""
    inspected = CallsKernel(_drive, (_kernel, _kernel_types), cache=False)
    x = np.linspace(0.0, 3.0, 5)
    inspected(x, 1.0, np.empty(5), 1)
    _drive_direct(x, 1.0, np.empty(5), 1)
    (signature,) = inspected.dispatcher.signatures
    assert "llvm.sin.f64" not in inspected.dispatcher.inspect_llvm(signature)
    assert "llvm.sin.f64" in _drive_direct.inspect_llvm(_drive_direct.signatures[0])


def test_the_kernels_exception_reaches_the_caller():
    with pytest.raises(ValueError, match="scale must not be zero"):
        drive(np.ones(3), 0.0, np.empty(3), 2)


def test_one_compilation_per_argument_types():
    x = np.ones(4)
    drive(x, 1.0, np.empty(4), 1)
    drive(np.zeros(9), 2.0, np.empty(9), 5)
    assert len(drive.dispatcher.signatures) == 1
    assert len(_kernel.signatures) == 1
    drive(np.ones((2, 2))[:, 0], 1.0, np.empty(2), 1)     # a strided view: its own types
    assert len(drive.dispatcher.signatures) == 2
    drive(np.ones(3), 1.0, np.empty(3), 1)                # the first types again: no third
    assert len(drive.dispatcher.signatures) == 2


def test_a_type_error_from_inside_the_call_is_not_taken_for_new_types():
    x = np.ones(3)
    drive(x, 1.0, np.empty(3), 1)
    before = list(drive.dispatcher.signatures)
    with pytest.raises(TypeError, match="a negative scale"):
        drive(x, -1.0, np.empty(3), 1)
    assert drive.dispatcher.signatures == before


def test_a_new_process_loads_the_driver_from_the_disk_cache(tmp_path):
    """The driver's signature (with the kernel's address type) is saved with numba's cache
    and found again: a second process compiles nothing."""
    import os
    import subprocess
    import sys
    probe = ("import sys; sys.path.insert(0, {tests!r})\n"
             "import numpy as np\n"
             "from numba.core.event import install_recorder\n"
             "import test_kernel_calls as t\n"
             "with install_recorder('numba:compile') as rec:\n"
             "    t.drive(np.ones(4), 1.0, np.empty(4), 2)\n"
             "print(sum(1 for _, ev in rec.buffer if ev.is_start))\n").format(
        tests=os.path.dirname(__file__))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path))
    counts = [int(subprocess.run([sys.executable, "-c", probe], env=env, text=True,
                                 capture_output=True, check=True).stdout.split()[-1])
              for _ in range(2)]
    assert counts[0] >= 2 and counts[1] == 0


@njit(cache=True)
def _twice(x, out):
    """A second kernel."""
    for i in range(x.size):
        out[i] = 2.0 * x[i]
    return out[0]


def _drive_two(kernel, second, x, scale, out, times):
    return kernel(x, scale, out) + second(x, out)


def test_several_kernels_each_by_address_in_the_order_given():
    both = CallsKernel(_drive_two, (_kernel, _kernel_types), (_twice, lambda x, *_: (x, x)))
    x = np.linspace(0.0, 1.0, 6)
    out = np.empty(6)
    got = both(x, 0.5, out, 1)
    want_first = _kernel(x, 0.5, np.empty(6))
    assert got == want_first + 2.0 * x[0]
    assert np.array_equal(out, 2.0 * x)


def test_threads_meeting_new_types_at_once_get_their_own_numbers():
    """Threads calling with arguments of several types at once, before and after a first
    call: each gets the direct call's numbers (the kernels' addresses and the driver's
    signatures are resolved under a lock; numba matches the rest)."""
    from concurrent.futures import ThreadPoolExecutor
    inputs = [np.ones(3), np.ones((2, 3))[:, 0], np.ones((3, 2))[:, 1], np.ones(5)] * 4
    want = [_drive_direct(x, 1.0, np.empty(x.size), 1) for x in inputs]
    for first in (None, np.ones(2)):
        fresh = CallsKernel(_drive, (_kernel, _kernel_types), cache=False)
        if first is not None:
            fresh(first, 1.0, np.empty(2), 1)
        with ThreadPoolExecutor(4) as pool:
            got = list(pool.map(lambda x: fresh(x, 1.0, np.empty(x.size), 1), inputs))
        assert got == want


@njit(cache=True)
def _scaled(x, scale):
    return x[0] * scale


def _drive_scaled(kernel, x, scale):
    return kernel(x, scale)


def test_arguments_of_new_types_compile_and_are_never_converted_lossily():
    """After an int scale, a float scale is not converted to the int signature (numba
    would, were the driver closed to compilation): it compiles its own."""
    scaled = CallsKernel(_drive_scaled, (_scaled, lambda x, scale: (x, scale)), cache=False)
    x = np.array([2.0])
    assert scaled(x, 3) == 6.0
    assert scaled(x, 1.5) == 3.0
    assert scaled(x, 3) == 6.0
    assert len(scaled.dispatcher.signatures) == 2
