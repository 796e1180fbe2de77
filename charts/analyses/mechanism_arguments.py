"""Argument checks of the analyses on a Mechanism (``charts.analyses.mechanism_angles``,
``mechanism_curvature``, ``mechanism_covariant``): the mechanism and its start state.

What those analyses raise: `MechanismError` where ``mech`` is not a Mechanism, (q0, v0) is not
a state of it, or the flow met a singular point (or left the finite numbers); ValueError for
another bad argument; each message names the argument."""
from __future__ import annotations

from ..geometry.checks import shown
from ..mechanism.errors import MechanismError
from ..mechanism.model import Mechanism

__all__ = ["mechanism_of", "mechanism_state", "STATE_TOL"]

#: |F(q0)| accepted for a start point: the tolerance of the tangent flow that runs from it
#: (``charts.mechanism.tangent_flow.MechanismTangentFlow``).
STATE_TOL = 1e-10


def mechanism_of(mech, name="mech"):
    """``mech`` if it is a ``charts.Mechanism``; `MechanismError` naming ``name`` otherwise."""
    if not isinstance(mech, Mechanism):
        raise MechanismError(f"{name} must be a charts.Mechanism, got {shown(mech)}")
    return mech


def mechanism_state(mech, q0, v0, names=("q0", "v0")):
    """(q0, v0) as arrays, q0 on F = 0 (|F| ≤ `STATE_TOL`, J of full rank) and v0 tangent
    there; `MechanismError` naming the argument otherwise."""
    qn, vn = names
    q0 = mech._point(q0, qn)
    try:
        q0 = mech.check_point(q0, tol=STATE_TOL)
    except MechanismError as exc:
        raise MechanismError(f"{qn}: {exc}") from None
    return q0, mech.check_tangent(q0, v0, vn)
