"""Symbolic geometry of the rotor constraint manifold in one coordinate chart.

The configuration manifold is Σ cos θᵢ = 0 (eq 1) with the kinetic metric
T = ½ Σ mᵢ uᵢ² (eq 2, unit masses in the paper).  Chart ``k`` eliminates θₖ:
its local coordinates are the remaining angles in increasing order,
cos θₖ = −C with C = Σ_{α≠k} cos θ_α, and sin θₖ = ±√(1 − C²) on one of two
sign branches.  The induced metric does not depend on the branch:

    g_αβ = m_α δ_αβ + m_k sin θ_α sin θ_β / (1 − C²)            (eq 13)

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
from functools import cached_property

import sympy as sp

__all__ = ["ChartGeometry", "local_indices"]


def local_indices(n: int, k: int) -> list[int]:
    """Ambient indices of chart ``k``'s local coordinates, in order."""
    return [i for i in range(n) if i != k]


@dataclass
class ChartGeometry:
    """Exact geometry of chart ``k`` of the N-rotor manifold.

    Symbols: ``theta[i]`` (all N ambient angles; θₖ itself never appears),
    ``m[i]`` (positive masses), ``v``, ``w`` (local vector components).
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
    def cos_sum(self):
        """C = Σ_{α≠k} cos θ_α = −cos θₖ."""
        return sp.Add(*[sp.cos(x) for x in self.q])

    @cached_property
    def sin2_k(self):
        """sin²θₖ = 1 − C², the chart's conditioning factor."""
        return 1 - self.cos_sum**2

    # -- metric (eq 13) -----------------------------------------------------
    @cached_property
    def metric(self) -> list:
        d, s = self.dim, [sp.sin(x) for x in self.q]
        mk = self.m[self.k]
        return [[(self.mloc[a] if a == b else 0) + mk * s[a] * s[b] / self.sin2_k
                 for b in range(d)] for a in range(d)]

    @cached_property
    def metric_inverse(self) -> list:
        """Sherman–Morrison inverse of diag(m) + (m_k/D) s sᵀ."""
        d, s = self.dim, [sp.sin(x) for x in self.q]
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
        """H_ab = Hess F(∂_a, ∂_b) of F = Σ cos θ pulled back to the chart, with
        ∂_a θₖ = −sin θ_a / sin θₖ:  H_ab = −(δ_ab cos θ_a − C sin θ_a sin θ_b / (1 − C²))."""
        d, s, c = self.dim, [sp.sin(x) for x in self.q], [sp.cos(x) for x in self.q]
        C, D = self.cos_sum, self.sin2_k
        return [[-((c[a] if a == b else 0) - C * s[a] * s[b] / D) for b in range(d)] for a in range(d)]

    @cached_property
    def normal_norm2(self):
        """|∇F|² in the metric diag(m): Σ_α sin²θ_α/m_α + sin²θₖ/mₖ."""
        return sp.Add(*[sp.sin(x) ** 2 / mm for x, mm in zip(self.q, self.mloc)]) + self.sin2_k / self.m[self.k]

    @cached_property
    def riemann(self) -> list:
        """R_abcd = ⟨R(∂_c, ∂_d)∂_b, ∂_a⟩ by the Gauss equation of the hypersurface F = 0 in
        the flat space (Rᴺ, diag m):  R_abcd = (H_ac H_bd − H_ad H_bc) / |∇F|².

        Only 1/(1 − C²) appears, so it evaluates to ~1e-15 even where the chart is poorly
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
        from d(Σ cos θ) = 0, x_k = −Σ_α sin θ_α x_α / sin θₖ."""
        return -sp.Add(*[sp.sin(self.q[a]) * x[a] for a in range(self.dim)]) / sin_k
