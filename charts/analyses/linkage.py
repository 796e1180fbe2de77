"""Analyses of the linkage of the Appendix: Lyapunov exponents (eqs 17–18 for the linkage's
flow), sectional curvature along the trajectory (Gauss equation), the distance of the manifold
from the cone points of Σ cos θ = 0, and the state of the ε → 0 comparison.

The linkage is a `charts.Mechanism` (``charts.mechanism.linkage.LinkageSystem``), so its runs
take the generic route: the mechanism's compiled tangent flow
(``charts.mechanism.tangent_flow.MechanismTangentFlow``: the KKT equations of motion and their
exact linearisation, RK4, projected back onto F = 0 and ker J every ``project_every``), eq
(18)'s Gram–Schmidt in the kinetic metric on positions, Σ Mⱼⱼ δqⱼ² (for a massless disk
Σ δθᵢ², the pulled-back metric).  What is the linkage's own here: its settings and result, the
health of its disk and the error that says what to do where it degenerates.

Curvature.  M ⊂ (R⁷, M) is a submanifold of the flat (R⁷, M); the Gauss equation of that
embedding (``Mechanism.gauss_equation_curvature``: the second fundamental form, no chart)
gives K(X, Y).  For a massless disk the metric counts θ only: the θ-projection of M is an
isometrically immersed hypersurface of R⁴.  Along a run, as in ``charts.analyses.curvature``,
the planes are (unit velocity, eᵢ) with eᵢ the Lyapunov vectors orthonormalised against it;
``fraction_positive`` counts K > 0.
"""
from __future__ import annotations

import inspect
from dataclasses import dataclass, field

import numpy as np

from ..io.archive import Archivable, attributes, dataset, exponent_coordinate
from ..io.file_settings import MEMBER_DIMS
from ..io.result_words import ANGULAR_VELOCITY, RATE, exponent_words
from ..jit.compilation import announces_compilation
from ..geometry.checks import finite_array, integer
from ..mechanism.errors import MechanismError
from ..mechanism.linkage import NQ, DegenerateMetricError
from ..mechanism.tangent_flow import MechanismTangentFlow
from ..solvers.status import IntegrationError, check_step
from .arguments import (MAX_MEMBERS, Documented, flag, linkage_system, positive_int,
                        positive_time, progress_reporter, inner_steps, project_steps, steps_of)
from .ensemble import EnsembleResult
from .lyapunov import exponents_from_marks
from .mechanism_ensemble import mechanism_ensemble
from .spectrum_quantities import SpectrumQuantities, reconstructed_spectra
from .statistics import batch_ends

__all__ = ["LinkageResult", "linkage_run", "run_steps", "linkage_ensemble", "linkage_trajectory",
           "gauss_curvature", "frame_curvatures", "cone_distance", "CONE_POINTS"]

#: Length of the linkage's state (q, v).
NY = 2 * NQ

#: The 14 components of the linkage's state (q, v): the rotors' angles, the disk's centre and
#: angle, then their velocities, with their units.
COMPONENTS = ("theta_0", "theta_1", "theta_2", "theta_3", "x", "y", "alpha", "u_0", "u_1",
              "u_2", "u_3", "x_dot", "y_dot", "alpha_dot")
COMPONENT_UNITS = ("rad",) * 4 + ("length", "length", "rad") + (ANGULAR_VELOCITY,) * 4 + (
    "length / time", "length / time", ANGULAR_VELOCITY)
#: Positive exponents of the linkage's geodesic flow (its configuration space is 3-dimensional,
#: as the rotors' N = 4 manifold: N − 2 = 2), and the relevant spectrum's size (2 · 3).
POSITIVE_EXPONENTS, SPECTRUM_SIZE = 2, 6

#: The six cone points of Σ cos θ = 0 (N = 4): two angles 0, two π.
CONE_POINTS = tuple(np.array(p, dtype=float) * np.pi for p in
                    [(0, 0, 1, 1), (0, 1, 0, 1), (0, 1, 1, 0), (1, 0, 0, 1), (1, 0, 1, 0),
                     (1, 1, 0, 0)])


