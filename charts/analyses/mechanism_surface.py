"""The surface integrals of a 2-dimensional Mechanism under the rotors' public name:
``charts.surface_integrals(mech, n_grid, route)`` hands a Mechanism that is not a RotorSystem
to ``charts.mechanism.surface.surface_integrals`` (the quadrature over its angle charts, the
sheets in closed form or found by Newton's method; ``charts.analyses.mechanism_route``)."""
from __future__ import annotations

from ..mechanism.surface import surface_integrals as mechanism_surface_integrals

__all__ = ["mechanism_surface_integrals"]
