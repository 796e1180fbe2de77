"""The angle test (section 4) for ensembles on a GPU: every member a thread, the window in
blocks so that the memory does not grow with its length.

Each member runs the passes of ``charts.analyses.hyperbolicity`` — the forward segments
(`forward_segments`: the tangent loop with restricted, Euclidean vectors, samples and
checkpoints) and the backward pass (``charts.analyses.adjoint_pass.backward_loop``: the
stacked loop with the adjoint hook, the sines at the samples) — compiled for the GPU; what
one thread does is `forward_member` and `backward_member`, which the CPU twin
(``backend="cpu"``) runs member after member, so the logic is tested without a GPU.

Blocks.  The window [0, t_final] after the transient is cut into blocks of at most
``block`` steps (a multiple of the checkpoint and sample steps), chosen from the memory
budget: a block stores the forward vectors at its samples and the states at its checkpoints
until the backward pass of that block has used them, never more.  Block i is one run of
`hyperbolicity_angles`'s passes in its own frame: the forward pass from the block's start
(block 0: the initial state, with the transient before the first sample; later blocks: one
checkpoint segment before their first sample) through the block and a backward transient
beyond it; then the backward pass from there down to the block's first sample.  The forward
flow's whole state is saved one segment before the block's end and restored afterwards, so
the forward pass overall is one continuous run (recomputing a transient's worth of steps
per block: the bits of the tangent loop do not depend on how it is chunked), and its
exponents are those of `hyperbolicity_angles`.  Each later block starts the backward vectors
afresh (stream [seed, 1, block]) and lets them converge over the backward transient, so with
one block a member equals `hyperbolicity_angles` bit for bit, and with several its angles
after the first block differ by the convergence error of the adjoint vectors
(tests/test_angle_blocks.py).  The cost: (t_final + blocks · 2 t_transient) of each pass.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from ..jit import njit

from ..solvers.device import (THREADS_PER_BLOCK, DeviceArrays, cuda_module, flow_states,
                              load_member, member_stops, store_member)
from ..solvers.status import RUNNING
from ..solvers.tangent import (Rotors, Stack, Stepping, check_memory,
                               orthonormalize, stacked_work, tangent_loop)
from .adjoint_pass import backward_loop, sample_sines
from .ensemble import member_states_of
from .forward_pass import AngleSettings, adjoint_start, angle_flow, forward_segments

__all__ = ["forward_member", "backward_member", "block_plan", "block_bytes", "angle_states",
           "angles_on_device", "kernel_functions", "BlockPlan"]

FORWARD, BACKWARD = 0, 1


@njit(cache=True, inline="always")
def forward_member(l, Zs, scs, counters, logsums, status, stopped, Vrec, CK, arrays, level,
                   speeds, dt, steps, no_events, none, Z, sc, counter, logsum, work):
    """What one thread does in a forward launch: member l's flow (Zs (L, 1 + m, 2N), scs,
    counters, logsums) into the local Z, sc, counter, logsum, `forward_segments` a … b−1 of
    its block (``steps`` = (ce, reorth, project, rec_start, sample, a, b, vec_end, S,
    record_start)), samples into Vrec[l, :S], checkpoints into CK[l] (CK[l, 0] = the state
    when a = 0; Vrec[l, 0] = the stacked state when ``record_start``: a first sample at the
    block's start), back into the member arrays; a stop is flagged (status, global step)."""
    if status[l] != RUNNING:
        return
    minv, m, wts, w = arrays
    ce, reorth, project, rec_start, sample, a, b, vec_end, S, record_start = steps
    R, d = Z.shape
    load_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum)
    if a == 0:
        for j in range(d):
            CK[l, 0, j] = Z[0, j]
        if record_start:
            for i in range(R):
                for j in range(d):
                    Vrec[l, 0, i * d + j] = Z[i, j]
    code = forward_segments(Stack(Z, sc, counter, logsum, no_events),
                            Rotors(minv, m, wts, level), Stepping(speeds[l], dt, w, True),
                            project, reorth, ce, rec_start, sample, Vrec[l, :S], CK[l], a, b,
                            vec_end, no_events, none, work, tangent_loop)
    store_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum, code, status, stopped)


