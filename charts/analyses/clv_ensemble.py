"""Covariant Lyapunov vectors (``charts.analyses.covariant``) of ensembles: `covariant_ensemble`
runs its members in processes on the CPU, or on a GPU with the forward pass one member per
thread and Ginelli's backward iteration and the angles on the host.

Each thread runs the forward pass of `covariant_lyapunov_vectors` — the tangent loop with D
vectors (`tangent_loop`), and at every sample `factor_sample`: the projection onto T_r, the
Gram–Schmidt vectors Q and the factor R kept — compiled for the GPU; what one thread does is
`clv_forward_member`, which the CPU twin (``backend="cpu"``) runs member after member, so the
logic is tested without a GPU.  The host then runs, member by member, the CPU route's own
backward iteration (`backward_coefficients`) and angles (`clv_samples`).

Blocks.  The window's S samples are cut into blocks sized to a memory budget.  Block i stores
the factors of its samples and of the samples of a backward transient after them (as many as
the CPU route stores after its window), from which Ginelli's iteration starts with a random C
(block 0: the CPU route's stream [seed, 2]; block i: [seed, 2, i]).  The forward flow is saved
where the block's own samples end and restored after the block, so the forward pass is one
continuous run: its Gram–Schmidt rates do not depend on the blocks.  With one block each
member equals `covariant_lyapunov_vectors` bit for bit; with several, the CLVs after the
first block differ by the backward iteration's convergence error over t_transient
(tests/test_clv_ensemble.py).
"""
from __future__ import annotations

import functools
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from ..solvers.device import THREADS_PER_BLOCK, DeviceArrays, cuda_module, flow_states, member_stops
from ..solvers.status import RUNNING
from ..solvers.tangent import check_memory
from .arguments import flag, progress_reporter
from .covariant import (CLVSettings, backward_coefficients, clv_flow, clv_forward_member,
                        clv_samples, clv_settings, covariant_lyapunov_vectors, covariant_result,
                        ginelli_start, result_bytes)
from .covariant import forward_members as _forward_cpu  # (the CPU twin of the CUDA kernel)
from .cluster import cluster_device
from .ensemble import (EnsembleResult, ensemble_arguments, ensemble_result, member_states_of,
                       run_ensemble)
from .arguments import rotor_system
from .mechanism_route import mechanism_route

__all__ = ["covariant_ensemble", "clv_ensemble_settings", "clvs_on_device",
           "clv_block_plan", "clv_block_bytes", "clv_states", "kernel_function"]


@mechanism_route("mechanism_ensemble", "covariant_ensemble")
def covariant_ensemble(system, n_trajectories, t_final, *, variant="restricted", speed=1.0,
                       seed=0, workers=None, progress=False, device="cpu", client=None,
                       **kwargs) -> EnsembleResult:
    """`covariant_lyapunov_vectors` on independent random states (seeds seed, seed+1, …;
    ``kwargs``: its settings): an `EnsembleResult` of `CovariantResult` members.  On the CPU
    in parallel processes; ``device="cuda"``: the forward pass every member a GPU thread,
    the window in blocks sized to the GPU's memory (module docstring: with one block each
    member equals `covariant_lyapunov_vectors`, with several the CLVs after the first block
    differ by the backward iteration's convergence error); ``keep_vectors`` is not offered
    there.  ``"auto"``: the GPU when there is one.  ``client``: the members run as tasks of a
    Dask cluster instead (a ``Client``, a scheduler's address, or "local": a LocalCluster of
    ``workers`` processes; ``charts.analyses.cluster``, docs/cluster.md)."""
    rotor_system(system)
    device = cluster_device(device, client)
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    if device == "cuda":
        if kwargs.get("keep_vectors"):
            raise ValueError("keep_vectors is not offered with device='cuda': the CLVs of every "
                             "member would stay in memory; run on the CPU")
        cfg = clv_ensemble_settings(system, t_final, variant, seed, kwargs)
        rep = progress_reporter(progress, n_trajectories * t_final,
                                f"CLV N={system.n} ensemble (GPU)")
        try:
            members = clvs_on_device(system, cfg, variant,
                                     list(range(seed, seed + n_trajectories)), speed,
                                     workers=workers or os.cpu_count() or 1,
                                     update=rep.update)
        finally:
            rep.close()
        return ensemble_result(members, system, seed, speed, t_final,
                               {**kwargs, "variant": variant, "device": "cuda"})
    cfg = clv_ensemble_settings(system, t_final, variant, seed, kwargs)
    check_memory(n_trajectories * result_bytes(cfg, system.n, flag("keep_vectors", kwargs.get("keep_vectors", False))),
                 f"the results of {n_trajectories} members ({cfg.S} samples each)",
                 "run fewer members, shorten t_final or raise sample_every")
    tau = cfg.tau
    short = (2 * tau, {"t_transient": 0.0})         # the priming call: two samples
    return run_ensemble(covariant_lyapunov_vectors, system, n_trajectories, t_final,
                        speed=speed, seed=seed, workers=workers, progress=progress,
                        desc=f"CLV N={system.n} ensemble", prime=short, variant=variant,
                        client=client, **kwargs)


