"""The smallest singular value of each of many small matrices, compiled: the sine of the
smallest angle between two subspaces given by orthonormal bases (the angle tests of
``charts.analyses.hyperbolicity`` and ``charts.analyses.covariant``, section 4).

3 × 3 matrices (the angle test at N = 5) take a closed route first: σ₃² is the smallest
root of the characteristic polynomial λ³ − tλ² + c₂λ − det² of MᵀM, whose coefficients
come from M directly (t = ‖M‖²_F, c₂ = ‖adj M‖²_F, det M), found by Newton's method from
0 (monotone: the cubic is increasing and concave below its smallest root).  Where the
rounding bound of that root exceeds `CLOSED_TOL`·σ_max (close smallest singular values, a
badly conditioned det) it is refined by the Rayleigh quotient ‖Mx‖/‖x‖ of its eigenvector x
of MᵀM, and where even that is ill-determined (nearly equal smallest singular values) the
matrix goes to the Jacobi rotations below."""
from __future__ import annotations

from math import copysign, sqrt

import numpy as np
from ..jit import njit

__all__ = ["smallest_singular_values", "smallest_singular_values_into", "sin_to_angle"]

#: the unit roundoff of float64: rows count as orthogonal below c·_EPS·|a||b|.
_EPS = 2.0 ** -52
#: largest rounding bound of the closed 3 × 3 route, relative to σ_max, that is accepted;
#: beyond it the root is refined by a Rayleigh quotient (`_rayleigh_3x3`).
CLOSED_TOL = 4e-15
#: smallest sin² of the angle between two rows of MᵀM − λI that the refinement accepts.
RAYLEIGH_MIN = 1e-6


@njit(cache=True, inline="always")
def _smallest_3x3(M, q):
    """σ_min of M[q] (3 × 3) by the closed route of the module doc, or −1 where its
    rounding bound exceeds `CLOSED_TOL`·σ_max."""
    a, b, c = M[q, 0, 0], M[q, 0, 1], M[q, 0, 2]
    d, e, f = M[q, 1, 0], M[q, 1, 1], M[q, 1, 2]
    g, h, i = M[q, 2, 0], M[q, 2, 1], M[q, 2, 2]
    c00 = e * i - f * h
    c01 = f * g - d * i
    c02 = d * h - e * g
    c10 = c * h - b * i
    c11 = a * i - c * g
    c12 = b * g - a * h
    c20 = b * f - c * e
    c21 = c * d - a * f
    c22 = a * e - b * d
    det = a * c00 + b * c01 + c * c02
    t = a * a + b * b + c * c + d * d + e * e + f * f + g * g + h * h + i * i
    c2 = (c00 * c00 + c01 * c01 + c02 * c02 + c10 * c10 + c11 * c11 + c12 * c12
          + c20 * c20 + c21 * c21 + c22 * c22)
    D = det * det
    if c2 == 0.0 or t == 0.0:
        return 0.0                       # rank ≤ 1
    # rounding bound of det (expansion along row 0, cofactors included)
    edet = 4.0 * _EPS * (abs(a) * (abs(e * i) + abs(f * h)) + abs(b) * (abs(f * g) + abs(d * i))
                         + abs(c) * (abs(d * h) + abs(e * g)))
    lam = 0.0
    for _ in range(100):
        p = ((lam - t) * lam + c2) * lam - D
        dp = (3.0 * lam - 2.0 * t) * lam + c2
        if p >= 0.0 or dp <= 0.0:
            break
        step = -p / dp
        new = lam + step
        if new <= lam:
            break
        lam = new
        if step <= 2.0 * _EPS * lam:
            break
    dp = (3.0 * lam - 2.0 * t) * lam + c2
    if dp <= 0.0:
        return -1.0
    # bound on δλ from the errors of det² and of evaluating the cubic, then δσ = δλ / 2σ
    err = (2.0 * abs(det) * edet + 8.0 * _EPS * (lam * (lam * (lam + t) + c2) + D)) / dp
    sig = sqrt(lam)
    if err > 2.0 * sig * CLOSED_TOL * sqrt(t) and err > (CLOSED_TOL * CLOSED_TOL) * t:
        return _rayleigh_3x3(a, b, c, d, e, f, g, h, i, lam)
    return sig