@njit(cache=True, inline="always")
def backward_member(l, status, stopped, phase, Ws, CK, Vrec, blogs, SF, SR, arrays, level, dt,
                    steps, no_events, none, Z, sc, counter, rec, work, samples):
    """What one thread does in a backward launch: W = Ws[l] into the rows of the local Z
    after the state, `backward_loop` over the block's checkpoints CK[l, :nseg + 1] down to its
    first sample, the sines into SF[l, :S], SR[l, :S], the adjoint log-norm sums added to
    blogs[l] (``steps`` = (ce, first_sample, sample, reorth, nseg, S, origin)); a stop is
    flagged with its global step (origin + the block's step) and phase BACKWARD."""
    if status[l] != RUNNING:
        return
    minv, m, wts, w = arrays
    ce, first, sample, reorth, nseg, S, origin = steps
    R, d = Z.shape
    for r in range(R - 1):
        for j in range(d):
            Z[1 + r, j] = Ws[l, r, j]
    code, step = backward_loop(CK[l, :nseg + 1], Z, sc, counter, rec,
                               Rotors(minv, m, wts, level), Stepping(0.0, dt, w, True), ce,
                               first, sample, reorth, Vrec[l, :S], blogs[l], SF[l, :S],
                               SR[l, :S], no_events, none, work, samples, sample_sines)
    if code != RUNNING:
        status[l] = code
        stopped[l] = origin + step
        phase[l] = BACKWARD


@njit(cache=True)
def _forward_cpu(Zs, scs, counters, logsums, status, stopped, Vrec, CK, arrays, level, speeds,
                 dt, steps, no_events, none):
    """`forward_member` for every member in turn (the CPU twin of the forward kernel)."""
    L, R, d = Zs.shape
    n = d // 2
    for l in range(L):
        forward_member(l, Zs, scs, counters, logsums, status, stopped, Vrec, CK, arrays, level,
                       speeds, dt, steps, no_events, none, np.empty((R, d)), np.empty((2, n)),
                       np.empty(1, dtype=np.int64), np.empty(R - 1), stacked_work(R, d))


@njit(cache=True)
def _backward_cpu(status, stopped, phase, Ws, CK, Vrec, blogs, SF, SR, arrays, level, dt, steps,
                  no_events, none):
    """`backward_member` for every member in turn (the CPU twin of the backward kernel)."""
    L, k, d = Ws.shape
    n = d // 2
    R = k + 1
    rows = steps[0] // steps[2] + 1
    for l in range(L):
        samples = (np.empty(d), np.empty((2, n)), np.empty((k, d)), np.empty(d), np.empty(d),
                   np.empty((2, k, k)), np.empty(2), np.empty((k, k)))
        backward_member(l, status, stopped, phase, Ws, CK, Vrec, blogs, SF, SR, arrays, level,
                        dt, steps, no_events, none, np.empty((R, d)), np.empty((2, n)),
                        np.empty(1, dtype=np.int64), np.empty((rows, R * d + d)),
                        stacked_work(R, d), samples)


#: Numba's CUDA module once `_cuda_kernels` found it usable (a global that the kernels read,
#: so that a stand-in can replace it in tests).
cuda = None


