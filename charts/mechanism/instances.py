"""Mechanisms given by their constraints: the rotor family of the paper (eqs 1, 9), the
triple linkage of Thurston–Weeks–Hunt–MacKay (Fig. 1a; the conventions of
shared/mechanisms/triple_linkage.md) and the flat four-rotor linkage of the paper's Appendix
(Fig. 1b; ``charts.mechanism.linkage.LinkageSystem``)."""
from __future__ import annotations

import numpy as np
import sympy as sp

from ..geometry.checks import number
from .model import Mechanism, MechanismError

__all__ = ["rotors", "triple_linkage", "appendix_linkage_model"]

#: The symbolic models, derived once per process and shared by instances with other
#: parameter values (``Mechanism.with_parameters``): rotors by n, the linkage by "with rods".
_MODELS = {}


def _number(name, x, positive=False, nonnegative=False):
    try:
        x = number(name, x)
    except ValueError as exc:
        raise MechanismError(str(exc)) from None
    if not np.isfinite(x) or (positive and not x > 0) or (nonnegative and not x >= 0):
        kind = "positive" if positive else "non-negative" if nonnegative else "finite"
        raise MechanismError(f"{name} must be {kind}, got {x}")
    return x


def rotors(n, masses=None, weights=None, level=0.0):
    """N rotors θ₁…θ_N on the level set Σ wᵢ cos θᵢ = level with T = ½ Σ mᵢ θ̇ᵢ² (the paper's
    eq (1) for w = 1, level 0): a Mechanism with parameters m1…mN, w1…wN, c."""
    if isinstance(n, bool) or int(n) != n or n < 2:
        raise MechanismError(f"n must be an integer >= 2, got {n!r}")
    n = int(n)
    masses = np.ones(n) if masses is None else np.asarray(masses, dtype=float)
    weights = np.ones(n) if weights is None else np.asarray(weights, dtype=float)
    for name, a in (("masses", masses), ("weights", weights)):
        if a.shape != (n,) or not np.all(np.isfinite(a)) or not np.all(a > 0):
            raise MechanismError(f"{name} must be {n} positive numbers, got {a.tolist()}")
    level = _number("level", level)
    key = ("rotors", n)
    if key not in _MODELS:
        th = sp.symbols(f"theta1:{n + 1}", real=True)
        m = sp.symbols(f"m1:{n + 1}", positive=True)
        w = sp.symbols(f"w1:{n + 1}", positive=True)
        c = sp.Symbol("c", real=True)
        params = {**{s: 1.0 for s in m}, **{s: 1.0 for s in w}, c: 0.0}
        _MODELS[key] = Mechanism(th, [sum(wi * sp.cos(t) for wi, t in zip(w, th)) - c],
                                 masses=m, parameters=params, periodic=th)
    values = {**{f"m{i + 1}": x for i, x in enumerate(masses)},
              **{f"w{i + 1}": x for i, x in enumerate(weights)}, "c": level}
    out = _MODELS[key].with_parameters(name=f"rotors(n={n})", **values)
    out.sheets = _rotor_sheets
    return out


def _rotor_sheets(mech, chart, ti, tj):
    """The points of the rotor surface with θ_i = ti, θ_j = tj (chart (i, j), N = 3): θ_k =
    ±arccos((c − w_i cos θ_i − w_j cos θ_j)/w_k), NaN where there is none; two (S, 3) arrays."""
    p = mech.parameter_values
    w = np.array([p[f"w{i + 1}"] for i in range(mech.n)])
    (i, j), k = chart, (set(range(mech.n)) - set(chart)).pop()
    cos_k = (p["c"] - w[i] * np.cos(ti) - w[j] * np.cos(tj)) / w[k]
    out = []
    for sign in (1.0, -1.0):
        q = np.empty((ti.size, 3))
        q[:, i], q[:, j] = ti, tj
        q[:, k] = np.where(np.abs(cos_k) < 1.0, sign * np.arccos(np.clip(cos_k, -1, 1)), np.nan)
        out.append(q)
    return out