def clv_ensemble_settings(system, t_final, variant, seed, kwargs) -> CLVSettings:
    """`clv_settings` of the call, the defaults those of `covariant_lyapunov_vectors`'s
    signature (one home); a setting it does not take is refused as there."""
    import inspect
    params = inspect.signature(covariant_lyapunov_vectors).parameters
    own = ("dt", "n_unstable", "t_transient", "sample_every", "project_every", "max_memory",
           "keep_vectors", "scratch")
    unknown = sorted(set(kwargs) - set(own))
    if unknown:
        raise TypeError(f"covariant_ensemble() got unexpected settings {unknown}")
    a = {k: kwargs.get(k, params[k].default) for k in own}
    return clv_settings(system, t_final, variant, a["dt"], a["n_unstable"], a["t_transient"],
                        a["sample_every"], a["project_every"], seed, a["max_memory"])


#: Numba's CUDA module once `_cuda_kernel` found it usable (a global that the kernel reads,
#: so that a stand-in can replace it in tests).
cuda = None


def kernel_function(n, D):
    """The Python function of the CUDA forward kernel for N = n and D vectors (the sizes of
    its local arrays)."""
    from numba import float64, int64

    R, d = D + 1, 2 * n
    RD, RD4 = R * d, 4 * R * d

    def forward(Zs, scs, counters, logsums, status, stopped, Qs, Rs, Ys, GS, minv, mass, wts, w,
                restricted, level, speeds, dt, steps, tau, no_events, none):
        l = cuda.grid(1)
        if l >= Zs.shape[0]:
            return
        clv_forward_member(l, Zs, scs, counters, logsums, status, stopped, Qs, Rs, Ys, GS,
                           (minv, mass, wts, w, restricted), level, speeds, dt, steps, tau,
                           no_events, none, cuda.local.array((R, d), float64),
                           cuda.local.array((2, n), float64), cuda.local.array(1, int64),
                           cuda.local.array(D, float64),
                           (cuda.local.array(RD, float64), cuda.local.array(RD4, float64),
                            cuda.local.array(n, float64), cuda.local.array(n, float64),
                            cuda.local.array(n, float64), cuda.local.array(n, float64),
                            cuda.local.array(n, float64), cuda.local.array(n, float64),
                            cuda.local.array(n, float64), cuda.local.array(n, float64)),
                           cuda.local.array((D, d), float64), cuda.local.array(D, float64))

    return forward


@functools.lru_cache(maxsize=None)
def _cuda_kernel(n, D):
    """The CUDA forward kernel of `kernel_function`, compiled at its first launch."""
    global cuda
    cuda = cuda_module()
    return cuda.jit(kernel_function(n, D))


def clv_block_bytes(cfg: CLVSettings, n, block) -> int:
    """Bytes one member stores for a block of ``block`` samples and the backward transient's
    samples after them: Q, R, the state and the Gram–Schmidt rates per sample."""
    D, d = cfg.D, 2 * n
    return 8 * (block + cfg.total - cfg.S) * (D * d + D * D + d + D)


