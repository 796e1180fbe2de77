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

__all__ = ["chart_coordinates", "local_masses", "ambient_index"]


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
