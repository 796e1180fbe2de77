"""Lyapunov spectra of the geodesic flow, section 2 (eqs 8, 17, 18), with masses.

The trajectory and k tangent vectors are advanced by the tangent kernel
(``charts.solvers.tangent``); every ``reorth_every`` the vectors are re-orthonormalised
(eq 18) in the product ``inner`` and the logarithms of the norms are summed.

``space="restricted"`` (default) keeps the vectors in the constraint-preserving subspace T_r
(``charts.geometry.projection``), so all 2N−2 computable exponents are physical;
``space="full"`` does not, and up to 2N exponents can be computed, two of them the
non-physical zeros of the directions that break the constraint (`identify_nonphysical`).

Error bars are batch means: the averaging time is cut into ``n_batches`` nearly equal
blocks (at re-orthonormalisation steps), each block gives an estimate of every exponent,
and the standard error is their std/√n_batches (two-sided).  ``lyapunov_ensemble``
(``charts.analyses.lyapunov_members``) instead runs independent trajectories and uses their
spread.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from ..jit.compilation import announces_compilation
from ..geometry.checks import option
from ..geometry.energy_shares import SHARE_BINS
from ..geometry.projection import project_tangent
from ..solvers.tangent import TangentFlow
from .arguments import (positive_int, positive_time, progress_reporter, project_steps,
                        start_state, steps_of, inner_steps, Documented)
from .lyapunov_result import LyapunovResult
from .statistics import batch_ends, batch_estimates
from . import transients
from .transients import (AUTO_EFOLDINGS, AUTO_RULE, AUTO_TRANSIENT_RANGE, PILOT_TIMES,
                         transient_rule)
from .arguments import rotor_system
from .mechanism_route import mechanism_route

__all__ = ["LyapunovResult", "LyapunovSettings", "lyapunov_settings", "lyapunov_flow",
           "lyapunov_spectrum", "lyapunov_schedule",
           "lyapunov_result", "chunk_sizes", "averaging_logs", "end_transient",
           "reconstruct_spectrum", "auto_transient", "resolve_transient", "transient_rule", "AUTO_EFOLDINGS",
           "PILOT_TIMES", "AUTO_TRANSIENT_RANGE", "AUTO_RULE",
           "identify_nonphysical", "exponents_from_marks"]


@dataclass(frozen=True)
class LyapunovSettings:
    """Validated settings of one Lyapunov run; every count is in RK4 steps of ``dt``."""
    dt: float
    k: int
    inner: str
    space: str
    transient: int
    total: int
    reorth: int
    project: int
    record: int
    n_batches: int
    seed: int

    @property
    def batch_ends(self):
        """Steps after the transient at which the batches end."""
        return batch_ends(self.total, self.n_batches, self.reorth)


def lyapunov_settings(system, t_final, *, dt=0.01, n_exponents=None, inner="theta",
                      space="restricted", t_transient=Documented(50.0), n_batches=20,
                      reorth_every=Documented(0.1), project_every=Documented(1.0),
                      record_every=Documented(1.0), seed=0) -> LyapunovSettings:
    """Check the arguments of `lyapunov_spectrum` (ValueError naming the bad one); its
    ``t_transient`` is a duration, a rule ("scaled", "auto") resolved by the caller first
    (`charts.analyses.transients.resolve_transient`)."""
    n = system.n
    dt = positive_time("dt", dt)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    space = option("space", space, ("restricted", "full"))
    kmax = {"restricted": 2 * n - 2, "full": 2 * n}[space]
    inner = option("inner (the paper's θ-only product 'theta', or 'full')", inner,
                   ("theta", "full"))
    if inner == "theta":
        kmax = min(kmax, n - 1 if space == "restricted" else n)
    k = n - 2 if n_exponents is None else positive_int("n_exponents", n_exponents)
    if not k <= kmax:
        raise ValueError(f"n_exponents={k} is out of range 1..{kmax} for inner={inner!r}, "
                         f"space={space!r}; use inner='full' for more than N−1 exponents")
    n_batches = positive_int("n_batches", n_batches, 2)
    total = steps_of("t_final", t_final, dt)
    record = steps_of("record_every", record_every, dt)
    # a default reorth_every divides t_final (and a record_every that is written); a default
    # record_every is then the nearest multiple of reorth
    reorth = inner_steps("reorth_every", reorth_every, dt, total, record_every, record)
    if isinstance(record_every, Documented):
        record = max(1, round(record / reorth)) * reorth
    project = project_steps(project_every, dt)
    if record % reorth:
        raise ValueError(f"record_every={record_every:g} must be a multiple of "
                         f"reorth_every={reorth_every:g}")
    if total % reorth:
        raise ValueError(f"t_final={t_final:g} must be a multiple of reorth_every={reorth_every:g}")
    if total < n_batches * reorth:
        raise ValueError(f"t_final={t_final:g} is too short for n_batches={n_batches} of at least "
                         f"reorth_every={reorth_every:g}; increase t_final")
    return LyapunovSettings(dt, k, inner, space, transient, total, reorth, project, record,
                            n_batches, positive_int("seed", seed, 0))


def lyapunov_flow(system, theta0, u0, cfg: LyapunovSettings) -> TangentFlow:
    """The tangent flow of a Lyapunov run from (theta0, u0) (validated here)."""
    theta0, u0 = start_state(system, theta0, u0, cfg.dt)
    return TangentFlow(system, theta0, u0, cfg.k, dt=cfg.dt, inner=cfg.inner,
                       restricted=cfg.space == "restricted", reorth_every=cfg.reorth,
                       project_every=cfg.project, seed=cfg.seed, share_bins=SHARE_BINS)


def exponents_from_marks(logsums, steps, dt):
    """(exponents (k,), batch estimates (B, k), stderr (k,)) from the log-norm sums
    ``logsums`` (B, k) at the batch ends ``steps`` (B,) after the transient."""
    T = np.asarray(steps, dtype=float) * dt
    L = np.asarray(logsums, dtype=float)
    batches, stderr = batch_estimates(L, T)
    return L[-1] / T[-1], batches, stderr


def reconstruct_spectrum(leading):
    """Full relevant spectrum of 2N−2 exponents from the leading N−2 (section 2: pairs
    ±λ from time reversibility and the symplectic structure, and two zeros: the flow
    direction and the energy shift)."""
    leading = np.asarray(leading, dtype=float)
    return np.concatenate([leading, [0.0, 0.0], -leading[::-1]])


def identify_nonphysical(system, theta, u, X):
    """Fraction of each row of X, shape (k, 2N), lying outside the constraint-preserving
    subspace T_r (1 − |P_r x|/|x| in the Euclidean norm): ≈ 1 for the non-physical
    directions, ≈ 0 for physical ones."""
    y = np.concatenate([theta, u])
    Xp = np.array(X, dtype=float)
    project_tangent(y, Xp, system.minv, system.weights)
    return 1.0 - np.linalg.norm(Xp, axis=1) / np.linalg.norm(X, axis=1)


@mechanism_route("mechanism_lyapunov", "lyapunov_spectrum")
@announces_compilation
def lyapunov_spectrum(system, theta0, u0, t_final, *, dt=0.01, n_exponents=None,
                      inner="theta", space="restricted", t_transient="scaled",
                      n_batches=20, reorth_every=Documented(0.1),
                      project_every=Documented(1.0), record_every=Documented(1.0), seed=0,
                      progress=False) -> LyapunovResult:
    """Lyapunov exponents of eq (8) along the trajectory from (theta0, u0), eqs (17)-(18).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
        Initial point on the manifold and tangent velocity; the exponents scale with
        the speed |u0| = √(Σ mᵢ u0ᵢ²) (the paper uses unit speed).
    t_final : float
        Averaging time after the transient (a multiple of ``reorth_every``).
    dt : float
        RK4 step.  A time written below must be a whole number of steps;
        a default left is the nearest whole number of steps at other dt (README,
        "Conventions").
    n_exponents : int, optional
        Number of exponents (default N−2, the leading ones; at most 2N−2 in the
        restricted space, 2N in the full space, N−1 with ``inner='theta'``).
    inner : {'theta', 'full'}
        Inner product of eq (18): θ-parts only (the paper's) or θ- and u-parts.
    space : {'restricted', 'full'}
        Keep the tangent vectors in the constraint-preserving subspace T_r, or not.
    t_transient : float, "scaled" or "auto"
        Time discarded first so that the vectors align with the Lyapunov vectors.
        "scaled" (default): 5 N² / speed time units, at least 50, 15 e-foldings of the
        measured smallest positive exponent ≈ 3 speed / N² (50 at N = 3, 125 at N = 5, 320 at
        N = 8, 20480 at N = 64; `charts.analyses.transients` gives the measurements: a fixed
        50 biased the smallest exponent of short runs by −11 % at N = 5 and −22 % at N = 8).
        "auto": `AUTO_EFOLDINGS` e-foldings of the smallest positive exponent from a pilot run
        (`auto_transient`).  The rule and the duration are recorded in ``params``
        (``transient_rule``, ``t_transient``).  Another Mechanism (the generic route,
        ``charts.analyses.mechanism_lyapunov``): default 50, "auto" or a duration; "scaled"
        is the rotors' measured law and is refused there.
    n_batches : int
        Number of blocks for the batch-means standard error.
    reorth_every : float
        Time between re-orthonormalisations (default 0.1, the nearest whole number of steps
        at other dt that divides t_final).  The trajectory does not depend on it and the
        log-norm sums of eq (18) telescope, so 0.1 (10 steps) gives the exponents of every
        step to ~1e-10 (tests/test_lyapunov.py) at a quarter less cost.
    project_every : float or None
        Time between projections of the state onto the invariants (default 1.0, the nearest
        whole number of steps at other dt; None: never).
    record_every : float
        Time between rows of the convergence history (a multiple of ``reorth_every``;
        default 1.0, the nearest such multiple at other dt).
    seed : int
        Seed of the random initial tangent vectors (``params["vectors_seed"]``).
    progress : bool or callable(t_done, t_total)

    Returns
    -------
    LyapunovResult

    Raises
    ------
    ValueError
        Bad arguments (named in the message).
    SingularPointError
        The trajectory reached a singular point of the manifold (N = 4).
    """
    rotor_system(system)
    if transient_rule(t_transient) is not None:
        # every other setting checked before a pilot runs (the transient is its outcome)
        lyapunov_settings(system, t_final, dt=dt, n_exponents=n_exponents, inner=inner,
                          space=space, t_transient=0.0, n_batches=n_batches,
                          reorth_every=reorth_every, project_every=project_every,
                          record_every=record_every, seed=seed)
        start_state(system, theta0, u0, dt)
    t_transient, rule = resolve_transient(t_transient, system, theta0, u0, dt=dt,
                                          n_exponents=n_exponents, inner=inner, space=space,
                                          seed=seed)
    cfg = lyapunov_settings(system, t_final, dt=dt, n_exponents=n_exponents, inner=inner,
                            space=space, t_transient=t_transient, n_batches=n_batches,
                            reorth_every=reorth_every, project_every=project_every,
                            record_every=record_every, seed=seed)
    flow = lyapunov_flow(system, theta0, u0, cfg)
    start = flow.y.copy()
    rep = progress_reporter(progress, (cfg.transient + cfg.total) * cfg.dt,
                            f"Lyapunov N={system.n}")
    where = "lyapunov_spectrum (ambient RK4)"
    flow.advance(cfg.transient, where=where)
    rep.update(cfg.transient * cfg.dt)
    end_transient(flow)
    logs = averaging_logs(flow, cfg, partial(flow.advance, where=where), rep.update)
    rep.close()
    res = lyapunov_result(system, cfg, logs, flow.speed, flow.shares, start)
    if rule is not None:
        res.params["transient_rule"] = rule
    return res


def resolve_transient(t_transient, system, theta0, u0, **pilot):
    """``charts.analyses.transients.resolve_transient`` with `auto_transient` as the pilot
    of "auto": the duration (and the rule's text) of ``t_transient`` for a run from
    (theta0, u0)."""
    return transients.resolve_transient(t_transient, system, theta0, u0, auto_transient,
                                         **pilot)


def auto_transient(system, theta0, u0, *, dt=0.01, n_exponents=None, inner="theta",
                   space="restricted", seed=0) -> Documented:
    """The transient of ``t_transient="auto"`` for a run from (theta0, u0): `AUTO_EFOLDINGS`
    over the smallest positive exponent of a pilot run (`PILOT_TIMES`, the run's own
    settings), within `AUTO_TRANSIENT_RANGE` (as a `Documented` duration: the nearest whole
    number of steps).  The pilot's times are the rule's, not the caller's: at any ``dt``
    they are the nearest whole numbers of steps (`Documented`), so that "auto" works for
    every valid step (50 time units need not be a whole number of steps)."""
    pilot = lyapunov_spectrum(system, theta0, u0, Documented(PILOT_TIMES[1]), dt=dt,
                              n_exponents=n_exponents, inner=inner, space=space,
                              t_transient=Documented(PILOT_TIMES[0]), n_batches=2, seed=seed)
    return transients.auto_duration(pilot.exponents)


def end_transient(flow) -> None:
    """The transient of ``flow`` (a `TangentFlow`, the lanes, or the linkage's flow, whose
    histogram is empty) is done: its log-norm sums and its energy-share histograms start
    from zero."""
    flow.logsum[...] = 0.0
    flow.shares[...] = 0


def averaging_logs(flow, cfg: LyapunovSettings, advance, update=None):
    """The averaging part of a Lyapunov run on ``flow`` (a `TangentFlow`, or the lanes'
    `LaneFlows`), its transient done and its log-norm sums zeroed: ``advance(steps, events=,
    event_logs=)`` in the `chunk_sizes` of ``cfg``, ``update(t)`` (optional) after each chunk
    with its time.  Returns the log-norm sums at the events of `lyapunov_schedule`, shape
    (events,) + ``flow.logsum.shape``."""
    _, _, events = lyapunov_schedule(cfg)
    logs = np.zeros((len(events),) + flow.logsum.shape)
    at = np.array(events, dtype=np.int64) + flow.steps  # the kernel counts from the start
    for size in chunk_sizes(cfg):
        advance(size, events=at, event_logs=logs)
        if update is not None:
            update(size * cfg.dt)
    return logs


def lyapunov_schedule(cfg: LyapunovSettings):
    """(records, batch ends, events): steps after the transient of the convergence history,
    of the batch ends, and of both (sorted), at which a run stores its log-norm sums."""
    records = sorted(set(range(cfg.record, cfg.total + 1, cfg.record)) | {cfg.total})
    ends = cfg.batch_ends
    return records, ends, sorted(set(records) | set(ends))


def chunk_sizes(cfg: LyapunovSettings):
    """The averaging steps cut into ~100 calls of the kernel (progress without per-record
    cost; the kernels are chunk-independent, so the cut changes no bit)."""
    c = min(cfg.total, 100)
    return np.diff([cfg.total * i // c for i in range(c + 1)])


def lyapunov_result(system, cfg: LyapunovSettings, logs, speed, shares=None,
                    start=None) -> LyapunovResult:
    """The `LyapunovResult` of a run from its log-norm sums ``logs`` (events, k) at the
    events of `lyapunov_schedule`; ``speed`` = |u0|; ``shares``: the histogram of the largest
    energy share over the averaging time; ``start``: the initial state (θ, u), shape (2N,),
    recorded as ``theta0``, ``u0`` so that a saved result can repeat its call."""
    n, k = system.n, cfg.k
    records, ends, events = lyapunov_schedule(cfg)
    row = {e: i for i, e in enumerate(events)}
    hist = logs[[row[r] for r in records]]
    marks = logs[[row[e] for e in ends]]
    exps, batches, stderr = exponents_from_marks(marks, ends, cfg.dt)
    t_rec = np.array(records, dtype=float) * cfg.dt
    running = hist / t_rec[:, None]
    if cfg.space == "restricted" and k == 2 * n - 2:
        spectrum = exps.copy()
    else:
        spectrum = reconstruct_spectrum(exps[: n - 2]) if k >= n - 2 else None
    params = dict(**system.describe(), t_final=cfg.total * cfg.dt, dt=cfg.dt,
                  inner=cfg.inner, space=cfg.space, t_transient=cfg.transient * cfg.dt,
                  n_batches=cfg.n_batches, reorth_every=cfg.reorth * cfg.dt,
                  project_every=cfg.project * cfg.dt or None, record_every=cfg.record * cfg.dt,
                  n_exponents=k, speed=speed, vectors_seed=cfg.seed,
                  state_seed="given")
    if start is not None:
        params.update(theta0=np.asarray(start[:n], dtype=float).tolist(),
                      u0=np.asarray(start[n:], dtype=float).tolist())
    return LyapunovResult(exps, stderr, spectrum, t_rec, running, batches, params,
                          None if shares is None else np.array(shares))
