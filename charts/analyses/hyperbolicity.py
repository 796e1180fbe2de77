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
from dataclasses import dataclass, replace

import numpy as np

from ..io.archive import Archivable, attributes, dataset, index_coordinate
from ..io.result_words import RATE, smallest_words
from ..jit.compilation import announces_compilation
from ..geometry.checks import finite_array, option
from ..solvers.status import RUNNING, status_error
from ..solvers.tangent import check_memory
from .adjoint_pass import adjoint_step, backward_kernel
from .angle_blocks import angles_on_device
from .angle_tally import SMALL_ANGLE
from .arguments import positive_time, progress_reporter, start_state, Documented
from .cluster import cluster_device
from .ensemble import EnsembleResult, ensemble_arguments, ensemble_result, run_ensemble
from .forward_pass import AngleSettings, adjoint_start, angle_flow, angle_settings, forward_kernel
from .singular_values import sin_to_angle, smallest_singular_values
from .statistics import small_value_law
from .arguments import rotor_system
from .mechanism_route import mechanism_route

__all__ = ["AngleResult", "angle_result", "angle_members", "hyperbolicity_angles",
           "hyperbolicity_ensemble", "angle_params", "angle_statistics", "short_settings",
           "check_cpu_store",
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
                        desc=f"angles N={system.n} ensemble", prime=short_settings(cfg),
                        client=client, **kwargs)


def short_settings(cfg):
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