def kernel_functions(n, m, rows):
    """The Python functions (forward, backward) of the CUDA kernels for N = n, m vectors and
    ``rows`` = samples per checkpoint segment + 1: the sizes of their local arrays."""
    from numba import float64, int64

    R, d = m + 1, 2 * n
    D, D4 = R * d, 4 * R * d
    RD = R * d + d

    def forward(Zs, scs, counters, logsums, status, stopped, Vrec, CK, minv, mass, wts, w,
                level, speeds, dt, steps, no_events, none):
        l = cuda.grid(1)
        if l >= Zs.shape[0]:
            return
        forward_member(l, Zs, scs, counters, logsums, status, stopped, Vrec, CK,
                       (minv, mass, wts, w), level, speeds, dt, steps, no_events, none,
                       cuda.local.array((R, d), float64), cuda.local.array((2, n), float64),
                       cuda.local.array(1, int64), cuda.local.array(m, float64),
                       (cuda.local.array(D, float64), cuda.local.array(D4, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64)))

    def backward(status, stopped, phase, Ws, CK, Vrec, blogs, SF, SR, minv, mass, wts, w, level,
                 dt, steps, no_events, none):
        l = cuda.grid(1)
        if l >= status.shape[0]:
            return
        backward_member(l, status, stopped, phase, Ws, CK, Vrec, blogs, SF, SR,
                        (minv, mass, wts, w), level, dt, steps, no_events, none,
                        cuda.local.array((R, d), float64), cuda.local.array((2, n), float64),
                        cuda.local.array(1, int64), cuda.local.array((rows, RD), float64),
                        (cuda.local.array(D, float64), cuda.local.array(D4, float64),
                         cuda.local.array(n, float64), cuda.local.array(n, float64),
                         cuda.local.array(n, float64), cuda.local.array(n, float64),
                         cuda.local.array(n, float64), cuda.local.array(n, float64),
                         cuda.local.array(n, float64), cuda.local.array(n, float64)),
                        (cuda.local.array(d, float64), cuda.local.array((2, n), float64),
                         cuda.local.array((m, d), float64), cuda.local.array(d, float64),
                         cuda.local.array(d, float64), cuda.local.array((2, m, m), float64),
                         cuda.local.array(2, float64), cuda.local.array((m, m), float64)))

    return forward, backward


@functools.lru_cache(maxsize=None)
def _cuda_kernels(n, m, rows):
    """(forward, backward) CUDA kernels of `kernel_functions`, compiled at their first launch."""
    global cuda
    cuda = cuda_module()
    return tuple(cuda.jit(f) for f in kernel_functions(n, m, rows))


@dataclass(frozen=True)
class BlockPlan:
    """The blocks of a windowed angle test: window steps per block, and the largest."""
    lengths: tuple

    @property
    def largest(self) -> int:
        return max(self.lengths)


def block_bytes(cfg: AngleSettings, block) -> int:
    """Bytes one member stores for a block of ``block`` window steps: the forward vectors
    and sines at its samples, the states at its checkpoints."""
    S = block // cfg.sample
    return 8 * (S * (1 + cfg.m) * 2 * cfg.n + 2 * S + checkpoint_rows(cfg, block) * 2 * cfg.n)


def checkpoint_rows(cfg: AngleSettings, block) -> int:
    """Checkpoints of a block of ``block`` window steps (the first block's, the longest):
    its segments before the first sample, through the window and the backward transient,
    plus the start."""
    return (max(cfg.n_tr, cfg.ce) + block + cfg.n_tr) // cfg.ce + 1


