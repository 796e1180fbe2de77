"""Ensembles of the analyses on any Mechanism: ``charts.lyapunov_ensemble``,
``hyperbolicity_ensemble``, ``hyperbolicity_tally`` and ``covariant_ensemble`` hand a
Mechanism that is not a RotorSystem to the functions of the same names here
(``charts.analyses.mechanism_route``), whose members are the single-trajectory analyses of
``charts.analyses.mechanism_lyapunov``, ``mechanism_angles`` and ``mechanism_covariant``.

The conventions are the rotors' ensembles' (``charts.analyses.ensemble.run_ensemble``, the
one home of what follows): member i starts from ``mech.random_state(seed=seed + i,
speed=speed)`` and its tangent vectors from ``seed + i`` (its results record ``state_seed``
and ``vectors_seed``, the ensemble ``members_seed``); the members run in ``workers``
processes of ``charts.analyses.worker_pool`` (the mechanism travels to them pickled,
``Mechanism.__getstate__``) or on a Dask cluster (``client``), the kernels compiled here
first by a short call of the member; progress in simulated time; the results' memory
planned before anything runs (``charts.solvers.tangent.check_memory``).  The result is an
`EnsembleResult`: the members, and for exponents their mean and its standard error across
the members.  Every member equals its analysis run alone from its state, bit for bit, in
any number of processes.

`mechanism_ensemble` runs any such member function (the Appendix linkage's ``linkage_run``,
``charts.analyses.linkage.linkage_ensemble``, is one).  `hyperbolicity_tally` keeps of the
angles only the sums of an ``AngleTally`` of one variant, "restricted" (the only angle a
mechanism has), run by the rotors' tally on the CPU; there is no GPU route for a mechanism.
"""
from __future__ import annotations

import inspect

from ..solvers.status import MAX_STEP_LENGTH
from ..solvers.tangent import check_memory
from ..geometry.checks import path as file_path
from .angle_tally import AngleTally, member_bytes
from .arguments import positive_int, positive_time, progress_reporter, project_steps
from .ensemble import EnsembleResult, ensemble_arguments, run_ensemble
from .tally_run import tally_on_cpu
from .mechanism_angles import angle_grid, mechanism_angles
from .mechanism_arguments import mechanism_of, unstable_of
from .mechanism_covariant import mechanism_clvs
from .mechanism_lyapunov import lyapunov_spectrum, resolve_transient, settings_before_pilot

__all__ = ["mechanism_ensemble", "lyapunov_ensemble", "hyperbolicity_ensemble",
           "hyperbolicity_tally", "covariant_ensemble", "member_settings", "step_of",
           "ensemble_transient"]

#: The arguments of a member function the ensemble sets itself (the others: ``kwargs``).
OWN = ("q0", "v0", "t_final", "seed")
#: The members whose ``t_transient`` may name a rule ("auto"; their `resolve_transient`).
RULED = (lyapunov_spectrum, mechanism_angles, mechanism_clvs)


def ensemble_transient(member, mech, t_final, speed, seed, kwargs):
    """(kwargs, rule text or None): where ``kwargs["t_transient"]`` names a rule and
    ``member`` is one of `RULED`, one duration for every member, as the rotors' ensembles:
    the first member's settings and state (``mech.random_state(seed=seed, speed=speed)``)
    checked by the member itself (``settings_before_pilot``), then its pilot run
    (``charts.analyses.mechanism_lyapunov.resolve_transient``); ``kwargs`` unchanged
    otherwise."""
    if member not in RULED or not isinstance(kwargs.get("t_transient"), str):
        return kwargs, None
    q0, v0 = mech.random_state(seed=seed, speed=speed)
    pilot = settings_before_pilot(member, mech, q0, v0, t_final, seed=seed, **kwargs)
    duration, text = resolve_transient(kwargs["t_transient"], mech, q0, v0, **pilot)
    return {**kwargs, "t_transient": duration}, text


def member_settings(member, kwargs) -> dict:
    """``kwargs`` if every key is a setting of ``member`` (its keyword arguments less the
    state, the length and the seed, which the ensemble sets); TypeError naming the first
    that is not, and the settings there are."""
    takes = list(inspect.signature(member).parameters)[1:]
    settings = [k for k in takes if k not in OWN]
    for key in kwargs:
        if key not in settings:
            raise TypeError(f"{key} is not a setting of the ensemble's members: "
                            f"{member.__name__} takes {', '.join(settings)}")
    return kwargs


