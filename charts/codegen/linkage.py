"""Symbolic constraints of the flat four-rotor linkage of the paper's Appendix (figure 1b).

Four rotors turn about axes at (1, 0), (0, 1), (−1, 0), (0, −1); a rod of length R joins the
hinge at distance ε on rotor i to a hinge at distance ρ from the centre (x, y) of a moving disk
turned by α.  With the Appendix's hinge coordinates

    rotor hinges  P₀ = (1 − ε cos θ₀, ε sin θ₀),   P₁ = (ε sin θ₁, 1 + ε cos θ₁),
                  P₂ = (−1 + ε cos θ₂, −ε sin θ₂), P₃ = (−ε sin θ₃, −1 − ε cos θ₃),
    disk hinges   D₀ = (x + ρ cos α, y + ρ sin α), D₁ = (x − ρ sin α, y + ρ cos α),
                  D₂ = (x − ρ cos α, y − ρ sin α), D₃ = (x + ρ sin α, y − ρ cos α),

the configuration q = (θ₀, θ₁, θ₂, θ₃, x, y, α) obeys the four constraints

    Fᵢ(q) = |Pᵢ − Dᵢ|² − R² = 0,   i = 0…3.

Everything the numerics need is a derivative of F: the Jacobian J = ∂F/∂q (4 × 7), the
Hessian contracted with one vector, Hᵢⱼ(w) = Σₖ ∂²Fᵢ/∂qⱼ∂qₖ wₖ (4 × 7), and the third
derivative contracted with three vectors, Tᵢ(v, v, w) = Σ ∂³Fᵢ/∂qⱼ∂qₖ∂qₗ vⱼ vₖ wₗ (4,), which
the variational equations need.  ε, ρ, R are symbols, so one generated module serves every
linkage.  The linkage is a ``charts.Mechanism``: ``charts.mechanism.instances.
appendix_linkage_model`` takes its constraints from here.
"""
from __future__ import annotations

from functools import cached_property

import sympy as sp

__all__ = ["LinkageSymbols", "NQ", "NC"]

#: Coordinates q = (θ₀…θ₃, x, y, α) and number of constraints.
NQ = 7
NC = 4


class LinkageSymbols:
    """The constraint functions of the Appendix and their derivatives, exact SymPy."""

    def __init__(self):
        self.q = list(sp.symbols("q0:7", real=True))
        self.eps, self.rho, self.R = sp.symbols("epsilon rho R", positive=True)
        self.v = list(sp.symbols("v0:7", real=True))
        self.w = list(sp.symbols("w0:7", real=True))

    def hinges(self):
        """(rotor hinges Pᵢ, disk hinges Dᵢ), each a list of four (x, y) pairs (Appendix)."""
        t0, t1, t2, t3, x, y, a = self.q
        e, r = self.eps, self.rho
        P = [(1 - e * sp.cos(t0), e * sp.sin(t0)), (e * sp.sin(t1), 1 + e * sp.cos(t1)),
             (-1 + e * sp.cos(t2), -e * sp.sin(t2)), (-e * sp.sin(t3), -1 - e * sp.cos(t3))]
        D = [(x + r * sp.cos(a), y + r * sp.sin(a)), (x - r * sp.sin(a), y + r * sp.cos(a)),
             (x - r * sp.cos(a), y - r * sp.sin(a)), (x + r * sp.sin(a), y - r * sp.cos(a))]
        return P, D

    @cached_property
    def constraints(self):
        """Fᵢ = |Pᵢ − Dᵢ|² − R², shape (4,)."""
        P, D = self.hinges()
        return [(p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2 - self.R ** 2 for p, d in zip(P, D)]

    @cached_property
    def jacobian(self):
        """J[i][j] = ∂Fᵢ/∂qⱼ, shape (4, 7)."""
        return [[sp.diff(F, qj) for qj in self.q] for F in self.constraints]

    @cached_property
    def hessian(self):
        """∂²Fᵢ/∂qⱼ∂qₖ, shape (4, 7, 7)."""
        return [[[sp.diff(Jij, qk) for qk in self.q] for Jij in row] for row in self.jacobian]

    @cached_property
    def hessian_vector(self):
        """Hᵢⱼ(w) = Σₖ ∂²Fᵢ/∂qⱼ∂qₖ wₖ, shape (4, 7)."""
        return [[sum(Hijk * wk for Hijk, wk in zip(Hij, self.w)) for Hij in Hi]
                for Hi in self.hessian]

    @cached_property
    def third_form(self):
        """Tᵢ(v, v, w) = derivative of vᵀ∇²Fᵢ v along w, shape (4,)."""
        out = []
        for Hi in self.hessian:
            quad = sum(Hi[j][k] * self.v[j] * self.v[k] for j in range(NQ) for k in range(NQ))
            out.append(sum(sp.diff(quad, qk) * wk for qk, wk in zip(self.q, self.w)))
        return out

    def first_order(self):
        """The Appendix's first-order constraints: the O(ε) part of Fᵢ with ρ = r·ε,
        (x, y) = ε·(ξ, η), shape (4,), each divided by 2ε (so −ε cos θ₀ − x − ρ cos α → ...)."""
        t = sp.Symbol("t", positive=True)
        xi, eta, r = sp.symbols("xi eta r", real=True)
        subs = {self.eps: t, self.rho: r * t, self.q[4]: t * xi, self.q[5]: t * eta, self.R: 1}
        return [sp.expand(sp.diff(F.subs(subs), t).subs(t, 0) / 2) for F in self.constraints]
