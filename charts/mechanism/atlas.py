"""The atlas of a Mechanism, by the implicit function theorem.

A chart is a choice of d = n − k independent coordinates (their sorted indices); the other k,
the dependent ones, are solved from F = 0 (``lift``, Newton on the local branch).  The
chart's parametrisation q(s) has derivatives ∂q/∂s, ∂²q/∂s², ∂³q/∂s³ that follow by
differentiating F(q(s)) = 0 (``embedding_jets``); the chart geometry
(``charts.mechanism.geometry``) is built on them.  The switching rule (``best_chart``) picks
the chart whose dependent block of J is best conditioned.
"""
from __future__ import annotations

import itertools

import numpy as np

from ..geometry.checks import finite_array, integer, shown
from .errors import MechanismError

__all__ = ["Atlas", "chart_scores"]


def chart_scores(J, charts):
    """The smallest singular value of the dependent block of J for each chart: J shape
    (..., k, n), ``charts`` a list of index tuples; shape (..., len(charts))."""
    n = J.shape[-1]
    out = []
    for ind in charts:
        dep = [i for i in range(n) if i not in ind]
        out.append(np.linalg.svd(J[..., dep], compute_uv=False)[..., -1])
    return np.stack(out, axis=-1)


class Atlas:
    """Charts of a mechanism: choosing, lifting, differentiating.

    The host class supplies: ``n``, ``k``, ``dim``, ``q``, ``name``, ``_eval`` and the point
    methods of ``dynamics.AmbientDynamics`` (``_point``, ``constraint``, ``jacobian``,
    ``check_point``).
    """

    def _chart_index(self, chart):
        try:
            chart = tuple(integer("chart", i, 0, self.n - 1) for i in chart)
        except (TypeError, ValueError):
            raise MechanismError(f"a chart is {self.dim} distinct coordinate indices in "
                                 f"0..{self.n - 1}, got {shown(chart)}") from None
        if len(chart) != self.dim or len(set(chart)) != self.dim or not all(0 <= i < self.n for i in chart):
            raise MechanismError(f"a chart is {self.dim} distinct coordinate indices in 0..{self.n - 1}"
                                 f", got {chart}")
        return tuple(sorted(chart))

    def all_charts(self):
        """Every chart, in ``itertools.combinations`` order."""
        return list(itertools.combinations(range(self.n), self.dim))

    def charts(self, q):
        """Every chart (the sorted indices of its independent coordinates) with its score, the
        smallest singular value of the Jacobian block of the dependent coordinates: a list of
        (chart, score), best conditioned first (score 0: the chart does not exist at q)."""
        every = self.all_charts()
        scores = chart_scores(self.jacobian(q), every)
        return sorted(((c, float(s)) for c, s in zip(every, scores)), key=lambda x: -x[1])

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
        try:
            s = finite_array("s", s, shape=(len(ind),))
        except ValueError as exc:
            raise MechanismError(f"{exc}: s is the chart's coordinates "
                                 f"{self.chart_names(ind)}") from None
        q = self._point(near, "near").copy()
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
        parametrisation q(s) at q, by differentiating F(q(s)) = 0 (implicit function theorem);
        the first ``order`` (1, 2 or 3) of them."""
        try:
            order = integer("order", order, 1, 3)
        except ValueError as exc:
            raise MechanismError(str(exc)) from None
        return self._embedding_jets(self._point(q), self._chart_index(chart), order)

    def _embedding_jets(self, q, ind, order=3):
        """`embedding_jets` at q of shape (..., n) (a batch of points; no checks): each jet
        with the batch's leading axes."""
        n, k, d = self.n, self.k, self.dim
        dep = [i for i in range(n) if i not in ind]
        batch = q.shape[:-1]
        J = self._eval("J", q)
        JD = J[..., dep]
        Phi = np.zeros(batch + (n, d))
        Phi[..., list(ind), range(d)] = 1.0
        Phi[..., dep, :] = -np.linalg.solve(JD, J[..., list(ind)])
        if order == 1:
            return (Phi,)
        F2 = self._eval("F2", q)
        rhs = np.einsum("...cij,...ia,...jb->...cab", F2, Phi, Phi).reshape(batch + (k, d * d))
        Q2 = np.zeros(batch + (n, d, d))
        Q2[..., dep, :, :] = -np.linalg.solve(JD, rhs).reshape(batch + (k, d, d))
        if order == 2:
            return Phi, Q2
        t = np.einsum("...cij,...iab,...jd->...cabd", F2, Q2, Phi)
        r = (np.einsum("...cijl,...ia,...jb,...ld->...cabd", self._eval("F3", q), Phi, Phi, Phi)
             + t + np.swapaxes(t, -1, -2) + np.einsum("...cabd->...cdba", t))
        Q3 = np.zeros(batch + (n, d, d, d))
        Q3[..., dep, :, :, :] = -np.linalg.solve(JD, r.reshape(batch + (k, d ** 3))
                                                 ).reshape(batch + (k, d, d, d))
        return Phi, Q2, Q3

    def _resolve(self, q, chart, near):
        """(point, chart): q is a point of the manifold in ambient coordinates (n,), or, with
        ``chart`` and ``near`` given, the chart coordinates (d,) lifted from ``near``."""
        try:
            q = finite_array("q", q)
        except ValueError as exc:
            raise MechanismError(str(exc)) from None
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
