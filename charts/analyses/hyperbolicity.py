"""Hyperbolicity test by angles between perturbation subspaces, section 4.

Along one reference trajectory x(t) of eq (8):

1. forward, m = N−2 tangent vectors V (eq 17) are integrated with QR re-orthonormalisation
   every 0.1 time units and at every sample (``charts.solvers.tangent.reorth_steps``); after
   a transient they span the expanding subspace E_u;
2. backward, m adjoint vectors W (ẇ = −J(x(t))ᵀ w) are integrated in reverse time with
   QR at the same steps; after a transient they span the orthogonal complement of E_cs, the subspace of zero
   and negative exponents (the pairing ⟨w, ξ⟩ is conserved);
3. at each sample point sin φ = σ_min(WᵀV), φ the smallest angle between E_u and E_cs.

Both bases are orthonormal in the Euclidean product of R^{2N} (the paper's "full" product;
with unequal masses the angle is still well defined, its values depend on the product).

Two variants are computed from the same V and W:

* ``full`` (the paper's): E_cs is taken in all of R^{2N}, so it contains the two
  non-physical directions that break the constraint (δF, δG ≠ 0; zero exponents);
* ``restricted``: everything in the invariant constraint-preserving subspace
  T_r = {ξ : ∇F·ξ = ∇G·ξ = 0}, ∇F = (−sin θ, 0), ∇G = (u cos θ, sin θ): W is projected
  Euclidean-orthogonally onto T_r and re-orthonormalised (the complement of E_cs ∩ T_r in
  T_r is the projection of the complement of E_cs), V lies in T_r already.

Memory: the trajectory is kept only as checkpoints every ``checkpoint_every``; the backward
pass (``charts.analyses.adjoint_pass``) restarts each segment from its checkpoint and integrates eq (8) backward jointly with
the adjoint (over one segment the backward RK4 retraces the forward one to ~1e-13), with the
forward kernel's step policy: near an N = 4 singular point a step is cut into equal
sub-steps within the cap of ``charts.solvers.status``.  (With fixed backward steps the angles
before a close approach differed from those of the covariant-vector route by up to 0.61
relative, with the policy by 1.1e-4: tests/test_covariant.py.)  The
forward vectors are stored only at the S sample points: S·m·2N floats.  Each set of
vectors is carried only where it is needed: V up to the window's end (then the state
alone, same bits), W back to the window's start (the first transient is not retraced).
"""
from __future__ import annotations

import os
import warnings
from contextlib import ExitStack
from dataclasses import dataclass, replace

import numpy as np

from ..io.archive import Archivable, attributes, dataset, index_coordinate
from ..io.result_words import RATE, smallest_words
from ..jit.compilation import announces_compilation
from ..geometry.checks import finite_array, option
from ..geometry.checks import path as file_path
from ..solvers.status import RUNNING, status_error
from ..solvers.tangent import check_memory
from .worker_pool import worker_pool
from .adjoint_pass import adjoint_step, backward_kernel
from .angle_blocks import angles_on_device
from .angle_tally import SMALL_ANGLE, SUMS, VARIANTS, AngleTally, member_bytes
from .arguments import positive_int, positive_time, progress_reporter, start_state, Documented
from .cluster import cluster_device, cluster_pool
from .ensemble import (EnsembleResult, ensemble_arguments, ensemble_result, run_ensemble,
                       stream_jobs)
from .forward_pass import AngleSettings, adjoint_start, angle_flow, angle_settings, forward_kernel
from .singular_values import sin_to_angle, smallest_singular_values
from .statistics import small_value_law
from .arguments import rotor_system
from .mechanism_route import mechanism_route

__all__ = ["AngleResult", "angle_result", "angle_members", "hyperbolicity_angles",
           "hyperbolicity_ensemble", "angle_params", "hyperbolicity_tally", "tally_on_device",
           "tally_on_cpu", "StoppedMember",
           "angle_statistics",
           "LAW_KEYS", "adjoint_step", "smallest_singular_values"]

