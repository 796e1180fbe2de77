"""``RotorSystem``: the constraint manifold Σ aᵢ cos θᵢ = c with metric Σ mᵢ dθᵢ² (eqs 1-13;
the paper's case is weights aᵢ = 1 and level c = 0).

The level set of F = Σ aᵢ cos θᵢ is empty for |c| > Σ|aᵢ| and singular exactly at the critical
values Σ ±aᵢ (a point with every sin θᵢ = 0 lies on it: a cone point when it is not an
extremum).  Policy (docs/families.md): an empty level set is a ValueError; a critical level
of any other manifold raises a ``CriticalLevelWarning`` naming the sign pattern; the paper's
manifold (equal weights, c = 0), however it is written (the defaults, ``weights=[1, 1, 1, 1]``
or ``[2, 2, 2, 2]``: the same level set), stays silent even where it is critical (N = 4, the
cone points every N = 4 run meets).

Points are ambient angle vectors ``theta``, shape (n,); tangent vectors are
ambient velocity vectors ``u``, shape (n,), with Σ aᵢ uᵢ sin θᵢ = 0 (eq 10).
Chart ``k`` uses the local coordinates θ without θₖ (see ``charts.geometry.atlas``);
its domain is sin θₖ ≠ 0, i.e. |Σ_{α≠k} a_α cos θ_α − c| < aₖ, and the sign of sin θₖ is the
chart's branch.

A RotorSystem is a ``charts.Mechanism`` (``isinstance`` holds: ``charts.mechanism.model``
registers it; docs/mechanisms.md) on the ambient coordinates q = θ.  Its own methods are the
rotors' structured O(N) routes; they also take a Mechanism's forms of their arguments (a chart
as the sorted tuple of its independent indices, ``tol=``, ``near=``, ``energy(q, v)``).  Every
other method of a Mechanism (the ambient KKT equations and their linearisation, the
projections of velocities and phase tangent vectors, the atlas's lift and jets, the Gauss
equation, the compiled tangent flow) is that of `RotorSystem.mechanism`: the generic rotor
Mechanism of the same masses, weights and level (``charts.mechanism.instances.rotors``, whose
symbolic model is derived on first use, once per N and process).  The mechanism layer sits
above this one, so that the rotors do not import SymPy: it is reached by name, on first use.
"""
from __future__ import annotations

import warnings
from importlib import import_module

import numpy as np

from .checks import finite_array, integer, number, shown
from .kernels import geometry
from .projection import project_constraint, tangent_part
from .rotor_charts import RotorCharts
from .structured import gauss_sectional
from .tolerances import MAX_ITERATIONS, TOL, positive_tolerance
from .topology import CRITICAL_RTOL, check_weights, critical_points

__all__ = ["RotorSystem", "TOL", "CriticalLevelWarning", "critical_levels"]

#: Most rotors a system may have (its arrays are O(N); the analyses plan their own memory).
MAX_N = 1 << 20
#: Largest number of entries of an array returned by ``christoffel`` / ``riemann`` (1 GiB of
#: floats): the Riemann array of N = 64 has 63⁴ ≈ 1.6e7 entries, that of N = 256 4.2e9.
MAX_ENTRIES = 2 ** 27


def _label(what, name) -> str:
    """``name``, an argument's name for messages, if it is a non-empty str (TypeError naming
    ``what`` otherwise)."""
    if not isinstance(name, str) or not name:
        raise TypeError(f"{what} must be a non-empty str (an argument's name in messages), "
                        f"got {shown(name)}")
    return name


class CriticalLevelWarning(UserWarning):
    """The level is a critical value of F = Σ aᵢ cos θᵢ: the manifold has singular points."""


#: Largest N whose 2ᴺ sign patterns are checked for criticality (2²⁰ ≈ 10⁶ sums).
CRITICAL_MAX_N = 20


def critical_levels(weights) -> np.ndarray:
    """The critical values Σ ±aᵢ of F = Σ aᵢ cos θᵢ (at θᵢ ∈ {0, π}), sorted, unique."""
    return np.unique(critical_points(weights)[0])