@njit(cache=True, inline="always")
def _rayleigh_3x3(a, b, c, d, e, f, g, h, i, lam):
    """σ_min of M = [[a, b, c], [d, e, f], [g, h, i]] as ‖Mx‖/‖x‖, x the eigenvector of MᵀM
    for its approximate smallest eigenvalue lam (the cross product of two rows of MᵀM − lam·I):
    the Rayleigh quotient's error is second order in x's, i.e. in lam's error over the gap
    to the next eigenvalue; −1 (Jacobi) where those rows are nearly parallel (nearly equal
    smallest singular values)."""
    g00 = a * a + d * d + g * g - lam
    g11 = b * b + e * e + h * h - lam
    g22 = c * c + f * f + i * i - lam
    g01 = a * b + d * e + g * h
    g02 = a * c + d * f + g * i
    g12 = b * c + e * f + h * i
    best = -1.0
    x0 = x1 = x2 = 0.0
    for k in range(3):        # the cross products r0 × r1, r0 × r2, r1 × r2 of the rows
        if k == 0:
            p0, p1, p2, q0, q1, q2 = g00, g01, g02, g01, g11, g12
        elif k == 1:
            p0, p1, p2, q0, q1, q2 = g00, g01, g02, g02, g12, g22
        else:
            p0, p1, p2, q0, q1, q2 = g01, g11, g12, g02, g12, g22
        y0 = p1 * q2 - p2 * q1
        y1 = p2 * q0 - p0 * q2
        y2 = p0 * q1 - p1 * q0
        yy = y0 * y0 + y1 * y1 + y2 * y2
        # sin² of the angle between the two rows
        rel = yy / ((p0 * p0 + p1 * p1 + p2 * p2) * (q0 * q0 + q1 * q1 + q2 * q2) + 1e-300)
        if rel > best:
            best = rel
            x0, x1, x2 = y0, y1, y2
    if not best > RAYLEIGH_MIN:
        return -1.0
    m0 = a * x0 + b * x1 + c * x2
    m1 = d * x0 + e * x1 + f * x2
    m2 = g * x0 + h * x1 + i * x2
    return sqrt((m0 * m0 + m1 * m1 + m2 * m2) / (x0 * x0 + x1 * x1 + x2 * x2))


@njit(cache=True)
def smallest_singular_values(M, out):
    """out[q] = the smallest singular value of M[q], shape (r, c) with r <= c, by one-sided
    Jacobi (Hestenes) rotations of the rows of a copy until they are orthogonal: their norms
    are then the singular values, each to high relative accuracy (rounding level for the
    small matrices of the angle tests)."""
    S, r, c = M.shape
    if r > c:
        raise ValueError("smallest_singular_values: M must have no more rows than columns")
    smallest_singular_values_into(M, out, np.empty((r, c)))


@njit(cache=True)
def smallest_singular_values_into(M, out, A):
    """`smallest_singular_values` with its work array A (r, c) given (r <= c, unchecked):
    allocates nothing, so that it compiles for a GPU thread too."""
    S, r, c = M.shape
    for q in range(S):
        if r == 3 and c == 3:
            sig = _smallest_3x3(M, q)
            if sig >= 0.0:
                out[q] = sig
                continue
        for i in range(r):               # loops, not a slice copy (no allocation)
            for x in range(c):
                A[i, x] = M[q, i, x]
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
            v = sqrt(nrm)
            if v < smin:                 # min(smin, v), which the GPU target lacks
                smin = v
        out[q] = smin


def sin_to_angle(sv):
    """φ = arcsin(sin φ) of sines of angles (the smallest singular values above), clipped to
    [0, 1] (rounding)."""
    return np.arcsin(np.clip(sv, 0.0, 1.0))
