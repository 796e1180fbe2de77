"""The extrinsic route to a Mechanism's curvature: the second fundamental form of the
configuration manifold C = {F = 0} embedded in the flat space (Rⁿ, M), M constant, and the
Gauss equation, with no chart and no Christoffel symbols: the independent check of
``charts.mechanism.geometry``.

M is positive semi-definite and definite on ker J (a massless joint is allowed); the
embedding is then isometric through L with M = LᵀL (its eigen-decomposition), into Rⁿ with the
Euclidean product.  For tangent vectors u, w, any z with J z = −∂²F(u, w) is a second-order
lift, and h(u, w) is the part of L z normal to L(ker J).  The Gauss equation:

    K(u, w) = [⟨h(u,u), h(w,w)⟩ − |h(u,w)|²] / (|u|²|w|² − ⟨u,w⟩²).
"""
from __future__ import annotations

import numpy as np

from .errors import MechanismError

__all__ = ["EmbeddingGeometry"]


class EmbeddingGeometry:
    """Second fundamental form and Gauss-equation curvature (constant metric only).

    The host class supplies: ``k``, ``dim``, ``constant_metric``, ``_eval`` and the point
    methods of ``dynamics.AmbientDynamics``.
    """

    def _isometry(self, q):
        """L with M(q) = LᵀL, batched like q; refuses a metric that is not constant or not
        positive semi-definite."""
        if not self.constant_metric:
            raise NotImplementedError("the Gauss-equation route is implemented for a constant "
                                      "metric (flat ambient space) only")
        lam, V = np.linalg.eigh(self._eval("M", q))
        if np.any(lam[..., 0] < -1e-12 * np.maximum(1.0, lam[..., -1])):
            raise MechanismError("the metric is not positive semi-definite")
        return np.sqrt(np.clip(lam, 0.0, None))[..., :, None] * np.swapaxes(V, -1, -2)

    def _normal_part(self, q, L, u, w):
        """h(u, w) at a batch q (..., n) for tangent u, w (..., n): shape (..., n)."""
        J = self._eval("J", q)
        rhs = -np.einsum("...cij,...i,...j->...c", self._eval("F2", q), u, w)
        z = np.einsum("...ic,...c->...i", np.linalg.pinv(J), rhs)
        T = L @ np.swapaxes(np.linalg.svd(J)[2][..., self.k:, :], -1, -2)   # L(ker J)
        Qt = np.linalg.qr(T)[0]
        Lz = np.einsum("...ij,...j->...i", L, z)
        return Lz - np.einsum("...ia,...a->...i", Qt, np.einsum("...ia,...i->...a", Qt, Lz))

    def second_fundamental_form(self, q, u, w):
        """h(u, w) of the embedding of the manifold in (Rⁿ, M), M constant: the normal part of
        L z, where M = LᵀL and z is any solution of J z = −∂²F(u, w) (a second-order lift);
        a vector of Rⁿ (the image space of L), no chart involved.  q must be on the manifold
        and u, w tangent there (`MechanismError` naming them otherwise)."""
        q = self.check_point(q)
        u, w = self.check_tangent(q, u, "u"), self.check_tangent(q, w, "w")
        return self._normal_part(q, self._isometry(q), u, w)

    def _gauss(self, q, L, u, w):
        """The Gauss equation at a batch: K of the planes (u, w), shape (...)."""
        huu, hww, huw = (self._normal_part(q, L, a, b) for a, b in ((u, u), (w, w), (u, w)))
        Lu, Lw = (np.einsum("...ij,...j->...i", L, x) for x in (u, w))
        area2 = (np.sum(Lu * Lu, -1) * np.sum(Lw * Lw, -1) - np.sum(Lu * Lw, -1) ** 2)
        return (np.sum(huu * hww, -1) - np.sum(huw * huw, -1)) / area2

    def gauss_equation_curvature(self, q, u, w):
        """K of the plane of the tangent vectors u, w at q by the Gauss equation of the
        embedding in the flat (Rⁿ, M): [⟨h(u,u), h(w,w)⟩ − |h(u,w)|²] / (|u|²|w|² − ⟨u,w⟩²).
        The independent route (second fundamental form; no chart, no Christoffel symbols)."""
        q = self.check_point(q)
        u, w = self.check_tangent(q, u, "u"), self.check_tangent(q, w, "w")
        L = self._isometry(q)
        self._area2(q, u, w)                                        # refuses a degenerate plane
        return float(self._gauss(q, L, u, w))

    def gauss_equation_curvatures(self, q):
        """The Gaussian curvature of a 2-dimensional configuration space at a batch of points
        q (S, n) of the manifold (unchecked) by the Gauss equation; shape (S,)."""
        if self.dim != 2:
            raise MechanismError(f"gauss_equation_curvatures is for 2-dimensional configuration "
                                 f"spaces (this one has dimension {self.dim})")
        q = np.asarray(q, dtype=float)
        L = self._isometry(q)
        T = np.linalg.svd(self._eval("J", q))[2][..., self.k:, :]        # (S, 2, n), ker J
        return self._gauss(q, L, T[..., 0, :], T[..., 1, :])
