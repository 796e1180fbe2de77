"""The flat four-rotor linkage of the paper's Appendix (Fig. 1b) as a `Mechanism`: its
configuration manifold, the projections onto its invariants and the degeneracy of its kinetic
metric.

Coordinates q = (θ₀, θ₁, θ₂, θ₃, x, y, α), shape (7,): the rotor angles and the disk's centre
and angle.  The manifold M = {F(q) = 0} (four constraints, the symbolic model
``charts.mechanism.instances.appendix_linkage_model``) is 3-dimensional.  Kinetic metric:
T = ½ vᵀ M v with M = diag(1, 1, 1, 1, m_d, m_d, I_d); the Appendix has massless disk
(m_d = I_d = 0), the metric Σ dθᵢ² pulled back to M.  Everything a `Mechanism` derives
(the ambient equations of motion, their linearisation, the atlas, the curvature) holds for
the linkage; this class adds the Appendix's parametrisation (ε, ρ, the disk), its seeded
states and its checks.

Degeneracy.  Write J = ∂F/∂q = [A | C] with A = ∂F/∂θ (4 × 4, diagonal: constraint i holds
only θᵢ) and C = ∂F/∂(x, y, α) (4 × 3).  A tangent vector with dθ = 0 is a δ(x, y, α) with
C δ = 0: the disk moves while the rotors stand still.  So the pulled-back metric is positive
definite exactly where C has rank 3; with m_d = I_d = 0 the flow needs that.  For ε → 0,
ρ = rε the Appendix's first-order solution has cos α = (cos θ₁ + cos θ₃)/(2r) and C loses rank
where sin α = 0, i.e. |cos θ₁ + cos θ₃| = 2r: never for r > 1, on two of the six cone points
of Σ cos θ = 0 for r = 1, on a fold bounding the reachable angles for r < 1.  The default
ρ = 2ε keeps |cos α| ≤ ½.  A small disk mass and moment of inertia make the metric
positive definite everywhere on M (``LinkageSystem(disk_mass=…, disk_inertia=…)``).
"""
from __future__ import annotations

import math

import numpy as np

from ..geometry.checks import finite_array, integer, number, shown
from ..geometry.system import RotorSystem
from ..solvers.status import IntegrationError
from .instances import appendix_linkage_model
from .model import Mechanism, MechanismError

__all__ = ["LinkageSystem", "DegenerateMetricError", "NQ", "NC", "LENGTH_MIN", "LENGTH_MAX"]

#: Coordinates q and constraints F of the linkage.
NQ = 7
NC = 4
#: The range of the crank ε and the disk radius ρ: [LENGTH_MIN, LENGTH_MAX).  Above, the
#: Appendix's small-linkage picture fails (rods R = 1, axes at distance 1).  Below, the
#: kinetic projection's KKT matrix (entries of order ε²) loses its digits
#: (``python scripts/linkage_eps_floor.py``, docs/linkage.md).
LENGTH_MIN = 1e-6
LENGTH_MAX = 0.5
#: |F| and |J v| above which a state is refused as off the manifold.
TOL = 1e-8
#: J Jᵀ is taken as singular (the four constraints dependent, M not a manifold there) where
#: the smallest singular value of J is below this fraction of the largest.
RANK_TOL = 1e-12


class DegenerateMetricError(MechanismError, IntegrationError):
    """The pulled-back metric degenerated (the disk could move with the rotors at rest): a
    `MechanismError` (a point where the flow is undefined) and an ``IntegrationError`` (a
    run that stopped), so that either ``except`` catches it."""


