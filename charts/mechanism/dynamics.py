"""The ambient dynamics of a Mechanism: the constrained equations of motion solved as one
saddle-point (KKT) system, their exact linearisation, and the projections onto the
configuration manifold F = 0 and its tangent spaces.

``acceleration`` solves

    [ M  −Jᵀ ] [ q̈ ]   [ −C(q, v)    ]
    [ J   0  ] [ λ  ] = [ −∂²F(v, v) ]

(the equations of ``charts.mechanism.symbolic``); it needs M positive definite only on
ker J, so massless coordinates (M singular, e.g. the free joint of the triple linkage with
``joint_mass=0``) are allowed.  The projections are Newton steps of minimum norm (points) and
M-orthogonal KKT solves (velocities, phase-space tangent vectors).
"""
from __future__ import annotations

import numpy as np

from ..geometry.checks import finite_array, integer, number, shown
from .errors import MechanismError
from .kernels import kkt_matrix, motion_rhs, tangent_motion_rhs

__all__ = ["AmbientDynamics", "RANK_TOL"]

#: Relative size σ_min/σ_max of the constraint Jacobian below which a point is refused.
RANK_TOL = 1e-9


def _tolerance(tol) -> float:
    """``tol`` as a positive finite float; `MechanismError` naming it otherwise."""
    try:
        tol = number("tol", tol)
    except ValueError as exc:
        raise MechanismError(str(exc)) from None
    if not tol > 0:
        raise MechanismError(f"tol must be positive, got {tol!r}")
    return tol

