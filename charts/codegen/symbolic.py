"""Symbolic geometry of the rotor constraint manifold in one coordinate chart.

The configuration manifold is the level set Σ aᵢ cos θᵢ = c (weights aᵢ > 0, level c; the
paper's eq (1) is a = 1, c = 0) with the kinetic metric T = ½ Σ mᵢ uᵢ² (eq 2, unit masses
in the paper).  Weights and level are *symbols*: one derivation (and one generated module
per N) serves every member of the family.  Chart ``k`` eliminates θₖ: its local coordinates
are the remaining angles in increasing order, aₖ cos θₖ = −C with
C = Σ_{α≠k} a_α cos θ_α − c, and aₖ sin θₖ = ±√D, D = aₖ² − C², on one of two sign branches
(the chart's domain is |C| < aₖ).  With σ_α = a_α sin θ_α the induced metric does not depend
on the branch:

    g_αβ = m_α δ_αβ + m_k σ_α σ_β / D                             (eq 13, weighted)

For a = 1, c = 0: C = Σ cos θ_α, D = 1 − C², and this is the paper's eq (13).  σ and κ are
opaque functions (``weighted_sincos``) with σ' = κ, κ' = −σ, so the derivation has the shape
of the unweighted one; ``paper`` substitutes a = 1, c = 0, σ → sin, κ → cos and gives the
very expressions the derivation gave before weights and level existed.

Everything here is exact SymPy, built without ``simplify`` and without generic
matrix inversion (the metric is diagonal plus rank one, so Sherman–Morrison
gives the inverse in closed form).  Christoffel symbols come from metric
derivatives.  Riemann is derived two ways: from second metric derivatives and
first-kind Christoffel symbols (the textbook route), and by the Gauss equation of
the hypersurface (the numerically stable route, which the generated code uses);
the tests prove they agree.

Index conventions (also used by the generated code and by ``RotorSystem``):

* ``christoffel[a][b][c]`` = Γ^a_bc, upper index first.
* ``riemann[a][b][c][d]`` = R_abcd = ⟨R(∂_c, ∂_d) ∂_b, ∂_a⟩ with
  R(X, Y) = ∇_X∇_Y − ∇_Y∇_X − ∇_[X,Y].  Then the sectional curvature is
  K(X, Y) = R_abcd X^a Y^b X^c Y^d / (|X|²|Y|² − ⟨X, Y⟩²), and the Jacobi
  equation reads J'' + R(J, v) v = 0.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache, cached_property

import sympy as sp

__all__ = ["ChartGeometry", "local_indices", "weighted_sincos"]


@cache
def weighted_sincos(i: int):
    """The SymPy functions σᵢ(θᵢ) = aᵢ sin θᵢ and κᵢ(θᵢ) = aᵢ cos θᵢ of rotor ``i``, opaque
    (σ' = κ, κ' = −σ) so that the derivation has the shape of the unweighted one with
    sin → σ, cos → κ; ``ChartGeometry.explicit`` writes them out."""
    wsin = type(f"wsin{i}", (sp.Function,), {"nargs": 1})
    wcos = type(f"wcos{i}", (sp.Function,), {"nargs": 1})
    wsin.fdiff = lambda self, argindex=1: wcos(self.args[0])
    wcos.fdiff = lambda self, argindex=1: -wsin(self.args[0])
    return wsin, wcos


def local_indices(n: int, k: int) -> list[int]:
    """Ambient indices of chart ``k``'s local coordinates, in order."""
    return [i for i in range(n) if i != k]


