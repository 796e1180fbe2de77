"""The engines of the chunked main pass of a scene run.

:class:`KernelEngine` — ambient RK4 with tangent vectors (the fused kernel; for a linkage
scene the mechanism's flow, ``charts.runs.mechanism_run.SceneFlow``, which has the same
interface);
:class:`IntegrateEngine` — ``charts.integrate`` (chart formulation or adaptive method).
Both advance a :class:`~charts.runs.run_state.RunState` in place chunk by chunk and call the
recorders at every recording position.  :func:`chunk_bounds` cuts the run into its
deterministic chunks.
"""
from __future__ import annotations

import math

import numpy as np

from ..analyses.statistics import batch_ends
from .plan import Plan, ticks
from .run_state import RunError, RunState
from .scene import Scene

__all__ = ["KernelEngine", "IntegrateEngine", "chunk_bounds", "record_interval",
           "lyapunov_batch_ends", "kernel_failure", "count_kernel_steps", "KERNEL_ROUTE",
           "recording_stops"]


def chunk_bounds(scene: Scene, plan: Plan) -> list[int]:
    """Chunk ends in units (steps for the kernel engine, samples otherwise) after the
    transient: every checkpoint_every, plus the Lyapunov batch boundaries."""
    run = scene.run
    unit = scene.integrator["dt"] if plan.engine == "kernel" else run["sample_dt"]
    total = ticks(run["t_final"], unit)
    every = ticks(run["checkpoint_every"], unit)
    ends = set(range(every, total, every)) | {total}
    ends |= set(lyapunov_batch_ends(scene, plan))
    return sorted(e for e in ends if 0 < e <= total)


def lyapunov_batch_ends(scene: Scene, plan: Plan) -> list[int]:
    """Steps after the transient at which the Lyapunov batches end (the API's, see
    ``charts.analyses.statistics.batch_ends``); none without a Lyapunov effect."""
    if "lyapunov" not in scene.effects:
        return []
    ly = scene.effects["lyapunov"]
    dt = scene.integrator["dt"]
    return batch_ends(ticks(scene.run["t_final"], dt), ly["n_batches"],
                      ticks(ly["reorth_every"], dt))


def record_interval(plan: Plan) -> int:
    """The stepping unit of the kernel engine: gcd of every recording interval."""
    g = 0
    for v in plan.every.values():
        g = math.gcd(g, v)
    return g


#: How the kernel engine names its route in an integration error.
KERNEL_ROUTE = "scene (ambient RK4)"


def kernel_failure(exc) -> RunError:
    """The `RunError` of a scene whose kernel engine stopped with ``exc`` (an
    ``IntegrationError``): what happened and what to change."""
    return RunError(f"{exc}; set [integrator] project = true or a smaller dt, or start from "
                    "another state")


def count_kernel_steps(st: RunState, nsteps: int) -> None:
    """Book ``nsteps`` RK4 steps of the kernel engine (4 evaluations each) in ``st``."""
    st.rhs += 4 * nsteps
    st.steps += nsteps


def recording_stops(start: int, end: int, unit, origin: int = 0) -> list[int]:
    """Where the kernel engine stops between units ``start`` and ``end`` to record: every
    multiple of ``unit`` counted from ``origin`` (the end of the transient), and ``end``
    (``unit`` None or 0: at ``end`` only)."""
    if not unit:
        return [end] if end > start else []
    stops, pos = [], start
    while pos < end:
        pos = min(end, origin + ((pos - origin) // unit + 1) * unit)
        stops.append(pos)
    return stops


class KernelEngine:
    """Ambient RK4 of eq (8) with k tangent vectors (eq 17) re-orthonormalised (eq 18): the
    run state's `TangentFlow` (``charts.solvers.tangent``); k = 0 integrates the state alone."""

    def __init__(self, st: RunState):
        self.st = st
        self.step_unit = record_interval(st.plan) or None

    def advance(self, nsteps: int):
        from ..mechanism.linkage import DegenerateMetricError
        from ..solvers.status import IntegrationError

        st = self.st
        try:
            st.flow.advance(nsteps, where=KERNEL_ROUTE)
        except DegenerateMetricError as exc:   # the message says what to do (disk inertia)
            raise RunError(f"{exc} In a scene: [system] disk_mass, disk_inertia.") from None
        except IntegrationError as exc:
            raise kernel_failure(exc) from None
        count_kernel_steps(st, nsteps)

    def run_chunk(self, start: int, end: int, recorders, origin: int = 0):
        """Advance from unit ``start`` to ``end``, stopping at every multiple of the
        recording unit counted from ``origin`` (the end of the transient) to record."""
        pos = start
        for nxt in recording_stops(start, end, self.step_unit if recorders else None, origin):
            self.advance(nxt - pos)
            pos = nxt
            for rec in recorders:
                rec(pos)


class IntegrateEngine:
    """``charts.integrate`` for the chart formulation and adaptive methods,
    called once per chunk with output at the sample times of that chunk.  The chart in use
    at the end of a chunk is the one the next chunk starts in (no spurious switch)."""

    def __init__(self, st: RunState):
        from ..solvers.integrate import integrate

        self.st = st
        self.integrate = integrate
        self.sdt = st.scene.run["sample_dt"]

    def run_chunk(self, start: int, end: int, recorders, origin: int = 0):
        from ..solvers.integrate import IntegrationError

        st, sc = self.st, self.st.scene
        n = st.system.n
        integ = sc.integrator
        m = end - start
        kw = dict(formulation=integ["formulation"], method=integ["method"],
                  project=integ["project"], t_eval=np.arange(1, m + 1) * self.sdt)
        if integ["method"] == "rk4":
            kw["dt"] = integ["dt"]
        else:
            kw.update(rtol=integ["rtol"], atol=integ["atol"])  # atol None: integrate's default
        if integ["formulation"] == "chart" and st.chart >= 0:
            kw["chart"] = st.chart
        t_start = start * self.sdt
        try:
            res = self.integrate(st.system, st.y[:n], st.y[n:], m * self.sdt, **kw)
        except IntegrationError as exc:
            raise RunError(f"the integration failed in the chunk starting at t = {t_start:g} "
                           f"(the times below count from that chunk's start): {exc}") from None
        except ValueError as exc:  # e.g. the state reached a singular point exactly
            raise RunError(f"the integration could not continue at t = {t_start:g}: {exc}") from None
        st.rhs += int(res.n_rhs)
        st.steps += int(res.n_steps)
        for t_sw, a, b in res.switches:
            st.rec["switches"].append([t_start + float(t_sw), float(a), float(b)])
            st.chart = int(b)
        for i in range(m):
            st.y = np.concatenate([res.theta[i], res.u[i]])
            for rec in recorders:
                rec(start + i + 1)