class AmbientDynamics:
    """Points, velocities and the ambient flow of a mechanism.

    The host class supplies: ``n``, ``k``, ``q`` (Symbols, for messages), ``name``,
    ``bounds``, ``_periodic_mask`` and ``_eval(key, q)`` (``symbolic.SymbolicJets``).
    """

    def _point(self, q, name="q"):
        try:
            return finite_array(name, q, shape=(self.n,))
        except ValueError as exc:
            raise MechanismError(f"{exc}: {name} is {self.n} finite numbers "
                                 f"({', '.join(s.name for s in self.q)})") from None

    def constraint(self, q):
        """F(q), shape (k,)."""
        return self._eval("F", self._point(q))

    def jacobian(self, q):
        """J(q) = ∂F/∂q, shape (k, n)."""
        return self._eval("J", self._point(q))

    def mass_matrix(self, q):
        """M(q), shape (n, n)."""
        return self._eval("M", self._point(q))

    def check_rank(self, q):
        """Raise MechanismError where J(q) has rank < k (σ_min/σ_max < RANK_TOL)."""
        J = self.jacobian(q)
        s = np.linalg.svd(J, compute_uv=False)
        if s[0] == 0 or s[-1] < RANK_TOL * s[0]:
            raise MechanismError(
                f"{self.name}: the constraint Jacobian has rank < {self.k} at q = {np.asarray(q).tolist()} "
                f"(singular values {s.tolist()}): a singular point, not a smooth manifold there")
        return J

    def check_point(self, q, tol=1e-8):
        """q as an array, checked to be on F = 0 (|F| ≤ tol) with J of full rank."""
        q = self._point(q)
        tol = _tolerance(tol)
        F = self.constraint(q)
        if np.max(np.abs(F)) > tol:
            raise MechanismError(f"q is off the constraint: |F| = {np.max(np.abs(F)):.3e} > {tol:g}; "
                                 "use project_point")
        self.check_rank(q)
        return q

    def check_tangent(self, q, u, name="u", tol=1e-8):
        """u as an array, checked to be tangent at q (|J u| ≤ tol · max(1, |u|))."""
        if not isinstance(name, str) or not name:
            raise MechanismError(f"name must be a non-empty str (the argument's name in "
                                 f"messages), got {shown(name)}")
        tol = _tolerance(tol)
        q = self._point(q)
        u = self._point(u, name)
        r = self.jacobian(q) @ u
        bound = tol * max(1.0, np.max(np.abs(u)))
        if np.max(np.abs(r)) > bound:
            raise MechanismError(f"{name} is not tangent at q: |J(q) {name}| = "
                                 f"{np.max(np.abs(r)):.3e} > tol·max(1, |{name}|) = {bound:.3e} "
                                 f"(tol = {tol:g}); use project_velocity")
        return u

    def _kkt(self, q, J=None, sign=-1.0):
        """(K, M, J) at q: K = [[M, sign·Jᵀ], [J, 0]] (`charts.mechanism.kernels.kkt_matrix`)."""
        M = self.mass_matrix(q)
        J = self.jacobian(q) if J is None else J
        K = np.empty((self.n + self.k,) * 2)
        kkt_matrix(M, J, sign, K)
        return K, M, J

    def multiplier_and_acceleration(self, q, v):
        """(q̈, λ) of the ambient equations (see the module docstring) at (q, v)."""
        q = self._point(q)
        v = self._point(v, "v")
        K, M, J = self._kkt(q)
        b = np.empty(self.n + self.k)
        motion_rhs(self._eval("dM", q), self._eval("F2", q), v, b)
        sol = np.linalg.solve(K, b)
        return sol[:self.n], sol[self.n:]

    def tangent_acceleration(self, q, v, dq, dv):
        """The linearisation of ``acceleration`` (for tangent vectors, the analogue of eq (17)):
        δq̈ at (q, v) along (δq, δv), shape (n,), from the differentiated KKT system
        K δ(q̈, λ) = δb − δK (q̈, λ) (exact, with ∂²M and ∂³F; no finite differences;
        `charts.mechanism.kernels.tangent_motion_rhs`)."""
        q, v = self._point(q), self._point(v, "v")
        dq, dv = self._point(dq, "dq"), self._point(dv, "dv")
        K, M, J = self._kkt(q)
        dM, F2 = self._eval("dM", q), self._eval("F2", q)
        b = np.empty(self.n + self.k)
        motion_rhs(dM, F2, v, b)
        x = np.linalg.solve(K, b)
        r = np.empty(self.n + self.k)
        tangent_motion_rhs(dM, self._eval("d2M", q), F2, self._eval("F3", q), v, x, dq, dv, r)
        return np.linalg.solve(K, r)[:self.n]

    def acceleration(self, q, v):
        """q̈ of the ambient constrained equations of motion at (q, v), shape (n,)."""
        return self.multiplier_and_acceleration(q, v)[0]

    def rhs(self, t, y):
        """(q̇, v̇) = (v, acceleration): the ambient flow for ``scipy.integrate.solve_ivp``."""
        return np.concatenate([y[self.n:], self.acceleration(y[:self.n], y[self.n:])])

    def inner(self, q, a, b):
        """⟨a, b⟩ = aᵀ M(q) b."""
        a, b = self._point(a, "a"), self._point(b, "b")
        with np.errstate(over="ignore", invalid="ignore"):
            out = float(a @ self.mass_matrix(self._point(q)) @ b)
        if not np.isfinite(out):
            raise MechanismError("a and b are too large: their inner product is beyond a "
                                 "float's range")
        return out

    def energy(self, q, v):
        """T = ½ vᵀ M(q) v."""
        v = self._point(v, "v")
        with np.errstate(over="ignore", invalid="ignore"):
            T = 0.5 * float(v @ self.mass_matrix(self._point(q)) @ v)
        if not np.isfinite(T):
            raise MechanismError("v is too large: its kinetic energy is beyond a float's range")
        return T
    def project_point(self, q, iterations=50, tol=1e-13):
        """A point on F = 0 near q: Newton with the minimum-norm step q ← q − J⁺F (J⁺ the
        pseudo-inverse, in coordinates: M may be singular); checks the rank at the result."""
        q = self._point(q).copy()
        tol = _tolerance(tol)
        try:
            iterations = integer("iterations", iterations, 1, 10 ** 6)
        except ValueError as exc:
            raise MechanismError(str(exc)) from None
        for _ in range(iterations):
            F = self.constraint(q)
            if np.max(np.abs(F)) <= tol:
                break
            q -= np.linalg.lstsq(self.jacobian(q), F, rcond=None)[0]
            if not np.all(np.isfinite(q)):
                break
        F = self.constraint(q) if np.all(np.isfinite(q)) else np.array([np.inf])
        if not np.max(np.abs(F)) <= 1e3 * tol:
            raise MechanismError(f"{self.name}: cannot project q onto F = 0: Newton did not "
                                 f"converge from it (|F| = {np.max(np.abs(F)):.3e}); start "
                                 "nearer the manifold")
        self.check_rank(q)
        return q

    def project_velocity(self, q, v):
        """The M-orthogonal projection of v onto ker J(q): v' with J v' = 0 and
        ⟨v' − v, w⟩_M = 0 for every w in ker J (a KKT solve; M definite on ker J suffices)."""
        q = self._point(q)
        v = self._point(v, "v")
        K, M, J = self._kkt(q, sign=1.0)
        sol = np.linalg.solve(K, np.concatenate([M @ v, np.zeros(self.k)]))
        return sol[:self.n]

    def project_tangent(self, q, u):
        """The M-orthogonal projection of the ambient vector u onto the tangent space at q, by
        the name ``RotorSystem.project_tangent`` has: `project_velocity`."""
        return self.project_velocity(q, self._point(u, "u"))

    def project_phase_tangent(self, q, v, dq, dv):
        """The projection of a phase-space tangent vector (δq, δv) at (q, v) onto the tangent
        space of TC = {F = 0, J v = 0}: the linearised constraints J δq = 0 and
        J δv + ∂²F(v, δq) = 0, each part M-orthogonally (KKT solves).  Returns (δq', δv')."""
        q, v = self._point(q), self._point(v, "v")
        dq = self.project_velocity(q, dq)
        dv = self._point(dv, "dv")
        K, M, J = self._kkt(q, sign=1.0)
        rhs = np.concatenate([M @ dv, -np.einsum("cij,i,j->c", self._eval("F2", q), v, dq)])
        return dq, np.linalg.solve(K, rhs)[:self.n]

    def wrap_angles(self, q):
        """q with its periodic coordinates taken into (−π, π] (the others unchanged)."""
        return np.where(self._periodic_mask, np.angle(np.exp(1j * np.asarray(q))), q)

    def tangent_basis(self, q):
        """An orthonormal (Euclidean) basis of ker J(q), shape (n, d)."""
        J = self.check_rank(q)
        return np.linalg.svd(J)[2][self.k:].T

    def random_state(self, seed=0, speed=1.0, attempts=200):
        """Random (q, v) on the manifold with vᵀMv = speed²: angles uniform in (−π, π], the
        other coordinates uniform in ``bounds``, projected by Newton (retried where it fails
        or lands near a singular point); v a projected Gaussian vector."""
        try:
            speed = number("speed", speed)
            seed = integer("seed", seed, 0)
            attempts = integer("attempts", attempts, 1, 10 ** 7)
        except ValueError as exc:
            raise MechanismError(str(exc)) from None
        if not speed > 0:
            raise MechanismError(f"speed must be positive and finite, got {speed}")
        rng = np.random.default_rng(seed)
        lo = np.array([-np.pi if p else self.bounds[s.name][0] for s, p in zip(self.q, self._periodic_mask)])
        hi = np.array([np.pi if p else self.bounds[s.name][1] for s, p in zip(self.q, self._periodic_mask)])
        at_rest = 0                 # points found whose velocity had no positive energy
        for _ in range(int(attempts)):
            try:
                q = self.project_point(rng.uniform(lo, hi))
                s = np.linalg.svd(self.jacobian(q), compute_uv=False)
                if s[-1] < 1e-3 * s[0]:
                    continue
                v = self.project_velocity(q, rng.normal(size=self.n))
                e = self.inner(q, v, v)
                if e > 1e-12:
                    q = self.wrap_angles(q)
                    return q, v * (speed / np.sqrt(e))
                at_rest += 1
            except (MechanismError, np.linalg.LinAlgError):
                continue
        why = (f": {at_rest} points had a tangent velocity of kinetic energy vᵀMv <= 0 (the "
               "metric must be positive definite on ker J)") if at_rest else ""
        raise MechanismError(f"{self.name}: no random point found in {attempts} attempts{why}")

