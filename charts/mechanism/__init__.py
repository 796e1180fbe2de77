"""Mechanisms: one symbolic model for every holonomic system (docs/mechanisms.md).

``Mechanism`` (coordinates, constraints F(q) = 0, a kinetic metric, parameters, as SymPy)
derives the ambient constrained equations of motion, projections, an atlas by the implicit
function theorem, the induced metric, Christoffel symbols, Riemann tensor and the
Gauss-equation curvature; ``rotors`` and ``triple_linkage`` are instances; ``integrate_ambient``
and ``integrate_chart`` integrate a mechanism's geodesic flow; ``surface_integrals`` gives the
area, ∫K dA and the curvature's sign of a 2-dimensional configuration surface.
``charts.mechanism.tangent_flow`` advances a state and tangent vectors by the compiled flow
and its linearisation (``kernels``, on the jets compiled by ``Mechanism.compiled_jets``); the
Lyapunov exponents built on it are ``charts.analyses.mechanism_lyapunov.lyapunov_spectrum``
(an analysis: it sits in the analyses layer, with the batch statistics).
"""
from .model import Mechanism, MechanismError
from .instances import rotors, triple_linkage
from .integrate import integrate_ambient, integrate_chart
from .surface import surface_integrals

__all__ = ["Mechanism", "MechanismError", "rotors", "triple_linkage", "integrate_ambient",
           "integrate_chart", "surface_integrals"]
