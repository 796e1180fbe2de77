"""Where the first call's compilation goes, pass by pass: numba's pipeline times of the kernel
an analysis compiles (its ``metadata["pipeline_times"]``), on an empty cache.

    NUMBA_CACHE_DIR=$(mktemp -d) CHARTS_CACHE_DIR=$(mktemp -d) python scripts/first_use_passes.py [N]

Prints the CPU seconds of the first `lyapunov_spectrum` at N (default 3) and the passes of
`tangent_kernel`'s compilation that took longest (the nested compilations of the functions it
calls without inlining them are inside its type inference)."""
import sys
import time

from charts import RotorSystem, lyapunov_spectrum
from charts.solvers.tangent import tangent_kernel

n = int(sys.argv[1]) if len(sys.argv) > 1 else 3
S = RotorSystem(n)
theta, u = S.random_state(seed=1)
t0 = time.process_time()
lyapunov_spectrum(S, theta, u, 2.0, t_transient=0.0, n_batches=2)
print(f"first lyapunov_spectrum at N = {n}: {time.process_time() - t0:.2f} s CPU")
for cres in tangent_kernel.overloads.values():
    for pipeline, passes in cres.metadata.get("pipeline_times", {}).items():
        times = sorted(((v.run, k) for k, v in passes.items()), reverse=True)
        print(f"tangent_kernel, pipeline {pipeline}: {sum(t for t, _ in times):.2f} s")
        for t, name in times[:6]:
            print(f"  {t:6.2f} s  {name}")