def gauss_curvature(system, q, X, Y):
    """Sectional curvature of the plane (X, Y) ⊂ T_q M (tangent vectors, shape (7,)) by the
    Gauss equation (module doc; ``Mechanism.gauss_equation_curvature``); X, Y need not be
    orthonormal.  q, X and Y are checked (shape (7,), finite; ValueError naming them)
    first."""
    q, X, Y = (finite_array(name, a, (NQ,)) for name, a in (("q", q), ("X", X), ("Y", Y)))
    return system.gauss_equation_curvature(q, X, Y)


def linkage_flow(system, q, v, k, *, dt, reorth_every=1, project_every=100, seed=0):
    """The linkage's state (q, v) and ``k`` tangent vectors on the generic route: the
    mechanism's `MechanismTangentFlow` re-orthonormalised every ``reorth_every`` steps in eq
    (18)'s product on positions (``inner="theta"``: Σ Mⱼⱼ δqⱼ²), projected onto F = 0 and
    ker J every ``project_every`` steps (0: never), the vectors ``seed``-random."""
    return MechanismTangentFlow(system, q, v, k, dt=dt, reorth=reorth_every,
                                project=project_every, inner="theta", seed=seed)


def advance_linkage(system, flow, steps, where):
    """``steps`` steps of `linkage_flow`'s flow (`MechanismTangentFlow.advance`, also for a
    subclass that calls this from its own ``advance``), its failure said in the linkage's words:
    `DegenerateMetricError` for a massless disk (the KKT matrix singular or the state
    non-finite: where the pulled-back metric degenerates, module doc of
    ``charts.mechanism.linkage``), ``IntegrationError`` otherwise; ``where`` names the run."""
    try:
        MechanismTangentFlow.advance(flow, steps)
    except (MechanismError, np.linalg.LinAlgError) as exc:
        t = flow.steps * flow.dt
        if system.massless_disk:
            raise DegenerateMetricError(
                f"{where}: the flow stopped after t = {t:.17g} ({exc}): with a massless disk "
                "the kinetic metric degenerates where the disk can move while the rotors "
                "stand still (∂F/∂(x, y, α) loses rank). Give the disk inertia: "
                "LinkageSystem(..., disk_mass=1e-2, disk_inertia=1e-3), or use rho > eps "
                "(docs/linkage.md), or reduce dt.") from None
        raise IntegrationError(f"{where}: the flow stopped after t = {t:.17g} ({exc}); "
                               "reduce dt.") from None


def disk_health(system, Q):
    """det(C̃ᵀC̃) at each configuration of Q (S, ≥ 7), C̃ = ∂F/∂(x, y, ρα) (the α column of
    ∂F/∂(x, y, α) divided by ρ): the squared product of its singular values, dimensionless,
    0 exactly where the massless disk's metric degenerates; shape (S,)."""
    Q = np.asarray(Q, dtype=float)[:, :NQ]
    C = system._eval("J", Q)[..., 4:].copy()
    C[..., 2] /= system.rho
    return np.linalg.det(np.swapaxes(C, -1, -2) @ C)