def triple_linkage(r, l=1.0, R=1.0, inertia=1.0, joint_mass=0.0, rod_mass=0.0):
    """The triple linkage: three discs (moment of inertia ``inertia``) on pivots
    P_j = R(cos α_j, sin α_j), α_j = 2π(j−1)/3, rim hinges Q_j = P_j + r(cos(α_j+θ_j),
    sin(α_j+θ_j)), three rods of length l to the free joint Z = (x, y) of mass ``joint_mass``;
    q = (θ1, θ2, θ3, x, y), constraints |Q_j − Z|² − l² = 0.  Uniform rods of mass
    ``rod_mass`` add (μ/6)(|Q̇_j|² + Q̇_j·Ż + |Ż|²) to T (a configuration-dependent metric).
    With l = R + rδ and r → 0 the constraint tends to Σ cos θ_j = 3δ."""
    r = _number("r", r, positive=True)
    l = _number("l", l, positive=True)
    R = _number("R", R, positive=True)
    inertia = _number("inertia", inertia, positive=True)
    joint_mass = _number("joint_mass", joint_mass, nonnegative=True)
    rod_mass = _number("rod_mass", rod_mass, nonnegative=True)
    span = 3 * r + abs(l - R)
    out = _linkage_model(bool(rod_mass)).with_parameters(
        r=r, l=l, R=R, I=inertia, m=joint_mass, mu=rod_mass,
        bounds={"x": (-span, span), "y": (-span, span)},
        name=f"triple_linkage(r={r:g}, l={l:g}, R={R:g})")
    out.sheets = _linkage_sheets
    return out