@dataclass
class ChartGeometry:
    """Exact geometry of chart ``k`` of the N-rotor manifold.

    Symbols: ``theta[i]`` (all N ambient angles; θₖ itself never appears),
    ``m[i]`` (positive masses), ``a[i]`` (positive weights), ``c`` (the level),
    ``v``, ``w`` (local vector components).
    All tensors are nested lists of SymPy expressions in local indices.
    """

    n: int
    k: int
    theta: list = field(init=False)
    m: list = field(init=False)

    def __post_init__(self):
        if self.n < 3:
            raise ValueError(f"need n >= 3 rotors, got n={self.n}")
        if not 0 <= self.k < self.n:
            raise ValueError(f"chart k={self.k} outside 0..{self.n - 1}")
        self.theta = list(sp.symbols(f"theta0:{self.n}", real=True))
        self.m = list(sp.symbols(f"m0:{self.n}", positive=True))
        self.a = list(sp.symbols(f"a0:{self.n}", positive=True))
        self.c = sp.Symbol("c", real=True)
        self.v = list(sp.symbols(f"v0:{self.dim}", real=True))
        self.w = list(sp.symbols(f"w0:{self.dim}", real=True))

    # -- chart data -------------------------------------------------------
    @property
    def dim(self) -> int:
        return self.n - 1

    @cached_property
    def idx(self) -> list[int]:
        return local_indices(self.n, self.k)

    @cached_property
    def q(self) -> list:
        """Local coordinates θ_α, α ≠ k."""
        return [self.theta[i] for i in self.idx]

    @cached_property
    def mloc(self) -> list:
        return [self.m[i] for i in self.idx]

    @cached_property
    def aloc(self) -> list:
        return [self.a[i] for i in self.idx]

    @cached_property
    def wsin(self) -> list:
        """σ_α = a_α sin θ_α (minus the gradient of F = Σ a cos θ, local part)."""
        return [weighted_sincos(i)[0](self.theta[i]) for i in self.idx]

    @cached_property
    def wcos(self) -> list:
        """κ_α = a_α cos θ_α (minus the Hessian of F, local part)."""
        return [weighted_sincos(i)[1](self.theta[i]) for i in self.idx]

    @cached_property
    def cos_sum(self):
        """C = Σ_{α≠k} a_α cos θ_α − c = −aₖ cos θₖ (the paper's Σ cos θ_α for a = 1, c = 0)."""
        return sp.Add(*self.wcos) - self.c

    @cached_property
    def substitutions(self) -> dict:
        """Values of the opaque functions σ_α = a_α sin θ_α, κ_α = a_α cos θ_α."""
        out = {}
        for i, s, c in zip(self.idx, self.wsin, self.wcos):
            out[s] = self.a[i] * sp.sin(self.theta[i])
            out[c] = self.a[i] * sp.cos(self.theta[i])
        return out

    @cached_property
    def paper_values(self) -> dict:
        """The paper's member of the family: a = 1, c = 0 (σ → sin, κ → cos)."""
        out = {self.c: 0}
        for i, s, c in zip(self.idx, self.wsin, self.wcos):
            out[s] = sp.sin(self.theta[i])
            out[c] = sp.cos(self.theta[i])
        out.update({a: 1 for a in self.a})
        return out

    def exact_values(self, masses, weights, level) -> dict:
        """The substitution of numbers for the symbols m, a, c: each float as the exact
        rational it is (its binary fraction), so that the algebra after it stays exact."""
        out = {self.c: sp.Rational(float(level))}
        out.update({m: sp.Rational(float(x)) for m, x in zip(self.m, masses)})
        out.update({a: sp.Rational(float(x)) for a, x in zip(self.a, weights)})
        return out

    def paper(self, nested):
        """``nested`` specialised to the paper's Σ cos θ = 0 (a = 1, c = 0): the same
        expressions the derivation gave before weights and level existed (``emit`` writes
        them as the paper's kernels, which keep their floating-point operations)."""
        if isinstance(nested, list):
            return [self.paper(x) for x in nested]
        return sp.sympify(nested).xreplace(self.paper_values)

    def explicit(self, nested):
        """``nested`` (a nested list or an expression) with σ, κ written out: a function of
        q, m, a, c only (for lambdify)."""
        if isinstance(nested, list):
            return [self.explicit(x) for x in nested]
        return sp.sympify(nested).xreplace(self.substitutions)

    @cached_property
    def sin2_k(self):
        """D = aₖ² − C² = (aₖ sin θₖ)², the chart's conditioning factor (1 − C² for a = 1)."""
        return self.a[self.k] ** 2 - self.cos_sum**2

    # -- metric (eq 13) -----------------------------------------------------
    @cached_property
    def metric(self) -> list:
        d, s = self.dim, self.wsin
        mk = self.m[self.k]
        return [[(self.mloc[a] if a == b else 0) + mk * s[a] * s[b] / self.sin2_k
                 for b in range(d)] for a in range(d)]

    @cached_property
    def metric_inverse(self) -> list:
        """Sherman–Morrison inverse of diag(m) + (m_k/D) σ σᵀ."""
        d, s = self.dim, self.wsin
        mk, ml = self.m[self.k], self.mloc
        denom = self.sin2_k + mk * sp.Add(*[s[a] ** 2 / ml[a] for a in range(d)])
        return [[(1 / ml[a] if a == b else 0) - mk * s[a] * s[b] / (ml[a] * ml[b] * denom)
                 for b in range(d)] for a in range(d)]

    @cached_property
    def dmetric(self) -> list:
        """∂_c g_ab as ``dmetric[a][b][c]``."""
        g, q = self.metric, self.q
        return [[[sp.diff(g[a][b], q[c]) for c in range(self.dim)]
                 for b in range(self.dim)] for a in range(self.dim)]

    # -- connection (eqs 14-16) -----------------------------------------------
    @cached_property
    def christoffel_first(self) -> list:
        """Γ_abc = ½(∂_b g_ac + ∂_c g_ab − ∂_a g_bc)."""
        dg, d = self.dmetric, self.dim
        return [[[sp.Rational(1, 2) * (dg[a][c][b] + dg[a][b][c] - dg[b][c][a])
                  for c in range(d)] for b in range(d)] for a in range(d)]

    @cached_property
    def christoffel(self) -> list:
        """Γ^a_bc = g^ae Γ_ebc (eq 15 for unit masses)."""
        gi, g1, d = self.metric_inverse, self.christoffel_first, self.dim
        return [[[sp.Add(*[gi[a][e] * g1[e][b][c] for e in range(d)])
                  for c in range(d)] for b in range(d)] for a in range(d)]

    def connection_contract(self, x: list, y: list) -> list:
        """Γ^a(x, y) = Γ^a_bc x^b y^c; −Γ(v, v) is the geodesic acceleration (eq 14),
        −Γ(v, p) the parallel-transport rate (eq 16)."""
        gi, g1, d = self.metric_inverse, self.christoffel_first, self.dim
        low = [sp.Add(*[g1[e][b][c] * x[b] * y[c] for b in range(d) for c in range(d)])
               for e in range(d)]
        return [sp.Add(*[gi[a][e] * low[e] for e in range(d)]) for a in range(d)]

    # -- curvature -----------------------------------------------------------------
    @cached_property
    def second_fundamental(self) -> list:
        """H_ab = Hess F(∂_a, ∂_b) of F = Σ a cos θ pulled back to the chart, with
        ∂_a θₖ = −σ_a / (aₖ sin θₖ):  H_ab = −(δ_ab κ_a − C σ_a σ_b / D)
        (the paper's −(δ_ab cos θ_a − C sin θ_a sin θ_b / (1 − C²)) for a = 1, c = 0)."""
        d, s, c = self.dim, self.wsin, self.wcos
        C, D = self.cos_sum, self.sin2_k
        return [[-((c[a] if a == b else 0) - C * s[a] * s[b] / D) for b in range(d)] for a in range(d)]

    @cached_property
    def normal_norm2(self):
        """|∇F|² in the metric diag(m): Σ_α σ_α²/m_α + D/mₖ."""
        return sp.Add(*[x ** 2 / mm for x, mm in zip(self.wsin, self.mloc)]) + self.sin2_k / self.m[self.k]

    @cached_property
    def riemann(self) -> list:
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ by the Gauss equation of the hypersurface F = 0 in
        the flat space (Rᴺ, diag m):  R_abcd = (H_ac H_bd − H_ad H_bc) / |∇F|².

        Only 1/D appears, so it evaluates to ~1e-15 even where the chart is poorly
        conditioned; ``riemann_from_metric`` (the textbook route) loses ~1e-16/sin⁸θₖ there.
        Tests check the two agree symbolically-numerically."""
        d, H, nn = self.dim, self.second_fundamental, self.normal_norm2
        return [[[[(H[a][c] * H[b][e] - H[a][e] * H[b][c]) / nn for e in range(d)]
                  for c in range(d)] for b in range(d)] for a in range(d)]

    @cached_property
    def riemann_from_metric(self) -> list:
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ from second metric derivatives:

        R_abcd = ½(∂_c∂_b g_ad + ∂_d∂_a g_bc − ∂_c∂_a g_bd − ∂_d∂_b g_ac)
                 + Γ_ead Γ^e_bc − Γ_eac Γ^e_bd
        """
        d, q, dg = self.dim, self.q, self.dmetric
        g1, g2 = self.christoffel_first, self.christoffel
        ddg = {}

        def h(a, b, c, e):  # ∂_c ∂_e g_ab, memoised
            key = (min(a, b), max(a, b), min(c, e), max(c, e))
            if key not in ddg:
                ddg[key] = sp.diff(dg[key[0]][key[1]][key[2]], q[key[3]])
            return ddg[key]

        out = [[[[None] * d for _ in range(d)] for _ in range(d)] for _ in range(d)]
        for a in range(d):
            for b in range(d):
                for c in range(d):
                    for e in range(d):
                        second = sp.Rational(1, 2) * (h(a, e, c, b) + h(b, c, e, a)
                                                      - h(b, e, c, a) - h(a, c, e, b))
                        quad = sp.Add(*[g1[f][a][e] * g2[f][b][c] - g1[f][a][c] * g2[f][b][e]
                                        for f in range(d)])
                        out[a][b][c][e] = second + quad
        return out

    def curvature_operator(self, x: list, y: list) -> list:
        """R(x, y)y as upper-index components.  With the Gauss form of ``riemann``,
        (R(x,y)y)_e = R_ebcd y^b x^c y^d = [H(e,x) H(y,y) − H(e,y) H(y,x)] / |∇F|², then
        raised with g^ae: O(d²) terms instead of a contraction of all d⁴ components."""
        d, H, gi, nn = self.dim, self.second_fundamental, self.metric_inverse, self.normal_norm2
        Hx = [sp.Add(*[H[e][c] * x[c] for c in range(d)]) for e in range(d)]
        Hy = [sp.Add(*[H[e][c] * y[c] for c in range(d)]) for e in range(d)]
        yHy = sp.Add(*[y[e] * Hy[e] for e in range(d)])
        yHx = sp.Add(*[y[e] * Hx[e] for e in range(d)])
        low = [(Hx[e] * yHy - Hy[e] * yHx) / nn for e in range(d)]
        return [sp.Add(*[gi[a][e] * low[e] for e in range(d)]) for a in range(d)]

    # -- maps between chart and ambient ---------------------------------------------
    def eliminated_velocity(self, x: list, sin_k):
        """Ambient component k of a tangent vector with local components ``x``:
        from d(Σ a cos θ) = 0, x_k = −Σ_α σ_α x_α / (aₖ sin θₖ)."""
        return -sp.Add(*[self.wsin[a] * x[a] for a in range(self.dim)]) / (self.a[self.k] * sin_k)
