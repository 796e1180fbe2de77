"""Lyapunov exponents of a Mechanism's geodesic flow (section 2's method on any holonomic
mechanism, docs/mechanisms.md).

The trajectory and k phase tangent vectors are advanced by the mechanism's compiled tangent
flow (``charts.mechanism.tangent_flow``: the KKT equations of motion and their exact
linearisation, RK4, projected back onto TC every ``project_every``); every ``reorth_every``
they are re-orthonormalised by eq (18) in the kinetic metric and the log-norms summed.  The
error bars are batch means, as for the rotors (``charts.analyses.lyapunov``).

What the spectrum of a geodesic flow looks like.  On a d-dimensional configuration manifold
the phase space TC has dimension 2d, so there are 2d exponents.  The flow is Hamiltonian and
reversible, so they come in pairs λ, −λ; two of them are zero, one for the flow direction
and one for the energy shell's normal (a change of speed only rescales time).  The d − 1
leading ones, λ₁ ≥ … ≥ λ_{d−1}, determine the rest: (λ₁, …, λ_{d−1}, 0, 0, −λ_{d−1}, …, −λ₁).
For a surface (d = 2) that is (λ₁, 0, 0, −λ₁), and Pesin's formula gives the Liouville
entropy of an ergodic flow as λ₁.  All exponents are proportional to the speed.
"""
from __future__ import annotations

from contextvars import ContextVar
from dataclasses import dataclass, field

import numpy as np

from ..geometry.checks import option
from ..io.archive import Archivable, attributes, dataset, exponent_coordinate
from ..io.result_words import RATE, exponent_words
from ..mechanism.tangent_flow import INNER_PRODUCTS, MechanismTangentFlow
from .arguments import Documented, positive_int, positive_time, project_steps, seed_of, steps_of
from . import transients
from .lyapunov import exponents_from_marks
from .mechanism_arguments import mechanism_of, mechanism_state
from .statistics import batch_ends
from .transients import PILOT_TIMES, auto_duration, transient_rule

__all__ = ["MechanismLyapunov", "lyapunov_spectrum", "mechanism_rule", "resolve_transient",
           "auto_transient", "settings_before_pilot"]