def block_plan(cfg: AngleSettings, members, budget, block=None) -> BlockPlan:
    """Cut the window into blocks whose stores for ``members`` fit ``budget`` bytes (or of
    ``block`` window steps, at most), each a multiple of the checkpoint and sample steps;
    ValueError with the numbers when the transient is not a whole number of checkpoint
    segments or not even one segment fits."""
    unit = np.lcm(cfg.ce, cfg.sample)
    if cfg.n_tr % cfg.ce or cfg.n_win % unit:
        raise ValueError(f"on the GPU route t_transient ({cfg.n_tr * cfg.dt:g}) must be a multiple "
                         f"of checkpoint_every ({cfg.ce * cfg.dt:g}) and t_final "
                         f"({cfg.n_win * cfg.dt:g}) a multiple of it and of sample_every "
                         f"({cfg.sample * cfg.dt:g})")
    fit = unit
    while fit + unit <= cfg.n_win and members * block_bytes(cfg, fit + unit) <= budget:
        fit += unit
    if members * block_bytes(cfg, unit) > budget:
        raise ValueError(f"{members} members need {members * block_bytes(cfg, unit) / 2**30:.2f} "
                         f"GiB for the shortest block ({unit * cfg.dt:g} time units), more than the "
                         f"{budget / 2**30:.2f} GiB budget; run fewer members at once")
    if block is not None:
        fit = max(unit, min(fit, int(block) // unit * unit))
    full, rest = divmod(cfg.n_win, fit)
    return BlockPlan(tuple([fit] * full + ([rest] if rest else [])))


def angle_states(job):
    """[(Zs, scs, speeds)]: the forward flows' initial stacked states, sin/cos and speeds of
    the seeds of ``job`` = (system, settings, seeds, speed), as `hyperbolicity_angles` starts
    them (for ``map_jobs``)."""
    system, cfg, seeds, speed = job
    from dataclasses import replace
    flows = [angle_flow(system, *system.random_state(seed=s, speed=speed), replace(cfg, seed=s))
             for s in seeds]
    return [flow_states(flows)]


@njit(cache=True)
def _orthonormal_starts(W, w):
    """Each W[l] (m, 2N) orthonormalised in ``w``, in place."""
    logs = np.zeros(W.shape[1])
    for l in range(W.shape[0]):
        orthonormalize(W[l], w, logs)


def angles_on_device(system, cfg: AngleSettings, seeds, speed, *, backend="cuda", workers=1,
                     budget=None, block=None, update=None, consume=None):
    """The angle test of the seeds (as `hyperbolicity_angles` with ``seed=s`` on
    ``system.random_state(seed=s, speed=speed)``), every member a GPU thread (``backend=
    "cuda"``) or in turn on the CPU (``"cpu"``: the same logic), the window in blocks
    (module docstring) sized to ``budget`` bytes (default: half the GPU's free memory, or
    `memory_budget` on the CPU) or to ``block`` window steps at most; ``update(t)`` gets
    the window time done by all members after each block.  Returns (sines full (L, S),
    sines restricted (L, S), forward log-norm sums (L, m), adjoint rates (L, m), speeds
    (L,)) (``charts.analyses.hyperbolicity.angle_members`` makes them `AngleResult` s).
    The first member that stops raises the error `hyperbolicity_angles` raises, naming its
    seed.  ``consume(sf, sr, stops)``: takes each block's sines (L, block's samples) in turn
    instead, and the sines returned are None (``charts.analyses.angle_tally``: memory
    independent of the window); a member that stops is then frozen, not raised, and
    ``stops`` lists every stopped member as (index, seed, time, error): its block's sines
    are not its angles."""
    L = len(seeds)
    arr = DeviceArrays(backend)
    if budget is None:
        budget = arr.budget()
    plan = block_plan(cfg, L, budget, block)
    check_memory(L * block_bytes(cfg, plan.largest), f"the angle test's stores of {L} members",
                 "run fewer members at once")
    Zs, scs, speeds = member_states_of(angle_states, system, cfg, seeds, speed, workers)
    n, m, d = cfg.n, cfg.m, 2 * cfg.n
    w = np.ones(d)                                  # the Euclidean product of the angle test
    ce, sample, n_tr = cfg.ce, cfg.sample, cfg.n_tr
    Smax = plan.largest // sample
    nmax = checkpoint_rows(cfg, plan.largest)
    arrays = tuple(arr.put(a) for a in (system.minv, system.masses, system.weights, w))
    dev = {"Zs": arr.put(Zs), "scs": arr.put(scs), "counters": arr.put(np.zeros(L, np.int64)),
           "logsums": arr.put(np.zeros((L, m))), "status": arr.put(np.full(L, RUNNING, np.int64)),
           "stopped": arr.put(np.zeros(L, np.int64)), "phase": arr.put(np.zeros(L, np.int64)),
           "speeds": arr.put(speeds), "Vrec": arr.put(np.zeros((L, Smax, (1 + m) * d))),
           "CK": arr.put(np.zeros((L, nmax, d))), "blogs": arr.put(np.zeros((L, m))),
           "SF": arr.put(np.zeros((L, Smax))), "SR": arr.put(np.zeros((L, Smax)))}
    no_events, none = arr.put(np.empty(0, np.int64)), arr.put(np.empty((0, 0)))
    if backend == "cuda":
        fwd_k, bwd_k = _cuda_kernels(n, m, ce // sample + 1)
        threads = THREADS_PER_BLOCK
        grid = -(-L // threads)

        def fwd(*a):        # the kernels take the system's arrays one by one
            fwd_k[grid, threads](*a[:8], *a[8], *a[9:])

        def bwd(*a):
            bwd_k[grid, threads](*a[:9], *a[9], *a[10:])
    else:
        fwd, bwd = _forward_cpu, _backward_cpu
    keep_going = consume is not None
    if consume is None:
        sf, sr = np.empty((L, cfg.samples)), np.empty((L, cfg.samples))

        def consume(sf_block, sr_block, stops):
            sf[:, done // sample: done // sample + S] = sf_block
            sr[:, done // sample: done // sample + S] = sr_block
    else:
        sf = sr = None
    level, dt = float(system.level), cfg.dt
    done, back_steps, origin = 0, 0, 0
    for i, B in enumerate(plan.lengths):
        first = n_tr if i == 0 else ce
        nseg = (first + B + n_tr) // ce
        rho = (first + B - ce) // ce                # segments before the restart point
        S = B // sample
        vec_end = origin + first + B
        common = (ce, cfg.reorth, cfg.project, origin + first, sample)
        record_start = 1 if (i == 0 and n_tr == 0) else 0
        for a, b in ((0, rho), (rho, nseg)):
            fwd(dev["Zs"], dev["scs"], dev["counters"], dev["logsums"], dev["status"],
                dev["stopped"], dev["Vrec"], dev["CK"], arrays, level, dev["speeds"], dt,
                common + (a, b, vec_end, S, record_start), no_events, none)
            if a == 0:
                saved = {k: arr.copy(dev[k]) for k in ("Zs", "scs", "counters", "logsums")}
        W = np.empty((L, m, d))
        if i == 0:
            for l, s in enumerate(seeds):
                W[l] = adjoint_start(_seeded(cfg, s), w)
        else:
            W[...] = np.random.default_rng([cfg.seed, 1, i]).normal(size=W.shape)
            _orthonormal_starts(W, w)
        bwd(dev["status"], dev["stopped"], dev["phase"], arr.put(W), dev["CK"], dev["Vrec"],
            dev["blogs"], dev["SF"], dev["SR"], arrays, level, dt,
            (ce, first, sample, cfg.reorth, nseg, S, origin), no_events, none)
        stops = _stops(arr, dev, seeds, dt)
        if stops and not keep_going:
            raise stops[0][3]
        consume(arr.get(dev["SF"])[:, :S], arr.get(dev["SR"])[:, :S], stops)
        back_steps += nseg * ce - first
        done += B
        if i + 1 < len(plan.lengths):
            for k, v in saved.items():
                dev[k] = v
            origin += rho * ce
        if update is not None:
            update(L * B * dt)
    return (sf, sr, arr.get(dev["logsums"]), arr.get(dev["blogs"]) / (back_steps * dt),
            speeds)


def _seeded(cfg, s):
    from dataclasses import replace
    return replace(cfg, seed=s)


def _stops(arr, dev, seeds, dt):
    """`member_stops` of the angle test, naming the pass (forward, backward) of each."""
    phase = arr.get(dev["phase"])
    return member_stops(arr, dev, seeds, dt, lambda l: (
        f"hyperbolicity_ensemble ({'backward' if phase[l] == BACKWARD else 'forward'} RK4, "
        f"member seed={seeds[l]})"))