def _check_family(n, weights, level):
    """Validated (weights, level); ValueError for bad or empty, warning for a critical level
    of any manifold but the paper's."""
    a = np.ones(n) if weights is None else check_weights(weights, n)
    level = number("level", level)
    total = float(a.sum())
    if abs(level) >= total * (1.0 - CRITICAL_RTOL):
        kind = "empty" if abs(level) > total * (1.0 + CRITICAL_RTOL) else "a single point"
        raise ValueError(f"level={level!r} leaves no manifold: the level set of sum(a cos theta) "
                         f"is {kind} for |level| >= sum(weights) = {total!r}")
    papers = level == 0.0 and bool(np.all(a == a[0]))   # Σ a cos θ = 0, a equal: Σ cos θ = 0
    if not papers and n <= CRITICAL_MAX_N:
        crit = critical_levels(a)
        hit = crit[np.abs(crit - level) <= CRITICAL_RTOL * total]
        if hit.size:
            warnings.warn(f"level={level!r} is the critical value {float(hit[0])!r} = sum(+-weights) "
                          f"of sum(a cos theta): the manifold has singular (cone) points where every "
                          f"sin theta = 0; runs may stop there (SingularPointError)",
                          CriticalLevelWarning, stacklevel=3)
    return a, level


def plane_area2(vv, ww, vw) -> float:
    """|v|²|w|² − ⟨v,w⟩², the squared area of the plane of a sectional curvature; ValueError
    when v, w do not span a plane (a zero vector, or parallel to ~1e-14 rad)."""
    if not (vv > 0 and ww > 0):
        raise ValueError("v and w must be nonzero tangent vectors: a zero vector spans no plane")
    area2 = vv * ww - vw ** 2
    if not area2 > 1e-28 * vv * ww:
        raise ValueError("v and w are (nearly) parallel: they do not span a 2-plane")
    return float(area2)