class LinkageSystem(Mechanism):
    """The linkage of the Appendix with crank ε, disk radius ρ (default 2ε), rods R = 1, unit
    rotor moments, and disk mass ``disk_mass`` and moment ``disk_inertia`` (default 0: the
    Appendix's massless disk; see the module doc for when that needs the disk's inertia).

    A `Mechanism` (q = (θ₀…θ₃, x, y, α), four constraints, ``n`` = 7 coordinates, ``dim``
    = 3) with parameters (eps, rho, R, m_d, I_d): its symbolic model
    (``appendix_linkage_model``) is derived once per process and shared by every
    LinkageSystem.  ``par`` = (ε, ρ, R, m_d, I_d), the parameter values; ``mass`` = diag(M),
    shape (7,); ``rotors`` = 4.
    """

    rotors = 4

    def __init__(self, eps, rho=None, *, disk_mass=0.0, disk_inertia=0.0):
        eps = _length("eps", eps)
        rho = 2.0 * eps if rho is None else _length("rho", rho)
        if not rho < LENGTH_MAX:
            raise ValueError(f"rho = 2 eps = {rho:g} must be < {LENGTH_MAX:g}: pass a smaller "
                             "eps or rho explicitly")
        dm = _nonnegative("disk_mass", disk_mass)
        di = _nonnegative("disk_inertia", disk_inertia)
        model = appendix_linkage_model().derive()
        # the model's description and derivations, shared (as Mechanism.with_parameters does)
        self.__dict__.update(model.__dict__)
        self.bounds = dict(model.bounds)
        self.eps, self.rho = eps, rho
        self.disk_mass, self.disk_inertia = dm, di
        self.param_values = np.array([eps, rho, 1.0, dm, di])
        self.par = self.param_values
        self.mass = np.array([1.0, 1.0, 1.0, 1.0, dm, dm, di])
        self.name = repr(self)

    def __repr__(self):
        return (f"LinkageSystem(eps={self.eps:g}, rho={self.rho:g}, disk_mass={self.disk_mass:g}, "
                f"disk_inertia={self.disk_inertia:g})")

    def __reduce__(self):
        """Pickled by its arguments (the symbolic model is derived again where it is loaded,
        once per process): ensembles send it to worker processes."""
        return (_linkage_system, (self.eps, self.rho, self.disk_mass, self.disk_inertia))

    def with_parameters(self, *, name=None, bounds=None, **values):
        """A LinkageSystem with other parameter values (eps, rho, m_d, I_d by name; R stays
        1, the Appendix's rods); ``name`` and ``bounds`` are not taken (MechanismError)."""
        if name is not None or bounds is not None or "R" in values:
            raise MechanismError("a LinkageSystem takes other eps, rho, m_d, I_d only (R = 1, "
                                 "its name and bounds are the Appendix's)")
        unknown = set(values) - {"eps", "rho", "m_d", "I_d"}
        if unknown:
            raise MechanismError(f"{sorted(unknown)} are not parameters of the linkage "
                                 "(eps, rho, m_d, I_d)")
        return LinkageSystem(values.get("eps", self.eps), values.get("rho", self.rho),
                             disk_mass=values.get("m_d", self.disk_mass),
                             disk_inertia=values.get("I_d", self.disk_inertia))

    @property
    def massless_disk(self) -> bool:
        return self.disk_mass == 0.0 or self.disk_inertia == 0.0

    # ------------------------------------------------------------------ evaluation
    def constraints(self, q):
        """F(q), shape (4,): `Mechanism.constraint` of q checked first (shape (7,), finite;
        ValueError naming q)."""
        return self.constraint(finite_array("q", q, (NQ,)))

    def jacobian(self, q):
        """J = ∂F/∂q, shape (4, 7): `Mechanism.jacobian` of q checked first (as
        `constraints`)."""
        return super().jacobian(finite_array("q", q, (NQ,)))

    def constraint_rank_margin(self, q) -> float:
        """Smallest over largest singular value of J at q (0 where the four constraints are
        dependent: J Jᵀ is singular and no projection onto M is defined there)."""
        s = np.linalg.svd(self.jacobian(q), compute_uv=False)
        return float(s[-1] / s[0]) if s[0] > 0 else 0.0

    def _check_rank(self, name, q, what):
        margin = self.constraint_rank_margin(q)
        if not margin > RANK_TOL:
            raise ValueError(
                f"{name} = {np.array2string(np.asarray(q), precision=4)} is a singular "
                f"configuration of the linkage: the constraints' Jacobian J has dependent rows "
                f"there (smallest/largest singular value {margin:.1e} <= {RANK_TOL:g}), so "
                f"{what}; start from another point, e.g. LinkageSystem.random_state or "
                "from_rotor_state")

    def disk_margin(self, q) -> float:
        """Smallest singular value of C = ∂F/∂(x, y, α) with the α column divided by ρ
        (dimensionless; 0 where the pulled-back metric degenerates, module doc)."""
        C = self.jacobian(q)[:, 4:].copy()
        C[:, 2] /= self.rho
        return float(np.linalg.svd(C, compute_uv=False)[-1])

    def speed(self, v) -> float:
        """Kinetic speed √(Σ mᵢ vᵢ²) of v (7,); ValueError naming v unless finite, of that
        shape and within a float's range."""
        v = finite_array("v", v, (NQ,))
        with np.errstate(over="ignore"):
            s = float(np.sqrt(np.sum(self.mass * v * v)))
        if not np.isfinite(s):
            raise ValueError("v is too large: its kinetic speed is beyond a float's range")
        return s

    def check_state(self, q, v, names=("q", "v")):
        """Validated float copies of (q, v), shape (7,) each; ValueError off the manifold,
        naming the bad one by ``names`` (the caller's names, e.g. ("q0", "v0"))."""
        if not (isinstance(names, tuple) and len(names) == 2
                and all(isinstance(s, str) and s for s in names)):
            raise TypeError(f"names must be a pair of non-empty str, got {shown(names)}")
        nq, nv = names
        q = finite_array(nq, q, (NQ,)).copy()
        v = finite_array(nv, v, (NQ,)).copy()
        F = np.max(np.abs(self.constraints(q)))
        if F > TOL:
            raise ValueError(f"{nq} is off the linkage's manifold (max|F| = {F:.2e} > {TOL:g}); "
                             "use LinkageSystem.project(q, v) or random_state")
        with np.errstate(over="ignore", invalid="ignore"):
            Jv = np.max(np.abs(self.jacobian(q) @ v))
        if not Jv <= TOL * max(1.0, np.max(np.abs(v))):
            raise ValueError(f"{nv} is not tangent to the manifold (max|J v| = {Jv:.2e}); "
                             "use LinkageSystem.project(q, v)")
        self._check_rank(nq, q, "the linkage has no tangent space there to move in")
        return q, v

    # ------------------------------------------------------------------ states
    def project(self, q, v, speed=None):
        """(q, v) moved onto F = 0 and J v = 0 (and to kinetic ``speed`` if given): new
        arrays, by the mechanism's projections (`Mechanism.project_point`: minimum-norm Newton
        steps until max|F| < 1e-15; `Mechanism.project_velocity`: M-orthogonal, a KKT solve,
        Euclidean where the massless disk's metric degenerates).  ValueError naming the
        argument for q or v not of shape (7,) or not finite, ``speed`` not a finite number
        >= 0, a singular configuration q (J Jᵀ singular: the Newton step is undefined), a q the
        Newton steps do not bring onto M, and a speed asked of a velocity without a tangent
        component."""
        q = finite_array("q", q, (NQ,))
        v = finite_array("v", v, (NQ,))
        if speed is not None:
            speed = _nonnegative("speed", speed)
        self._check_rank("q", q, "the Newton step onto the manifold is undefined")
        try:
            q = self.project_point(q, iterations=50, tol=1e-15)
        except MechanismError as exc:
            raise ValueError(f"could not put q on the manifold ({exc}); start nearer, e.g. "
                             "from_rotor_state") from None
        self._check_rank("q", q, "the tangent space is undefined")
        with np.errstate(all="ignore"):
            try:
                v = self.project_velocity(q, v)
            except np.linalg.LinAlgError:
                v = v + np.nan                          # the Euclidean projection below
        if not np.all(np.isfinite(v)):
            J = self.jacobian(q)
            v = finite_array("v", v - np.linalg.lstsq(J, J @ v, rcond=None)[0], (NQ,))
        if speed:
            E = float(np.sum(self.mass * v * v))
            if not E > 0.0:
                raise ValueError(f"v has no component tangent to the manifold at q, so it "
                                 f"cannot be given the speed {speed:g}; pass a velocity with a "
                                 "tangent part (e.g. from random_state) or speed=None")
            v = v * (speed / math.sqrt(E))
        return q, v

    def first_order_disk(self, theta, branch=1):
        """(x, y, α) of the Appendix's first-order solution for the angles theta: x = ε(c₂ −
        c₀)/2, y = ε(c₁ − c₃)/2, cos α = ε(c₁ + c₃)/(2ρ), sign of sin α = ``branch``."""
        branch = _branch(branch)
        c = np.cos(finite_array("theta", theta, (4,)))
        ca = np.clip(self.eps * (c[1] + c[3]) / (2.0 * self.rho), -1.0, 1.0)
        return np.array([self.eps * (c[2] - c[0]) / 2, self.eps * (c[1] - c[3]) / 2,
                         math.copysign(math.acos(ca), branch)])

    def from_rotor_state(self, theta, u, branch=1):
        """The linkage state nearest a state (θ, u) of Σ cos θ = 0: the first-order disk, then
        projected onto the invariants with θ-speed |u| (the ε → 0 comparison)."""
        theta = finite_array("theta", theta, (4,))
        u = finite_array("u", u, (4,))
        q = np.concatenate([theta, self.first_order_disk(theta, branch)])
        return self.project(q, np.concatenate([u, np.zeros(3)]),
                            speed=float(np.linalg.norm(u)) if self.massless_disk else None)

    def describe(self) -> dict:
        """The system as the settings of a result (``params``): the rotor count (4), ε, ρ, the
        disk's mass and moment."""
        return dict(n=self.rotors, eps=self.eps, rho=self.rho, disk_mass=self.disk_mass,
                    disk_inertia=self.disk_inertia)

    def random_state(self, seed=0, speed=1.0, branch=1):
        """A random state on M (the disk on ``branch``) with a random tangent velocity of
        kinetic speed ``speed``.

        The angles are the rotor state's of the same seed, ``RotorSystem(4).random_state(seed)``
        (uniform θ₀…θ₂ with |Σ cos| ≤ 1, random sign of sin θ₃, on Σ cos θ = 0), moved onto M
        by `from_rotor_state` (the first-order disk, then the Newton projection).  M lies O(ε)
        off Σ cos θ = 0, so the angles differ from the rotor's by O(ε), not by 0: max over i
        of |Δθᵢ| = c ε + O(ε²) with c set by the state, over seeds 0–19 from 0.055 (seed 1) to
        3.02 (seed 7), mean 1.19, for ε = 10⁻³ and 10⁻⁴ (0.040 to 3.11 at ε = 0.1;
        ``python scripts/linkage_seeds.py``).  The velocity is drawn anew in the linkage's
        seven coordinates (stream seed + 7919) and projected: it is not the rotor state's
        (max |Δθ̇ᵢ| 0.14 to 1.69 at speed 1 over those seeds), nor, therefore, is the
        trajectory.  `from_rotor_state` starts from a given rotor state, velocity included."""
        seed = integer("seed", seed, 0)
        theta, u = RotorSystem(4).random_state(seed=seed, speed=1.0)
        q, v = self.from_rotor_state(theta, u, branch)
        v = np.random.default_rng(seed + 7919).normal(size=NQ)
        return self.project(q, v, speed=_positive("speed", speed))


