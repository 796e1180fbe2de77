"""Mechanisms given by their constraints: the rotor family of the paper (eqs 1, 9) and the
triple linkage of Thurston–Weeks–Hunt–MacKay (Fig. 1a; the conventions of
shared/mechanisms/triple_linkage.md)."""
from __future__ import annotations

import numpy as np
import sympy as sp

from .model import Mechanism, MechanismError

__all__ = ["rotors", "triple_linkage"]

#: The symbolic models, derived once per process and shared by instances with other
#: parameter values (``Mechanism.with_parameters``): rotors by n, the linkage by "with rods".
_MODELS = {}


def _number(name, x, positive=False, nonnegative=False):
    try:
        x = float(x)
    except (TypeError, ValueError):
        raise MechanismError(f"{name} must be a real number, got {x!r}") from None
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
    return _MODELS[key].with_parameters(name=f"rotors(n={n})", **values)


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
    return _linkage_model(bool(rod_mass)).with_parameters(
        r=r, l=l, R=R, I=inertia, m=joint_mass, mu=rod_mass,
        bounds={"x": (-span, span), "y": (-span, span)},
        name=f"triple_linkage(r={r:g}, l={l:g}, R={R:g})")


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