@dataclass(frozen=True, eq=False, repr=False)
class MechanismLyapunov(Archivable):
    """Result of `lyapunov_spectrum`; saved by ``save(path)`` (NetCDF, kind
    ``"mechanism_lyapunov"``) and read back by ``charts.load``.

    exponents : (k,)  the exponents (1/time), in eq (18)'s Gram–Schmidt order: largest first
        once converged.
    stderr : (k,)  two-sided standard errors (batch means).
    batches : (n_batches, k)  the per-batch estimates behind ``stderr``.
    energy_error : float  the largest |T/T₀ − 1| at the batch ends (RK4 and the projections
        do not conserve the energy exactly).
    params : dict  the settings, the mechanism (``mechanism``: its name, ``parameters``: its
        parameter values, ``coordinates``: the names of q) and the start (``q0``, ``v0``;
        ``state_seed`` "given": the caller gave them; ``vectors_seed``: the seed of the random
        tangent vectors).
    """
    exponents: np.ndarray
    stderr: np.ndarray
    batches: np.ndarray
    energy_error: float
    params: dict = field(default_factory=dict)

    KIND = "mechanism_lyapunov"

    def summary(self) -> str:
        """One line: the exponents ± their standard errors, the averaging time and batches."""
        lam = ", ".join(f"{x:+.4f} ± {s:.4f}" for x, s in zip(self.exponents, self.stderr))
        p = self.params
        return (f"{p['mechanism']}: λ = {lam} (t = {p['t_final']:g}, {p['n_batches']} batches, "
                f"dt = {p['dt']:g}, speed {p['speed']:.6g})")

    def summary_parts(self):
        """The mechanism, the averaging time and the exponents ± their standard errors."""
        p = self.params
        T = p.get("t_final")
        return [str(p.get("mechanism", "")), f"T = {T:g}" if T is not None else "",
                exponent_words(self.exponents, self.stderr)]

    def to_xarray(self):
        """Dataset: exponents, stderr (exponent); batches (batch, exponent), with the batch
        ends' averaging times as the coordinate ``batch_t``; the settings (``params``) and
        ``energy_error`` as attributes."""
        p = self.params
        ends = batch_ends(round(p["t_final"] / p["dt"]), p["n_batches"],
                          round(p["reorth_every"] / p["dt"]))
        data = {"exponents": (("exponent",), self.exponents, RATE,
                              "Lyapunov exponents λᵢ (eq 18), λ₁ the largest"),
                "stderr": (("exponent",), self.stderr, RATE, "two-sided standard error"),
                "batches": (("batch", "exponent"), self.batches, RATE, "batch estimates")}
        coords = {"exponent": exponent_coordinate(len(self.exponents)),
                  "batch_t": (("batch",), np.asarray(ends, dtype=float) * p["dt"], "time",
                              "averaging time at the batch's end")}
        return dataset(self.KIND, data, coords=coords,
                       attrs={"params": p, "energy_error": float(self.energy_error)},
                       title=f"Lyapunov spectrum of the mechanism {p.get('mechanism')} "
                             "(charts.analyses.mechanism_lyapunov.lyapunov_spectrum)")

    @classmethod
    def from_xarray(cls, ds):
        attrs = attributes(ds)
        return cls(exponents=ds["exponents"].values, stderr=ds["stderr"].values,
                   batches=ds["batches"].values, energy_error=float(attrs["energy_error"]),
                   params=attrs["params"])

    def plot(self, ax=None, **kw):
        """The exponents ± their standard errors against i, each beside its batch estimates
        (the spread the error bars come from); ``(fig, ax)``
        (``charts.plotting.mechanism.plot_mechanism_exponents``)."""
        from ..plotting.mechanism import plot_mechanism_exponents
        return plot_mechanism_exponents(self.exponents, self.stderr, self.batches,
                                        self.params, ax=ax, **kw)


