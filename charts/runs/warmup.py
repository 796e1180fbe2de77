"""Compile the kernels once, after an install, so that the first real call does not wait.

numba compiles a kernel on its first call and keeps it in its on-disk cache (``__pycache__``
beside the sources, or ``NUMBA_CACHE_DIR``), keyed by the source file's time stamp and the
CPU; an install or upgrade starts with an empty cache, and the first ``lyapunov_spectrum``
then spends 10–15 s of CPU compiling (docs/performance.md, "Cold start").  ``charts warmup``
(`warmup`) makes one tiny call of each analysis for each N, through the public functions
themselves, so every kernel they use is compiled and cached; afterwards a new process loads
them in ~0.05 s.  The ambient kernels (Lyapunov, angles, waveforms) do not depend on N; the
chart kernels of `integrate` and of the curvature's exact route are compiled per N.
"""
from __future__ import annotations

import time

from ..analyses.curvature import curvature_along_trajectory
from ..analyses.hyperbolicity import hyperbolicity_angles
from ..analyses.lyapunov import lyapunov_spectrum
from ..compilation import compile_timer
from ..geometry.system import RotorSystem
from ..solvers.integrate import integrate

__all__ = ["TASKS", "DEFAULT_N", "warmup"]

#: The rotor counts warmed up by default: those whose chart kernels are shipped.
DEFAULT_N = (3, 4, 5, 6)

#: name -> a tiny call of the analysis (as short as its arguments allow).
TASKS = {
    "lyapunov": lambda S, th, u: lyapunov_spectrum(S, th, u, 0.2, t_transient=0.0, n_batches=2),
    "integrate": lambda S, th, u: integrate(S, th, u, 0.1),
    "curvature": lambda S, th, u: curvature_along_trajectory(S, th, u, 0.2, t_transient=0.0),
    "angles": lambda S, th, u: hyperbolicity_angles(S, th, u, 0.2, t_transient=0.0),
}


def warmup(ns=DEFAULT_N, analyses=None, report=None) -> list[dict]:
    """Call each analysis in ``analyses`` (names of `TASKS`; default all) once for every N in
    ``ns``, compiling its kernels (or loading them from the cache).  Returns one row per call:
    {analysis, n, compile (s spent compiling: 0 when everything came from the cache, which
    numba's compile events do not time), cpu (s)}; ``report(row)`` is called after each."""
    names = list(TASKS) if analyses is None else list(analyses)
    unknown = [a for a in names if a not in TASKS]
    if unknown:
        raise ValueError(f"analyses: unknown {unknown}; choose from {list(TASKS)}")
    rows = []
    for n in ns:
        S = RotorSystem(n)
        th, u = S.random_state(seed=1)
        for name in names:
            spent = [0.0]
            c0 = time.process_time()
            with compile_timer(lambda s: spent.__setitem__(0, spent[0] + s)):
                TASKS[name](S, th, u)
            rows.append(dict(analysis=name, n=n, compile=spent[0], cpu=time.process_time() - c0))
            if report is not None:
                report(rows[-1])
    return rows
