"""charts: geodesic flows on the configuration manifolds of mechanically coupled rotators.

Kuznetsov, "Chaos and hyperchaos of geodesic flows on curved manifolds corresponding to
mechanically coupled rotators".  Public surface:

* ``RotorSystem(n, masses=None)`` — the manifold Σ cos θᵢ = 0, its charts and curvature.
"""
from .system import RotorSystem

__all__ = ["RotorSystem"]
__version__ = "0.1.0"
