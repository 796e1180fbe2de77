"""The hyperbolicity test of section 4 on any Mechanism: the angle φ between the expanding
subspace E_u and the centre-stable subspace E_cs = E_0 ⊕ E_s of the geodesic flow, within
the tangent space of the phase space TC = {F = 0, J v = 0} (docs/mechanisms.md).

1. forward, m = d − 1 tangent vectors (the mechanism's compiled tangent flow,
   ``charts.mechanism.tangent_flow``, kept in the tangent space of TC by its projections)
   converge to E_u; the state and the vectors are stored at the sample points;
2. backward, the same flow with step −dt and m vectors converges to the subspace that grows
   in reverse time, E_s.  The backward base point is put back on the stored forward state at
   every sample point, so it never drifts from the forward trajectory;
3. E_0 = span{(v, a), (0, v)}, a = q̈ (the flow direction and the change of speed: the flow
   at speed (1 + s)|v| is the reparametrised one, so both directions are neutral);
4. sin φ = σ_min of the part of an orthonormal basis of E_u orthogonal to E_cs.

Inner product: the kinetic metric on both parts, ⟨a, b⟩ = δq_aᵀ M δq_b + δv_aᵀ M δv_b at the
sample's q (definite on the tangent space of TC, also where M is only semi-definite, as
for a massless joint).  For the rotors with unit masses it is the Euclidean product of the
rotors' (θ, u), and the tangent space of TC is their constraint-preserving subspace T_r: the
angles are those of the ``restricted`` variant of ``charts.analyses.hyperbolicity``, reached
by another route (backward tangent vectors instead of adjoint vectors, the KKT flow instead of
the closed form of eq (8)).

Why a result of its own rather than ``AngleResult``: the rotors' result carries two variants,
``full`` (E_cs in all of R^{2N}, with the two directions that break the constraint) and
``restricted``; a mechanism's tangent flow lives in the tangent space of TC by construction,
so only the restricted variant exists.  `MechanismAngles` keeps ``AngleResult``'s field names
for what it has (``t``, ``phi_restricted``, ``forward_exponents``, ``adjoint_exponents``,
``params``) and its ``statistics`` (`angle_statistics`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..geometry.checks import option
from ..io.archive import Archivable, attributes, dataset, index_coordinate
from ..io.result_words import RATE, smallest_words
from ..mechanism.tangent_flow import MechanismTangentFlow
from ..solvers.tangent import reorth_steps
from .angle_tally import SMALL_ANGLE
from .arguments import Documented, steps_of
from .hyperbolicity import angle_statistics
from .mechanism_arguments import unstable_of
from .mechanism_lyapunov import closing_checks, opening_checks
from .singular_values import sin_to_angle

__all__ = ["MechanismAngles", "mechanism_angles", "angle_grid", "sin_angle", "root_metric"]


@dataclass(frozen=True, eq=False, repr=False)
class MechanismAngles(Archivable):
    """Result of `mechanism_angles` (``AngleResult``'s names for what a mechanism has);
    saved by ``save(path)`` (NetCDF, kind ``"mechanism_angles"``), read back by
    ``charts.load``.

    t : (S,) sample times; phi_restricted : (S,) the angles φ between E_u and E_cs (rad);
    forward_exponents : (m,) growth rates of the forward vectors over [0, t_transient +
    t_final]; adjoint_exponents : (m,) growth rates of the backward vectors over [t_transient,
    end] (both ≈ λ₁ … λ_m when the passes converged); params : the settings, the mechanism and
    the start.
    """
    t: np.ndarray
    phi_restricted: np.ndarray
    forward_exponents: np.ndarray
    adjoint_exponents: np.ndarray
    params: dict = field(default_factory=dict)

    def statistics(self, variant="restricted", small=SMALL_ANGLE):
        """`angle_statistics` of the angles (``AngleResult.statistics``'s keys); ``variant``
        "restricted" only: a mechanism has no ``full`` variant (module docstring)."""
        if variant == "full":
            raise ValueError("variant='full' does not exist for a mechanism: its tangent "
                             "vectors stay in the tangent space of TC (use 'restricted')")
        option("variant", variant, ("restricted",))
        return angle_statistics(self.phi_restricted, small)

    KIND = "mechanism_angles"

    def summary_parts(self):
        """The smallest angle (a lost, non-finite sample left out)."""
        return [f"min φ restricted {smallest_words(self.phi_restricted)}"]

    def to_xarray(self):
        """Dataset: phi_restricted (t); forward_exponents, adjoint_exponents (vector); the
        settings as attributes (``AngleResult``'s names, without ``phi_full``)."""
        return dataset(self.KIND, {
            "phi_restricted": (("t",), self.phi_restricted, "rad",
                               "angle in the tangent space of TC (kinetic product)"),
            "forward_exponents": (("vector",), self.forward_exponents, RATE),
            "adjoint_exponents": (("vector",), self.adjoint_exponents, RATE)},
            coords={"t": (("t",), self.t, "time"),
                    "vector": index_coordinate("vector", len(self.forward_exponents),
                                               "i of the i-th forward / backward vector, from 1")},
            attrs={"params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        return cls(t=ds["t"].values, phi_restricted=ds["phi_restricted"].values,
                   forward_exponents=ds["forward_exponents"].values,
                   adjoint_exponents=ds["adjoint_exponents"].values,
                   params=attributes(ds)["params"])

    def plot(self, ax=None, kind="histogram", **kw):
        """``kind="histogram"``: the histogram of the angles, ``(fig, axes)``
        (``charts.plotting.plot_angles``); ``"time"``: φ(t) on a log axis, ``(fig, ax)``
        (``charts.plotting.plot_angles_series``), as ``AngleResult.plot``."""
        phis = {"restricted": self.phi_restricted}
        if option("kind", kind, ("histogram", "time")) == "time":
            from ..plotting import plot_angles_series
            return plot_angles_series(self.t, phis, ax=ax, **kw)
        from ..plotting import plot_angles
        return plot_angles(phis, axes=ax, **kw)

    def summary(self) -> str:
        """One line: the smallest angle, the share below `SMALL_ANGLE`, the growth rates."""
        s = self.statistics()
        return (f"{self.params['mechanism']}: min φ {s['min']:.3g} rad, "
                f"{100 * s['frac_small']:.2g} % below {s['small']:g}, {s['n']} samples; "
                f"forward rates {np.round(self.forward_exponents, 4).tolist()}, backward "
                f"{np.round(self.adjoint_exponents, 4).tolist()}")


def root_metric(M):
    """The symmetric square root of the positive semi-definite M (negative rounding
    clipped): ⟨a, b⟩_M = (√M a)·(√M b)."""
    lam, U = np.linalg.eigh(M)
    return (U * np.sqrt(np.clip(lam, 0.0, None))) @ U.T


def sin_angle(mech, q, v, U, S):
    """sin φ between E_u = span of the rows of U (m, 2n) and E_cs = span(S (m, 2n), (v, a),
    (0, v)) at the state (q, v), in the kinetic product on (δq, δv) (module docstring)."""
    n = mech.n
    a = mech.acceleration(q, v)
    C = np.vstack([S, np.concatenate([v, a]), np.concatenate([np.zeros(n), v])])
    L = root_metric(mech.mass_matrix(q))

    def basis(X):                   # orthonormal columns spanning the rows of X, isometric
        return np.linalg.qr(np.hstack([X[:, :n] @ L, X[:, n:] @ L]).T)[0]
    Qu, Qc = basis(U), basis(C)
    R = Qu - Qc @ (Qc.T @ Qu)
    return float(np.linalg.svd(R, compute_uv=False)[-1])


def angle_grid(dt, t_final, t_transient, sample_every) -> tuple:
    """(t_final, t_transient, sample_every) of `mechanism_angles` in steps of ``dt``, the
    defaults placed as its docstring says; ValueError naming a time that is not on the
    grid."""
    total = steps_of("t_final", t_final, dt)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    sample = steps_of("sample_every", sample_every, dt, divides=total if isinstance(
        t_transient, Documented) or not transient else np.gcd(total, transient))
    if isinstance(t_transient, Documented):
        transient = sample * round(transient / sample)
    if total % sample or transient % sample:
        raise ValueError(f"t_final={t_final:g} and t_transient={t_transient:g} must be "
                         f"multiples of sample_every={sample_every:g}")
    return total, transient, sample


def mechanism_angles(mech, q0, v0, t_final, *, dt=0.01, n_unstable=None,
                     t_transient=Documented(100.0), sample_every=Documented(0.1),
                     project_every=Documented(1.0), seed=0) -> MechanismAngles:
    """Angles φ between E_u and E_cs along ``mech``'s trajectory from (q0, v0) (module
    docstring), the restricted test of ``charts.hyperbolicity_angles`` on any mechanism.

    Parameters
    ----------
    mech : charts.Mechanism
    q0, v0 : ndarray, shape (n,)
        A point on F = 0 and a tangent velocity there (``mech.random_state``).
    t_final : float
        Length of the analysed window; the trajectory runs t_transient + t_final +
        t_transient so that both passes converge before it.
    dt : float
        RK4 step of both passes.  A time written below must be a whole number of steps; a
        default left is the nearest whole number of steps at other dt (README,
        "Conventions").
    n_unstable : int, optional
        m, the dimension of E_u (default d − 1, the number of positive exponents of a
        d-dimensional configuration manifold; at most d − 1).
    t_transient : float or "auto"
        Convergence time of each pass (>= 0, a multiple of ``sample_every``; default 100,
        the nearest such multiple at other settings).  "auto": the pilot of
        ``charts.analyses.mechanism_lyapunov.auto_transient`` (this dt, project_every and
        seed), on the grid of ``sample_every`` and recorded in ``params``
        (``transient_rule``); "scaled" is refused.
    sample_every : float
        Time between sample points (default 0.1, the nearest whole number of steps at other
        dt that divides t_final and a written t_transient).
    project_every : float or None
        Time between projections onto TC (default 1.0; None: never).
    seed : int
        Seed of the random initial vectors of both passes.

    Returns
    -------
    MechanismAngles

    Raises
    ------
    MechanismError, ValueError
        Naming the argument: ``opening_checks``, ``unstable_of``, ``mechanism_state``
        (``charts.analyses.mechanism_arguments``) and the time grid's checks.
    """
    rule, dt = opening_checks(mech, t_transient, dt)
    m = unstable_of(mech, n_unstable)
    total, transient, sample = angle_grid(dt, t_final, Documented(0.0) if rule else
                                          t_transient, sample_every)
    project, seed, q0, v0, t_transient, rule = closing_checks(
        mech, q0, v0, rule, t_transient, dt, project_every, seed)
    if rule:
        total, transient, sample = angle_grid(dt, t_final, t_transient, sample_every)
    S, Sb = total // sample, transient // sample
    reorth = reorth_steps(dt, sample)
    n = mech.n

    fw = MechanismTangentFlow(mech, q0, v0, m, dt=dt, reorth=reorth, project=project,
                              inner="full", seed=seed)
    fw.advance(transient)
    ys = np.empty((S + Sb + 1, 2 * n))          # the states from the window's start on
    Us = np.empty((S, m, 2 * n))                # the forward vectors in the window
    for j in range(S + Sb + 1):
        if j:
            fw.advance(sample)
        ys[j] = fw.y
        if j < S:
            Us[j] = fw.X
        if j == S:
            fexp = fw.logsum / (fw.steps * dt)
    qb = mech.project_point(ys[-1, :n])        # (its state is put on ys at every sample;
    vb = mech.project_velocity(qb, ys[-1, n:])  # projected for the start of its vectors)
    bw = MechanismTangentFlow(mech, qb, vb, m, dt=-dt, reorth=reorth, project=project,
                              inner="full", seed=seed)
    sines = np.empty(S)
    for j in range(S + Sb, 0, -1):
        bw.Z[0] = ys[j]
        bw.advance(sample)
        if j - 1 < S:
            q, v = ys[j - 1, :n], ys[j - 1, n:]
            sines[j - 1] = sin_angle(mech, q, v, Us[j - 1], bw.X)
    bexp = bw.logsum / (bw.steps * dt)
    speed = float(np.sqrt(2 * mech.energy(q0, v0)))
    params = dict(mechanism=mech.name, parameters=mech.parameter_values, dt=dt,
                  n_unstable=m, t_final=total * dt, t_transient=transient * dt,
                  sample_every=sample * dt, project_every=project * dt or None, speed=speed,
                  vectors_seed=seed, state_seed="given", q0=q0.tolist(), v0=v0.tolist())
    if rule:
        params["transient_rule"] = rule
    t = (transient + np.arange(S) * sample) * dt
    return MechanismAngles(t, sin_to_angle(sines), fexp, bexp, params)
