"""The one exception of ``charts.mechanism``."""
from __future__ import annotations

__all__ = ["MechanismError"]


class MechanismError(ValueError):
    """An invalid mechanism or a point where it is not a smooth manifold."""