def _linkage_sheets(mech, chart, ta, tb):
    """The points of the triple linkage with θ_a = ta, θ_b = tb (chart (a, b) of two angles):
    Z on both intersections of the circles of radius l about the hinges Q_a, Q_b, then θ_k of
    the third disc on both intersections of its rim with the circle of radius l about Z; four
    (S, 5) arrays, NaN rows where a sheet has no point (for ``charts.mechanism.surface``)."""
    p = mech.parameter_values
    r, l, R = p["r"], p["l"], p["R"]
    (a, b), k = chart, (set(range(3)) - set(chart)).pop()
    alpha = 2 * np.pi * np.arange(3) / 3
    P = R * np.stack([np.cos(alpha), np.sin(alpha)], 1)

    def hinge(j, t):
        return P[j] + r * np.stack([np.cos(alpha[j] + t), np.sin(alpha[j] + t)], -1)
    A, B = hinge(a, ta), hinge(b, tb)
    d = np.linalg.norm(B - A, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        perp = np.stack([A[:, 1] - B[:, 1], B[:, 0] - A[:, 0]], -1) / d[:, None]
        half = np.sqrt(l * l - d * d / 4)                   # NaN where the rods a, b miss
        out = []
        for s in (1.0, -1.0):
            Z = (A + B) / 2 + s * half[:, None] * perp
            D = P[k] - Z
            nD = np.linalg.norm(D, axis=-1)
            c = (l * l - nD ** 2 - r * r) / (2 * r * nD)   # cos of the hinge's angle from D
            acos = np.where(np.abs(c) < 1.0, np.arccos(np.clip(c, -1, 1)), np.nan)
            for sign in (1.0, -1.0):
                q = np.empty((ta.size, 5))
                q[:, a], q[:, b] = ta, tb
                q[:, k] = np.angle(np.exp(1j * (np.arctan2(D[:, 1], D[:, 0]) + sign * acos
                                                - alpha[k])))
                q[:, 3:] = Z
                out.append(q)
    return out


def _linkage_model(rods):
    """The triple linkage's symbolic Mechanism (parameters r, l, R, I, m, mu), with the rods'
    kinetic energy (a configuration-dependent metric) or without (M constant)."""
    key = ("triple_linkage", rods)
    if key in _MODELS:
        return _MODELS[key]
    th = sp.symbols("theta1:4", real=True)
    x, y = sp.symbols("x y", real=True)
    rs, ls, Rs, I, m, mu = sp.symbols("r l R I m mu", real=True)
    Z = sp.Matrix([x, y])
    Q = []
    for j in range(3):
        a = 2 * sp.pi * j / 3
        P = Rs * sp.Matrix([sp.cos(a), sp.sin(a)])
        Q.append(P + rs * sp.Matrix([sp.cos(a + th[j]), sp.sin(a + th[j])]))
    constraints = [((Qj - Z).T * (Qj - Z))[0] - ls ** 2 for Qj in Q]
    M = sp.diag(I, I, I, m, m)
    if rods:
        qd = sp.symbols("qd1:6", real=True)
        Zd = sp.Matrix(qd[3:])
        T = 0
        for j, Qj in enumerate(Q):
            Qd = Qj.diff(th[j]) * qd[j]
            T += mu / 6 * ((Qd.T * Qd)[0] + (Qd.T * Zd)[0] + (Zd.T * Zd)[0])
        T = sp.expand(T)
        M = M + sp.Matrix(5, 5, lambda i, k: sp.simplify(sp.diff(T, qd[i], qd[k])))
    _MODELS[key] = Mechanism((*th, x, y), constraints, M,
                             parameters={rs: 0.1, ls: 1.0, Rs: 1.0, I: 1.0, m: 0.0, mu: 1.0 if rods else 0.0},
                             periodic=th, name="triple_linkage")
    return _MODELS[key]


def _appendix_hinges(q, eps, rho):
    """The hinges of the Appendix linkage (Fig. 1b), the one home of that formula: four
    rotors turn about axes at (1, 0), (0, 1), (−1, 0), (0, −1); a rod of length R joins the
    hinge at distance ε on rotor i to the hinge at distance ρ from the centre (x, y) of a
    disk turned by α.  For SymPy q = (θ₀, θ₁, θ₂, θ₃, x, y, α), ε and ρ:
    (rotor hinges Pᵢ, disk hinges Dᵢ), each a list of four (x, y) pairs,

        P₀ = (1 − ε cos θ₀, ε sin θ₀),   P₁ = (ε sin θ₁, 1 + ε cos θ₁),
        P₂ = (−1 + ε cos θ₂, −ε sin θ₂), P₃ = (−ε sin θ₃, −1 − ε cos θ₃),
        D₀ = (x + ρ cos α, y + ρ sin α), D₁ = (x − ρ sin α, y + ρ cos α),
        D₂ = (x − ρ cos α, y − ρ sin α), D₃ = (x + ρ sin α, y − ρ cos α)."""
    t0, t1, t2, t3, x, y, a = q
    e, r = eps, rho
    P = [(1 - e * sp.cos(t0), e * sp.sin(t0)), (e * sp.sin(t1), 1 + e * sp.cos(t1)),
         (-1 + e * sp.cos(t2), -e * sp.sin(t2)), (-e * sp.sin(t3), -1 - e * sp.cos(t3))]
    D = [(x + r * sp.cos(a), y + r * sp.sin(a)), (x - r * sp.sin(a), y + r * sp.cos(a)),
         (x - r * sp.cos(a), y - r * sp.sin(a)), (x + r * sp.sin(a), y - r * sp.cos(a))]
    return P, D


def appendix_linkage_model():
    """The Appendix linkage's symbolic Mechanism (Fig. 1b), derived once per process:
    q = (θ₀, θ₁, θ₂, θ₃, x, y, α), the four constraints Fᵢ = |Pᵢ − Dᵢ|² − R² of the hinges
    of `_appendix_hinges`, M = diag(1, 1, 1, 1, m_d, m_d, I_d), parameters (eps, rho, R, m_d,
    I_d) with the values of ``LinkageSystem(0.05)``; the angles periodic.  ``LinkageSystem``
    carries it."""
    key = ("appendix_linkage",)
    if key in _MODELS:
        return _MODELS[key]
    q = sp.symbols("theta0:4 x y alpha", real=True)
    eps, rho, R, md, Id = sp.symbols("eps rho R m_d I_d", real=True)
    P, D = _appendix_hinges(q, eps, rho)
    F = [(p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2 - R ** 2 for p, d in zip(P, D)]
    _MODELS[key] = Mechanism(q, F, masses=[1, 1, 1, 1, md, md, Id],
                             parameters={eps: 0.05, rho: 0.1, R: 1.0, md: 0.0, Id: 0.0},
                             periodic=(*q[:4], q[6]), name="appendix_linkage")
    return _MODELS[key]
