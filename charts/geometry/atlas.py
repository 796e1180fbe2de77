"""The atlas: N charts × 2 branches, and the relabelling between a chart and the generated
canonical chart.

Chart k eliminates θₖ: its local coordinates are the other angles in increasing order, and
the sign of sin θₖ is its branch.  The generated code (``charts.generated.rotor_nN``) is
written for the canonical chart k = N − 1; chart k is the same code with θₖ moved last,
which is why it takes the local masses (m without mₖ, then mₖ).
"""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["chart_coordinates", "local_masses", "ambient_index", "local_index",
           "eliminated_component"]


def chart_coordinates(n: int, k: int) -> list[int]:
    """Ambient indices of the local coordinates of chart k, in local order."""
    return [i for i in range(n) if i != k]


def local_masses(masses, k: int) -> np.ndarray:
    """Masses in the local order of chart k: (m without mₖ, mₖ)."""
    masses = np.asarray(masses, dtype=float)
    return np.concatenate([np.delete(masses, k), masses[k:k + 1]])


@njit(cache=True, inline="always")
def ambient_index(a, k):
    """Ambient index of local coordinate a of chart k."""
    return a if a < k else a + 1


@njit(cache=True, inline="always")
def local_index(i, k):
    """Local coordinate of ambient index i ≠ k in chart k (the inverse of `ambient_index`)."""
    return i if i < k else i - 1


@njit(cache=True, inline="always")
def eliminated_component(q, x, o, d, sk):
    """The eliminated rotor's component of the tangent vector with local components
    x[o:o+d] at local angles q (the first d entries) of chart k, where sin θₖ = sk:
    xₖ = −Σ_α x_α sin q_α / sin θₖ (tangency, eq 10)."""
    acc = 0.0
    for a in range(d):
        acc += x[o + a] * np.sin(q[a])
    return -acc / sk
