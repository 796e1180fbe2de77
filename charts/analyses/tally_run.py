"""The angle test tallied as it runs (`hyperbolicity_tally`, docs/hyperbolicity.md "At scale"):
the members of `charts.analyses.hyperbolicity.hyperbolicity_ensemble`, their angles added to
an `AngleTally` and dropped, on the CPU (chunks of members in a process pool or on a Dask
cluster, checkpointed after each chunk) or on the device (the blocks of
``charts.analyses.angle_blocks``), the same tally bit for bit on every route."""
from __future__ import annotations

import os
import warnings
from contextlib import ExitStack

import numpy as np

from ..geometry.checks import path as file_path
from ..solvers.tangent import check_memory
from .angle_blocks import angles_on_device
from .angle_tally import SUMS, VARIANTS, AngleTally, member_bytes
from .arguments import positive_int, progress_reporter, rotor_system
from .cluster import cluster_device, cluster_pool
from .ensemble import ensemble_arguments, stream_jobs
from .forward_pass import angle_settings
from .hyperbolicity import angle_params, check_cpu_store, hyperbolicity_angles, short_settings
from .mechanism_route import mechanism_route
from .worker_pool import worker_pool

__all__ = ["hyperbolicity_tally", "tally_on_cpu", "tally_on_device", "StoppedMember",
           "TALLY_CHUNK"]


@mechanism_route("mechanism_ensemble", "hyperbolicity_tally")
def hyperbolicity_tally(system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                        progress=False, device="cpu", budget=None, chunk=None, checkpoint=None,
                        client=None, **kwargs) -> AngleTally:
    """The angle test of `hyperbolicity_ensemble` (seeds seed, seed + 1, …; ``kwargs``: its
    settings), tallied as it runs into an `AngleTally` instead of kept.  ``device="cuda"``:
    memory per member independent of ``t_final``, every member a GPU thread, the window in
    the blocks of ``charts.analyses.angle_blocks`` (``budget``: bytes of GPU memory for one
    block's stores, default half the free memory; the sines tallied on ``workers`` threads);
    ``"cpu"``: the members in chunks of ``chunk`` consecutive seeds (default: about four
    chunks per process, at most `TALLY_CHUNK` members), each chunk a job in ``workers``
    processes or a task of the Dask cluster ``client`` (a ``Client``, a scheduler's address,
    or "local": a LocalCluster of ``workers`` processes; ``charts.analyses.cluster``,
    docs/cluster.md): there its members run one after the other by `hyperbolicity_angles`,
    each member's window held while it runs (at most `MAX_STORE` bytes of forward vectors:
    refused beyond, with the remedy), its angles tallied there and dropped; only the
    chunk's tally comes back, its members' rows put into this tally in seed order, so this
    process holds the tally alone, whatever ``t_final``.  The same tally, bit for bit, on
    every route and chunk size.  With ``checkpoint`` (a path) the tally of the members done
    is saved there after each chunk merged, and a run that finds it there (the same call,
    any ``chunk``, ``workers`` or ``client``) goes on from it instead of starting again; a
    lost worker or a Ctrl-C costs the chunks in flight; removed when the run is whole."""
    rotor_system(system)
    device = cluster_device(device, client)
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    if budget is not None:
        budget = positive_int("budget", budget)
    if checkpoint is not None:
        checkpoint = file_path("checkpoint", checkpoint)
    check_memory(n_trajectories * member_bytes(), f"the sums of a tally of {n_trajectories} members",
                 "run fewer members (several tallies combine with AngleTally.merged)")
    cfg = angle_settings(system, t_final, seed=seed, **kwargs)
    params = dict(angle_params(system, cfg, float(speed)), device=device, members_seed=seed)
    for own in ("vectors_seed", "state_seed"):      # each member's: the tally's ``seeds``
        params.pop(own)
    rep = progress_reporter(progress, n_trajectories * t_final,
                            f"angles N={system.n} tally ({device.upper()})")
    try:
        if device == "cuda":
            tally = AngleTally.empty(n_trajectories, params)
            tally_on_device(system, cfg, tally, speed, workers=workers or os.cpu_count() or 1,
                            budget=budget, update=rep.update)
        else:
            check_cpu_store(cfg, t_final)
            tally = tally_on_cpu(system, short_settings(cfg), n_trajectories, t_final, params, speed,
                                 seed, workers, chunk, checkpoint, rep, kwargs, client)
    finally:
        rep.close()
    tally._open.clear()                     # the run is whole: nothing left to carry
    return tally


#: The most members of one chunk of `hyperbolicity_tally` on the CPU by default (a chunk's
#: members run one after the other on one worker; a checkpoint after each chunk).
TALLY_CHUNK = 64


