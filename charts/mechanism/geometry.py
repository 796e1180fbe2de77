"""The intrinsic geometry of a Mechanism in its charts: the induced metric g = Φᵀ M Φ, its
first and second derivatives from the embedding's jets (``charts.mechanism.atlas``), the
Christoffel symbols, the Riemann tensor, the Gaussian and the sectional curvature.

Riemann convention (as ``charts.RotorSystem.riemann``): R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ and the
sectional curvature K(X, Y) = R_abcd X^a Y^b X^c Y^d / (|X|²|Y|² − ⟨X,Y⟩²).  Index order of
the jets: dg[a, b, c] = ∂_c g_ab, d2g[a, b, c, e] = ∂_c∂_e g_ab, Γ[a, b, c] = Γ^a_bc.

Every tensor function here takes a leading batch of points (``...``): the public methods
evaluate one checked point, ``gaussian_curvatures`` a batch (the surface integrals).
"""
from __future__ import annotations

import numpy as np

from .errors import MechanismError

__all__ = ["ChartGeometry", "christoffel_from_jets", "riemann_from_jets"]


def christoffel_from_jets(g, dg):
    """(g⁻¹, Γ) from g (..., d, d) and dg (..., d, d, d): Γ^a_bc = g^{ad} [bc, d] with
    [bc, d] = ½(∂_b g_dc + ∂_c g_db − ∂_d g_bc)."""
    gi = np.linalg.inv(g)
    first = 0.5 * (np.einsum("...dcb->...bcd", dg) + np.einsum("...dbc->...bcd", dg) - dg)
    return gi, np.einsum("...ad,...bcd->...abc", gi, first)


def riemann_from_jets(g, dg, d2g):
    """R_abcd (..., d, d, d, d) from the metric jets (the module's convention)."""
    gi, G = christoffel_from_jets(g, dg)
    # ∂_e Γ^a_bc = ∂_e g^{ad} [bc,d] + g^{ad} ∂_e [bc,d]
    dfirst = 0.5 * (np.einsum("...dcbe->...bcde", d2g) + np.einsum("...dbce->...bcde", d2g)
                    - d2g)                                          # ∂_e [bc, d]
    first = np.einsum("...da,...abc->...bcd", g, G)
    dgi = -np.einsum("...af,...fge,...gd->...ade", gi, dg, gi)
    dG = (np.einsum("...ade,...bcd->...abce", dgi, first)
          + np.einsum("...ad,...bcde->...abce", gi, dfirst))
    # R^a_bcd = ∂_c Γ^a_db − ∂_d Γ^a_cb + Γ^a_ce Γ^e_db − Γ^a_de Γ^e_cb
    Rup = (np.einsum("...adbc->...abcd", dG) - np.einsum("...acbd->...abcd", dG)
           + np.einsum("...ace,...edb->...abcd", G, G) - np.einsum("...ade,...ecb->...abcd", G, G))
    return np.einsum("...af,...fbcd->...abcd", g, Rup)


class ChartGeometry:
    """The induced metric and its curvature in a chart.

    The host class supplies: ``dim``, ``_eval``, the atlas (``atlas.Atlas``: ``_resolve``,
    ``_chart_of``, ``_chart_index``, ``_embedding_jets``) and the point checks of
    ``dynamics.AmbientDynamics``.
    """

    def _metric_jets(self, q, chart):
        """(g, ∂g, ∂²g) of the induced metric in ``chart`` at q (..., n)."""
        Phi, Q2, Q3 = self._embedding_jets(q, chart)
        M, dM, d2M = self._eval("M", q), self._eval("dM", q), self._eval("d2M", q)
        MPhi = M @ Phi
        dMs = np.einsum("...ijl,...lc->...ijc", dM, Phi)            # ∂_c M along the chart
        g = np.swapaxes(Phi, -1, -2) @ MPhi
        A = np.einsum("...iac,...ib->...abc", Q2, MPhi)              # Q2_acᵀ M Φ_b
        dg = A + np.swapaxes(A, -3, -2) + np.einsum("...ia,...ijc,...jb->...abc", Phi, dMs, Phi)
        d2Ms = (np.einsum("...ijlm,...lc,...me->...ijce", d2M, Phi, Phi)
                + np.einsum("...ijl,...lce->...ijce", dM, Q2))
        B = (np.einsum("...iace,...ib->...abce", Q3, MPhi)
             + np.einsum("...iac,...ij,...jbe->...abce", Q2, M, Q2)
             + np.einsum("...iac,...ije,...jb->...abce", Q2, dMs, Phi)
             + np.einsum("...iae,...ijc,...jb->...abce", Q2, dMs, Phi))
        d2g = (B + np.einsum("...abce->...bace", B)
               + np.einsum("...ia,...ijce,...jb->...abce", Phi, d2Ms, Phi))
        return g, dg, d2g

    def metric(self, q, chart=None, near=None):
        """The induced metric g_ab in ``chart`` (default: best conditioned) at the point q of the
        manifold (ambient coordinates, shape (n,); or its chart coordinates, shape (d,), with
        ``chart`` and ``near``, an ambient point that picks the branch), shape (d, d)."""
        q, chart = self._resolve(q, chart, near)
        Phi = self._embedding_jets(q, chart, order=1)[0]
        return Phi.T @ self.mass_matrix(q) @ Phi

    def _gamma(self, q, chart):
        """Γ^a_bc at a point of the manifold in ``chart`` (no checks; for integrators)."""
        Phi, Q2 = self._embedding_jets(q, chart, order=2)
        M, dM = self._eval("M", q), self._eval("dM", q)
        A = np.einsum("iac,ib->abc", Q2, M @ Phi)
        dg = A + A.transpose(1, 0, 2) + np.einsum("ia,ijl,lc,jb->abc", Phi, dM, Phi, Phi)
        return christoffel_from_jets(Phi.T @ M @ Phi, dg)[1]

    def christoffel(self, q, chart=None, near=None):
        """Γ^a_bc of the induced metric in ``chart`` at q, shape (d, d, d)."""
        q, chart = self._resolve(q, chart, near)
        g, dg, _ = self._metric_jets(q, chart)
        return christoffel_from_jets(g, dg)[1]

    def riemann(self, q, chart=None, near=None):
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ of the induced metric in ``chart`` at q, shape (d,)*4."""
        q, chart = self._resolve(q, chart, near)
        return riemann_from_jets(*self._metric_jets(q, chart))

    def _require_surface(self, what):
        if self.dim != 2:
            raise MechanismError(f"{what} is for 2-dimensional configuration spaces "
                                 f"(this one has dimension {self.dim}); use sectional_curvature")

    def gaussian_curvature(self, q, chart=None, near=None):
        """K = R_0101 / det g (a 2-dimensional configuration space), by the intrinsic route."""
        self._require_surface("gaussian_curvature")
        q, chart = self._resolve(q, chart, near)
        return float(self.gaussian_curvatures(q[None], chart)[0])

    def gaussian_curvatures(self, q, chart):
        """K = R_0101 / det g at a batch of points q (S, n) of the manifold (unchecked), all in
        ``chart``; shape (S,).  Use a chart that is well conditioned at every point
        (``best_charts``)."""
        self._require_surface("gaussian_curvatures")
        g, dg, d2g = self._metric_jets(np.asarray(q, dtype=float), self._chart_index(chart))
        return riemann_from_jets(g, dg, d2g)[..., 0, 1, 0, 1] / np.linalg.det(g)

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
