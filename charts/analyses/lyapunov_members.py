"""Lyapunov ensembles: independent trajectories of `lyapunov_spectrum` advanced together,
in the vector lanes of one CPU kernel (``charts.solvers.lanes``, in parallel processes) or
each in its own GPU thread (``charts.solvers.device``); every member a `LyapunovResult`
(bit for bit `lyapunov_spectrum`'s on the CPU)."""
from __future__ import annotations

import inspect
import os
from dataclasses import replace
from functools import partial

import numpy as np

from ..geometry.energy_shares import SHARE_BINS
from ..solvers.device import DeviceFlows, cuda_module, device_bytes, flow_states
from ..solvers.lanes import MIN_LANES, LaneFlows, lanes_pay
from ..solvers.tangent import check_memory, inner_weights
from .arguments import progress_reporter
from .arguments import rotor_system
from .cluster import cluster_device, cluster_pool
from .ensemble import (EnsembleResult, ensemble_arguments, ensemble_result, map_jobs,
                       member_states_of)
from .lyapunov import (averaging_logs, end_transient, lyapunov_flow, lyapunov_result,
                       lyapunov_schedule, lyapunov_settings, resolve_transient)
from .transients import transient_rule
from .mechanism_route import mechanism_route

__all__ = ["lyapunov_ensemble", "lyapunov_lanes", "lyapunov_device", "member_states", "members_pay",
           "plan_memory", "result_bytes", "LANE_BLOCK", "MIN_LANES"]


