"""``RotorSystem``: the constraint manifold Σ cos θᵢ = 0 with metric Σ mᵢ dθᵢ² (eqs 1-13).

Points are ambient angle vectors ``theta``, shape (n,); tangent vectors are
ambient velocity vectors ``u``, shape (n,), with Σ uᵢ sin θᵢ = 0 (eq 10).
Chart ``k`` uses the local coordinates θ without θₖ (see ``charts.geometry.atlas``);
its domain is sin θₖ ≠ 0 and the sign of sin θₖ is the chart's branch.
"""
from __future__ import annotations

import numpy as np

from .atlas import chart_coordinates, local_masses
from .checks import finite_array, integer, number
from .kernels import geometry
from .projection import project_constraint, tangent_part
from .structured import gauss_sectional

__all__ = ["RotorSystem", "TOL"]

#: Tolerances used to decide whether input lies on the manifold.  Points produced by
#: the integrators satisfy the constraint to ~1e-13; 1e-8 accepts user input rounded
#: to ~8 digits and rejects anything visibly off the manifold.
TOL = {"constraint": 1e-8, "tangency": 1e-8, "chart_domain": 1e-10}
#: Largest number of entries of an array returned by ``christoffel`` / ``riemann`` (1 GiB of
#: floats): the Riemann array of N = 64 has 63⁴ ≈ 1.6e7 entries, that of N = 256 4.2e9.
MAX_ENTRIES = 2 ** 27


def plane_area2(vv, ww, vw) -> float:
    """|v|²|w|² − ⟨v,w⟩², the squared area of the plane of a sectional curvature; ValueError
    when v, w do not span a plane (a zero vector, or parallel to ~1e-14 rad)."""
    if not (vv > 0 and ww > 0):
        raise ValueError("v and w must be nonzero tangent vectors: a zero vector spans no plane")
    area2 = vv * ww - vw ** 2
    if not area2 > 1e-28 * vv * ww:
        raise ValueError("v and w are (nearly) parallel: they do not span a 2-plane")
    return float(area2)