def mechanism_ensemble(member, mech, n_trajectories, t_final, *, speed=1.0, seed=0,
                       workers=None, progress=False, client=None, member_bytes=0, prime=None,
                       desc=None, **kwargs) -> EnsembleResult:
    """``member(mech, q0, v0, t_final, seed=s, **kwargs)`` from ``mech.random_state(seed=s,
    speed=speed)``, s = seed, seed + 1, … (``n_trajectories`` ≥ 2 of them), in ``workers``
    processes (default: all cores; 1: here) or on the Dask cluster ``client`` (module
    docstring); ``member_bytes``: the size of one member's result, refused beyond the memory
    budget before anything runs; ``prime``: (t_final, settings) of the short call that
    compiles the kernels here before the workers start; ``desc``: the progress line's
    name.  Bad arguments: ValueError or MechanismError naming them, TypeError for a setting
    ``member`` does not take."""
    mechanism_of(mech)
    member_settings(member, kwargs)
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    step_of(member, kwargs, speed)
    check_memory(n_trajectories * int(member_bytes),
                 f"the results of {n_trajectories} members over t_final={float(t_final):g}",
                 "run fewer members, shorten t_final, or sample less often (sample_every)")
    kwargs, rule = ensemble_transient(member, mech, t_final, speed, seed, kwargs)
    res = run_ensemble(member, mech, n_trajectories, t_final, speed=speed, seed=seed,
                       workers=workers, progress=progress, client=client,
                       desc=desc or f"{member.__name__} {mech.name} ensemble", prime=prime,
                       notice=(f"{member.__name__} of {mech.name}", None), **kwargs)
    if rule is not None:
        for m in res.members:
            m.params["transient_rule"] = rule
        res.params["transient_rule"] = rule
    return res


def step_of(member, kwargs, speed) -> float:
    """The members' dt (``kwargs``' or ``member``'s default), checked, and refused
    (ValueError naming the speed) where a step at ``speed`` is longer than
    ``charts.solvers.status.MAX_STEP_LENGTH``, as the rotors' ``check_step`` refuses it."""
    dt = positive_time("dt", kwargs.get("dt", inspect.signature(member).parameters["dt"].default))
    if dt * speed > MAX_STEP_LENGTH:
        raise ValueError(f"speed={speed:g} is too large for dt={dt:g}: dt·speed = "
                         f"{dt * speed:g} > {MAX_STEP_LENGTH:g} per step, so the samples alias "
                         f"the motion; use speed <= {MAX_STEP_LENGTH / dt:.3g} (the exponents "
                         "are proportional to the speed)")
    return dt


def _samples(t_final, kwargs, every, default):
    """About how many samples a member stores: t_final / ``every`` (its default ``default``),
    for the memory plan (the member puts the grid exactly)."""
    return int(positive_time("t_final", t_final) / positive_time(every, kwargs.get(every, default))) + 1


def _prime(kwargs, **short):
    """(t_final, settings) of the call that compiles a member's kernels: two steps of the
    members' dt, no transient, ``short`` (its re-orthonormalisation or sampling every step)."""
    dt = positive_time("dt", kwargs.get("dt", 0.01))
    return 2 * dt, {"t_transient": 0.0, **{k: dt if v is None else v for k, v in short.items()}}


def lyapunov_ensemble(mech, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                      progress=False, client=None, **kwargs) -> EnsembleResult:
    """``charts.analyses.mechanism_lyapunov.lyapunov_spectrum`` from ``n_trajectories``
    random states of ``mech`` (module docstring; ``kwargs``: its settings): an
    `EnsembleResult` of `MechanismLyapunov` members, ``exponents`` and ``stderr`` their mean
    and its standard error across the members, ``error_ratio`` the members' own batch errors
    over their spread."""
    mechanism_of(mech)
    member_settings(lyapunov_spectrum, kwargs)
    k = kwargs.get("n_exponents")
    k = mech.dim - 1 if k is None else positive_int("n_exponents", k)
    batches = positive_int("n_batches", kwargs.get("n_batches", 20), 2)
    return mechanism_ensemble(lyapunov_spectrum, mech, n_trajectories, t_final, speed=speed,
                              seed=seed, workers=workers, progress=progress, client=client,
                              member_bytes=8 * k * (batches + 2),
                              prime=_prime(kwargs, n_batches=2, reorth_every=None),
                              desc=f"Lyapunov {mech.name} ensemble", **kwargs)