def lyapunov_spectrum(mech, q0, v0, t_final, *, dt=0.01, n_exponents=None, inner="theta",
                      t_transient=Documented(50.0), n_batches=20,
                      reorth_every=Documented(0.1), project_every=Documented(1.0),
                      seed=0) -> MechanismLyapunov:
    """Lyapunov exponents of ``mech``'s geodesic flow along the trajectory from (q0, v0).

    Parameters
    ----------
    mech : charts.mechanism.Mechanism
    q0, v0 : ndarray, shape (n,)
        A point on F = 0 (|F| ≤ 1e-10; ``mech.project_point``) and a tangent velocity there
        (``mech.project_velocity``).  The exponents scale with the speed √(v0ᵀ M v0).
    t_final : float
        Averaging time after the transient, a whole number of steps.
    dt : float
        RK4 step.
    n_exponents : int, optional
        Number of exponents; default d − 1, the positive ones of a d-dimensional manifold
        (module docstring); at most d with ``inner="theta"``, 2d with ``inner="full"``.
    inner : {"theta", "full"}
        Eq (18)'s inner product: the kinetic metric on the position parts δq (the paper's
        θ-only product) or on δq and δv.
    t_transient : float or "auto"
        Time discarded first, so that the vectors align (default 50, the rotors' default at
        N = 3: 25 e-foldings at λ₁ ≈ 0.5 and unit speed).  "auto": `auto_transient` (a
        pilot run with these settings); the rule and the duration are recorded in ``params``
        (``transient_rule``, ``t_transient``).  The rotors' "scaled" is refused
        (`mechanism_rule`).
    n_batches : int
        Blocks of the batch-means standard error (≥ 2).
    reorth_every : float
        Time between re-orthonormalisations (default 0.1, the nearest whole number of steps
        that divides the run).
    project_every : float or None
        Time between projections onto TC (default 1.0; None: never).
    seed : int
        Seed of the random initial tangent vectors (``params["vectors_seed"]``).

    Returns
    -------
    MechanismLyapunov

    Raises
    ------
    MechanismError
        ``mech`` is not a Mechanism, (q0, v0) is not a state of it, or the flow met a
        singular point.
    ValueError
        Another bad argument (named in the message).
    """
    rule, dt = opening_checks(mech, t_transient, dt)
    inner = option("inner", inner, INNER_PRODUCTS)
    d = mech.dim
    kmax = d if inner == "theta" else 2 * d
    k = d - 1 if n_exponents is None else positive_int("n_exponents", n_exponents)
    if k > kmax:
        hint = f"; use inner='full' for up to {2 * d}" if inner == "theta" else ""
        raise ValueError(f"n_exponents={k} is out of range 1..{kmax} for a {d}-dimensional "
                         f"manifold with inner={inner!r}{hint}")
    total = steps_of("t_final", t_final, dt)
    transient = 0 if rule else steps_of("t_transient", t_transient, dt, allow_zero=True)
    n_batches = positive_int("n_batches", n_batches, 2)
    reorth = steps_of("reorth_every", reorth_every, dt, divides=total)
    if total % reorth:
        raise ValueError(f"t_final={t_final:g} must be a multiple of reorth_every={reorth_every:g}")
    if total < n_batches * reorth:
        raise ValueError(f"t_final={t_final:g} is too short for n_batches={n_batches} of at "
                         f"least reorth_every={reorth_every:g}; increase t_final")
    project = 0 if project_every is None else steps_of("project_every", project_every, dt)
    seed = seed_of(seed)
    q0, v0 = mechanism_state(mech, q0, v0)
    if rule:                  # every other setting and the state checked: the pilot runs
        t_transient, rule = resolve_transient(t_transient, mech, q0, v0, dt=dt,
                                              n_exponents=n_exponents, inner=inner,
                                              project_every=project_every, seed=seed)
        transient = steps_of("t_transient", t_transient, dt, allow_zero=True)

    flow = MechanismTangentFlow(mech, q0, v0, k, dt=dt, reorth=reorth, project=project,
                                inner=inner, seed=seed)
    E0 = flow.energy()
    flow.advance(transient)
    flow.logsum[:] = 0.0
    start = flow.steps
    ends = batch_ends(total, n_batches, reorth)
    logs = np.zeros((n_batches, k))
    energy_error = 0.0
    for b, end in enumerate(ends):
        flow.advance(start + end - flow.steps)
        logs[b] = flow.logsum
        energy_error = max(energy_error, abs(flow.energy() / E0 - 1.0))
    exponents, batches, stderr = exponents_from_marks(logs, ends, dt)
    params = dict(mechanism=mech.name, parameters=mech.parameter_values, dt=dt,
                  t_final=total * dt, t_transient=transient * dt, n_batches=n_batches,
                  reorth_every=reorth * dt, project_every=project * dt or None, inner=inner,
                  vectors_seed=seed, state_seed="given", speed=float(np.sqrt(2 * E0)),
                  coordinates=[c.name for c in mech.q], q0=q0.tolist(), v0=v0.tolist())
    if rule:
        params["transient_rule"] = rule
    return MechanismLyapunov(exponents, stderr, batches, float(energy_error), params)


#: Set while `settings_before_pilot` runs an analysis: its pilot is not run but reported.
_CHECKING = ContextVar("charts_mechanism_transient_check", default=False)


class _PilotReached(Exception):
    """An analysis run by `settings_before_pilot` checked every setting and reached its
    pilot, whose settings this carries."""

    def __init__(self, pilot):
        super().__init__("pilot reached")
        self.pilot = pilot


