"""Certified non-hyperbolicity for N ≥ 4: flat, totally geodesic tori of antipodal pairs.

Pair rotors with equal masses and weights, (i₁, j₁), …, (i_p, j_p), and put every other rotor
at θ = π/2.  On the level c = 0 the set

    T = {θ_{jᵣ} = θ_{iᵣ} + π for every pair, θ_l = π/2 for the others}

lies in the manifold (each pair's cosines cancel), and it is a flat torus of dimension p with
the induced metric Σᵣ (m_{iᵣ} + m_{jᵣ}) dtᵣ².  It is totally geodesic: for a velocity
tangent to T the geodesic equation (14) gives zero acceleration (the constraint force
vanishes: the pairs' terms of Λ cancel), so the straight lines of T are geodesics of the
manifold.  Then along any geodesic γ of T and any unit w ⊥ γ' in T (parallel along γ, as T
is flat and totally geodesic), J(t) = w and J(t) = t·w are Jacobi fields (the curvature of
the plane (γ', w) is that of T, zero): solutions of the linearised flow, transverse to the
flow, that stay bounded or grow linearly in both directions of time.  For p ≥ 2 — every N ≥ 4
of the paper, N = 4 and 5 included — a closed geodesic of T (one pair turning, the others at
±π/2, away from every singular point) carries such a periodic field J = w: a closed orbit that
is not hyperbolic, which an Anosov flow cannot have, so the geodesic flow is not Anosov.
(Eberlein's criterion is not used: it is for smooth closed manifolds, and at even N the
manifold has cone points, some on T.)  For N = 3, p = 1: T is a closed geodesic only, no
contradiction with the Anosov property.

The proof is done by the library's own symbolic geometry (``charts.codegen.symbolic``) in a
chart that holds T: the constraint, the tangency (eq 10) and the contraction Γᵃ_bc q̇ᵇ q̇ᶜ
vanish identically on T, the pulled-back metric is constant, the curvature of T's planes is
zero.  The numerical evidence is the monodromy of the closed geodesic by the tangent
kernel: the in-T Jacobi field's Jordan block and the multipliers transverse to T.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import sympy as sp

from ..codegen.symbolic import ChartGeometry
from ..geometry.checks import integer, shown
from ..solvers.tangent import TangentFlow
from .arguments import rotor_system

__all__ = ["FlatTorusCertificate", "antipodal_torus", "certify_flat_torus", "torus_plan",
           "MAX_TORUS_N", "MAX_TORUS_STEPS"]

#: Most rotors whose torus is proved: the symbolic proof works in a chart of dimension N − 1
#: (Christoffel symbols and Riemann tensor of (N − 1)³ and (N − 1)⁴ entries, simplified by
#: SymPy); measured on one core: N = 4, 6, 8, 10, 12 took 2, 6, 15, 37, 81 s (odd N less:
#: N = 9, 6.7 s), growing about 2.2 times per two rotors.
MAX_TORUS_N = 12
#: Most RK4 steps per period of the closed geodesic: 4096 (the default) already closes it to
#: rounding; 2²⁰ steps of the 2N + 1 stacked vectors of N = 12 take about 2 s (80 ns a
#: vector and step, measured).
MAX_TORUS_STEPS = 1 << 20


def antipodal_torus(system):
    """(pairs, lone) of the antipodal torus of ``system`` (module doc): pairs of rotors with
    equal mass and weight (in index order), the rest at π/2; None where the level is not 0
    or no two rotors are alike."""
    if system.level != 0.0:
        return None
    free = list(range(system.n))
    pairs = []
    while free:
        i = free.pop(0)
        match = [j for j in free if system.masses[j] == system.masses[i]
                 and system.weights[j] == system.weights[i]]
        if match:
            free.remove(match[0])
            pairs.append((i, match[0]))
    if not pairs:
        return None
    paired = {q for pair in pairs for q in pair}
    return pairs, [q for q in range(system.n) if q not in paired]


@dataclass
class FlatTorusCertificate:
    """The outcome of `certify_flat_torus`: ``verdict`` ``"not hyperbolic"`` (a flat totally
    geodesic torus of dimension ≥ 2 proved), ``"no conclusion"`` (dimension 1: a closed
    geodesic only) or ``"no antipodal torus"``; ``pairs``, ``lone``, ``dimension``;
    ``proof``: each symbolic step and its exact result; ``closed_geodesic`` and
    ``monodromy``: the numerical evidence."""
    verdict: str
    pairs: list
    lone: list
    dimension: int
    proof: list
    closed_geodesic: dict | None
    monodromy: dict | None
    params: dict

    def to_dict(self) -> dict:
        return asdict(self)


def _symbolic_proof(system, pairs, lone, offset=sp.pi):
    """The steps of the module doc, exact, in the chart that eliminates a lone rotor (or the
    second rotor of the first pair); each (statement, holds).  ``offset``: θⱼ − θᵢ of each
    pair (π; other values are for tests: a set that is not on the level set must fail)."""
    n = system.n
    k = lone[0] if lone else pairs[0][1]
    g = ChartGeometry(n, k)
    ts = sp.symbols(f"t0:{len(pairs)}", real=True)
    ws = sp.symbols(f"w0:{len(pairs)}", real=True)
    theta, vel = {}, {}
    for r, (i, j) in enumerate(pairs):
        theta[i], theta[j] = ts[r], ts[r] + offset
        vel[i] = vel[j] = ws[r]
    for q in lone:
        theta[q], vel[q] = sp.pi / 2, sp.Integer(0)
    values = g.exact_values(system.masses, system.weights, system.level)
    on_T = {g.theta[q]: theta[q] for q in range(n) if q != k}

    probe = {x: sp.Rational(3 + 2 * i, 7) for i, x in enumerate(ts + ws)}

    def zero(expr):
        """Whether expr vanishes identically on T: a nonzero value at a point of T disproves
        it at once (exact rationals, 30 digits); else SymPy's simplification proves it."""
        e = g.explicit(expr).xreplace(values).subs(on_T)
        if abs(sp.N(e.xreplace(probe), 30)) > 1e-20:
            return False
        return sp.simplify(e) == 0

    a = [values[g.a[q]] for q in range(n)]
    steps = []
    constraint = sp.Add(*[a[q] * sp.cos(theta[q]) for q in range(n)]) - values[g.c]
    steps.append(("T lies on the level set: sum a cos theta - c = 0 on T",
                  sp.simplify(constraint) == 0))
    tangency = sp.Add(*[a[q] * vel[q] * sp.sin(theta[q]) for q in range(n)])
    steps.append(("T's velocities are tangent (eq 10): sum a u sin theta = 0 on T",
                  sp.simplify(tangency) == 0))
    qd = [vel[q] for q in g.idx]
    Gam = g.christoffel
    geodesic = all(zero(sp.Add(*[Gam[x][b][c] * qd[b] * qd[c] for b in range(g.dim)
                                 for c in range(g.dim) if qd[b] != 0 and qd[c] != 0]))
                   for x in range(g.dim))
    steps.append((f"totally geodesic: Gamma^a_bc qdot^b qdot^c = 0 on T in chart {k} (eq 14: "
                  "T's straight lines are geodesics)", geodesic))
    # the coordinate fields ∂/∂t_r of T in the chart's coordinates
    E = [[sp.Integer(1) if q in pair else sp.Integer(0) for q in g.idx] for pair in pairs]
    G = g.metric
    gT = [[sp.simplify(g.explicit(sp.Add(*[G[x][y] * E[r][x] * E[s][y] for x in range(g.dim)
                                           for y in range(g.dim) if E[r][x] != 0 and E[s][y] != 0]))
                       .xreplace(values).subs(on_T)) for s in range(len(pairs))]
          for r in range(len(pairs))]
    flat = all(sp.diff(x, t) == 0 for row in gT for x in row for t in ts)
    steps.append((f"flat: the induced metric is constant, {[[str(x) for x in row] for row in gT]}",
                  flat))
    R = g.riemann
    plane = True
    for r in range(len(pairs)):
        for s in range(r + 1, len(pairs)):
            idx = [(x, E[r][x]) for x in range(g.dim) if E[r][x] != 0]
            jdx = [(x, E[s][x]) for x in range(g.dim) if E[s][x] != 0]
            term = sp.Add(*[R[a_][b][c][d] * ea * eb * ec * ed for a_, ea in idx for b, eb in jdx
                            for c, ec in idx for d, ed in jdx])
            plane &= zero(term)
    steps.append(("the sectional curvature of T's planes is 0 (R(e_r, e_s, e_r, e_s) = 0, the "
                  "Gauss route)", plane))
    return [dict(statement=s, holds=bool(h)) for s, h in steps]