def hyperbolicity_ensemble(mech, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                           progress=False, client=None, **kwargs) -> EnsembleResult:
    """``charts.analyses.mechanism_angles.mechanism_angles`` (the restricted angle test)
    from ``n_trajectories`` random states of ``mech`` (module docstring; ``kwargs``: its
    settings): an `EnsembleResult` of `MechanismAngles` members
    (``concatenate("phi_restricted")`` pools their angles)."""
    mechanism_of(mech)
    member_settings(mechanism_angles, kwargs)
    m = unstable_of(mech, kwargs.get("n_unstable"))
    S = _samples(t_final, kwargs, "sample_every", 0.1)
    return mechanism_ensemble(mechanism_angles, mech, n_trajectories, t_final, speed=speed,
                              seed=seed, workers=workers, progress=progress, client=client,
                              member_bytes=8 * (2 * S + 2 * m + 2 * mech.n),
                              prime=_prime(kwargs, sample_every=None),
                              desc=f"angles {mech.name} ensemble", **kwargs)


def hyperbolicity_tally(mech, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                        progress=False, chunk=None, checkpoint=None, client=None,
                        **kwargs) -> AngleTally:
    """The angle test of `hyperbolicity_ensemble` (``kwargs``: the settings of
    ``mechanism_angles``) tallied as it runs into an `AngleTally` of the one variant a
    mechanism has, ``"restricted"``, instead of kept: the rotors' tally on the CPU
    (``charts.analyses.tally_run.tally_on_cpu``: chunks of ``chunk`` consecutive seeds
    in ``workers`` processes or on ``client``'s cluster, each member's angles tallied in its
    worker and dropped, ``checkpoint`` saved after each chunk and resumed from), its
    ``statistics("restricted")`` the verdict's numbers.  The same tally, bit for bit, in any
    number of processes and chunks."""
    mechanism_of(mech)
    member_settings(mechanism_angles, kwargs)
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    if checkpoint is not None:
        checkpoint = file_path("checkpoint", checkpoint)
    check_memory(n_trajectories * member_bytes(1), f"the sums of a tally of {n_trajectories} "
                 "members", "run fewer members (several tallies combine with AngleTally.merged)")
    default = inspect.signature(mechanism_angles).parameters
    get = lambda key: kwargs.get(key, default[key].default)       # noqa: E731
    dt = step_of(mechanism_angles, kwargs, speed)
    kwargs, rule = ensemble_transient(mechanism_angles, mech, t_final, speed, seed, kwargs)
    total, transient, sample = angle_grid(dt, t_final, get("t_transient"), get("sample_every"))
    project = project_steps(get("project_every"), dt)
    params = dict(mechanism=mech.name, parameters=mech.parameter_values, dt=dt,
                  n_unstable=unstable_of(mech, get("n_unstable")), t_final=total * dt,
                  t_transient=transient * dt, sample_every=sample * dt,
                  project_every=project * dt or None, speed=float(speed), device="cpu",
                  members_seed=seed)
    if rule is not None:
        params["transient_rule"] = rule
    rep = progress_reporter(progress, n_trajectories * t_final, f"angles {mech.name} tally (CPU)")
    try:
        tally = tally_on_cpu(mech, _prime(kwargs, sample_every=None), n_trajectories, t_final,
                             params, speed, seed, workers, chunk, checkpoint, rep, kwargs,
                             client, variants=("restricted",), n=mech.name)
    finally:
        rep.close()
    tally._open.clear()                     # the run is whole: nothing left to carry
    return tally


def covariant_ensemble(mech, n_trajectories, t_final, *, variant="restricted", speed=1.0,
                       seed=0, workers=None, progress=False, client=None,
                       **kwargs) -> EnsembleResult:
    """``charts.analyses.mechanism_covariant.mechanism_clvs`` from ``n_trajectories``
    random states of ``mech`` (module docstring; ``kwargs``: its settings): an
    `EnsembleResult` of `CovariantResult` members."""
    mechanism_of(mech)
    member_settings(mechanism_clvs, kwargs)
    D, n = 2 * mech.dim, mech.n
    S = _samples(t_final, kwargs, "sample_every", 0.1)
    per = 8 * S * (2 + 2 * D + 2 * n + (D * 2 * n if kwargs.get("keep_vectors") else 0))
    return mechanism_ensemble(mechanism_clvs, mech, n_trajectories, t_final, speed=speed,
                              seed=seed, workers=workers, progress=progress, client=client,
                              member_bytes=per, prime=_prime(kwargs, sample_every=None),
                              desc=f"CLV {mech.name} ensemble", variant=variant, **kwargs)