@dataclass(eq=False, repr=False)
class LinkageResult(SpectrumQuantities, Archivable):
    """One run of `linkage_run`.

    exponents, stderr : (k,)  Lyapunov exponents (1/time) with batch-means standard errors.
    batches : (n_batches, k)  per-block estimates.
    t : (S,)  sample times after the transient; states : (S, 14) the sampled (q, v).
    K : (S, k)  sectional curvatures K(v̂, eᵢ) (module doc).
    min_sin2 : float  smallest Σ sin²θᵢ at the samples (0 at a cone point of Σ cos θ = 0).
    min_health : float  smallest det(C̃ᵀC̃) at the samples (`disk_health`).

    The relevant spectrum (`spectrum`), the Kolmogorov–Sinai entropy and the Kaplan–Yorke
    dimension are those of the rotors' N = 4 (the same pairs ±λ and two zeros), from the two
    leading exponents (``n_exponents`` ≥ 2).
    """
    exponents: np.ndarray
    stderr: np.ndarray
    batches: np.ndarray
    t: np.ndarray
    states: np.ndarray
    K: np.ndarray
    min_sin2: float
    min_health: float
    params: dict = field(default_factory=dict)

    def fraction_positive(self):
        """Fraction of samples with K(v̂, eᵢ) > 0, shape (k,)."""
        return (self.K > 0).mean(axis=0)

    @property
    def spectrum(self):
        """(6,): the relevant spectrum λ₁, λ₂, 0, 0, −λ₂, −λ₁ from the two leading exponents
        (None when fewer were computed)."""
        if len(self.exponents) < POSITIVE_EXPONENTS:
            return None
        return reconstructed_spectra(self.exponents, POSITIVE_EXPONENTS, SPECTRUM_SIZE)[0]

    def _spectra(self):
        if self.spectrum is None:
            raise ValueError(f"this result holds {len(self.exponents)} exponent, not the two "
                             "positive ones; run linkage_run with n_exponents >= 2")
        return self.spectrum, reconstructed_spectra(self.batches, POSITIVE_EXPONENTS,
                                                    SPECTRUM_SIZE)

    KIND = "linkage"

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``); the exponents counted from 1 (λ₁ the largest, as
        `LyapunovResult`'s); the state's 14 components are q (θ₀…θ₃ and the disk's three
        coordinates), then their velocities."""
        data = {"exponents": (("exponent",), self.exponents, RATE,
                              "Lyapunov exponents λᵢ, λ₁ the largest"),
                "stderr": (("exponent",), self.stderr, RATE, "batch-means standard error"),
                "batches": (("batch", "exponent"), self.batches, RATE, "batch estimates"),
                "K": (("sample", "exponent"), self.K, "1 / rad^2",
                      "sectional curvature K(unit velocity, e_i) (Gauss equation)"),
                "states": (("sample", "component"), self.states, "see component_units",
                           "the sampled state (q, v)")}
        coords = {"t": (("sample",), self.t, "time", "after the transient"),
                  "exponent": exponent_coordinate(len(self.exponents)),
                  "component": (("component",), np.array(COMPONENTS), "1",
                                "θ₀…θ₃, the disk's x, y, α, then their velocities"),
                  "component_units": (("component",), np.array(COMPONENT_UNITS), "1",
                                      "the unit of each component of states"),
                  **q_component_coordinates()}
        return dataset(self.KIND, data, coords=coords, attrs={
            "params": self.params, "min_sin2": self.min_sin2, "min_health": self.min_health})

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        return cls(ds["exponents"].values, ds["stderr"].values, ds["batches"].values,
                   ds["t"].values, ds["states"].values, ds["K"].values, float(a["min_sin2"]),
                   float(a["min_health"]), a["params"])

    def plot(self, ax=None, **kw):
        """Histograms of the sectional curvatures K(v̂, eᵢ), one panel per plane
        (``charts.plotting.plot_curvature``); the exponents in the title; ``(fig, axes)``."""
        from ..plotting import plot_curvature
        pm = ", ".join(f"{e:.4f} ± {s:.4f}" for e, s in zip(self.exponents, self.stderr))
        kw.setdefault("title", f"linkage ε = {self.params.get('eps'):g}: exponents {pm}")
        return plot_curvature({"Gauss equation": self.K}, axes=ax, **kw)

    def summary_parts(self):
        """The exponents ± their standard errors and the smallest Σ sin²θᵢ met."""
        return [exponent_words(self.exponents, self.stderr), f"min Σ sin²θ {self.min_sin2:.3g}"]


def q_component_coordinates() -> dict:
    """The coordinates that name the 7 components of q (θ₀…θ₃, x, y, α: the first of
    `COMPONENTS`) and their units, along the dimension of the settings q0 and v0 (v0 holds
    their rates) in an ensemble's file (``charts.io.file_settings.MEMBER_DIMS``), for `dataset`'s
    ``coords``: a run's file has them too, naming the entries of ``params_q0``, ``params_v0``."""
    dim = MEMBER_DIMS["q0"]
    return {dim: ((dim,), np.array(COMPONENTS[:NQ]), "1",
                  "component of q (q0; v0 holds their rates), as component"),
            f"{dim}_units": ((dim,), np.array(COMPONENT_UNITS[:NQ]), "1",
                             "the unit of each component of q0 (of v0: the same per time)")}


def frame_curvatures(system, row, k):
    """K(v̂, eᵢ), i = 1…k, shape (k,), at a recorded row [y; ξ¹…ξᵏ] (shape ≥ (14 (1 + k),),
    e.g. ``flow.Z.ravel()`` of `linkage_flow`): the planes of the module doc (the Gauss
    equation of ``charts.mechanism.embedding``, the k planes as one batch at the row's q)."""
    fr = _frame(system, row, k)
    q = np.broadcast_to(row[:NQ], (k, NQ))
    return system._gauss(q, system._isometry(q), np.broadcast_to(fr[0], (k, NQ)),
                         np.array(fr[1:]))


def _frame(system, row, k):
    """(v̂, e₁…e_k) from a recorded row [y; ξ¹…ξᵏ]: the position parts, M-orthonormalised."""
    w = system.mass
    vecs = [row[NQ:NY]] + [row[NY * (r + 1):NY * (r + 1) + NQ] for r in range(k)]
    out = []
    for x in vecs:
        x = x.copy()
        for e in out:
            x -= np.sum(w * x * e) * e
        out.append(x / np.sqrt(np.sum(w * x * x)))
    return out


def run_steps(dt, t_final, reorth_every, sample_every):
    """(t_final, reorth_every, sample_every) of `linkage_run` in steps dt: a written time a
    whole number of steps or ValueError; a `Documented` default placed as the signature's
    docstring says — as lyapunov_spectrum's record_every: a default reorth_every divides
    t_final (and a sample_every that is written); a default sample_every is then the nearest
    multiple of reorth_every that divides t_final.  A linkage scene places its defaults
    with it (``charts.runs.scene``)."""
    total = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt)
    reorth = inner_steps("reorth_every", reorth_every, dt, total, sample_every, sample)
    if isinstance(sample_every, Documented):
        sample = reorth * steps_of("sample_every", sample_every, reorth * dt,
                                   divides=total // reorth)
    return total, reorth, sample


@announces_compilation
def linkage_run(system, q0, v0, t_final, *, dt=0.01, n_exponents=2,
                t_transient=Documented(50.0), n_batches=20, reorth_every=Documented(0.1),
                project_every=Documented(1.0), sample_every=Documented(1.0), curvature=True,
                seed=0, progress=False) -> LinkageResult:
    """Lyapunov exponents and curvature samples of the linkage from (q0, v0).

    Parameters as in ``lyapunov_spectrum`` (times in time units): ``t_final`` averaging time
    after ``t_transient`` (default 50); ``n_exponents`` (≤ 3, the dimension) leading
    exponents in the product of the kinetic metric on positions; ``reorth_every`` time
    between re-orthonormalisations (default 0.1); ``project_every`` time between
    projections onto the invariants (default 1.0, None: never); ``sample_every`` time
    between curvature samples (a multiple of ``reorth_every``, default 1.0);
    ``curvature=False`` skips the Gauss-equation evaluations.  A time you write must be a
    whole number of steps dt (or is refused); a default you leave is the nearest whole
    number of steps at other dt (README, "Conventions"): a default ``reorth_every`` the
    largest count at most that which divides t_final (and a written ``sample_every``), a
    default ``sample_every`` the nearest multiple of ``reorth_every`` that divides t_final.
    """
    linkage_system(system)
    curvature = flag("curvature", curvature)
    q0, v0 = system.check_state(q0, v0, ("q0", "v0"))
    if not system.speed(v0) > 0:
        raise ValueError("v0 has zero kinetic speed: the geodesic flow needs a nonzero speed")
    dt = check_step(positive_time("dt", dt), float(system.speed(v0)), 4)
    k = positive_int("n_exponents", n_exponents)
    if k > system.dim:
        raise ValueError(f"n_exponents={k} is out of range 1..{system.dim}")
    total, reorth, sample = run_steps(dt, t_final, reorth_every, sample_every)
    if total % reorth or sample % reorth:
        raise ValueError(f"t_final={t_final:g} and sample_every={sample_every:g} must be "
                         f"multiples of reorth_every={reorth_every:g}")
    if total % sample:
        raise ValueError(f"t_final={t_final:g} must be a multiple of sample_every={sample_every:g}")
    n_batches = positive_int("n_batches", n_batches, 2)
    if total < n_batches * reorth:
        raise ValueError(f"t_final={t_final:g} is too short for n_batches={n_batches}")
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    seed = positive_int("seed", seed, 0)
    project = project_steps(project_every, dt)
    flow = linkage_flow(system, q0, v0, k, dt=dt, reorth_every=reorth, project_every=project,
                        seed=seed)
    rep = progress_reporter(progress, (transient + total) * dt, f"linkage eps={system.eps:g}")
    where = "linkage_run (RK4)"
    advance_linkage(system, flow, transient, where)
    rep.update(transient * dt)
    flow.logsum[:] = 0.0
    ends = batch_ends(total, n_batches, reorth)
    logs = np.zeros((len(ends), k))
    S = total // sample
    rows = np.zeros((S, NY * (1 + k)))
    pos = 0
    for stop in sorted(set(ends) | set(range(sample, total + 1, sample))):
        advance_linkage(system, flow, stop - pos, where)
        rep.update((stop - pos) * dt)
        pos = stop
        for i, end in enumerate(ends):
            if end == stop:
                logs[i] = flow.logsum
        if stop % sample == 0:
            rows[stop // sample - 1] = flow.Z.ravel()
    rep.close()
    exps, batches, stderr = exponents_from_marks(logs, ends, dt)
    K = np.full((S, k), np.nan)
    if curvature:
        for i in range(S):
            K[i] = frame_curvatures(system, rows[i], k)
    states = rows[:, :NY].copy()
    min_sin2 = float(np.min(np.sum(np.sin(states[:, :4]) ** 2, axis=1)))
    # the settings as run, and the initial state: enough to repeat the call from a saved file
    params = dict(**system.describe(), t_final=total * dt, dt=dt,
                  t_transient=transient * dt, n_batches=n_batches, reorth_every=reorth * dt,
                  sample_every=sample * dt, project_every=project * dt if project else None,
                  n_exponents=k, curvature=bool(curvature), speed=system.speed(v0),
                  vectors_seed=seed, state_seed="given",
                  q0=q0.tolist(), v0=v0.tolist())
    return LinkageResult(exps, stderr, batches, np.arange(1, S + 1) * sample * dt, states, K,
                         min_sin2, float(np.min(disk_health(system, states))), params)


def linkage_ensemble(system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                     progress=False, client=None, **kwargs) -> EnsembleResult:
    """`linkage_run` from ``n_trajectories`` random states of kinetic speed ``speed``
    (``system.random_state(seed=s, speed=speed)``, seeds seed, seed+1, …; also the seeds of
    the tangent vectors), in ``workers`` processes (default: all cores); ``kwargs``: the
    settings of `linkage_run`: the ensemble of any mechanism
    (``charts.analyses.mechanism_ensemble.mechanism_ensemble``) with `linkage_run` as its
    member.  Returns an `EnsembleResult` (mean exponents, their standard
    error across the members, the members' error ratio), saved and loaded like every other.

    With several workers the kernels are compiled once, here, before the workers start (and
    announced here): a `linkage_run` of the first seed over two re-orthonormalisations, no
    transient, with the members' dt, exponents, projection and curvature setting, so the
    workers load what it compiled from numba's disk cache (``prime``).
    ``client``: the members run as tasks of a Dask cluster instead (a ``Client``, a
    scheduler's address, or "local": a LocalCluster of ``workers`` processes;
    ``charts.analyses.cluster``, docs/cluster.md)."""
    linkage_system(system)
    n_trajectories = integer("n_trajectories", n_trajectories, 2, MAX_MEMBERS)
    return mechanism_ensemble(linkage_run, system, n_trajectories, t_final, speed=speed,
                              seed=seed, workers=workers, progress=progress, client=client,
                              member_bytes=_member_bytes(t_final, kwargs), prime=_prime(kwargs),
                              desc=f"linkage eps={system.eps:g} ensemble", **kwargs)


def _member_bytes(t_final, kwargs) -> int:
    """Bytes of one member's `LinkageResult` (its samples of curvature and state, its
    exponents and batches) with the settings ``kwargs`` (`linkage_run`'s defaults for the rest)."""
    default = inspect.signature(linkage_run).parameters

    def get(key):
        return kwargs.get(key, default[key].default)
    dt = positive_time("dt", get("dt"))
    total, _, sample = run_steps(dt, t_final, get("reorth_every"), get("sample_every"))
    k = positive_int("n_exponents", get("n_exponents"))
    n_batches = positive_int("n_batches", get("n_batches"), 2)
    return 8 * ((total // max(sample, 1) + 1) * (k + NY + 1) + k * (n_batches + 3))


def _prime(kwargs):
    """(t_final, settings) of the short `linkage_run` that compiles the members' kernels: two
    re-orthonormalisations, two batches, a sample at each, no transient; every other setting
    (dt, n_exponents, project_every, curvature) the members' own."""
    default = inspect.signature(linkage_run).parameters
    dt = positive_time("dt", kwargs.get("dt", default["dt"].default))
    reorth = dt * steps_of("reorth_every", kwargs.get("reorth_every",
                                                      default["reorth_every"].default), dt)
    return 2 * reorth, {"t_transient": 0.0, "n_batches": 2, "sample_every": reorth}


@announces_compilation
def linkage_trajectory(system, q0, v0, t_final, *, dt=0.01, sample_every=Documented(0.1),
                       project_every=Documented(1.0)):
    """The trajectory from (q0, v0) sampled every ``sample_every`` (default 0.1, dividing
    t_final), projected onto the invariants every ``project_every`` (default 1.0, None:
    never): (t (S + 1,), states (S + 1, 14)), row 0 the initial state (RK4 of the
    mechanism's flow, `linkage_flow`).  Times written must be whole numbers of steps dt; a default
    left is the nearest whole number of steps at other dt (README, "Conventions")."""
    linkage_system(system)
    q0, v0 = system.check_state(q0, v0, ("q0", "v0"))
    dt = positive_time("dt", dt)
    total = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=total)
    if total % sample:
        raise ValueError(f"t_final={t_final:g} must be a multiple of sample_every={sample_every:g}")
    flow = linkage_flow(system, q0, v0, 0, dt=dt, project_every=project_steps(project_every, dt))
    out = [flow.Z[0].copy()]
    for _ in range(total // sample):
        advance_linkage(system, flow, sample, "linkage_trajectory (RK4)")
        out.append(flow.Z[0].copy())
    return np.arange(len(out)) * sample * dt, np.array(out)


def cone_distance(system, cone, branch=1):
    """Euclidean distance in θ from the cone point ``cone`` (shape (4,), a `CONE_POINTS`
    entry) to the linkage's manifold on disk branch ``branch`` (sign of sin α): the minimum
    of |θ − cone| over F(q) = 0 (SLSQP from the first-order point near the cone point)."""
    from scipy.optimize import minimize

    cone = np.asarray(cone, dtype=float)
    start = cone + 0.05 * np.array([1.0, -1.0, 1.0, -1.0])
    q0 = np.concatenate([start, system.first_order_disk(start, branch)])
    fun = lambda q: float(np.sum((q[:4] - cone) ** 2))
    jac = lambda q: np.concatenate([2 * (q[:4] - cone), np.zeros(3)])
    res = minimize(fun, q0, jac=jac, method="SLSQP", tol=1e-14, options=dict(maxiter=500),
                   constraints=[dict(type="eq", fun=system.constraints, jac=system.jacobian)])
    if not res.success or np.max(np.abs(system.constraints(res.x))) > 1e-10:
        raise RuntimeError(f"cone_distance did not converge: {res.message}")
    return float(np.sqrt(res.fun)), res.x
