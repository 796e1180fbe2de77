"""Ensembles of the analyses on any Mechanism: ``charts.lyapunov_ensemble``,
``hyperbolicity_ensemble`` and ``covariant_ensemble`` hand a Mechanism that is not a
RotorSystem to `lyapunov_ensemble`, `hyperbolicity_ensemble` and `covariant_ensemble` here
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
``charts.analyses.linkage.linkage_ensemble``, is one).
"""
from __future__ import annotations

import inspect

from ..solvers.status import MAX_STEP_LENGTH
from ..solvers.tangent import check_memory
from .arguments import positive_int, positive_time
from .ensemble import EnsembleResult, ensemble_arguments, run_ensemble
from .mechanism_angles import mechanism_angles
from .mechanism_arguments import mechanism_of, unstable_of
from .mechanism_covariant import mechanism_clvs
from .mechanism_lyapunov import lyapunov_spectrum

__all__ = ["mechanism_ensemble", "lyapunov_ensemble", "hyperbolicity_ensemble",
           "covariant_ensemble", "member_settings"]

#: The arguments of a member function the ensemble sets itself (the others: ``kwargs``).
OWN = ("q0", "v0", "t_final", "seed")


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
    dt = positive_time("dt", kwargs.get("dt", inspect.signature(member).parameters["dt"].default))
    if dt * speed > MAX_STEP_LENGTH:
        raise ValueError(f"speed={speed:g} is too large for dt={dt:g}: dt·speed = "
                         f"{dt * speed:g} > {MAX_STEP_LENGTH:g} per step, so the samples alias "
                         f"the motion; use speed <= {MAX_STEP_LENGTH / dt:.3g} (the exponents "
                         "are proportional to the speed)")
    check_memory(n_trajectories * int(member_bytes),
                 f"the results of {n_trajectories} members over t_final={float(t_final):g}",
                 "run fewer members, shorten t_final, or sample less often (sample_every)")
    return run_ensemble(member, mech, n_trajectories, t_final, speed=speed, seed=seed,
                        workers=workers, progress=progress, client=client,
                        desc=desc or f"{member.__name__} {mech.name} ensemble", prime=prime,
                        notice=(f"{member.__name__} of {mech.name}", None), **kwargs)


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