def clv_block_plan(cfg: CLVSettings, n, members, budget, block=None) -> tuple:
    """The blocks' lengths in samples: as many as fit ``budget`` bytes for ``members`` (or
    ``block`` at most); ValueError with the numbers when not even one sample fits."""
    if members * clv_block_bytes(cfg, n, 1) > budget:
        need = members * clv_block_bytes(cfg, n, 1) / 2**30
        raise ValueError(f"{members} members need {need:.2f}"
                         f" GiB for the shortest block (one sample and the backward transient's "
                         f"{cfg.total - cfg.S}), more than the {budget / 2**30:.2f} GiB budget; "
                         "run fewer members at once or raise sample_every")
    fixed = clv_block_bytes(cfg, n, 0)                   # the backward transient's samples
    per = clv_block_bytes(cfg, n, 1) - fixed              # and each sample of the block
    fit = max(1, min(cfg.S, (budget // members - fixed) // per))
    if block is not None:
        fit = max(1, min(fit, int(block)))
    full, rest = divmod(cfg.S, fit)
    return tuple([fit] * full + ([rest] if rest else []))


def clv_states(job):
    """[(Zs, scs, speeds)]: the forward flows' initial stacked states, sin/cos and speeds of
    the seeds of ``job`` = (system, (settings, variant), seeds, speed), as
    `covariant_lyapunov_vectors` starts them (for ``map_jobs``)."""
    system, (cfg, variant), seeds, speed = job
    flows = [clv_flow(system, *system.random_state(seed=s, speed=speed), cfg._replace(seed=s),
                      variant) for s in seeds]
    return [flow_states(flows)]


def clvs_on_device(system, cfg: CLVSettings, variant, seeds, speed, *, backend="cuda",
                   workers=1, budget=None, block=None, update=None) -> list:
    """[`CovariantResult`] of the seeds, each as `covariant_lyapunov_vectors` with
    ``seed=s`` on ``system.random_state(seed=s, speed=speed)`` would return it (bit for bit
    with one block), the forward pass every member a GPU thread (``backend="cuda"``) or in
    turn on the CPU (``"cpu"``), in blocks (module docstring) sized to ``budget`` bytes
    (default: half the GPU's free memory, or `memory_budget` on the CPU) or to ``block``
    samples at most; ``update(t)`` gets the window time done by all members after each
    block.  The first member that stops raises the error `covariant_lyapunov_vectors`
    raises, naming its seed."""
    L, n = len(seeds), system.n
    arr = DeviceArrays(backend)
    if budget is None:
        budget = arr.budget()
    plan = clv_block_plan(cfg, n, L, budget, block)
    extra = cfg.total - cfg.S                       # the backward transient's samples
    rows = max(plan) + extra
    D, d = cfg.D, 2 * n
    check_memory(2 * L * clv_block_bytes(cfg, n, max(plan)) + 8 * L * cfg.total * (3 * D + d),
                 f"the CLVs' stores of {L} members", "run fewer members at once")
    Zs, scs, speeds = member_states_of(clv_states, system, (cfg, variant), seeds, speed, workers)
    restricted = variant == "restricted"
    arrays = tuple(arr.put(a) for a in (system.minv, system.masses, system.weights, np.ones(d)))
    dev = {"Zs": arr.put(Zs), "scs": arr.put(scs), "counters": arr.put(np.zeros(L, np.int64)),
           "logsums": arr.put(np.zeros((L, D))), "status": arr.put(np.full(L, RUNNING, np.int64)),
           "stopped": arr.put(np.zeros(L, np.int64)), "speeds": arr.put(speeds),
           "Q": arr.put(np.zeros((L, rows, D, d))), "R": arr.put(np.zeros((L, rows, D, D))),
           "Y": arr.put(np.zeros((L, rows, d))), "GS": arr.put(np.zeros((L, rows, D)))}
    no_events, none = arr.put(np.empty(0, np.int64)), arr.put(np.empty((0, 0)))
    if backend == "cuda":
        kernel = _cuda_kernel(n, D)
        grid = -(-L // THREADS_PER_BLOCK)

        def forward(*a):        # the kernel takes the system's arrays one by one
            kernel[grid, THREADS_PER_BLOCK](*a[:10], *a[10], restricted, *a[11:])
    else:
        def forward(*a):
            _forward_cpu(*a[:10], (*a[10], restricted), *a[11:])
    reorth = cfg.n_steps + 1
    phi, phi_v = np.empty((L, cfg.S)), np.empty((L, cfg.S))
    lost, gs = np.empty((L, cfg.S, D)), np.empty((L, cfg.S, D))
    states = np.empty((L, cfg.S, d))
    level, dt = float(system.level), cfg.dt
    a = 0
    for i, B in enumerate(plan):
        saved = None
        for ja, jb in ((a, a + B), (a + B, a + B + extra)):
            steps = (cfg.n_tr, cfg.sample, cfg.project, reorth, a, ja, jb)
            forward(dev["Zs"], dev["scs"], dev["counters"], dev["logsums"], dev["status"],
                    dev["stopped"], dev["Q"], dev["R"], dev["Y"], dev["GS"], arrays, level,
                    dev["speeds"], dt, steps, cfg.tau, no_events, none)
            if saved is None:                       # the flow where the block's samples end
                saved = {k: arr.copy(dev[k]) for k in ("Zs", "scs", "counters", "logsums")}
        stops = member_stops(arr, dev, seeds, dt, lambda l: (
            f"covariant_ensemble (RK4, {variant}, member seed={seeds[l]})"))
        if stops:
            raise stops[0][3]
        Q, R, Y, G = (arr.get(dev[k]) for k in ("Q", "R", "Y", "GS"))

        def backward(l, i=i, a=a, B=B):
            """Member l's backward iteration and angles over block i (numba and LAPACK
            without the GIL: the members on ``workers`` threads)."""
            C = ginelli_start(seeds[l], D, None if i == 0 else i)
            Cs, lo = np.empty((B + extra, D, D)), np.zeros((B + extra, D))
            backward_coefficients(np.ascontiguousarray(R[l, :B + extra]), C, Cs, lo)
            _, phi[l, a:a + B], phi_v[l, a:a + B] = clv_samples(Q[l, :B], Cs[:B], cfg.m, n)
            lost[l, a:a + B] = lo[1:B + 1]
            gs[l, a:a + B] = G[l, 1:B + 1]
            states[l, a:a + B] = Y[l, :B]
        if workers > 1:
            with ThreadPoolExecutor(workers) as pool:
                list(pool.map(backward, range(L)))
        else:
            for l in range(L):
                backward(l)
        for k, v in saved.items():
            dev[k] = v
        a += B
        if update is not None:
            update(L * B * cfg.tau)
    return [covariant_result(system, cfg._replace(seed=s), variant, phi[l], phi_v[l], lost[l],
                             gs[l], states[l], None, float(speeds[l]),
                             system.random_state(seed=s, speed=speed))
            for l, s in enumerate(seeds)]
