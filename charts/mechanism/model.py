"""A holonomic mechanism: coordinates q (angles and lengths), constraints F(q) = 0 of any
codimension k, a kinetic metric M(q) and parameters, all given as SymPy expressions.

What is symbolic and what is numerical.  SymPy differentiates, once and cached: the
constraint Jacobian J = ∂F/∂q, the constraint derivatives ∂²F, ∂³F, the metric M and its
derivatives ∂M, ∂²M, and the ambient equations of motion (the paper's eqs (4)-(8)
generalised: λ is its Λ, from the constraint differentiated twice as in its eq (5)):

    M q̈ − Jᵀλ = −C(q, v),   C_i = Σ_jk (∂_j M_ik − ½ ∂_i M_jk) v^j v^k,
    J q̈        = −Σ_jk ∂²F/∂q_j∂q_k v^j v^k                 (F differentiated twice in time)

(`Mechanism.ambient_equations`).  Each derivative tensor is lambdified to NumPy (only its
non-zero entries, the parameters as arguments) and the rest is exact linear algebra on these
jets at a point, no finite differences:

* ``acceleration`` solves the saddle-point (KKT) system above for (q̈, λ); it needs M positive
  definite only on ker J, so massless coordinates (M singular, e.g. the free joint of the
  triple linkage with ``joint_mass=0``) are allowed;
* a chart is a choice of d = n − k independent coordinates (implicit function theorem); the
  embedding's derivatives ∂q/∂s, ∂²q/∂s², ∂³q/∂s³ follow by differentiating F(q(s)) = 0, and
  give the induced metric g = Φᵀ M Φ, its first and second derivatives, the Christoffel
  symbols and the Riemann tensor (the *intrinsic* route);
* ``gauss_equation_curvature`` is the *independent* route: the second fundamental form of the
  embedding in (Rⁿ, M) (M constant, positive semi-definite, definite on ker J) and the Gauss
  equation, with no chart.

Riemann convention (as ``charts.RotorSystem.riemann``): R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ and the
sectional curvature K(X, Y) = R_abcd X^a Y^b X^c Y^d / (|X|²|Y|² − ⟨X,Y⟩²).
"""
from __future__ import annotations

import itertools
import keyword
from functools import cached_property

import numpy as np
import sympy as sp

__all__ = ["Mechanism", "MechanismError"]

#: Relative size σ_min/σ_max of the constraint Jacobian below which a point is refused.
RANK_TOL = 1e-9


class MechanismError(ValueError):
    """An invalid mechanism or a point where it is not a smooth manifold."""


def _symbol(name, what):
    if isinstance(name, sp.Symbol):
        name = name.name
    if not isinstance(name, str) or not name.isidentifier() or keyword.iskeyword(name):
        raise MechanismError(f"{what} names must be Python identifiers (str or sympy.Symbol), "
                             f"got {name!r}")
    return sp.Symbol(name, real=True)


def _sparse_lambdify(args, array):
    """f(*args) -> np.ndarray of the shape of the SymPy ``array``, only its non-zero entries
    evaluated (one lambdified function for all of them)."""
    arr = sp.Array(array)
    shape = arr.shape
    flat = list(sp.flatten(arr.tolist())) if len(shape) else [arr]
    nz = [(i, e) for i, e in enumerate(flat) if e != 0]
    idx = np.array([i for i, _ in nz], dtype=np.intp)
    size = int(np.prod(shape)) if len(shape) else 1
    if not nz:
        return lambda *a: np.zeros(shape)
    fn = sp.lambdify(args, [e for _, e in nz], modules="numpy", cse=True)

    def f(*a):
        out = np.zeros(size)
        out[idx] = fn(*a)
        return out.reshape(shape)
    return f


