"""Compile the kernels once, after an install, so that the first real call does not wait.

numba compiles a kernel on its first call and keeps it in its on-disk cache (``__pycache__``
beside the sources, or ``NUMBA_CACHE_DIR``), keyed by the source file's time stamp and the
CPU; an install or upgrade starts with an empty cache, and the first ``lyapunov_spectrum``
then spends 10–15 s of CPU compiling (docs/performance.md, "Cold start").  ``charts warmup``
(`warmup`) makes one tiny call of each analysis for each N, through the public functions
themselves, so every kernel they use is compiled and cached; afterwards a new process loads
them in ~0.05 s.  The ambient kernels (Lyapunov, angles, CLVs, waveforms) do not depend on N;
the chart kernels of `integrate` and of the curvature's exact route are compiled per N.

The calls run in parallel processes (one per core), in `stages`, so that each kernel is
compiled by one process: the tangent kernel, which every ambient analysis's kernel calls,
first (beside the chart kernels, which need nothing of it), then the analyses built on it,
which load it from the disk cache.
"""
from __future__ import annotations

import os
import time

from ..analyses.covariant import covariant_lyapunov_vectors
from ..analyses.curvature import curvature_along_trajectory
from ..analyses.hyperbolicity import hyperbolicity_angles
from ..analyses.lyapunov import lyapunov_spectrum
from ..analyses.lyapunov_members import MIN_LANES, lyapunov_ensemble
from ..jit.compilation import compile_timer
from ..geometry.system import RotorSystem
from ..solvers.integrate import integrate

__all__ = ["TASKS", "DEFAULT_N", "DEFAULT_ANALYSES", "warmup", "stages"]

#: The rotor counts warmed up by default: those whose chart kernels are shipped.
DEFAULT_N = (3, 4, 5, 6)

#: name -> a tiny call of the analysis (as short as its arguments allow).
TASKS = {
    "lyapunov": lambda S, th, u: lyapunov_spectrum(S, th, u, 0.2, t_transient=0.0, n_batches=2),
    "integrate": lambda S, th, u: (integrate(S, th, u, 0.1),     # without transport, and with
                                   integrate(S, th, u, 0.1, transport=u)),
    "integrate_ambient": lambda S, th, u: integrate(S, th, u, 0.1, formulation="ambient"),
    "curvature": lambda S, th, u: curvature_along_trajectory(S, th, u, 0.2, t_transient=0.0),
    "angles": lambda S, th, u: hyperbolicity_angles(S, th, u, 0.2, t_transient=0.0),
    "clv": lambda S, th, u: covariant_lyapunov_vectors(S, th, u, 0.4, t_transient=0.1),
    "lanes": lambda S, th, u: lyapunov_ensemble(S, MIN_LANES, 0.2, workers=1, t_transient=0.0,
                                                n_batches=2, lanes=True),
}
#: What `warmup` compiles unless asked otherwise: every analysis's first call.  Not the
#: lanes of the ensembles (``"lanes"``: 20 s for each N): an ensemble takes them only where
#: they are compiled or where it runs long enough to pay for compiling them
#: (``charts.solvers.lanes.lanes_pay``), so no first call waits for them.
DEFAULT_ANALYSES = tuple(name for name in TASKS if name != "lanes")

#: The analyses whose kernels are compiled per N (chart kernels); the others' are N-generic.
PER_N = ("integrate", "curvature")
#: The stage of each analysis's first N (`stages`): lyapunov compiles the tangent kernel
#: that angles, curvature and clv call, integrate the loop and projections that
#: integrate_ambient shares (at once, both compiled them: 7 s against 4 s after);
#: clv waits for angles (their shared singular values).
STAGE = {"lyapunov": 0, "integrate": 0, "integrate_ambient": 1, "angles": 1, "curvature": 1,
         "clv": 2, "lanes": 1}


def stages(ns, names):
    """The calls (analysis, N) in stages: the calls of a stage share no kernel that is not
    already compiled by an earlier stage, so they run in parallel without compiling one
    kernel twice.  The first N of each analysis in its `STAGE`; further N of the analyses
    with chart kernels in the next stage (their N-generic parts compiled by then); the loads
    of the N-generic kernels for further N last."""
    out = [[] for _ in range(4)]
    for name in names:
        out[STAGE[name]].append((name, ns[0]))
        for n in ns[1:]:
            out[STAGE[name] + 1 if name in PER_N else 3].append((name, n))
    return [s for s in out if s]


def _call(task):
    """One tiny call (analysis, N): {analysis, n, compile (s compiling: 0 when everything
    came from the cache, which numba's compile events do not time), cpu (s)}."""
    name, n = task
    S = RotorSystem(n)
    th, u = S.random_state(seed=1)
    spent = [0.0]
    c0 = time.process_time()
    with compile_timer(lambda s: spent.__setitem__(0, spent[0] + s)):
        TASKS[name](S, th, u)
    return dict(analysis=name, n=n, compile=spent[0], cpu=time.process_time() - c0)


def warmup(ns=DEFAULT_N, analyses=None, report=None, workers=None, pool=None) -> list[dict]:
    """Call each analysis in ``analyses`` (names of `TASKS`; default `DEFAULT_ANALYSES`) once
    for every N in ``ns``, compiling its kernels (or loading them from the cache), in
    ``workers`` processes (default: one per core; 1: in this process) or in the executor
    ``pool``, stage by stage (`stages`).  Returns one row per call, in the order of ``ns`` then ``analyses``:
    {analysis, n, compile, cpu (s, in the process that made the call)}; ``report(row)`` is
    called as each finishes."""
    names = list(DEFAULT_ANALYSES) if analyses is None else list(analyses)
    unknown = [a for a in names if a not in TASKS]
    if unknown:
        raise ValueError(f"analyses: unknown {unknown}; choose from {list(TASKS)}")
    ns = list(ns)
    plan = stages(ns, names)
    widest = max(len(s) for s in plan)
    workers = workers or os.cpu_count() or 1
    rows = []

    def done(row):
        rows.append(row)
        if report is not None:
            report(row)

    if pool is not None:
        _staged(plan, pool, done)
    elif workers == 1 or widest == 1:
        for stage in plan:
            for task in stage:
                done(_call(task))
    else:
        from ..analyses.worker_pool import worker_pool
        with worker_pool(min(workers, widest)) as own:
            _staged(plan, own, done)
    order = {(name, n): i for i, (n, name) in enumerate((n, a) for n in ns for a in names)}
    return sorted(rows, key=lambda r: order[(r["analysis"], r["n"])])


def _staged(plan, pool, done):
    """The stages' calls in the executor ``pool``, a stage once the one before has ended."""
    from concurrent.futures import as_completed
    for stage in plan:
        for fut in as_completed([pool.submit(_call, task) for task in stage]):
            done(fut.result())