#: the fields of `small_value_law` that `angle_statistics` reports as ``law_<field>``.
LAW_KEYS = ("count", "exponent", "exponent_se", "coef2", "coef2_se")
#: refuse to allocate more than this for the stored forward vectors (bytes).
MAX_STORE = 1 << 30
def stored_bytes(cfg: AngleSettings) -> int:
    """Bytes `hyperbolicity_angles` stores: the forward vectors at every sample."""
    return cfg.samples * cfg.m * 2 * cfg.n * 8


def check_cpu_store(cfg: AngleSettings, t_final) -> None:
    """ValueError, before any work, when a member on the CPU would keep more than `MAX_STORE`
    bytes of forward vectors over its window (`hyperbolicity_tally`; ``charts verdict
    --statistics`` plans every system with it first)."""
    if stored_bytes(cfg) > MAX_STORE:
        raise ValueError(f"on the CPU each member keeps its window's forward vectors: "
                         f"{stored_bytes(cfg) / 2**20:.0f} MB for T = {t_final:g}, more than "
                         f"{MAX_STORE / 2**20:.0f} MB; run more members with a shorter window "
                         "each, or on a GPU (device='cuda')")


#: forward segments per compiled call (the progress is reported between calls).
_SEGMENTS = 1000


@dataclass(eq=False, repr=False)
class AngleResult(Archivable):
    """Angles φ (rad) between E_u and E_cs at the S sample points.

    t : (S,) sample times; phi_full, phi_restricted : (S,) the two variants;
    forward_exponents, adjoint_exponents : (m,) growth rates seen by V over [0, t_transient +
    t_final] and (backward) by W over [t_transient, end], the spans where each is carried: a
    check that both passes converged to the expanding subspaces.
    """
    t: np.ndarray
    phi_full: np.ndarray
    phi_restricted: np.ndarray
    forward_exponents: np.ndarray
    adjoint_exponents: np.ndarray
    params: dict

    def summary_parts(self):
        """The smallest angle of each variant (a lost, non-finite sample left out)."""
        return [f"min φ full {smallest_words(self.phi_full)}",
                f"restricted {smallest_words(self.phi_restricted)}"]

    def statistics(self, variant="restricted", small=SMALL_ANGLE):
        """`angle_statistics` of the angles of ``variant`` ("restricted" or "full"): a dict
        with the keys ``min``, ``median``, ``p001``, ``p01``, ``n``, ``small``,
        ``frac_small`` and the small-angle law's ``law_exponent``, ``law_exponent_se``,
        ``law_coef2``, ``law_coef2_se``, ``law_count`` (None where undefined).  To compare
        variants, call it once for each."""
        variant = option("variant", variant, ("restricted", "full"))
        return angle_statistics(self.phi_restricted if variant == "restricted" else self.phi_full,
                                small)

    KIND = "angles"

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``)."""
        return dataset(self.KIND, {
            "phi_full": (("t",), self.phi_full, "rad", "angle, full 2N-dim tangent space"),
            "phi_restricted": (("t",), self.phi_restricted, "rad",
                               "angle, constraint-preserving tangent space"),
            "forward_exponents": (("vector",), self.forward_exponents, RATE),
            "adjoint_exponents": (("vector",), self.adjoint_exponents, RATE)},
            coords={"t": (("t",), self.t, "time"),
                    "vector": index_coordinate("vector", len(self.forward_exponents),
                                               "i of the i-th tangent / adjoint vector, from 1")},
            attrs={"params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        return cls(t=ds["t"].values, phi_full=ds["phi_full"].values,
                   phi_restricted=ds["phi_restricted"].values,
                   forward_exponents=ds["forward_exponents"].values,
                   adjoint_exponents=ds["adjoint_exponents"].values,
                   params=attributes(ds)["params"])

    def plot(self, ax=None, kind="histogram", **kw):
        """``kind="histogram"``: histograms of the angles φ (both variants), ``(fig, axes)``
        (``charts.plotting.plot_angles``); ``"time"``: φ(t) on a log axis,
        ``window=(t0, t1)`` for a span of a long run, ``(fig, ax)``
        (``charts.plotting.plot_angles_series``)."""
        phis = {"full": self.phi_full, "restricted": self.phi_restricted}
        if kind == "time":
            from ..plotting import plot_angles_series
            return plot_angles_series(self.t, phis, ax=ax, **kw)
        if kind != "histogram":
            raise ValueError(f"kind must be 'histogram' or 'time', got {kind!r}")
        from ..plotting import plot_angles
        return plot_angles(phis, axes=ax, **kw)


def angle_statistics(phi, small=SMALL_ANGLE):
    """Summary of the finite angles ``phi`` (rad; a non-empty 1-D array, in time order), a
    dict with the keys

    * ``min``, ``median``, ``p001`` and ``p01`` (the 0.1 % and 1 % percentiles), ``n`` (the
      sample size), ``small`` (the threshold) and ``frac_small`` (the fraction below it);
    * the law of the small angles P(φ < x) = A x^β below ``small``
      (``charts.analyses.statistics.small_value_law``, 10 batches): ``law_exponent`` β̂ ±
      ``law_exponent_se``, ``law_coef2`` A for β = 2 ± ``law_coef2_se``, ``law_count`` the
      samples below ``small`` — each None where undefined (fewer than two batches holding
      angles below ``small``, or an angle of exactly 0; with no angle below ``small`` the
      exponent and both errors are None, while ``law_count`` = 0 and A = 0 record that none
      fell below)."""
    phi = finite_array("phi", phi, ndim=1)
    if phi.size == 0:
        raise ValueError("phi must hold at least one angle, got an empty array")
    small = positive_time("small", small)
    out = dict(min=float(phi.min()), frac_small=float((phi < small).mean()),
               p001=float(np.percentile(phi, 0.1)), p01=float(np.percentile(phi, 1)),
               median=float(np.median(phi)), n=int(phi.size), small=small)
    law = small_value_law(phi, small, n_batches=min(10, phi.size)) if out["min"] > 0 else {}
    for k in LAW_KEYS:        # undefined (no angle below, one batch, an angle of 0): None
        v = law.get(k)
        out[f"law_{k}"] = v if v is not None and np.isfinite(v) else None
    return out


@mechanism_route("mechanism_angles", "mechanism_angles")
@announces_compilation
def hyperbolicity_angles(system, theta0, u0, t_final, *, dt=0.01, n_unstable=None,
                         t_transient=Documented(100.0), sample_every=Documented(0.1),
                         checkpoint_every=Documented(1.0), project_every=Documented(1.0),
                         seed=0, progress=False) -> AngleResult:
    """Angles between the expanding subspace E_u and the zero-and-contracting subspace E_cs
    along the trajectory from (theta0, u0), in both variants of section 4: ``full`` (the
    paper's: E_cs in all of R^{2N}, with the two directions that break the constraint) and
    ``restricted`` (E_cs within the constraint-preserving tangent space T_r); the method,
    the memory and the backward pass: the docstring of ``charts.analyses.hyperbolicity``,
    the two variants compared: docs/reproduce.md.

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
    t_final : float
        Length of the analysed window; the trajectory runs t_transient + t_final +
        t_transient so that V (forward) and W (backward) converge before it.
    dt : float
        RK4 step of both passes.  A time written below must be a whole number of steps;
        a default left is the nearest whole number of steps at other dt (README,
        "Conventions").
    n_unstable : int, optional
        m, the dimension of E_u (default N−2, the number of positive exponents).
    t_transient : float
        Convergence time of each pass (>= 0).
    sample_every : float
        Time between sample points (memory S·m·2N·8 bytes for the forward vectors; default
        0.1, the nearest whole number of steps at other dt that divides t_final).
    checkpoint_every : float
        Time between stored trajectory checkpoints of the forward pass (default 1.0, the
        nearest whole number of steps at other dt).
    project_every : float or None
        Time between projections of the forward state onto the invariants (default 1.0, the
        nearest whole number of steps at other dt; None: never).
    seed : int
        Seed of the random initial vectors of both passes.
    progress : bool or callable(t_done, t_total)

    Returns
    -------
    AngleResult
    """
    rotor_system(system)
    cfg = angle_settings(system, t_final, dt=dt, n_unstable=n_unstable, t_transient=t_transient,
                         sample_every=sample_every, checkpoint_every=checkpoint_every,
                         project_every=project_every, seed=seed)
    n, m, dt, n_tr, n_win, sample, ce = cfg.n, cfg.m, cfg.dt, cfg.n_tr, cfg.n_win, cfg.sample, cfg.ce
    project, reorth, S = cfg.project, cfg.reorth, cfg.samples
    theta0, u0 = start_state(system, theta0, u0, dt)
    need = stored_bytes(cfg)
    if need > MAX_STORE:
        raise ValueError(f"storing {S} samples needs {need / 2**20:.0f} MB; increase sample_every "
                         f"or split t_final into several runs")
    nseg = -(-(2 * n_tr + n_win) // ce)
    nsteps = nseg * ce
    flow = angle_flow(system, theta0, u0, cfg)
    rep = progress_reporter(progress, 2 * nsteps * dt, f"angles N={n}")
    ck = np.empty((nseg + 1, 2 * n))
    ck[0] = flow.y
    states = np.empty((S, (1 + m) * 2 * n))
    if n_tr == 0:  # the first sample is the initial point (the kernel records after steps)
        states[0] = flow.Z.ravel()
    for a in range(0, nseg, _SEGMENTS):
        b = min(nseg, a + _SEGMENTS)
        status = forward_kernel(flow.stack(), flow.rotors(), flow.stepping(), project, reorth,
                                ce, n_tr, sample, states, ck, a, b, n_tr + n_win)
        if status != RUNNING:
            raise status_error(status, flow.steps * dt, "hyperbolicity_angles (forward RK4)")
        rep.update((b - a) * ce * dt)
    W = adjoint_start(cfg, flow.w)
    sf = np.empty(S)
    sr = np.empty(S)
    blog = np.zeros(m)
    status, step = backward_kernel(ck, W, flow.rotors(), flow.stepping(), ce, n_tr, sample,
                                   reorth, states, blog, sf, sr)
    if status != RUNNING:
        raise status_error(status, step * dt, "hyperbolicity_angles (backward RK4)")
    rep.update(nsteps * dt)
    rep.close()
    return angle_result(system, cfg, sf, sr, flow.logsum, blog / ((nsteps - n_tr) * dt),
                        flow.speed, (theta0, u0))


def angle_result(system, cfg: AngleSettings, sf, sr, forward_logs, adjoint_exponents, speed,
                 start=None):
    """The `AngleResult` of a run from the sines at its samples (full, restricted), the
    forward pass's log-norm sums over [0, t_transient + t_final] and the adjoint's rates;
    ``start``: the initial state (theta0, u0), recorded so that a saved result can repeat
    its call."""
    t = (cfg.n_tr + np.arange(cfg.samples) * cfg.sample) * cfg.dt
    params = angle_params(system, cfg, speed)
    if start is not None:
        params.update(theta0=np.asarray(start[0], dtype=float).tolist(),
                      u0=np.asarray(start[1], dtype=float).tolist())
    return AngleResult(t, sin_to_angle(sf), sin_to_angle(sr),
                       forward_logs / ((cfg.n_tr + cfg.n_win) * cfg.dt), adjoint_exponents,
                       params)


def angle_params(system, cfg: AngleSettings, speed) -> dict:
    """The settings of an angle test with ``cfg`` as its results record them (the system,
    every duration in time units, the speed, the seed)."""
    dt = cfg.dt
    return dict(**system.describe(), dt=dt, n_unstable=cfg.m, t_final=cfg.n_win * dt,
                t_transient=cfg.n_tr * dt, sample_every=cfg.sample * dt, speed=speed,
                checkpoint_every=cfg.ce * dt, project_every=cfg.project * dt or None,
                vectors_seed=cfg.seed, state_seed="given")


@mechanism_route("mechanism_ensemble", "hyperbolicity_ensemble")
def hyperbolicity_ensemble(system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                           progress=False, device="cpu", client=None,
                           **kwargs) -> EnsembleResult:
    """`hyperbolicity_angles` on independent random states (seeds seed, seed+1, …) in
    parallel processes; returns an `EnsembleResult` (``concatenate("phi_restricted")`` joins
    the angles of all members for statistics).

    ``device="cuda"``: every member a GPU thread, the window in blocks sized to the GPU's
    memory (``charts.analyses.angle_blocks``: the same passes; with one block each member
    equals `hyperbolicity_angles`, with several the angles after the first block differ by
    the adjoint vectors' convergence error, e^(−λ_m·t_transient)); t_transient must then be a
    multiple of checkpoint_every.  ``"auto"``: the GPU when there is one.

    ``client``: the members run as tasks of a Dask cluster instead (a ``Client``, a
    scheduler's address, or "local": a LocalCluster of ``workers`` processes;
    ``charts.analyses.cluster``, docs/cluster.md), the same members bit for bit."""
    rotor_system(system)
    device = cluster_device(device, client)
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    cfg = angle_settings(system, t_final, seed=seed, **kwargs)
    check_memory(n_trajectories * 8 * (3 * cfg.samples + 2 * cfg.m),
                 f"the angles of {n_trajectories} members ({cfg.samples} samples each)",
                 "run fewer members or sample less often (sample_every)")
    if device == "cuda":
        rep = progress_reporter(progress, n_trajectories * t_final,
                                f"angles N={system.n} ensemble (GPU)")
        members = angle_members(system, cfg, list(range(seed, seed + n_trajectories)), speed,
                                workers=workers or os.cpu_count() or 1, update=rep.update)
        rep.close()
        return ensemble_result(members, system, seed, speed, t_final, {**kwargs, "device": "cuda"})
    return run_ensemble(hyperbolicity_angles, system, n_trajectories, t_final, speed=speed,
                        seed=seed, workers=workers, progress=progress,
                        desc=f"angles N={system.n} ensemble", prime=_short(cfg),
                        client=client, **kwargs)


def _short(cfg):
    """(t_final, settings) of the priming call that compiles the members' kernels here: two
    samples on the members' grid, no transient."""
    every = cfg.sample * cfg.dt
    return 2 * every, {"t_transient": 0.0, "sample_every": every}


def angle_members(system, cfg: AngleSettings, seeds, speed, **kw):
    """[`AngleResult`] of the seeds by ``charts.analyses.angle_blocks.angles_on_device``
    (every member a GPU thread, ``backend="cuda"``, or its CPU twin; ``kw``: its arguments),
    each as `hyperbolicity_angles` with ``seed=s`` from ``system.random_state(seed=s,
    speed=speed)`` would return it (bit for bit with one block)."""
    sf, sr, logs, adjoint, speeds = angles_on_device(system, cfg, seeds, speed, **kw)
    return [angle_result(system, replace(cfg, seed=s), sf[l], sr[l], logs[l], adjoint[l],
                         float(speeds[l]), system.random_state(seed=s, speed=speed))
            for l, s in enumerate(seeds)]


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
            tally = tally_on_cpu(system, _short(cfg), n_trajectories, t_final, params, speed,
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