@mechanism_route("mechanism_ensemble", "lyapunov_ensemble")
def lyapunov_ensemble(system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                      progress=False, device="cpu", lanes=None, client=None,
                      **kwargs) -> EnsembleResult:
    """`lyapunov_spectrum` from ``n_trajectories`` independent random initial states of speed
    ``speed`` (seeds seed, seed+1, …; also the seeds of their tangent vectors; ``kwargs``:
    the settings of `lyapunov_spectrum`).

    The trajectories run in blocks of up to `LANE_BLOCK`, the blocks in ``workers`` parallel
    processes (default: all cores; 1: in this process), a block's members together in the
    vector lanes of one kernel (``charts.solvers.lanes``) or one after the other in the
    one-trajectory kernel: ``lanes`` None (default) takes the lanes where they pay
    (``charts.solvers.lanes.lanes_pay``: their kernel is compiled for this N and k, or the
    ensemble is long enough to pay for compiling it), True always (from `MIN_LANES` members
    a block), False never; a GPU run (``device="cuda"``) ignores it.  Each member is the
    `LyapunovResult` of `lyapunov_spectrum` on its state, bit for bit, on either route
    (tests/test_lanes.py).  A member that stops (e.g. at a singular point) raises the error
    `lyapunov_spectrum` raises for it, naming its seed.  Returns an `EnsembleResult`:
    ``members``, and ``exponents`` / ``stderr``, the mean over the trajectories and its
    standard error.

    ``device="cuda"`` advances every member in its own GPU thread instead
    (``charts.solvers.device``: the same loop and equations compiled for the GPU; the
    members' bits differ from the CPU's by the GPU's fused multiply-adds and libm, see
    there); ``"auto"``: the GPU when there is one.  ``workers`` then only builds the
    members' initial states.

    ``client``: the blocks run as tasks of a Dask cluster instead (a ``Client``, a
    scheduler's address, or "local": a LocalCluster of ``workers`` processes;
    ``charts.analyses.cluster``, docs/cluster.md), as many blocks as the cluster has
    threads at least; the same members, bit for bit, as in local processes."""
    rotor_system(system)
    unknown = sorted(set(kwargs) - SETTINGS)
    if unknown:
        raise TypeError(f"lyapunov_ensemble() got an unexpected keyword argument {unknown[0]!r} "
                        f"(its settings are lyapunov_spectrum's: {', '.join(sorted(SETTINGS))})")
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    device = cluster_device(device, client)
    if lanes is not None and not isinstance(lanes, bool):
        raise ValueError(f"lanes must be None (where they pay), True or False, got {lanes!r}")
    kwargs.setdefault("t_transient", "scaled")            # lyapunov_spectrum's default
    rule = transient_rule(kwargs["t_transient"])
    if rule is not None:                                   # one transient for all members:
        # every other setting and the memory checked before a pilot runs
        plan_memory(system, lyapunov_settings(system, t_final, seed=seed,
                                              **{**kwargs, "t_transient": 0.0}),
                    n_trajectories, device)
        pilot = {k: kwargs[k] for k in ("dt", "n_exponents", "inner", "space") if k in kwargs}
        tr, text = resolve_transient(rule, system, *system.random_state(seed=seed, speed=speed),
                                     seed=seed, **pilot)      # the first member's state
        dt = kwargs.get("dt", 0.01)
        kwargs = {**kwargs, "t_transient": round(float(tr) / dt) * dt, "transient_rule": text}
    rule = kwargs.pop("transient_rule", None)
    cfg = lyapunov_settings(system, t_final, seed=seed, **kwargs)
    if rule is not None:
        kwargs = {**kwargs, "transient_rule": rule}
    plan_memory(system, cfg, n_trajectories, device)
    if device == "cuda":
        rep = progress_reporter(progress, n_trajectories * t_final,
                                f"Lyapunov N={system.n} ensemble (GPU)")
        members = lyapunov_device((system, cfg, list(range(seed, seed + n_trajectories)), speed),
                                  rep.update, "cuda", workers or os.cpu_count() or 1)
        rep.close()
        return ensemble_result(members, system, seed, speed, t_final, {**kwargs, "device": "cuda"})
    with cluster_pool(client, workers) as (pool, slots):
        cores = slots or os.cpu_count() or 1
        n_blocks = min(n_trajectories, max(cores, -(-n_trajectories // LANE_BLOCK)))
        cut = [n_trajectories * b // n_blocks for b in range(n_blocks + 1)]
        jobs = [(system, cfg, list(range(seed + a, seed + b)), speed)
                for a, b in zip(cut, cut[1:])]
        desc = f"Lyapunov N={system.n} ensemble"
        if lanes is None:                   # decided once: the parent compiles for every block
            lanes = members_pay(system, cfg, max(np.diff(cut)), n_trajectories)
        run = partial(lyapunov_lanes, lanes=lanes)
        if pool is None and (n_blocks == 1 or workers == 1):   # here: progress chunk by chunk
            rep = progress_reporter(progress, n_trajectories * t_final, desc)
            members = [m for job in jobs for m in run(job, rep.update)]
            rep.close()
        else:
            # the blocks' route (lanes or one by one) over two re-orthonormalisations
            short = replace(cfg, transient=0, total=2 * cfg.reorth, n_batches=2,
                            record=cfg.reorth)
            members = map_jobs(run, jobs, np.diff(cut), slots, t_final, progress, desc,
                               prime=(run, (system, short, jobs[0][2], speed)),
                               name="lyapunov_ensemble", n=system.n, pool=pool)
    return ensemble_result(members, system, seed, speed, t_final, kwargs)


#: The keyword settings `lyapunov_ensemble` passes on to every member (`lyapunov_spectrum`'s,
#: less the state, the length, the seed and the progress, which the ensemble sets itself).
SETTINGS = frozenset(inspect.signature(lyapunov_settings).parameters) - {"system", "t_final",
                                                                        "seed"}


def result_bytes(cfg) -> int:
    """Bytes of one member's `LyapunovResult`: its history, batches and exponents (k each)
    and its histogram of energy shares."""
    records, ends, _ = lyapunov_schedule(cfg)
    return 8 * (cfg.k * (2 * len(records) + len(ends) + 4) + SHARE_BINS)


def plan_memory(system, cfg, members, device) -> None:
    """Refuse, before anything is built, an ensemble whose results exceed this machine's
    memory budget, or whose members' states on the GPU (`DeviceFlows`, with the initial
    states built on the host) exceed half its free memory: ValueError with the numbers."""
    check_memory(members * result_bytes(cfg),
                 f"the results of {members} members (history of {cfg.total // cfg.record} records)",
                 "run fewer members or record less often (record_every)")
    if device == "cuda":
        per = device_bytes(system.n, cfg.k, SHARE_BINS)
        check_memory(2 * members * per, f"the initial states of {members} members",
                     "run fewer members at once")
        free = cuda_module().current_context().get_memory_info()[0]
        if members * per > free // 2:
            raise ValueError(f"{members} members need {members * per / 2**30:.1f} GiB on the GPU, "
                             f"more than half its free {free / 2**30:.1f} GiB; run fewer members "
                             "at once")


#: Most trajectories one lane kernel advances together (larger ensembles: several blocks).
LANE_BLOCK = 64


def lyapunov_lanes(job, update=None, lanes=None):
    """[`LyapunovResult`] of the seeds of ``job`` = (system, settings, seeds, speed), from
    ``system.random_state(seed=s, speed=speed)``, advanced together by `LaneFlows` where
    ``lanes`` (None: where they pay, ``charts.solvers.lanes.lanes_pay``; never for fewer than
    `MIN_LANES`), else one after the other (the same bits); ``update(t)`` (optional) gets the
    averaging time done by all members after each chunk."""
    system, cfg, seeds, speed = job
    if lanes is None:
        lanes = members_pay(system, cfg, len(seeds))
    cfgs = [replace(cfg, seed=s) for s in seeds]
    flows = [lyapunov_flow(system, *system.random_state(seed=s, speed=speed), c)
             for s, c in zip(seeds, cfgs)]
    if not lanes or len(seeds) < MIN_LANES:
        logs = []
        starts = [f.y.copy() for f in flows]
        for f, c, s in zip(flows, cfgs, seeds):
            w = _where(s)
            f.advance(cfg.transient, where=w)
            end_transient(f)
            logs.append(averaging_logs(f, c, partial(f.advance, where=w), update))
        return [lyapunov_result(system, c, lg, f.speed, f.shares, y0)
                for c, lg, f, y0 in zip(cfgs, logs, flows, starts)]
    return _members_of(LaneFlows(flows), system, cfg, seeds, update)


def members_pay(system, cfg, lanes, runs=None) -> bool:
    """`lanes_pay` for members of the settings ``cfg`` (their transient and averaging steps),
    ``lanes`` to a kernel and ``runs`` in all."""
    return lanes_pay(system.n, cfg.k, lanes, cfg.transient + cfg.total, runs)


def lyapunov_device(job, update=None, backend="cuda", workers=1):
    """`lyapunov_lanes` with every member in its own GPU thread (``backend="cuda"``) or the
    same logic on the CPU (``"cpu"``), by ``charts.solvers.device.DeviceFlows``; the members'
    initial states are built in ``workers`` processes (`member_states`)."""
    system, cfg, seeds, speed = job
    states = member_states_of(member_states, system, cfg, seeds, speed, workers)
    flows = DeviceFlows(system, states, dt=cfg.dt, w=inner_weights(system, cfg.inner),
                        restricted=cfg.space == "restricted", reorth_every=cfg.reorth,
                        project_every=cfg.project, share_bins=SHARE_BINS, backend=backend)
    return _members_of(flows, system, cfg, seeds, update)


def member_states(job):
    """[(Zs, scs, speeds)]: the stacked initial states (L, 1 + k, 2N), weighted sin/cos
    (L, 2, N) and speeds (L,) of the seeds of ``job`` (as in `lyapunov_lanes`), in a list
    of one (for ``map_jobs``)."""
    system, cfg, seeds, speed = job
    flows = [lyapunov_flow(system, *system.random_state(seed=s, speed=speed),
                           replace(cfg, seed=s)) for s in seeds]
    return [flow_states(flows)]


def _where(seed):
    return f"lyapunov_ensemble (ambient RK4, member seed={seed})"


def _members_of(lanes, system, cfg, seeds, update):
    """The members' `LyapunovResult` s of a run on ``lanes`` (`LaneFlows` or `DeviceFlows`,
    none advanced): the transient, then `averaging_logs`; the first member that stopped
    raises its error."""
    def advance(steps, **kw):
        lanes.advance(steps, **kw)
        for l in lanes.stopped_lanes()[:1]:
            raise lanes.error(l, _where(seeds[l]))

    starts = [lanes.lane(i)[0].copy() for i in range(len(seeds))]
    advance(cfg.transient)
    end_transient(lanes)
    logs = averaging_logs(lanes, cfg, advance,
                          None if update is None else lambda t: update(len(seeds) * t))
    return [lyapunov_result(system, replace(cfg, seed=s), logs[:, i], float(lanes.speed[i]),
                            lanes.shares[i], starts[i]) for i, s in enumerate(seeds)]
