"""The smallest singular value of each of many small matrices, compiled: the sine of the
smallest angle between two subspaces given by orthonormal bases (the angle tests of
``charts.analyses.hyperbolicity`` and ``charts.analyses.covariant``, section 4)."""
from __future__ import annotations

from math import copysign, sqrt

import numpy as np
from numba import njit

__all__ = ["smallest_singular_values"]

#: the unit roundoff of float64: rows count as orthogonal below c·_EPS·|a||b|.
_EPS = 2.0 ** -52


@njit(cache=True)
def smallest_singular_values(M, out):
    """out[q] = the smallest singular value of M[q], shape (r, c) with r <= c, by one-sided
    Jacobi (Hestenes) rotations of the rows of a copy until they are orthogonal: their norms
    are then the singular values, each to high relative accuracy (rounding level for the
    small matrices of the angle tests)."""
    S, r, c = M.shape
    if r > c:
        raise ValueError("smallest_singular_values: M must have no more rows than columns")
    A = np.empty((r, c))
    for q in range(S):
        A[:, :] = M[q]
        for sweep in range(60):
            rotated = False
            for i in range(r - 1):
                for j in range(i + 1, r):
                    a = 0.0
                    b = 0.0
                    g = 0.0
                    for x in range(c):
                        a += A[i, x] * A[i, x]
                        b += A[j, x] * A[j, x]
                        g += A[i, x] * A[j, x]
                    if abs(g) <= c * _EPS * sqrt(a * b):
                        continue
                    rotated = True
                    zeta = (b - a) / (2.0 * g)
                    t = copysign(1.0, zeta) / (abs(zeta) + sqrt(1.0 + zeta * zeta))
                    cs = 1.0 / sqrt(1.0 + t * t)
                    sn = cs * t
                    for x in range(c):
                        u = A[i, x]
                        v = A[j, x]
                        A[i, x] = cs * u - sn * v
                        A[j, x] = sn * u + cs * v
            if not rotated:
                break
        smin = np.inf
        for i in range(r):
            nrm = 0.0
            for x in range(c):
                nrm += A[i, x] * A[i, x]
            smin = min(smin, sqrt(nrm))
        out[q] = smin
