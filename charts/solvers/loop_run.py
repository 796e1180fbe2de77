"""One run of the compiled integration loop: a formulation's state, the loop's work arrays
and its output buffers, advanced a chunk at a time (the part of ``integrate`` that SciPy's
``OdeSolver`` plays for ``solve_ivp``).

:class:`LoopRun` owns what :func:`charts.solvers.loop.drive` reads and writes: the
formulation's state and parameters, the loop state (``charts.solvers.loop.LOOP_STATE``),
the stage and interpolant work arrays, the switch log, the invariant monitor and the segment buffers of dense output.
:class:`SampleBuffer` owns the sampled rows: at the ``t_eval`` times, or after every step in
buffers that are kept when full and replaced, so that a long run never copies its samples.
"""
from __future__ import annotations

import math

import numpy as np

from . import loop as D
from .ambient_formulation import AmbientFlow
from .chart_formulation import ChartFlow
from .dense import DenseSolution
from .integration_arguments import TOLERANCES, IntegrationArguments
from .status import CAP_FRACTION

__all__ = ["LoopRun", "SampleBuffer"]

_METHOD_CODES = {"rk4": D.METHOD_RK4, "dop853": D.METHOD_DOP853}
_FORMULATION_CLASSES = {"ambient": AmbientFlow, "chart": ChartFlow}
#: Rows of the every-step output buffer: at least this many, and up to a chunk (at most
#: `_EVERY_STEP_BYTES`): each time it fills, the compiled loop returns to Python (≈ 0.1 ms of
#: dispatch per call).
_EVERY_STEP_BUFFER = 4096
_EVERY_STEP_BYTES = 1 << 24
_LOG_CAPACITY = 1024


class SampleBuffer:
    """The sampled ambient rows ``(θ, u, p¹…pᵏ)`` of a run and their integration times.

    With ``t_eval`` (``args.use_eval``) one buffer holds a row for every sample time; without,
    the loop writes a row after every step, and a full buffer is kept and replaced by
    :meth:`drain`.  The t = 0 row is the input itself, exactly."""

    def __init__(self, args: IntegrationArguments, state, width: int):
        self.use_eval = args.use_eval
        self.parts_t, self.parts_y = [], []
        row0 = np.concatenate([args.theta0, args.sign * args.u0, args.P.ravel()])
        if self.use_eval:
            te = args.s_eval
            first = 1 if te[0] == 0.0 else 0
            if first:
                self.parts_t.append(np.array([0.0]))
                self.parts_y.append(row0[None, :])
            state["ieval"] = first
            self.T = np.zeros(te.size - first)
            self.Y = np.zeros((te.size - first, width))
        else:
            # RK4: room for the whole run unless the cap shortens steps, up to _EVERY_STEP_BYTES
            expected = (math.ceil(args.t_final / args.dt) + 2 if args.method == "rk4"
                        else args.chunk_steps)
            rows = max(_EVERY_STEP_BUFFER, min(expected, _EVERY_STEP_BYTES // (8 * width)))
            self.T = np.empty(rows)
            self.Y = np.empty((rows, width))
            self.T[0] = 0.0
            self.Y[0] = row0
            state["nout"] = 1

    def drain(self, state) -> None:
        """Keep a full every-step buffer and give the loop a fresh one."""
        if not self.use_eval and int(state["nout"][0]) == self.T.size:
            self.parts_t.append(self.T)
            self.parts_y.append(self.Y)
            self.T = np.empty_like(self.T)
            self.Y = np.empty_like(self.Y)
            state["nout"] = 0

    def close(self, state):
        """(s, Y): every sample's integration time (increasing) and row."""
        nout = int(state["nout"][0])
        self.parts_t.append(self.T[:nout])
        self.parts_y.append(self.Y[:nout])
        if len(self.parts_y) == 1 and 2 * nout >= self.Y.shape[0]:  # one buffer, mostly used: no copy
            return self.parts_t[0], self.parts_y[0]
        return np.concatenate(self.parts_t), np.concatenate(self.parts_y, axis=0)


class LoopRun:
    """The loop of :func:`charts.solvers.loop.drive` set up for one ``integrate`` call.

    Attributes: ``form`` (the formulation), ``state`` (the loop state), ``samples``
    (:class:`SampleBuffer`), ``sol`` (:class:`DenseSolution` or None; kept for events too),
    ``switches`` (chart switches as (s, from, to), in integration time), ``mon`` (running max
    of the invariants' drift)."""

    def __init__(self, args: IntegrationArguments):
        system = args.system
        kw = {"tau": args.tau, "chart": args.chart} if args.formulation == "chart" else {}
        self.form = _FORMULATION_CLASSES[args.formulation](
            system, project=args.project, cap_fraction=CAP_FRACTION[args.method], **kw)
        self.y, self.par, self.ipar = self.form.initial(args.theta0, args.sign * args.u0, args.P)
        # (rhs, step, cap, post, to_ambient, invariants)
        self.hooks = self.form.hooks(args.method, args.P.shape[0])
        self.state = D.new_state(_METHOD_CODES[args.method], args.t_final, args.dt,
                                 args.rtol, args.atol, float(system.energy(args.u0)),
                                 TOLERANCES["singular_S"], args.use_eval, args.chunk_steps,
                                 args.record_segments)
        ny = self.y.size
        n = system.n
        na = (2 + args.P.shape[0]) * n
        self.K = np.zeros((16, ny))
        self.F = np.zeros((7, ny))
        self.ytmp = np.zeros(ny)
        self.ynew = np.zeros(ny)
        self.inv = np.zeros(3)
        self.log = np.zeros((_LOG_CAPACITY, 3))
        self.mon = np.zeros(3)
        seg_cap = min(args.chunk_steps, 4096) if args.record_segments else 1
        self.Seg = np.zeros((seg_cap, D.segment_layout(ny, self.par.size)[3]))
        self.ISeg = np.zeros((seg_cap, self.ipar.size), dtype=np.int64)
        self.s_eval = args.s_eval
        self.sol = (DenseSolution(self.hooks[4], ny, self.par.size, n, na, args.t0, args.sign)
                    if args.record_segments else None)
        self.samples = SampleBuffer(args, self.state, na)
        self.switches = list(self.form.initial_switches)

    @property
    def s(self) -> float:
        """The integration time reached."""
        return float(self.state["t"][0])

    @property
    def n_steps(self) -> int:
        return int(self.state["nsteps"][0])

    def advance(self) -> int:
        """Run the loop for one chunk, then collect what it wrote (samples, switches,
        interpolants); returns the loop's status code (``charts.solvers.status``)."""
        samples = self.samples
        status = D.drive(*self.hooks, self.y, self.par, self.ipar, self.state,
                         D.Output(self.s_eval, samples.T, samples.Y, self.log, self.mon,
                                  self.Seg, self.ISeg),
                         D.Work(self.K, self.F, self.ytmp, self.ynew, self.inv))
        samples.drain(self.state)
        self.switches.extend(self.form.drain_log(self.log, self.ipar))
        if self.sol is not None:
            self.sol.extend(self.Seg, self.ISeg, int(self.state["nseg"][0]))
            self.state["nseg"] = 0
        return status

    def counters(self) -> dict:
        """Accepted steps, rejected attempts and right-hand-side evaluations so far."""
        state = self.state
        return dict(n_steps=int(state["nsteps"][0]), n_rejected=int(state["nrej"][0]),
                    n_rhs=int(state["nrhs"][0]))