def tally_on_cpu(system, short, L, t_final, params, speed, seed, workers, chunk, checkpoint,
                 rep, kwargs, client, variants=VARIANTS, n=None) -> AngleTally:
    """`hyperbolicity_tally` on the CPU: chunks of members as jobs (`_tally_chunk`) in one
    process pool or on ``client``'s cluster, each chunk's tally merged here in seed order
    (`_merge_chunk`) and saved to ``checkpoint`` (``members_done``), resumed from it;
    ``short``: (t_final, settings) of the call that compiles the kernels here first;
    ``variants``: the angles of each member the tally keeps (a Mechanism's: "restricted"),
    ``n``: the N of the compile notice (default ``system.n``)."""
    if chunk is not None:
        chunk = positive_int("chunk", chunk)
    tally, done = AngleTally.empty(L, params, variants), 0
    if checkpoint is not None and os.path.exists(checkpoint):
        tally, done = AngleTally.resumed(checkpoint, L, tally.params)
        rep.update(done * t_final)
    with ExitStack() as stack:
        pool, slots = stack.enter_context(cluster_pool(client, workers))
        slots = slots or os.cpu_count() or 1
        size = chunk or max(1, min(TALLY_CHUNK, -(-L // (4 * slots))))
        cuts = np.linspace(0, L, max(1, L // size) + 1).round().astype(int)
        # a checkpoint of another chunk size goes on from its members done
        spans = [(max(int(a), done), int(b)) for a, b in zip(cuts[:-1], cuts[1:]) if b > done]
        jobs = [(system, seed + a, b - a, speed, t_final, params, kwargs, variants)
                for a, b in spans]
        if pool is None and slots > 1 and len(jobs) > 1:   # one pool; an interrupt cancels
            pool = worker_pool(min(slots, len(jobs)))   # what is queued
            stack.callback(pool.shutdown, cancel_futures=True)
        t_short, short = short                  # compiles the kernels here first
        prime = (_tally_chunk, (system, seed, 1, speed, t_short, params, {**kwargs, **short},
                                variants))
        parts = stream_jobs(_tally_chunk, jobs, 1 if pool is None else slots, prime=prime,
                            name="hyperbolicity_tally", n=system.n if n is None else n,
                            pool=pool)
        stack.callback(parts.close)             # an error or a Ctrl-C: nothing more started
        for (a, b), (part,) in zip(spans, parts):
            _merge_chunk(tally, part, a)
            if checkpoint is not None and b < L:
                tally.params["members_done"] = b
                tally.save(checkpoint)
                tally.params.pop("members_done")
            rep.update((b - a) * t_final)
    if checkpoint is not None and os.path.exists(checkpoint):
        os.remove(checkpoint)                    # the run is whole: its result is returned
    return tally


def _tally_chunk(job):
    """In a worker: [the `AngleTally` of the members of ``job`` = (system, first seed,
    members, speed, t_final, the tally's params, settings, variants)], each member's angles
    by `hyperbolicity_angles` (a Mechanism's by its route) from ``system.random_state(seed=s,
    speed=speed)`` (as `hyperbolicity_ensemble`'s members), its ``phi_<variant>`` tallied and
    dropped."""
    system, first, count, speed, t_final, params, kwargs, variants = job
    part = AngleTally.empty(count, dict(params, members_seed=first), variants)
    for i in range(count):
        s = first + i
        theta0, u0 = system.random_state(seed=s, speed=speed)
        m = hyperbolicity_angles(system, theta0, u0, t_final, seed=s, **kwargs)
        for v in variants:
            part.add(getattr(m, f"phi_{v}")[None, :], i, variant=v)
    part._open.clear()                      # whole members: nothing carried, nothing sent
    return [part]


def _merge_chunk(tally, part, first):
    """The members of ``part`` (a chunk's tally from `_tally_chunk`, members first, first +
    1, …) into ``tally``'s rows, its sums as the chunk's worker made them."""
    rows = slice(first, first + part.n_members)
    if not np.array_equal(tally.seeds[rows], part.seeds):
        raise ValueError(f"a chunk of seeds {part.seeds.tolist()} does not fit rows "
                         f"{first} … of a tally of seeds {tally.seeds[0]} …")
    for k in SUMS:
        if k == "n":
            tally.n[rows] = part.n
        else:
            getattr(tally, k)[:, rows] = getattr(part, k)


def tally_on_device(system, cfg, tally, speed, *, backend="cuda", workers=1, **kw):
    """The angle test of ``tally``'s members (seeds ``tally.params["members_seed"]`` on) by
    ``charts.analyses.angle_blocks.angles_on_device`` (``backend``, ``kw``: its arguments),
    each block's sines added to ``tally`` on ``workers`` threads as they arrive."""
    seeds = tally.seeds.tolist()
    alive = np.ones(tally.n_members, bool)

    def consume(sf, sr, stops):
        for l, s, t, message in stops:
            if alive[l]:
                alive[l] = False
                tally.params.setdefault("stopped", []).append([s, t])
                warnings.warn(f"{message}; its angles before this block are kept", StoppedMember)
        tally.add_both(sf, sr, threads=workers, alive=alive)
    angles_on_device(system, cfg, seeds, speed, backend=backend, workers=workers,
                     consume=consume, **kw)
    return tally


class StoppedMember(UserWarning):
    """A member of a tallied angle test stopped (at a singular point, on a non-finite
    value): the others go on; its angles up to the block before count."""