class Mechanism:
    """A holonomic mechanism.

    Parameters
    ----------
    coordinates : sequence of str or sympy.Symbol
        The n ambient coordinates q.
    constraints : sequence of SymPy expressions
        F(q) = 0, k of them (1 ≤ k < n), in the coordinates and parameters.
    metric : SymPy matrix (n, n), optional
        The kinetic metric, T = ½ q̇ᵀ M(q) q̇ (constant or configuration-dependent).
    masses : sequence of n numbers or expressions, optional
        Instead of ``metric``: M = diag(masses) (masses and moments of inertia).
    parameters : dict, optional
        {name or Symbol: value} for every other symbol in the expressions.
    periodic : sequence of str, optional
        The coordinates that are angles (period 2π); default none.
    bounds : dict, optional
        {name: (lo, hi)} where ``random_state`` draws the non-periodic coordinates
        (default (−1, 1)) before projecting onto F = 0.
    name : str, optional
    """

    def __init__(self, coordinates, constraints, metric=None, *, masses=None, parameters=None,
                 periodic=(), bounds=None, name="mechanism"):
        self.name = str(name)
        if isinstance(coordinates, (str, sp.Symbol)):
            raise MechanismError("coordinates must be a sequence of names, not one name")
        self.q = tuple(_symbol(c, "coordinate") for c in coordinates)
        names = [s.name for s in self.q]
        if len(set(names)) != len(names):
            raise MechanismError(f"coordinate names must be distinct, got {names}")
        self.n = len(self.q)
        if self.n < 2:
            raise MechanismError(f"need at least 2 coordinates, got {names}")
        parameters = dict(parameters or {})
        self.params = tuple(_symbol(p, "parameter") for p in parameters)
        clash = set(names) & {p.name for p in self.params}
        if clash:
            raise MechanismError(f"{sorted(clash)} are both coordinates and parameters")
        values = []
        for p, v in parameters.items():
            try:
                v = float(v)
            except (TypeError, ValueError):
                raise MechanismError(f"parameter {p} must be a real number, got {v!r}") from None
            if not np.isfinite(v):
                raise MechanismError(f"parameter {p} must be finite, got {v}")
            values.append(v)
        self.param_values = np.array(values, dtype=float)
        # every symbol is made real: map the user's symbols (by name) onto ours
        self._names = {s.name: s for s in self.q + self.params}

        if isinstance(constraints, sp.Basic) and not isinstance(constraints, sp.MatrixBase):
            constraints = [constraints]
        F = [self._expr(c, f"constraint {i}") for i, c in enumerate(constraints)]
        self.k = len(F)
        if not 1 <= self.k < self.n:
            raise MechanismError(f"need 1 <= (number of constraints) < (number of coordinates) "
                                 f"= {self.n}, got {self.k} constraints")
        self.F = sp.Matrix(F)

        if (metric is None) == (masses is None):
            raise MechanismError("give exactly one of metric (an n x n SymPy matrix) or masses "
                                 "(n entries)")
        if masses is not None:
            masses = list(masses)
            if len(masses) != self.n:
                raise MechanismError(f"masses must have one entry per coordinate ({self.n}), "
                                     f"got {len(masses)}")
            metric = sp.diag(*[self._expr(m, f"mass {i}") for i, m in enumerate(masses)])
        else:
            metric = sp.Matrix(metric)
            if metric.shape != (self.n, self.n):
                raise MechanismError(f"metric must be {self.n} x {self.n}, got {metric.shape}")
            metric = metric.applyfunc(lambda e: self._expr(e, "metric entry"))
            if not (metric - metric.T).applyfunc(sp.expand).is_zero_matrix:
                raise MechanismError("metric must be symmetric")
        self.M = metric
        self.periodic = tuple(_symbol(p, "periodic coordinate").name for p in periodic)
        unknown = set(self.periodic) - set(names)
        if unknown:
            raise MechanismError(f"periodic names {sorted(unknown)} are not coordinates {names}")
        self._periodic_mask = np.array([s.name in self.periodic for s in self.q])
        self.bounds = {s.name: (-1.0, 1.0) for s in self.q}
        for c, b in (bounds or {}).items():
            if c not in self.bounds:
                raise MechanismError(f"bounds for {c!r}: not a coordinate of {names}")
            lo, hi = map(float, b)
            if not lo < hi:
                raise MechanismError(f"bounds for {c!r} must be (lo, hi) with lo < hi, got {b}")
            self.bounds[c] = (lo, hi)
        self.dim = self.n - self.k

    def with_parameters(self, *, name=None, bounds=None, **values):
        """A copy with other parameter values (by name) that shares this one's symbolic
        derivations and lambdified functions (the parameters are their arguments): no
        re-derivation.  ``bounds`` updates ``random_state``'s boxes."""
        import copy
        self.derive()                               # derive once, share with every copy
        out = copy.copy(self)
        out.param_values = self.param_values.copy()
        index = {p.name: i for i, p in enumerate(self.params)}
        for k, v in values.items():
            if k not in index:
                raise MechanismError(f"{k!r} is not a parameter of {self.name} "
                                     f"({sorted(index)})")
            try:
                v = float(v)
            except (TypeError, ValueError):
                raise MechanismError(f"parameter {k} must be a real number, got {v!r}") from None
            if not np.isfinite(v):
                raise MechanismError(f"parameter {k} must be finite, got {v}")
            out.param_values[index[k]] = v
        out.bounds = dict(self.bounds)
        for c, b in (bounds or {}).items():
            if c not in out.bounds:
                raise MechanismError(f"bounds for {c!r}: not a coordinate")
            lo, hi = map(float, b)
            if not lo < hi:
                raise MechanismError(f"bounds for {c!r} must be (lo, hi) with lo < hi, got {b}")
            out.bounds[c] = (lo, hi)
        if name is not None:
            out.name = str(name)
        return out

    @property
    def parameter_values(self) -> dict:
        """{name: value} of the parameters."""
        return {p.name: float(v) for p, v in zip(self.params, self.param_values)}

    def _expr(self, e, what):
        try:
            e = sp.sympify(e)
        except (sp.SympifyError, TypeError) as err:
            raise MechanismError(f"{what} is not a SymPy expression: {e!r}") from err
        subs = {}
        for s in e.free_symbols:
            if s.name not in self._names:
                raise MechanismError(
                    f"{what} = {e} contains {s.name!r}, which is neither a coordinate "
                    f"{[c.name for c in self.q]} nor a parameter {[p.name for p in self.params]}")
            subs[s] = self._names[s.name]
        e = e.xreplace(subs)
        if e.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise MechanismError(f"{what} = {e} is not finite")
        return e

    def __repr__(self):
        return (f"Mechanism({self.name!r}: q = ({', '.join(s.name for s in self.q)}), "
                f"{self.k} constraint(s), dim {self.dim})")

    # ---------------------------------------------------------------- symbolic derivations
    @cached_property
    def J(self):
        """∂F/∂q, SymPy (k, n)."""
        return self.F.jacobian(self.q)

    @cached_property
    def F2(self):
        """∂²F_a/∂q_i∂q_j, SymPy Array (k, n, n)."""
        return sp.Array([[[sp.diff(self.J[a, i], self.q[j]) for j in range(self.n)]
                          for i in range(self.n)] for a in range(self.k)])

    @cached_property
    def F3(self):
        """∂³F, SymPy Array (k, n, n, n)."""
        return sp.Array([[[[sp.diff(self.F2[a, i, j], x) for x in self.q] for j in range(self.n)]
                           for i in range(self.n)] for a in range(self.k)])

    @cached_property
    def dM(self):
        """∂_l M_ij as dM[i, j, l], SymPy Array (n, n, n)."""
        return sp.Array([[[sp.diff(self.M[i, j], x) for x in self.q] for j in range(self.n)]
                         for i in range(self.n)])

    @cached_property
    def d2M(self):
        """∂_l∂_m M_ij as d2M[i, j, l, m], SymPy Array (n, n, n, n)."""
        return sp.Array([[[[sp.diff(self.dM[i, j, l], x) for x in self.q] for l in range(self.n)]
                          for j in range(self.n)] for i in range(self.n)])

    @cached_property
    def constant_metric(self) -> bool:
        """True when M does not depend on q."""
        return all(e == 0 for e in sp.flatten(self.dM.tolist()))

    def ambient_equations(self):
        """The ambient constrained equations as SymPy: (velocity symbols v, acceleration symbols
        a, multiplier symbols λ, the n + k equations, each an expression = 0):
        M a + C(q, v) − Jᵀλ and J a + vᵀ ∂²F v (the constraint differentiated twice)."""
        v = sp.symbols(" ".join(f"v_{s.name}" for s in self.q), real=True, seq=True)
        a = sp.symbols(" ".join(f"a_{s.name}" for s in self.q), real=True, seq=True)
        lam = sp.symbols(" ".join(f"lambda{i}" for i in range(self.k)), real=True, seq=True)
        V, A, L = sp.Matrix(v), sp.Matrix(a), sp.Matrix(lam)
        C = sp.Matrix([sum((self.dM[i, kk, j] - sp.Rational(1, 2) * self.dM[j, kk, i]) * v[j] * v[kk]
                           for j in range(self.n) for kk in range(self.n)) for i in range(self.n)])
        eqs = list(self.M * A + C - self.J.T * L)
        eqs += [sum(self.F2[c, i, j] * v[i] * v[j] for i in range(self.n) for j in range(self.n))
                + (self.J[c, :] * A)[0] for c in range(self.k)]
        return v, a, lam, eqs

    # ---------------------------------------------------------------- numerical functions
    @cached_property
    def _num(self):
        """The lambdified jets (arguments: the n coordinates, then the parameters)."""
        args = self.q + self.params
        return {"F": _sparse_lambdify(args, list(self.F)),
                "J": _sparse_lambdify(args, self.J.tolist()),
                "F2": _sparse_lambdify(args, self.F2),
                "F3": _sparse_lambdify(args, self.F3),
                "M": _sparse_lambdify(args, self.M.tolist()),
                "dM": _sparse_lambdify(args, self.dM),
                "d2M": _sparse_lambdify(args, self.d2M)}

    def derive(self):
        """Derive and lambdify everything now (otherwise done on first use); returns self."""
        self._num
        return self

    def _eval(self, key, q):
        return self._num[key](*q, *self.param_values)

    def _point(self, q, name="q"):
        q = np.asarray(q, dtype=float)
        if q.shape != (self.n,) or not np.all(np.isfinite(q)):
            raise MechanismError(f"{name} must be {self.n} finite numbers "
                                 f"({', '.join(s.name for s in self.q)}), got {np.asarray(q).tolist()}")
        return q

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
        F = self.constraint(q)
        if np.max(np.abs(F)) > tol:
            raise MechanismError(f"q is off the constraint: |F| = {np.max(np.abs(F)):.3e} > {tol:g}; "
                                 "use project_point")
        self.check_rank(q)
        return q

    def _kkt(self, q, J=None):
        M = self.mass_matrix(q)
        J = self.jacobian(q) if J is None else J
        K = np.zeros((self.n + self.k,) * 2)
        K[:self.n, :self.n] = M
        K[:self.n, self.n:] = -J.T
        K[self.n:, :self.n] = J
        return K, M, J

    def multiplier_and_acceleration(self, q, v):
        """(q̈, λ) of the ambient equations (see the module docstring) at (q, v)."""
        q = self._point(q)
        v = self._point(v, "v")
        K, M, J = self._kkt(q)
        dM = self._eval("dM", q)
        C = np.einsum("ikj,j,k->i", dM, v, v) - 0.5 * np.einsum("jki,j,k->i", dM, v, v)
        rhs = np.concatenate([-C, -np.einsum("cij,i,j->c", self._eval("F2", q), v, v)])
        sol = np.linalg.solve(K, rhs)
        return sol[:self.n], sol[self.n:]

    def tangent_acceleration(self, q, v, dq, dv):
        """The linearisation of ``acceleration`` (for tangent vectors, the analogue of eq (17)):
        δq̈ at (q, v) along (δq, δv), shape (n,), from the differentiated KKT system
        K δ(q̈, λ) = δb − δK (q̈, λ) (exact, with ∂²M and ∂³F; no finite differences)."""
        q, v = self._point(q), self._point(v, "v")
        dq, dv = self._point(dq, "dq"), self._point(dv, "dv")
        K, M, J = self._kkt(q)
        dM, d2M, F2 = self._eval("dM", q), self._eval("d2M", q), self._eval("F2", q)
        C = np.einsum("ikj,j,k->i", dM, v, v) - 0.5 * np.einsum("jki,j,k->i", dM, v, v)
        b = np.concatenate([-C, -np.einsum("cij,i,j->c", F2, v, v)])
        x = np.linalg.solve(K, b)
        dJ = np.einsum("cil,l->ci", F2, dq)
        dK = np.zeros_like(K)
        dK[:self.n, :self.n] = np.einsum("ijl,l->ij", dM, dq)
        dK[:self.n, self.n:] = -dJ.T
        dK[self.n:, :self.n] = dJ
        W = dM - 0.5 * dM.transpose(2, 1, 0)            # W[i, k, j] = ∂_j M_ik − ½ ∂_i M_jk
        dC = (np.einsum("ikjl,j,k,l->i", d2M, v, v, dq)
              - 0.5 * np.einsum("jkil,j,k,l->i", d2M, v, v, dq)
              + np.einsum("ikj,j,k->i", W, dv, v) + np.einsum("ikj,j,k->i", W, v, dv))
        db = np.concatenate([-dC, -np.einsum("cijl,i,j,l->c", self._eval("F3", q), v, v, dq)
                             - 2.0 * np.einsum("cij,i,j->c", F2, v, dv)])
        return np.linalg.solve(K, db - dK @ x)[:self.n]

    def acceleration(self, q, v):
        """q̈ of the ambient constrained equations of motion at (q, v), shape (n,)."""
        return self.multiplier_and_acceleration(q, v)[0]

    def rhs(self, t, y):
        """(q̇, v̇) = (v, acceleration): the ambient flow for ``scipy.integrate.solve_ivp``."""
        return np.concatenate([y[self.n:], self.acceleration(y[:self.n], y[self.n:])])

    def inner(self, q, a, b):
        """⟨a, b⟩ = aᵀ M(q) b."""
        return float(a @ self.mass_matrix(q) @ b)

    def energy(self, q, v):
        """T = ½ vᵀ M(q) v."""
        return 0.5 * self.inner(q, v, v)

    def project_point(self, q, iterations=50, tol=1e-13):
        """A point on F = 0 near q: Newton with the minimum-norm step q ← q − J⁺F (J⁺ the
        pseudo-inverse, in coordinates: M may be singular); checks the rank at the result."""
        q = self._point(q).copy()
        for _ in range(int(iterations)):
            F = self.constraint(q)
            if np.max(np.abs(F)) <= tol:
                break
            q -= np.linalg.lstsq(self.jacobian(q), F, rcond=None)[0]
            if not np.all(np.isfinite(q)):
                break
        F = self.constraint(q) if np.all(np.isfinite(q)) else np.array([np.inf])
        if not np.max(np.abs(F)) <= 1e3 * tol:
            raise MechanismError(f"{self.name}: Newton projection did not converge "
                                 f"(|F| = {np.max(np.abs(F)):.3e})")
        self.check_rank(q)
        return q

    def project_velocity(self, q, v):
        """The M-orthogonal projection of v onto ker J(q): v' with J v' = 0 and
        ⟨v' − v, w⟩_M = 0 for every w in ker J (a KKT solve; M definite on ker J suffices)."""
        q = self._point(q)
        v = self._point(v, "v")
        K, M, J = self._kkt(q)
        K[:self.n, self.n:] = J.T
        sol = np.linalg.solve(K, np.concatenate([M @ v, np.zeros(self.k)]))
        return sol[:self.n]

    def project_phase_tangent(self, q, v, dq, dv):
        """The projection of a phase-space tangent vector (δq, δv) at (q, v) onto the tangent
        space of TC = {F = 0, J v = 0}: the linearised constraints J δq = 0 and
        J δv + ∂²F(v, δq) = 0, each part M-orthogonally (KKT solves).  Returns (δq', δv')."""
        q, v = self._point(q), self._point(v, "v")
        dq = self.project_velocity(q, dq)
        dv = self._point(dv, "dv")
        K, M, J = self._kkt(q)
        K[:self.n, self.n:] = J.T
        rhs = np.concatenate([M @ dv, -np.einsum("cij,i,j->c", self._eval("F2", q), v, dq)])
        return dq, np.linalg.solve(K, rhs)[:self.n]

    def tangent_basis(self, q):
        """An orthonormal (Euclidean) basis of ker J(q), shape (n, d)."""
        J = self.check_rank(q)
        return np.linalg.svd(J)[2][self.k:].T

    def random_state(self, seed=0, speed=1.0, attempts=200):
        """Random (q, v) on the manifold with vᵀMv = speed²: angles uniform in (−π, π], the
        other coordinates uniform in ``bounds``, projected by Newton (retried where it fails
        or lands near a singular point); v a projected Gaussian vector."""
        if not (np.isfinite(speed) and speed > 0):
            raise MechanismError(f"speed must be positive and finite, got {speed}")
        rng = np.random.default_rng(int(seed))
        lo = np.array([-np.pi if p else self.bounds[s.name][0] for s, p in zip(self.q, self._periodic_mask)])
        hi = np.array([np.pi if p else self.bounds[s.name][1] for s, p in zip(self.q, self._periodic_mask)])
        for _ in range(int(attempts)):
            try:
                q = self.project_point(rng.uniform(lo, hi))
                s = np.linalg.svd(self.jacobian(q), compute_uv=False)
                if s[-1] < 1e-3 * s[0]:
                    continue
                v = self.project_velocity(q, rng.normal(size=self.n))
                e = self.inner(q, v, v)
                if e > 1e-12:
                    q = np.where(self._periodic_mask, np.angle(np.exp(1j * q)), q)
                    return q, v * (speed / np.sqrt(e))
            except (MechanismError, np.linalg.LinAlgError):
                continue
        raise MechanismError(f"{self.name}: no random point found in {attempts} attempts")

    # ---------------------------------------------------------------- charts
    def _chart_index(self, chart):
        chart = tuple(int(i) for i in chart)
        if len(chart) != self.dim or len(set(chart)) != self.dim or not all(0 <= i < self.n for i in chart):
            raise MechanismError(f"a chart is {self.dim} distinct coordinate indices in 0..{self.n - 1}"
                                 f", got {chart}")
        return tuple(sorted(chart))

    def charts(self, q):
        """Every chart (the sorted indices of its independent coordinates) with its score, the
        smallest singular value of the Jacobian block of the dependent coordinates: a list of
        (chart, score), best conditioned first (score 0: the chart does not exist at q)."""
        J = self.jacobian(q)
        out = []
        for ind in itertools.combinations(range(self.n), self.dim):
            dep = [i for i in range(self.n) if i not in ind]
            out.append((ind, float(np.linalg.svd(J[:, dep], compute_uv=False)[-1])))
        return sorted(out, key=lambda x: -x[1])

    def best_chart(self, q):
        """The chart whose dependent block of J is best conditioned (largest smallest singular
        value; ties: the first in ``itertools.combinations`` order): the switching rule."""
        return self.charts(q)[0][0]

    def chart_names(self, chart):
        """The names of the independent coordinates of ``chart``."""
        return tuple(self.q[i].name for i in self._chart_index(chart))

    def lift(self, s, chart, near, iterations=50, tol=1e-13):
        """The point q of the manifold with q[chart] = s, the dependent coordinates solved by
        Newton from ``near`` (the implicit function theorem's local branch)."""
        ind = self._chart_index(chart)
        dep = [i for i in range(self.n) if i not in ind]
        q = self._point(near).copy()
        q[list(ind)] = s
        for _ in range(int(iterations)):
            F = self.constraint(q)
            if np.max(np.abs(F)) <= tol:
                return q
            q[dep] -= np.linalg.solve(self.jacobian(q)[:, dep], F)
        if np.max(np.abs(self.constraint(q))) > 1e3 * tol:
            raise MechanismError(f"{self.name}: cannot lift {np.asarray(s).tolist()} in chart {ind}")
        return q

    def embedding_jets(self, q, chart, order=3):
        """(Φ, Q2, Q3): ∂q/∂s (n, d), ∂²q/∂s² (n, d, d), ∂³q/∂s³ (n, d, d, d) of the chart's
        parametrisation q(s) at q, by differentiating F(q(s)) = 0 (implicit function theorem)."""
        ind = self._chart_index(chart)
        q = self._point(q)
        dep = [i for i in range(self.n) if i not in ind]
        J = self.jacobian(q)
        JD = J[:, dep]
        F2 = self._eval("F2", q)
        d = self.dim
        Phi = np.zeros((self.n, d))
        Phi[list(ind), range(d)] = 1.0
        Phi[dep] = -np.linalg.solve(JD, J[:, list(ind)])
        Q2 = np.zeros((self.n, d, d))
        Q2[dep] = -np.linalg.solve(JD, np.einsum("cij,ia,jb->cab", F2, Phi, Phi).reshape(self.k, -1)
                                   ).reshape(len(dep), d, d)
        if order == 1:
            return (Phi,)
        if order == 2:
            return Phi, Q2
        t = np.einsum("cij,iab,jd->cabd", F2, Q2, Phi)
        r = (np.einsum("cijk,ia,jb,kd->cabd", self._eval("F3", q), Phi, Phi, Phi)
             + t + t.transpose(0, 1, 3, 2) + t.transpose(0, 3, 2, 1))
        Q3 = np.zeros((self.n, d, d, d))
        Q3[dep] = -np.linalg.solve(JD, r.reshape(self.k, -1)).reshape(len(dep), d, d, d)
        return Phi, Q2, Q3

    def _metric_jets(self, q, chart):
        """(g, ∂g, ∂²g) of the induced metric in ``chart`` at q: g[a, b], dg[a, b, c] = ∂_c g_ab,
        d2g[a, b, c, e] = ∂_c∂_e g_ab."""
        Phi, Q2, Q3 = self.embedding_jets(q, chart)
        M, dM, d2M = self._eval("M", q), self._eval("dM", q), self._eval("d2M", q)
        MPhi = M @ Phi
        dMs = np.einsum("ijl,lc->ijc", dM, Phi)                      # ∂_c M along the chart
        g = Phi.T @ MPhi
        A = np.einsum("iac,ib->abc", Q2, MPhi)                       # Q2_acᵀ M Φ_b
        dg = A + A.transpose(1, 0, 2) + np.einsum("ia,ijc,jb->abc", Phi, dMs, Phi)
        d2Ms = (np.einsum("ijlm,lc,me->ijce", d2M, Phi, Phi) + np.einsum("ijl,lce->ijce", dM, Q2))
        B = (np.einsum("iace,ib->abce", Q3, MPhi) + np.einsum("iac,ij,jbe->abce", Q2, M, Q2)
             + np.einsum("iac,ije,jb->abce", Q2, dMs, Phi) + np.einsum("iae,ijc,jb->abce", Q2, dMs, Phi))
        d2g = B + B.transpose(1, 0, 2, 3) + np.einsum("ia,ijce,jb->abce", Phi, d2Ms, Phi)
        return g, dg, d2g

    def _resolve(self, q, chart, near):
        """(point, chart): q is a point of the manifold in ambient coordinates (n,), or, with
        ``chart`` and ``near`` given, the chart coordinates (d,) lifted from ``near``."""
        q = np.asarray(q, dtype=float)
        if q.shape == (self.dim,) and self.dim != self.n:
            if chart is None or near is None:
                raise MechanismError(f"q has {self.dim} entries: chart coordinates need chart= and "
                                     f"near= (an ambient point for the branch); or give all {self.n}")
            q = self.lift(q, chart, near)
        elif near is not None:
            raise MechanismError("near= is for chart coordinates q (d entries) only")
        q = self.check_point(q)
        return q, self._chart_of(q, chart)

    def _chart_of(self, q, chart):
        return self.best_chart(q) if chart is None else self._chart_index(chart)

    def metric(self, q, chart=None, near=None):
        """The induced metric g_ab in ``chart`` (default: best conditioned) at the point q of the
        manifold (ambient coordinates, shape (n,); or its chart coordinates, shape (d,), with
        ``chart`` and ``near``, an ambient point that picks the branch), shape (d, d)."""
        q, chart = self._resolve(q, chart, near)
        Phi = self.embedding_jets(q, chart)[0]
        return Phi.T @ self.mass_matrix(q) @ Phi

    def _christoffel(self, g, dg):
        gi = np.linalg.inv(g)
        # [bc, d] = ½(∂_b g_dc + ∂_c g_db − ∂_d g_bc), dg[a, b, c] = ∂_c g_ab
        first = 0.5 * (np.einsum("dcb->bcd", dg) + np.einsum("dbc->bcd", dg) - dg)
        return gi, np.einsum("ad,bcd->abc", gi, first)

    def _gamma(self, q, chart):
        """Γ^a_bc at a point of the manifold in ``chart`` (no checks; for integrators)."""
        Phi, Q2 = self.embedding_jets(q, chart, order=2)
        M, dM = self._eval("M", q), self._eval("dM", q)
        A = np.einsum("iac,ib->abc", Q2, M @ Phi)
        dg = A + A.transpose(1, 0, 2) + np.einsum("ia,ijl,lc,jb->abc", Phi, dM, Phi, Phi)
        return self._christoffel(Phi.T @ M @ Phi, dg)[1]

    def christoffel(self, q, chart=None, near=None):
        """Γ^a_bc of the induced metric in ``chart`` at q, shape (d, d, d)."""
        q, chart = self._resolve(q, chart, near)
        g, dg, _ = self._metric_jets(q, chart)
        return self._christoffel(g, dg)[1]

    def riemann(self, q, chart=None, near=None):
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ of the induced metric in ``chart`` at q, shape (d,)*4."""
        q, chart = self._resolve(q, chart, near)
        g, dg, d2g = self._metric_jets(q, chart)
        gi, G = self._christoffel(g, dg)
        # ∂_e Γ^a_bc = ∂_e g^{ad} [bc,d] + g^{ad} ∂_e [bc,d]
        dfirst = 0.5 * (np.einsum("dcbe->bcde", d2g) + np.einsum("dbce->bcde", d2g)
                        - np.einsum("bcde->bcde", d2g))               # ∂_e [bc, d]
        first = np.einsum("da,abc->bcd", g, G)
        dgi = -np.einsum("af,fge,gd->ade", gi, dg, gi)
        dG = np.einsum("ade,bcd->abce", dgi, first) + np.einsum("ad,bcde->abce", gi, dfirst)
        # R^a_bcd = ∂_c Γ^a_db − ∂_d Γ^a_cb + Γ^a_ce Γ^e_db − Γ^a_de Γ^e_cb
        Rup = (np.einsum("adbc->abcd", dG) - np.einsum("acbd->abcd", dG)
               + np.einsum("ace,edb->abcd", G, G) - np.einsum("ade,ecb->abcd", G, G))
        return np.einsum("af,fbcd->abcd", g, Rup)

    def gaussian_curvature(self, q, chart=None, near=None):
        """K = R_0101 / det g (a 2-dimensional configuration space), by the intrinsic route."""
        if self.dim != 2:
            raise MechanismError(f"gaussian_curvature is for 2-dimensional configuration spaces "
                                 f"(this one has dimension {self.dim}); use sectional_curvature")
        q, chart = self._resolve(q, chart, near)
        return float(self.riemann(q, chart)[0, 1, 0, 1] / np.linalg.det(self.metric(q, chart)))

    def check_tangent(self, q, u, name="u", tol=1e-8):
        u = self._point(u, name)
        r = self.jacobian(q) @ u
        if np.max(np.abs(r)) > tol * max(1.0, np.max(np.abs(u))):
            raise MechanismError(f"{name} is not tangent: |J {name}| = {np.max(np.abs(r)):.3e}; "
                                 "use project_velocity")
        return u

    def _area2(self, q, u, w):
        M = self.mass_matrix(q)
        a2 = (u @ M @ u) * (w @ M @ w) - (u @ M @ w) ** 2
        if not a2 > 1e-14 * (u @ M @ u) * (w @ M @ w):
            raise MechanismError("u and w do not span a plane")
        return a2

    def sectional_curvature(self, q, u, w, chart=None):
        """K of the plane of the ambient tangent vectors u, w at q, by the intrinsic route
        (Riemann tensor of the induced metric in ``chart``)."""
        q = self.check_point(q)
        u, w = self.check_tangent(q, u, "u"), self.check_tangent(q, w, "w")
        chart = self._chart_of(q, chart)
        x, y = u[list(chart)], w[list(chart)]
        R = self.riemann(q, chart)
        return float(np.einsum("abcd,a,b,c,d->", R, x, y, x, y) / self._area2(q, u, w))

    def second_fundamental_form(self, q, u, w):
        """h(u, w) of the embedding of the manifold in (Rⁿ, M), M constant: the normal part of
        L z, where M = LᵀL and z is any solution of J z = −∂²F(u, w) (a second-order lift);
        a vector of Rⁿ (the image space of L), no chart involved."""
        if not self.constant_metric:
            raise NotImplementedError("the Gauss-equation route is implemented for a constant "
                                      "metric (flat ambient space) only")
        M = self.mass_matrix(q)
        lam, V = np.linalg.eigh(M)
        if lam[0] < -1e-12 * max(1.0, lam[-1]):
            raise MechanismError("the metric is not positive semi-definite")
        L = np.sqrt(np.clip(lam, 0.0, None))[:, None] * V.T
        J = self.jacobian(q)
        z = np.linalg.lstsq(J, -np.einsum("cij,i,j->c", self._eval("F2", q), u, w), rcond=None)[0]
        T = L @ self.tangent_basis(q)                                # the tangent space in R^n
        Qt = np.linalg.qr(T)[0]
        Lz = L @ z
        return Lz - Qt @ (Qt.T @ Lz)

    def gauss_equation_curvature(self, q, u, w):
        """K of the plane of the tangent vectors u, w at q by the Gauss equation of the
        embedding in the flat (Rⁿ, M): [⟨h(u,u), h(w,w)⟩ − |h(u,w)|²] / (|u|²|w|² − ⟨u,w⟩²).
        The independent route (second fundamental form; no chart, no Christoffel symbols)."""
        q = self.check_point(q)
        u, w = self.check_tangent(q, u, "u"), self.check_tangent(q, w, "w")
        huu = self.second_fundamental_form(q, u, u)
        hww = self.second_fundamental_form(q, w, w)
        huw = self.second_fundamental_form(q, u, w)
        return float((huu @ hww - huw @ huw) / self._area2(q, u, w))
