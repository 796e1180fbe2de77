"""The tangent flow's Schur-complement route (charts.mechanism.tangent_flow: a constant,
definite metric M solves the KKT systems through M⁻¹ computed once) against its KKT route on
the same flow, and which mechanisms take it.

Tolerance: the two routes solve the same linear systems in different orders of operations
(a few ulps per stage); over 300 RK4 steps (t = 3) of a chaotic flow (λ₁ ≲ 0.6, e^{λt} ≲ 6)
these stay below 1e-15 · 1200 stages · 6 ≈ 1e-11, relative to entries of order one (measured:
≤ 6e-14 over 1000 steps).
"""
import numpy as np
import pytest

from charts.mechanism import rotors, triple_linkage
from charts.mechanism.tangent_flow import MechanismTangentFlow

TOL = 1e-11


def _flow(mech, inner, kkt=False):
    q0, v0 = mech.random_state(seed=3)
    k = 2 if inner == "theta" else 2 * mech.dim
    flow = MechanismTangentFlow(mech, q0, v0, k, dt=0.01, reorth=10, project=100, inner=inner)
    if kkt:                                     # the same flow with its KKT route
        flow._work = flow._work[:5] + (False,) + flow._work[6:]
    return flow


@pytest.mark.parametrize("mech, schur", [
    (rotors(3), True),                                      # diagonal masses
    (triple_linkage(0.2, joint_mass=0.5), True),            # constant, definite
    (triple_linkage(0.1), False),                           # a massless joint: M semi-definite
    (triple_linkage(0.1, rod_mass=1.0), False),             # M depends on q
])
def test_the_schur_route_is_taken_where_m_is_constant_and_definite(mech, schur):
    assert _flow(mech, "theta")._work[5] is schur


@pytest.mark.parametrize("mech", [rotors(3).with_parameters(m1=1.0, m2=2.0, m3=3.0),
                                  triple_linkage(0.2, joint_mass=0.5)])
@pytest.mark.parametrize("inner", ["theta", "full"])
def test_schur_route_equals_the_kkt_route(mech, inner):
    a, b = _flow(mech, inner), _flow(mech, inner, kkt=True)
    assert a._work[5] and not b._work[5]
    a.advance(300)
    b.advance(300)
    assert np.abs(a.Z - b.Z).max() < TOL
    assert np.abs(a.logsum - b.logsum).max() < TOL