def mechanism_rule(t_transient, mech):
    """The rule ``t_transient`` names on ``mech`` ("auto"), None for a duration; ValueError
    for another string (the nearest rule suggested) and for "scaled": that rule is the
    rotors', 5 N² / speed from their measured λ_{N−2} ≈ 3 / N²
    (``charts.analyses.transients``), and a mechanism has no such N nor measurement."""
    rule = transient_rule(t_transient)
    if rule == "scaled":
        raise ValueError(f"t_transient='scaled' is the rotors' rule (5 N^2 / speed, from their "
                         f"measured smallest positive exponent 3 / N^2) and is not defined for "
                         f"the mechanism {mech.name}: give t_transient='auto' (a pilot run) or "
                         "a duration")
    return rule


def opening_checks(mech, t_transient, dt):
    """(rule, dt): the first checks of every analysis on a mechanism (angles, curvature,
    CLVs) -- ``mech`` a Mechanism of dimension 2 or more (`mechanism_of`), the rule its
    ``t_transient`` names (`mechanism_rule`: "auto", or None for a duration) and the checked
    step ``dt``."""
    mechanism_of(mech)
    return mechanism_rule(t_transient, mech), positive_time("dt", dt)


def closing_checks(mech, q0, v0, rule, t_transient, dt, project_every, seed):
    """(project steps, seed, q0, v0, t_transient, rule): the last checks of an analysis on a
    mechanism (the projection cadence, the seed, the state: ``mechanism_state``) and then,
    for the rule "auto", its pilot (`resolve_transient`: t_transient the duration, rule the
    recorded rule); a duration and None pass unchanged."""
    project = project_steps(project_every, dt)
    seed = seed_of(seed)
    q0, v0 = mechanism_state(mech, q0, v0)
    if rule:                  # every other setting and the state checked: the pilot runs
        t_transient, rule = resolve_transient(t_transient, mech, q0, v0, dt=dt,
                                              project_every=project_every, seed=seed)
    return project, seed, q0, v0, t_transient, rule


def auto_transient(mech, q0, v0, *, dt=0.01, n_exponents=None, inner="theta",
                   project_every=Documented(1.0), seed=0) -> Documented:
    """The transient of ``t_transient="auto"`` on ``mech`` from (q0, v0): the rotors' rule
    (``charts.analyses.transients.auto_duration``: `AUTO_EFOLDINGS` over the smallest
    positive exponent, floored at 1 % of the largest, within `AUTO_TRANSIENT_RANGE`) on a
    pilot `lyapunov_spectrum` of ``PILOT_TIMES[1]`` after ``PILOT_TIMES[0]`` (the nearest
    whole numbers of steps) with the run's settings."""
    pilot = lyapunov_spectrum(mech, q0, v0, Documented(PILOT_TIMES[1]), dt=dt,
                              n_exponents=n_exponents, inner=inner,
                              t_transient=Documented(PILOT_TIMES[0]), n_batches=2,
                              project_every=project_every, seed=seed)
    return auto_duration(pilot.exponents)


def resolve_transient(t_transient, mech, q0, v0, **pilot):
    """(duration, rule text or None) of ``t_transient`` on ``mech`` from (q0, v0)
    (``charts.analyses.transients.resolve_transient`` with `auto_transient` as the pilot of
    "auto"; "scaled" refused, `mechanism_rule`).  Check the run's other settings first: the
    pilot runs here."""
    if mechanism_rule(t_transient, mech) and _CHECKING.get():
        raise _PilotReached(pilot)
    return transients.resolve_transient(t_transient, mech, q0, v0, auto_transient, **pilot)


def settings_before_pilot(analysis, mech, q0, v0, t_final, **kwargs) -> dict:
    """The pilot settings of ``analysis(mech, q0, v0, t_final, **kwargs)`` (a mechanism
    analysis that resolves its transient by `resolve_transient`; ``kwargs["t_transient"]`` a
    rule), every other setting and the state checked by the analysis itself, without running
    it nor its pilot: an ensemble checks its members' settings so, then runs one pilot for
    all."""
    token = _CHECKING.set(True)
    try:
        analysis(mech, q0, v0, t_final, **kwargs)
    except _PilotReached as reached:
        return reached.pilot
    finally:
        _CHECKING.reset(token)
    raise RuntimeError(f"{analysis.__name__} ran without reaching its pilot")