class RotorSystem:
    """N rotors with moments of inertia ``masses`` (default all 1, the paper's case)."""

    def __init__(self, n: int, masses=None):
        n = integer("n (the number of rotors)", n)      # 4.0 and np.int64(4) count; 3.5 no
        if n < 3:
            raise ValueError(f"n must be >= 3 (n=2 has no 1-dimensional smooth manifold), got n={n}")
        self.n = int(n)
        if masses is None:
            masses = np.ones(self.n)
        try:
            masses = np.asarray(masses, dtype=float)
        except (TypeError, ValueError):
            raise ValueError(f"masses must be {self.n} numbers, got {masses!r}") from None
        if masses.shape != (self.n,):
            raise ValueError(f"masses must have length n={self.n}, got shape {masses.shape}")
        if not np.all(np.isfinite(masses)) or np.any(masses <= 0):
            raise ValueError(f"masses must be finite and positive, got {masses.tolist()}")
        self.masses = masses
        self.minv = 1.0 / masses
        self.dim = self.n - 1
        self._gen = geometry(self.n)  # generated for the shipped N, structured otherwise

    def __repr__(self):
        return f"RotorSystem(n={self.n}, masses={self.masses.tolist()})"

    # -- validation --------------------------------------------------------------------
    def check_point(self, theta) -> np.ndarray:
        theta = finite_array("theta", theta, shape=(self.n,))
        F = np.cos(theta).sum()
        if abs(F) > TOL["constraint"]:
            raise ValueError(f"theta is off the manifold: sum(cos theta) = {F:.3e} "
                             f"(tolerance {TOL['constraint']:g}); use RotorSystem.project_point")
        return theta

    def check_tangent(self, theta, u, name="u") -> np.ndarray:
        u = finite_array(name, u, shape=(self.n,))
        G = float(u @ np.sin(theta))
        scale = max(1.0, float(np.linalg.norm(u)))
        if abs(G) > TOL["tangency"] * scale:
            raise ValueError(f"{name} is not tangent to the manifold: sum({name} sin theta) = {G:.3e} "
                             f"(tolerance {TOL['tangency']:g}); use RotorSystem.project_tangent")
        return u

    def check_state(self, theta, u):
        theta = self.check_point(theta)
        u = self.check_tangent(theta, u)
        if not np.isfinite(self.energy(u)):
            raise ValueError("u is too large: its kinetic energy overflows a float; rescale it")
        return theta, u

    # -- invariants and projections ----------------------------------------------------
    def energy(self, u):
        return 0.5 * np.sum(self.masses * np.asarray(u) ** 2, axis=-1)

    def speed(self, u):
        """|u|_g = √(Σ mᵢ uᵢ²)."""
        return np.sqrt(2.0 * self.energy(u))

    def inner(self, theta, a, b):
        """Metric inner product of ambient tangent vectors: Σ mᵢ aᵢ bᵢ."""
        a = finite_array("a", a, shape=(self.n,))
        b = finite_array("b", b, shape=(self.n,))
        return float(np.sum(self.masses * a * b))

    def project_point(self, theta, iterations=50):
        """Nearest-ish point on the manifold (Newton along M⁻¹∇F, ``projection.project_constraint``)."""
        theta = np.array(theta, dtype=float)
        if theta.shape != (self.n,) or not np.all(np.isfinite(theta)):
            raise ValueError(f"theta must be {self.n} finite angles, got {theta.tolist()}")
        if not project_constraint(theta, self.masses, integer("iterations", iterations, 1)):
            raise ValueError("cannot project: the point is a critical point of sum(cos theta)")
        return theta

    def project_tangent(self, theta, u):
        """M-orthogonal projection of an ambient vector onto the tangent space."""
        return tangent_part(finite_array("theta", theta, shape=(self.n,)),
                            finite_array("u", u, shape=(self.n,)), self.minv)

    def random_state(self, seed=0, speed=1.0):
        """Random (theta, u) on the manifold with Σ mᵢuᵢ² = speed²."""
        if not number("speed", speed) > 0:
            raise ValueError(f"speed must be positive and finite, got {speed}")
        rng = np.random.default_rng(integer("seed", seed, 0))
        while True:
            theta = rng.uniform(-np.pi, np.pi, self.n)
            k = rng.integers(self.n)
            C = np.cos(theta).sum() - np.cos(theta[k])
            if abs(C) < 0.999:
                theta[k] = np.sign(theta[k]) * np.arccos(-C)
                if abs(np.sin(theta).max()) > 0.05 or self.n > 3:
                    break
        u = self.project_tangent(theta, rng.normal(size=self.n))
        u *= speed / self.speed(u)  # not rescale_speed: its rounding would move every seeded state
        return theta, u

    # -- charts --------------------------------------------------------------------------
    def best_chart(self, theta) -> int:
        """The chart with the largest |sin θₖ| (the best conditioned metric)."""
        return int(np.argmax(np.abs(np.sin(theta))))

    def _chart(self, theta, chart):
        theta = self.check_point(theta)
        k = self.best_chart(theta) if chart is None else chart
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= k < self.n:
            raise ValueError(f"chart must be an integer in 0..{self.n - 1}, got {chart!r}")
        sk = np.sin(theta[k])
        if abs(sk) < TOL["chart_domain"]:
            best = self.best_chart(theta)
            if abs(np.sin(theta[best])) < TOL["chart_domain"]:
                raise ValueError(f"theta = {theta.tolist()} is a singular point of the manifold "
                                 "(every sin theta_i = 0: the gradient of sum(cos theta) "
                                 "vanishes); the metric and curvature are not defined there in "
                                 "any chart")
            raise ValueError(f"theta is outside the domain of chart {k}: sin(theta_{k}) = {sk:.2e}; "
                             f"use chart={best} (the best conditioned) or chart=None")
        idx = chart_coordinates(self.n, k)
        return int(k), idx, theta[idx], local_masses(self.masses, k)

    def to_chart(self, theta, u, chart):
        """Local coordinates and velocity components of (theta, u) in ``chart``."""
        k, idx, q, _ = self._chart(theta, chart)
        return q, np.asarray(u, dtype=float)[idx]

    def from_chart(self, q, v, chart, branch):
        """Ambient (theta, u) from local (q, v) of ``chart`` on sign branch ``branch`` = ±1."""
        chart = integer("chart", chart, 0, self.n - 1)
        if isinstance(branch, bool) or branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1 (the sign of sin theta_{chart}), "
                             f"got {branch!r}")
        q = finite_array("q", q, shape=(self.dim,))
        v = finite_array("v", v, shape=(self.dim,))
        C = np.cos(q).sum()
        if abs(C) >= 1.0:
            raise ValueError(f"q is outside the domain of chart {chart}: |sum cos q| = {abs(C):.6f} >= 1")
        sk = np.copysign(np.sqrt(1.0 - C * C), branch)
        theta = np.insert(q, chart, np.arctan2(sk, -C))
        u = np.insert(v, chart, self._gen.eliminated_component(q, v, sk))
        return theta, u

    def metric(self, theta, chart=None):
        """g_ab (eq 13) in ``chart`` (default: best conditioned), shape (n−1, n−1)."""
        _, _, q, m = self._chart(theta, chart)
        return self._gen.metric(q, m, np.empty((self.dim, self.dim)))

    def metric_inverse(self, theta, chart=None):
        _, _, q, m = self._chart(theta, chart)
        return self._gen.metric_inverse(q, m, np.empty((self.dim, self.dim)))

    def _array(self, name, rank):
        if self.dim ** rank > MAX_ENTRIES:
            raise ValueError(f"the {name} array of N={self.n} has {self.dim}^{rank} entries (more than "
                             f"{MAX_ENTRIES}); use the contractions (christoffel_contract, "
                             f"curvature_operator, sectional_curvature) instead")
        return np.empty((self.dim,) * rank)

    def christoffel(self, theta, chart=None):
        """Γ^a_bc (eq 15), upper index first, shape (n−1,)*3."""
        _, _, q, m = self._chart(theta, chart)
        return self._gen.christoffel(q, m, self._array("Christoffel", 3))

    def christoffel_contract(self, theta, v, w, chart=None):
        """Γ^a_bc v^b w^c (eqs 14, 16) for ambient tangent vectors v, w, without the N³ array
        (O(N) for the structured kernels); local components of ``chart``, shape (n−1,)."""
        k, idx, q, m = self._chart(theta, chart)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        return -self._gen.transport_rate(q, v[idx], w[idx], m, np.empty(self.dim))

    def riemann(self, theta, chart=None):
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩, all indices down, shape (n−1,)*4.

        Sectional curvature: K(X, Y) = R_abcd X^a Y^b X^c Y^d / (|X|²|Y|² − ⟨X,Y⟩²)."""
        _, _, q, m = self._chart(theta, chart)
        return self._gen.riemann(q, m, self._array("Riemann", 4))

    def curvature_operator(self, theta, x, y, chart=None):
        """(R(x, y) y)^a in ``chart`` for ambient tangent vectors x, y (the Jacobi operator,
        J'' + R(J, v) v = 0), shape (n−1,)."""
        k, idx, q, m = self._chart(theta, chart)
        x = self.check_tangent(theta, x, "x")
        y = self.check_tangent(theta, y, "y")
        return self._gen.curvature_operator(q, x[idx], y[idx], m, np.empty(self.dim))

    def sectional_curvature(self, theta, v, w, chart=None):
        """Exact sectional curvature of the plane spanned by ambient tangent vectors v, w at
        theta: ⟨R(x, y)y, x⟩ / (|x|²|y|² − ⟨x,y⟩²) from the curvature operator of ``chart``
        (default: best conditioned; generated or structured, see ``kernels``), O(N) when
        structured (the ambient inner product is the chart's metric)."""
        theta = self.check_point(theta)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        k, idx, q, m = self._chart(theta, chart)
        ip = lambda a, b: self.inner(theta, a, b)
        area2 = plane_area2(ip(v, v), ip(w, w), ip(v, w))
        r = self._gen.curvature_operator(q, v[idx], w[idx], m, np.empty(self.dim))
        r = np.insert(r, k, self._gen.eliminated_component(q, r, np.sin(theta[k])))
        return float(ip(v, r) / area2)

    def sectional_curvature_gauss(self, theta, v, w):
        """Sectional curvature by the Gauss equation of the hypersurface F = Σcos θ = 0 in
        (Rᴺ, diag m): K = [h(v,v)h(w,w) − h(v,w)²] / (|∇F|² (|v|²|w|² − ⟨v,w⟩²)) with
        h = Hess F = −diag(cos θ) and |∇F|² = Σ sin²θ/m.  An independent route to K."""
        theta = self.check_point(theta)
        v = self.check_tangent(theta, v, "v")
        w = self.check_tangent(theta, w, "w")
        plane_area2(self.inner(theta, v, v), self.inner(theta, w, w), self.inner(theta, v, w))
        K, _ = gauss_sectional(theta, v, w, self.masses)
        return float(K)
