"""Eq (18)'s Gram–Schmidt, for the solvers: it lives in `charts.geometry.gram_schmidt`, below
both the solvers and ``charts.mechanism``, which use it."""
from ..geometry.gram_schmidt import (inner_term, orthonormal_rows, orthonormalize,
                                     orthonormalize_lanes)

__all__ = ["inner_term", "orthonormalize", "orthonormal_rows", "orthonormalize_lanes"]