def _linkage_system(eps, rho, disk_mass, disk_inertia):
    """`LinkageSystem` from its arguments (unpickling)."""
    return LinkageSystem(eps, rho, disk_mass=disk_mass, disk_inertia=disk_inertia)


def _branch(branch) -> int:
    """``branch``: +1 or −1, the sign of sin α of the disk (ValueError otherwise)."""
    if isinstance(branch, bool) or np.ndim(branch) != 0 or branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1 (the sign of sin α), got {shown(branch)}")
    return int(branch)


def _length(name, x) -> float:
    """ε or ρ as a float in [`LENGTH_MIN`, `LENGTH_MAX`); ValueError naming it otherwise."""
    x = number(name, x)
    if not LENGTH_MIN <= x < LENGTH_MAX:
        raise ValueError(
            f"{name} = {x:g} is outside [{LENGTH_MIN:g}, {LENGTH_MAX:g}): above, the linkage is "
            "not small against its rods R = 1 (the Appendix); below, the kinetic projection "
            "loses its digits (docs/linkage.md)")
    return x


def _nonnegative(name, x) -> float:
    x = number(name, x)
    if not x >= 0:
        raise ValueError(f"{name} must be a finite number >= 0, got {x!r}")
    return x


def _positive(name, x) -> float:
    x = number(name, x)
    if not x > 0:
        raise ValueError(f"{name} must be a positive finite number, got {x!r}")
    return x
