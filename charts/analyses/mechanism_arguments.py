"""Argument checks of the analyses on a Mechanism (``charts.analyses.mechanism_angles``,
``mechanism_curvature``, ``mechanism_covariant``): the mechanism and its start state.

What those analyses raise: `MechanismError` where ``mech`` is not a Mechanism, (q0, v0) is not
a state of it, or the flow met a singular point (or left the finite numbers); ValueError for
another bad argument; each message names the argument."""
from __future__ import annotations

import numpy as np

from ..geometry.checks import integer, shown
from ..mechanism.errors import MechanismError
from ..mechanism.model import Mechanism

__all__ = ["mechanism_of", "mechanism_state", "unstable_of", "STATE_TOL"]

#: |F(q0)| accepted for a start point: the tolerance of the tangent flow that runs from it
#: (``charts.mechanism.tangent_flow.MechanismTangentFlow``).
STATE_TOL = 1e-10


def mechanism_of(mech, name="mech"):
    """``mech`` if it is a ``charts.Mechanism`` of dimension d ≥ 2 (a geodesic flow with an
    expanding direction and a plane for a curvature); `MechanismError` naming ``name``
    otherwise."""
    if not isinstance(mech, Mechanism):
        raise MechanismError(f"{name} must be a charts.Mechanism, got {shown(mech)}")
    if mech.dim < 2:
        raise MechanismError(f"{name}: {mech.name} has a {mech.dim}-dimensional configuration "
                             "space: no expanding direction, no sectional curvature")
    return mech


def unstable_of(mech, n_unstable) -> int:
    """m, the dimension of E_u: d − 1 for None (the positive exponents of a d-dimensional
    configuration space), else 1 … d − 1; ValueError naming n_unstable otherwise."""
    d = mech.dim
    if n_unstable is None:
        return d - 1
    try:
        return integer("n_unstable", n_unstable, 1, d - 1)
    except ValueError as exc:
        raise ValueError(f"{exc} (E_u of a {d}-dimensional configuration space has at most "
                         f"{d - 1} dimension{'s' if d > 2 else ''})") from None


def mechanism_state(mech, q0, v0, names=("q0", "v0")):
    """(q0, v0) as arrays, q0 on F = 0 (|F| ≤ `STATE_TOL`, J of full rank) and v0 tangent
    there with a positive speed √(v0ᵀ M v0) (the flow's time and its exponents scale with it; at
    rest there is no flow direction); `MechanismError` naming the argument otherwise."""
    qn, vn = names
    q0 = mech._point(q0, qn)
    try:
        q0 = mech.check_point(q0, tol=STATE_TOL)
    except MechanismError as exc:
        raise MechanismError(f"{qn}: {exc}") from None
    v0 = mech.check_tangent(q0, v0, vn)
    energy = float(v0 @ mech.mass_matrix(q0) @ v0)
    if not (energy > 0 and np.isfinite(energy)):
        raise MechanismError(f"{vn} must be a moving state: its speed² {vn}ᵀ M {vn} = "
                             f"{energy:.3g} (a state at rest has no geodesic to follow)")
    return q0, v0
