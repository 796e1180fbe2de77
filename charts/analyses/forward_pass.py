"""The forward pass of the angle test (section 4, ``charts.analyses.hyperbolicity``): its
settings, its flow (m restricted tangent vectors in the Euclidean product), the segments of
the tangent loop that record the vectors at the samples and the state at the checkpoints,
and the adjoint vectors the backward pass (``charts.analyses.adjoint_pass``) starts from."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ..jit import njit

from ..solvers.driver import Phases
from ..solvers.status import RUNNING
from ..jit.kernel_calls import CallsKernel
from ..solvers.tangent import (Records, Stack, TangentFlow, orthonormalize, reorth_steps,
                               tangent_kernel, tangent_kernel_types)
from .arguments import (Documented, positive_int, positive_time, project_steps, samples_of,
                        steps_of, unstable_dimension)

__all__ = ["AngleSettings", "angle_settings", "angle_flow", "adjoint_start", "forward_segments",
           "forward_kernel"]


@dataclass(frozen=True)
class AngleSettings:
    """Validated settings of one angle test; every count in RK4 steps of ``dt``."""
    n: int
    m: int
    dt: float
    n_tr: int
    n_win: int
    sample: int
    ce: int
    project: int
    reorth: int
    seed: int

    @property
    def samples(self) -> int:
        return self.n_win // self.sample


def angle_settings(system, t_final, *, dt=0.01, n_unstable=None, t_transient=Documented(100.0),
                   sample_every=Documented(0.1), checkpoint_every=Documented(1.0),
                   project_every=Documented(1.0), seed=0) -> AngleSettings:
    """Check the arguments of `hyperbolicity_angles` (ValueError naming the bad one)."""
    n = system.n
    m = unstable_dimension(n, n_unstable)
    dt = positive_time("dt", dt)
    n_tr = steps_of("t_transient", t_transient, dt, allow_zero=True)
    n_win = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=n_win)
    ce = steps_of("checkpoint_every", checkpoint_every, dt)
    project = project_steps(project_every, dt)
    seed = positive_int("seed", seed, 0)
    if samples_of(n_win, sample, t_final, sample_every) < 1:
        raise ValueError(f"t_final={t_final:g} holds no sample; increase it or lower sample_every")
    reorth = reorth_steps(dt, sample, n_tr, ce)  # orthonormal at every sample and segment end
    return AngleSettings(n, m, dt, n_tr, n_win, sample, ce, project, reorth, seed)


def angle_flow(system, theta0, u0, cfg: AngleSettings) -> TangentFlow:
    """The forward pass's flow from a validated state: m restricted tangent vectors,
    Euclidean, seeded with ``cfg.seed``."""
    return TangentFlow(system, theta0, u0, cfg.m, dt=cfg.dt, inner="euclidean", restricted=True,
                       reorth_every=cfg.reorth, project_every=cfg.project, seed=cfg.seed)


def adjoint_start(cfg: AngleSettings, w, block=None):
    """The backward pass's initial vectors W (m, 2N), orthonormal in ``w``: from the stream
    [seed, 1] (and the block number, for the later blocks of a windowed run)."""
    key = [cfg.seed, 1] if block is None else [cfg.seed, 1, block]
    W = np.random.default_rng(key).normal(size=(cfg.m, 2 * cfg.n))
    orthonormalize(W, w, np.zeros(cfg.m))
    return W


def _forward_kernel(kernel, stack, rotors, stepping, project, reorth, ce, rec_start, rec_every,
                    states, ck, a, b, vec_end):
    """`forward_segments` on the CPU: with ``kernel``, `tangent_kernel` (which allocates its
    work), called by address (`forward_kernel`)."""
    return forward_segments(stack, rotors, stepping, project, reorth, ce, rec_start, rec_every,
                            states, ck, a, b, vec_end, np.empty(0, dtype=np.int64),
                            np.empty((0, 0)), None, kernel)


#: `_forward_kernel` compiled with the tangent kernel called by address (its code not
#: compiled into the forward pass a second time: ``charts.jit.kernel_calls``)
forward_kernel = CallsKernel(_forward_kernel, (tangent_kernel, tangent_kernel_types))


@njit(cache=True, inline="always")
def forward_segments(stack, rotors, stepping, project, reorth, ce, rec_start, rec_every, states,
                     ck, a, b, vec_end, no_events, none, work, kernel):
    """Forward segments a … b−1 of ``ce`` steps of the tangent loop (``stack``: `Stack`,
    restricted vectors, projected every ``project`` steps, re-orthonormalised every
    ``reorth``, samples recorded into ``states`` from ``rec_start`` every ``rec_every``
    steps), the state at each segment's end into ck[i + 1]; after global step ``vec_end``
    the state alone (its bits do not depend on the vectors).  Returns the loop's status.
    ``kernel``: `tangent_kernel` (CPU, ``work`` None) or `tangent_loop` on the work arrays
    ``work`` (``charts.solvers.tangent.stacked_work``), which allocates nothing: in a GPU
    thread (``charts.analyses.angle_blocks``); no_events (0,), none (0, 0)."""
    Z, counter = stack.Z, stack.counter
    alone = Stack(Z[:1], stack.sc, counter, stack.logsum, stack.shares)
    # ``restricted`` (True) from the caller, not the literal True, and typed zeros, not the
    # literal 0: a literal argument compiles the loop once more (a signature of its own
    # beside TangentFlow.advance's, which every other analysis compiles: 8 s)
    zero = np.int64(0)
    sampled = Phases(project, reorth, rec_start, rec_every)
    unsampled = Phases(project, reorth, zero, zero)
    samples = Records(states, no_events, none)
    nothing = Records(none, no_events, none)
    for i in range(a, b):
        left = ce
        if counter[0] < vec_end:
            k = vec_end - counter[0]
            if ce < k:
                k = ce
            status, _ = kernel(stack, rotors, stepping, sampled, samples, k, work)
            if status != RUNNING:
                return status
            left -= k
        if left > 0:
            status, _ = kernel(alone, rotors, stepping, unsampled, nothing, left, work)
            if status != RUNNING:
                return status
        for j in range(Z.shape[1]):      # a loop, not a slice copy (adjoint_pass)
            ck[i + 1, j] = Z[0, j]
    return RUNNING
