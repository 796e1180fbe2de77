"""The rotors' atlas (docs/architecture.md; the paper's section 1): chart k eliminates θₖ, its
domain is sin θₖ ≠ 0 and the sign of sin θₖ is its branch; the switching rule takes the largest
|aₖ sin θₖ|.  ``RotorCharts`` is the part of ``RotorSystem`` that chooses, checks and converts
charts, taking a chart as the eliminated angle k or as a Mechanism's sorted tuple of the
independent indices, and forwards a Mechanism's atlas (lift, jets, Gaussian curvature) to the
generic rotor Mechanism (``RotorSystem.mechanism``).

The host class supplies ``n``, ``dim``, ``masses``, ``weights``, ``level``, ``_gen``,
``is_paper_family``, ``check_point`` and ``mechanism``.
"""
from __future__ import annotations

import numpy as np

from .atlas import best_charts, chart_coordinates, eliminated_angle, local_masses, local_weights
from .checks import finite_array, integer, shown
from .tolerances import MAX_ITERATIONS, TOL, positive_tolerance

__all__ = ["RotorCharts"]


class RotorCharts:
    """Charts of the rotors: choosing (`best_chart`), checking a point's chart (`_chart`),
    converting (`to_chart`, `from_chart`) and a Mechanism's atlas in either chart form."""

    def best_chart(self, theta):
        """The chart with the largest |aₖ sin θₖ| (the best conditioned metric; |sin θₖ| for
        the paper's weights; ties: the lowest index) at theta (N,), an int; or at each of the
        points theta (..., N), an int array: the switching rule's argmax
        (``charts.geometry.atlas.best_sine``)."""
        theta = finite_array("theta", theta)
        if theta.ndim == 0 or theta.shape[-1] != self.n:
            raise ValueError(f"theta must have shape (..., {self.n}), got {theta.shape}")
        s = np.abs(self.weights * np.sin(theta))
        k = best_charts(np.ascontiguousarray(s.reshape(-1, self.n))).reshape(s.shape[:-1])
        return int(k) if k.ndim == 0 else k

    def _chart_index(self, chart) -> tuple:
        """``chart`` as a Mechanism's chart, the sorted tuple of its N − 1 independent indices:
        given as the eliminated angle k (every index but k) or as such a tuple (any order)."""
        if not isinstance(chart, (tuple, list, np.ndarray)):
            if isinstance(chart, bool) or not isinstance(chart, (int, np.integer)) \
                    or not 0 <= chart < self.n:
                raise self._chart_error(chart)
            return tuple(i for i in range(self.n) if i != chart)
        try:
            ind = sorted(integer("chart", i, 0, self.n - 1) for i in chart)
        except (TypeError, ValueError):
            ind = None
        if ind is None or len(ind) != self.dim or len(set(ind)) != self.dim:
            raise self._chart_error(chart)
        return tuple(ind)

    def _chart_error(self, chart) -> ValueError:
        """The refusal of ``chart``, neither form of a chart (`_chart_index`)."""
        return ValueError(f"chart must be an integer in 0..{self.n - 1} (the eliminated angle) "
                          f"or the {self.dim} other indices (a Mechanism's chart), got "
                          f"{shown(chart)}")

    def _eliminated(self, chart):
        """k, the eliminated angle, of a chart given as a Mechanism's tuple of the independent
        indices; ``chart`` itself otherwise (the callers check an int)."""
        if not isinstance(chart, (tuple, list, np.ndarray)):
            return chart
        ind = set(self._chart_index(chart))
        return next(i for i in range(self.n) if i not in ind)

    def _chart_of(self, theta, chart) -> tuple:
        """A Mechanism's chart (tuple) of ``chart`` (either form), or of `best_chart` at theta."""
        return self._chart_index(self.best_chart(theta) if chart is None else chart)

    def _ambient(self, theta, chart, near):
        """theta; or with ``near`` (a Mechanism's form) the point whose coordinates in
        ``chart`` are theta (N − 1,), on the branch of the ambient point ``near`` (lifted by
        `mechanism`)."""
        if near is None:
            return theta
        if chart is None:
            raise ValueError("near= needs chart=: the chart whose coordinates theta are")
        return self.mechanism._resolve(theta, self._chart_index(chart), near)[0]

    def _resolve(self, theta, chart, near, name="theta"):
        """(point, chart), as a Mechanism's: the checked ambient point (`_ambient`) and its
        chart (the tuple form; `best_chart` for None), theta in its domain (`_chart`)."""
        theta = self.check_point(self._ambient(theta, chart, near), name)
        return theta, self._chart_index(self._chart(theta, chart, name)[0])

    def _chart(self, theta, chart, name="theta"):
        """(k, local indices, q, local masses, local weights) of ``chart`` (the eliminated
        angle k, or a Mechanism's tuple of the independent indices) at theta (checked, on the
        manifold and in the chart's domain; ``name`` its name in messages)."""
        theta = self.check_point(theta, name)
        k = self.best_chart(theta) if chart is None else self._eliminated(chart)
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= k < self.n:
            raise self._chart_error(chart)
        if not self._in_chart(theta, k):
            best = self.best_chart(theta)
            if not self._in_chart(theta, best):
                raise ValueError(f"{name} = {theta.tolist()} is a singular point of the manifold "
                                 "(every sin theta_i = 0: the gradient of sum(a cos theta) "
                                 "vanishes); the metric and curvature are not defined there in "
                                 "any chart")
            raise ValueError(f"{name} is outside the domain of chart {k}: sin(theta_{k}) = "
                             f"{np.sin(theta[k]):.2e}; use chart={best} (the best conditioned) "
                             "or chart=None")
        idx = chart_coordinates(self.n, k)
        return (int(k), idx, theta[idx], local_masses(self.masses, k),
                local_weights(self.weights, k))

    def _in_chart(self, theta, k) -> bool:
        """Whether theta lies in the domain of chart k: |sin θₖ| ≥ the tolerance, and the
        chart's functions' divisor D = aₖ² − (Σ_{α≠k} a_α cos θ_α − c)², computed from the
        local angles as they compute it, positive (it rounds to 0 within ~1e-8 of the edge)."""
        if abs(np.sin(theta[k])) < TOL["chart_domain"]:
            return False
        idx = chart_coordinates(self.n, k)
        return eliminated_angle(theta[idx], self.dim, local_weights(self.weights, k),
                                self.level, 1.0)[2] > 0.0

    def to_chart(self, theta, u, chart):
        """Local coordinates and velocity components of (theta, u) in ``chart``."""
        k, idx, q, _, _ = self._chart(theta, chart)
        return q, finite_array("u", u, shape=(self.n,))[idx]

    def from_chart(self, q, v, chart, branch):
        """Ambient (theta, u) from local (q, v) of ``chart`` (k or a Mechanism's tuple) on sign
        branch ``branch`` = ±1."""
        chart = integer("chart", self._eliminated(chart), 0, self.n - 1)
        if isinstance(branch, bool) or np.ndim(branch) != 0 or branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1 (the sign of sin theta_{chart}), "
                             f"got {shown(branch)}")
        q = finite_array("q", q, shape=(self.dim,))
        v = finite_array("v", v, shape=(self.dim,))
        a = local_weights(self.weights, chart)
        ck, sk, D = eliminated_angle(q, self.dim, a, self.level, float(branch))
        if not D > 0.0:
            what = "|sum cos q|" if self.is_paper_family else "|sum a cos q - level|"
            C = abs(a[-1] * ck)
            raise ValueError(f"q is outside the domain of chart {chart}: {what} = {C:.6f} >= "
                             f"{a[-1]:g} (no theta_{chart} solves the constraint); use another "
                             "chart (RotorSystem.best_chart)")
        theta = np.insert(q, chart, np.arctan2(sk, ck))
        u = np.insert(v, chart, self._gen.eliminated_component(q, v, a, sk))
        return theta, u

    # -- a Mechanism's atlas, with a chart in either form --------------------------------
    def lift(self, s, chart, near, iterations=50, tol=1e-13):
        """The point with the coordinates s (N − 1,) in ``chart`` (k or a Mechanism's tuple),
        the eliminated angle solved by Newton from the ambient point ``near`` (its branch):
        `mechanism`'s ``lift``, within ``tol`` in at most ``iterations`` steps."""
        s = finite_array("s", s, shape=(self.dim,))
        chart = self._chart_index(chart)
        near = finite_array("near", near, shape=(self.n,))
        iterations = integer("iterations", iterations, 1, MAX_ITERATIONS)
        tol = positive_tolerance(tol)
        try:
            return self.mechanism.lift(s, chart, near, iterations, tol)
        except ValueError:
            raise ValueError(f"cannot lift s = {s.tolist()} in chart {chart} from near = "
                             f"{near.tolist()} to within tol = {tol:g} in iterations = "
                             f"{iterations} Newton steps (no such point on that branch?)") from None

    def embedding_jets(self, q, chart, order=3):
        """∂q/∂s, ∂²q/∂s², ∂³q/∂s³ of ``chart`` (k or a Mechanism's tuple) at q, the first
        ``order`` (1 to 3) of them: `mechanism`'s ``embedding_jets`` (the implicit function
        theorem on the symbolic jets)."""
        q, chart = self._resolve(q, chart, None, "q")
        return self.mechanism.embedding_jets(q, chart, integer("order", order, 1, 3))

    def chart_names(self, chart):
        """The names of the independent coordinates of ``chart`` (k or a Mechanism's tuple)."""
        return self.mechanism.chart_names(self._chart_index(chart))

    def gaussian_curvature(self, theta, chart=None, near=None):
        """K of the configuration surface (N = 3) at theta in ``chart`` (either form; default:
        `best_chart`), by a Mechanism's intrinsic route (`mechanism`'s
        ``gaussian_curvatures`` at the checked point); ``near`` as `metric`'s."""
        theta, chart = self._resolve(theta, chart, near)
        return float(self.mechanism.gaussian_curvatures(theta[None], chart)[0])

    def gaussian_curvatures(self, q, chart):
        """K at a batch of points q (S, 3) of the surface (unchecked), all in ``chart`` (either
        form): `mechanism`'s ``gaussian_curvatures``."""
        return self.mechanism.gaussian_curvatures(q, self._chart_index(chart))

    def _gamma(self, q, chart):
        """Γ^a_bc in ``chart`` (either form) from the symbolic jets (`mechanism`'s, unchecked)."""
        return self.mechanism._gamma(q, self._chart_index(chart))