def _monodromy(system, pairs, lone, steps):
    """The monodromy of the closed geodesic of T on which the first pair turns at unit speed
    and every other rotor stays at π/2 (or its pair's π/2 + π), by `TangentFlow` with the 2N
    unit vectors and no re-orthonormalisation over one period."""
    n = system.n
    i, j = pairs[0]
    w = 1.0 / np.sqrt(system.masses[i] + system.masses[j])
    period = 2.0 * np.pi / w
    theta = np.full(n, np.pi / 2)
    for (p, q) in pairs[1:]:
        theta[q] = np.pi / 2 + np.pi
    theta[i], theta[j] = 0.3, 0.3 + np.pi
    u = np.zeros(n)
    u[i] = u[j] = w
    flow = TangentFlow(system, theta, u, 2 * n, dt=period / steps, inner="euclidean",
                       restricted=False, reorth_every=steps + 1, project_every=0)
    flow.Z[1:] = np.eye(2 * n)
    flow.advance(steps, where="closed geodesic of the antipodal torus")
    M = flow.Z[1:].T.copy()                       # columns: images of the unit vectors
    y = flow.y
    off = max(abs(np.angle(np.exp(1j * (y[q] - y[p] - np.pi)))) for p, q in pairs)
    off = max([off] + [abs(y[q] - np.pi / 2) for q in lone])
    out = dict(period=period, steps=int(steps), max_distance_from_torus=float(off),
               return_error=float(np.abs(np.angle(np.exp(1j * (y[:n] - theta)))).max()))
    if len(pairs) >= 2:                            # the in-T Jacobi field w ⊥ γ'
        p, q = pairs[1]
        e = np.zeros(2 * n)
        e[[p, q]] = 1.0 / np.sqrt(2.0)
        ev = np.concatenate([np.zeros(n), e[:n]])  # a velocity perturbation along w
        expect = np.concatenate([period * e[:n], e[:n]])
        out["jordan_residual"] = float(np.abs(M @ ev - expect).max() / period)
        out["position_residual"] = float(np.abs(M @ e - e).max())
    mult = np.linalg.eigvals(M)
    far = mult[np.abs(np.log(np.abs(mult))) > 1e-6]
    out["transverse_multipliers"] = sorted(float(abs(x)) for x in far)
    out["transverse_exponents"] = sorted(float(np.log(abs(x)) / period) for x in far)
    return dict(theta0=theta.tolist(), u0=u.tolist(), period=period), out


