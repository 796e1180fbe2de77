"""Compile the GPU kernels to PTX on a machine without a GPU: the Lyapunov kernel
(``charts.solvers.device``), the angle test's forward and backward kernels
(``charts.analyses.angle_blocks``) and the CLVs' forward kernel
(``charts.analyses.clv_ensemble``, restricted: D = 2N − 2), for compute capability 9.0.

    pip install nvidia-cuda-nvcc-cu12        # libnvvm and libdevice, no driver needed
    CUDA_HOME=$(python -c "import nvidia.cuda_nvcc, os; print(os.path.dirname(nvidia.cuda_nvcc.__file__))") \\
        python scripts/gpu_compile_check.py 5 3

Prints the size of each kernel's PTX, its compile time and its fused multiply-adds.  Numba
asks the current device for its compute capability when it compiles a called device function;
without a GPU this script answers 9.0 for it.
"""
import sys
import time

import numba.cuda.dispatcher as dispatcher
from numba import cuda, types as t

import charts.analyses.angle_blocks as angle_blocks
import charts.analyses.clv_ensemble as clv_ensemble
import charts.solvers.device as device


class _H100:
    compute_capability = (9, 0)


dispatcher.get_current_device = lambda: _H100()
device.cuda = angle_blocks.cuda = clv_ensemble.cuda = cuda

n, m = (int(x) for x in sys.argv[1:3]) if len(sys.argv) > 2 else (5, 3)
a3, a2, a1, i1, f8 = t.float64[:, :, ::1], t.float64[:, ::1], t.float64[::1], t.int64[::1], t.float64
lyapunov = (a3, a3, i1, i1, i1, a1, a1, a1, f8, a1, f8, t.int64, t.int64, a1, t.boolean, t.int64,
            a2, i1, a3, t.int64[:, ::1])
forward = (a3, a3, i1, a2, i1, i1, a3, a3, a1, a1, a1, a1, f8, a1, f8, t.UniTuple(t.int64, 10),
           i1, a2)
backward = (i1, i1, i1, a3, a3, a3, a2, a2, a2, a1, a1, a1, a1, f8, f8, t.UniTuple(t.int64, 7),
            i1, a2)
a4 = t.float64[:, :, :, ::1]
clv = (a3, a3, i1, a2, i1, i1, a4, a4, a3, a3, a1, a1, a1, a1, t.boolean, f8, a1, f8,
       t.UniTuple(t.int64, 7), f8, i1, a2)
fwd, bwd = angle_blocks.kernel_functions(n, m, 11)
for name, fn, sig in ((f"lyapunov N={n} k={m}", device.kernel_function(n, m), lyapunov),
                      (f"angles forward N={n} m={m}", fwd, forward),
                      (f"angles backward N={n} m={m}", bwd, backward),
                      (f"CLV forward N={n} D={2 * n - 2}",
                       clv_ensemble.kernel_function(n, 2 * n - 2), clv)):
    t0 = time.perf_counter()
    ptx, _ = cuda.compile_ptx(fn, sig, cc=(9, 0))
    print(f"{name}: {len(ptx)} chars of PTX in {time.perf_counter() - t0:.1f} s, "
          f"{ptx.count('fma.rn.f64')} fused multiply-adds")