class RotorSystem(RotorCharts):
    """N rotors with moments of inertia ``masses`` (default all 1, the paper's case) on the
    constraint Σ ``weights``ᵢ cos θᵢ = ``level`` (default weights all 1, level 0: eq 9).

    A ``charts.Mechanism`` with one constraint (module docstring): the methods written here
    are the rotors' structured ones, the others a Mechanism's, through `mechanism`."""

    #: A Mechanism's k, its number of constraints: Σ aᵢ cos θᵢ = c.
    k = 1
    #: The instance's own fields, all that a pickle carries (`mechanism` is rebuilt on use).
    _FIELDS = ("n", "masses", "minv", "weights", "level", "dim", "_gen")

    def __init__(self, n: int, masses=None, weights=None, level=0.0):
        n = integer("n (the number of rotors)", n)      # 4.0 and np.int64(4) count; 3.5 no
        if n < 3:
            raise ValueError(f"n must be >= 3 (n=2 has no 1-dimensional smooth manifold), got n={n}")
        if n > MAX_N:
            raise ValueError(f"n must be at most {MAX_N} rotors, got n={n}")
        self.n = int(n)
        masses = np.ones(self.n) if masses is None else finite_array("masses", masses,
                                                                       shape=(self.n,))
        if np.any(masses <= 0):
            raise ValueError(f"masses must be positive, got {masses.tolist()}")
        self.masses = masses
        self.minv = 1.0 / masses
        self.weights, self.level = _check_family(self.n, weights, level)
        self.dim = self.n - 1
        # generated for the shipped N (the paper's module for a = 1, c = 0), structured otherwise
        self._gen = geometry(self.n, self.weights, self.level)

    @property
    def is_paper_family(self) -> bool:
        """True for the paper's constraint Σ cos θ = 0 (all weights 1, level 0)."""
        return bool(np.all(self.weights == 1.0) and self.level == 0.0)

    def __repr__(self):
        if self.is_paper_family:
            return f"RotorSystem(n={self.n}, masses={self.masses.tolist()})"
        return (f"RotorSystem(n={self.n}, masses={self.masses.tolist()}, "
                f"weights={self.weights.tolist()}, level={self.level!r})")

    # -- the Mechanism -------------------------------------------------------------------
    @property
    def name(self) -> str:
        """The Mechanism's name: ``RotorSystem(n=N)``."""
        return f"RotorSystem(n={self.n})"

    @property
    def mechanism(self):
        """The generic rotor ``charts.Mechanism`` of these masses, weights and level
        (``charts.mechanism.instances.rotors(n, masses, weights, level)``), made on first use
        and kept: the home of every Mechanism method this class does not write itself (module
        docstring).  Its symbolic model is shared by every system of this N; nothing is
        derived before a method needs it."""
        twin = self.__dict__.get("_mechanism")
        if twin is None:
            # the mechanism layer is above this one: by name, on first use
            rotors = import_module("charts.mechanism.instances").rotors
            twin = self.__dict__["_mechanism"] = rotors(self.n, self.masses, self.weights,
                                                        self.level)
        return twin

    def __getattr__(self, name):
        """A Mechanism's attribute that this class does not define: `mechanism`'s."""
        if name.startswith("__") or "n" not in self.__dict__:    # (copy and pickle look up
            raise AttributeError(name)                            #  dunders before __dict__)
        twin = self.mechanism
        if not hasattr(twin, name):
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        return getattr(twin, name)

    def __getstate__(self):
        """The fields of `_FIELDS` (`mechanism` holds compiled functions: made anew on use)."""
        return {k: self.__dict__[k] for k in self._FIELDS}

    # -- validation --------------------------------------------------------------------
    def describe(self) -> dict:
        """The system as the settings of a result (``params``): N, masses, weights, level."""
        return dict(n=self.n, masses=self.masses.tolist(), weights=self.weights.tolist(),
                    level=float(self.level))

    @property
    def constraint_scale(self) -> float:
        """The size of the constraint's terms, max(maxᵢ |aᵢ|, |level|): the tolerances of
        `check_point` and `check_tangent` are relative to it (1 for the paper's weights), so
        that weights of 1e-10 or 1e9 are checked as strictly as weights of 1."""
        return max(float(np.max(np.abs(self.weights))), abs(self.level))

    def check_point(self, theta, name="theta", *, tol=None) -> np.ndarray:
        """theta (N,) as a float array after checking it is on the manifold:
        |Σ aᵢ cos θᵢ − level| within ``TOL['constraint']`` × `constraint_scale`; ValueError
        naming ``name`` (the caller's name of the argument) otherwise.  With ``tol`` (a
        Mechanism's form, ``check_point(q, tol=...)``): within ``tol`` itself, and theta not a
        singular point (every aᵢ sin θᵢ = 0: the Jacobian has rank 0), as a Mechanism's."""
        theta = finite_array(_label("name", name), theta, shape=(self.n,))
        F = float(self.weights @ np.cos(theta)) - self.level
        given = tol is not None
        tol = positive_tolerance(tol) if given else TOL["constraint"] * self.constraint_scale
        if abs(F) > tol:
            what = "sum(cos theta)" if self.is_paper_family else "sum(a cos theta) - level"
            raise ValueError(f"{name} is off the manifold: {what} = {F:.3e} "
                             f"(tolerance {'tol=' * given}{tol:g}); use RotorSystem.project_point")
        if given and not np.any(self.weights * np.sin(theta)):
            raise ValueError(f"{name} = {theta.tolist()} is a singular point of the manifold "
                             "(every sin theta_i = 0: the constraint's Jacobian vanishes)")
        return theta

    def check_tangent(self, theta, u, name="u", *, tol=None) -> np.ndarray:
        """u (N,) as a float array after checking it is tangent at theta:
        |Σ uᵢ aᵢ sin θᵢ| within ``TOL['tangency']`` × `constraint_scale` × max(1, |u|).  With
        ``tol`` (a Mechanism's form): within ``tol`` × max(1, maxᵢ |uᵢ|), as a Mechanism's."""
        name = _label("name", name)
        theta = finite_array("theta", theta, shape=(self.n,))
        u = finite_array(name, u, shape=(self.n,))
        G = float(u @ (self.weights * np.sin(theta)))
        given = tol is not None
        if given:
            tol = positive_tolerance(tol) * max(1.0, float(np.max(np.abs(u))))
        else:
            tol = TOL["tangency"] * self.constraint_scale * max(1.0, float(np.linalg.norm(u)))
        if abs(G) > tol:
            what = f"sum({name} sin theta)" if self.is_paper_family else f"sum({name} a sin theta)"
            raise ValueError(f"{name} is not tangent to the manifold: {what} = {G:.3e} "
                             f"(tolerance {'from tol ' * given}{tol:g}); use "
                             "RotorSystem.project_tangent")
        return u

    def check_state(self, theta, u, names=("theta", "u")):
        """(theta, u) as float arrays after checking them: theta on the manifold, u tangent
        there, finite energy; ValueError naming the bad one (by ``names``, the caller's
        names of the two arguments, e.g. ("theta0", "u0"))."""
        if not (isinstance(names, tuple) and len(names) == 2):
            raise TypeError(f"names must be a pair of str, got {shown(names)}")
        theta = self.check_point(theta, _label("names", names[0]))
        u = self.check_tangent(theta, u, _label("names", names[1]))
        with np.errstate(over="ignore"):
            E = 0.5 * np.sum(self.masses * u ** 2)
        if not np.isfinite(E):
            raise ValueError(f"{names[1]} is too large: its kinetic energy overflows a float; "
                             "rescale it")
        return theta, u

    # -- invariants and projections ----------------------------------------------------
    def energy(self, u, v=None):
        """Kinetic energy ½ Σ mᵢuᵢ² of the velocities u (..., N); ValueError naming u
        unless u is finite with last axis N and its energy is within a float's range.
        ``energy(q, v)``, a Mechanism's form: T = ½ Σ mᵢvᵢ² of the velocity v (N,) at the point
        q (N,) (the metric is constant: q is only checked), a float."""
        if v is not None:
            finite_array("q", u, shape=(self.n,))
            return float(self.energy(finite_array("v", v, shape=(self.n,))))
        u = finite_array("u", u)
        if u.ndim == 0 or u.shape[-1] != self.n:
            raise ValueError(f"u must have shape (..., {self.n}), got {u.shape}")
        with np.errstate(over="ignore"):
            E = 0.5 * np.sum(self.masses * u ** 2, axis=-1)
        if not np.all(np.isfinite(E)):
            raise ValueError("u is too large: its kinetic energy is beyond a float's range")
        return E

    def speed(self, u):
        """|u|_g = √(Σ mᵢ uᵢ²)."""
        return np.sqrt(2.0 * self.energy(u))

    def inner(self, theta, a, b):
        """Metric inner product of ambient tangent vectors at theta: Σ mᵢ aᵢ bᵢ (the
        metric is constant: theta may be None, else it is checked, finite of shape (N,))."""
        if theta is not None:
            finite_array("theta", theta, shape=(self.n,))
        a = finite_array("a", a, shape=(self.n,))
        b = finite_array("b", b, shape=(self.n,))
        return float(np.sum(self.masses * a * b))

    def project_point(self, theta, iterations=50):
        """Nearest-ish point on the manifold (Newton along M⁻¹∇F, ``projection.project_constraint``)."""
        theta = finite_array("theta", theta, shape=(self.n,)).copy()
        if not project_constraint(theta, self.masses, self.weights, self.level,
                                  integer("iterations", iterations, 1, MAX_ITERATIONS)):
            raise ValueError("cannot project: the point is a critical point of sum(a cos theta)")
        return theta

    def project_tangent(self, theta, u):
        """M-orthogonal projection of an ambient vector onto the tangent space."""
        return tangent_part(finite_array("theta", theta, shape=(self.n,)),
                            finite_array("u", u, shape=(self.n,)), self.minv, self.weights)

    def random_state(self, seed=0, speed=1.0):
        """Random (theta, u) on the manifold with Σ mᵢuᵢ² = speed²."""
        if not number("speed", speed) > 0:
            raise ValueError(f"speed must be positive and finite, got {speed}")
        rng = np.random.default_rng(integer("seed", seed, 0))
        a, c = self.weights, self.level
        for _ in range(100000):
            theta = rng.uniform(-np.pi, np.pi, self.n)
            k = rng.integers(self.n)
            if self.is_paper_family:  # the historical draw, kept for seeded states
                C = np.cos(theta).sum() - np.cos(theta[k])
            else:  # cos θₖ = (c − Σ_{i≠k} aᵢ cos θᵢ) / aₖ, written as −C
                C = (a @ np.cos(theta) - a[k] * np.cos(theta[k]) - c) / a[k]
            if abs(C) < 0.999:
                theta[k] = np.sign(theta[k]) * np.arccos(-C)
                if abs(np.sin(theta).max()) > 0.05 or self.n > 3:
                    break
        else:
            raise ValueError(f"no random point found on {self!r} (the level set is too small)")
        u = self.project_tangent(theta, rng.normal(size=self.n))
        u *= speed / self.speed(u)  # not rescale_speed: its rounding would move every seeded state
        return theta, u

    def metric(self, theta, chart=None, near=None):
        """g_ab (eq 13) in ``chart`` (default: best conditioned), shape (n−1, n−1).  ``chart``:
        the eliminated angle k or a Mechanism's tuple of the independent indices; with
        ``near``, theta may be the chart's coordinates (a Mechanism's form, `_ambient`)."""
        _, _, q, m, a = self._chart(self._ambient(theta, chart, near), chart)
        return self._gen.metric(q, m, a, self.level, np.empty((self.dim, self.dim)))

    def metric_inverse(self, theta, chart=None, near=None):
        """The inverse metric g^{ij}, (N − 1, N − 1), of chart ``chart`` (default: the best
        chart at theta) at the point theta (eq 12); ``chart`` and ``near`` as `metric`'s."""
        _, _, q, m, a = self._chart(self._ambient(theta, chart, near), chart)
        return self._gen.metric_inverse(q, m, a, self.level, np.empty((self.dim, self.dim)))

    def _array(self, name, rank):
        if self.dim ** rank > MAX_ENTRIES:
            raise ValueError(f"the {name} array of N={self.n} has {self.dim}^{rank} entries (more than "
                             f"{MAX_ENTRIES}); use the contractions (christoffel_contract, "
                             f"curvature_operator, sectional_curvature) instead")
        return np.empty((self.dim,) * rank)

    def christoffel(self, theta, chart=None, near=None):
        """Γ^a_bc (eq 15), upper index first, shape (n−1,)*3; ``chart`` and ``near`` as
        `metric`'s."""
        _, _, q, m, a = self._chart(self._ambient(theta, chart, near), chart)
        return self._gen.christoffel(q, m, a, self.level, self._array("Christoffel", 3))

    def christoffel_contract(self, theta, v, w, chart=None):
        """Γ^a_bc v^b w^c (eqs 14, 16) for ambient tangent vectors v, w, without the N³ array
        (O(N) for the structured kernels); local components of ``chart``, shape (n−1,)."""
        k, idx, q, m, a = self._chart(theta, chart)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        return -self._gen.transport_rate(q, v[idx], w[idx], m, a, self.level, np.empty(self.dim))

    def riemann(self, theta, chart=None, near=None):
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩, all indices down, shape (n−1,)*4; ``chart`` and
        ``near`` as `metric`'s.

        Sectional curvature: K(X, Y) = R_abcd X^a Y^b X^c Y^d / (|X|²|Y|² − ⟨X,Y⟩²)."""
        _, _, q, m, a = self._chart(self._ambient(theta, chart, near), chart)
        return self._gen.riemann(q, m, a, self.level, self._array("Riemann", 4))

    def curvature_operator(self, theta, x, y, chart=None):
        """(R(x, y) y)^a in ``chart`` for ambient tangent vectors x, y (the Jacobi operator,
        J'' + R(J, v) v = 0), shape (n−1,)."""
        k, idx, q, m, a = self._chart(theta, chart)
        x = self.check_tangent(theta, x, "x")
        y = self.check_tangent(theta, y, "y")
        return self._gen.curvature_operator(q, x[idx], y[idx], m, a, self.level, np.empty(self.dim))

    def sectional_curvature(self, theta, v, w, chart=None):
        """Exact sectional curvature of the plane spanned by ambient tangent vectors v, w at
        theta: ⟨R(x, y)y, x⟩ / (|x|²|y|² − ⟨x,y⟩²) from the curvature operator of ``chart``
        (default: best conditioned; generated or structured, see ``kernels``), O(N) when
        structured (the ambient inner product is the chart's metric)."""
        theta = self.check_point(theta)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        k, idx, q, m, a = self._chart(theta, chart)
        ip = lambda x, y: self.inner(theta, x, y)
        area2 = plane_area2(ip(v, v), ip(w, w), ip(v, w))
        r = self._gen.curvature_operator(q, v[idx], w[idx], m, a, self.level, np.empty(self.dim))
        r = np.insert(r, k, self._gen.eliminated_component(q, r, a, np.sin(theta[k])))
        return float(ip(v, r) / area2)

    def sectional_curvature_gauss(self, theta, v, w):
        """Sectional curvature by the Gauss equation of the hypersurface F = Σ a cos θ = c in
        (Rᴺ, diag m): K = [h(v,v)h(w,w) − h(v,w)²] / (|∇F|² (|v|²|w|² − ⟨v,w⟩²)) with
        h = Hess F = −diag(a cos θ) and |∇F|² = Σ a² sin²θ/m.  An independent route to K."""
        theta = self.check_point(theta)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        plane_area2(self.inner(theta, v, v), self.inner(theta, w, w), self.inner(theta, v, w))
        K, _ = gauss_sectional(theta, v, w, self.masses, self.weights)
        return float(K)