def torus_plan(system, steps=4096) -> int:
    """``steps`` checked for `certify_flat_torus` of ``system`` before any work: a whole
    number of RK4 steps per period in 1..`MAX_TORUS_STEPS`, and N at most `MAX_TORUS_N`
    (the symbolic proof's cost); ValueError with the numbers otherwise."""
    n = system.n
    steps = integer("steps", steps, 1)
    if steps > MAX_TORUS_STEPS:
        work = float(min(steps, 10 ** 300)) * (2 * n + 1)
        raise ValueError(f"steps={shown(steps)} RK4 steps per period, with the 2N + 1 = {2 * n + 1} "
                         f"stacked vectors of N = {n}, is {work:.3g} vector steps (about "
                         f"{work * 80e-9:.3g} s at 80 ns each), more than the {MAX_TORUS_STEPS} "
                         "steps allowed; 4096 (the default) already closes the geodesic to "
                         "rounding")
    if n > MAX_TORUS_N:
        def count(x):
            return f"{x:,}" if x < 10 ** 9 else f"{x:.3g}"
        raise ValueError(f"N = {n} rotors: the flat-torus proof works symbolically in a chart of "
                         f"dimension {n - 1}, with {count((n - 1) ** 3)} Christoffel symbols and "
                         f"{count((n - 1) ** 4)} curvature components to simplify; it took 81 s at "
                         f"N = {MAX_TORUS_N} (about 2.2 times more per two rotors), so it is run "
                         f"for N <= {MAX_TORUS_N} only")
    return steps


def certify_flat_torus(system, *, steps=4096) -> FlatTorusCertificate:
    """Prove (symbolically) the flat totally geodesic antipodal torus of ``system`` and
    compute the monodromy of its closed geodesic (``steps`` RK4 steps per period, a whole
    number in 1..`MAX_TORUS_STEPS`; N at most `MAX_TORUS_N`: `torus_plan`, checked before
    any work); see the module doc for what it implies."""
    rotor_system(system)
    steps = torus_plan(system, steps)
    params = dict(**system.describe(), steps=steps)
    found = antipodal_torus(system)
    if found is None:
        return FlatTorusCertificate("no antipodal torus", [], [], 0, [], None, None, params)
    pairs, lone = found
    proof = _symbolic_proof(system, pairs, lone)
    geodesic, monodromy = _monodromy(system, pairs, lone, steps)
    holds = all(s["holds"] for s in proof)
    verdict = ("not hyperbolic" if holds and len(pairs) >= 2 else
               "no conclusion" if holds else "proof failed")
    return FlatTorusCertificate(verdict, [list(p) for p in pairs], lone, len(pairs), proof,
                                geodesic, monodromy, params)
