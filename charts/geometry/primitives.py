"""The pieces every compiled kernel shares, below the equations: the weighted sines and cosines
a sin θ, a cos θ of the angles (`sincos`, libm; `shifted`, from a nearby point) and the lane
block of the vectorised loops (`LANE_WIDTH`)."""
from __future__ import annotations

from math import cos, sin

import numpy as np
from ..jit import njit

__all__ = ["sincos", "shifted", "SHIFT_MAX", "LANE_WIDTH"]

#: Lanes per block of the lane loops: every lane count L passed to the ``*_lanes`` loops is a
#: multiple of it, so each block is a loop of constant length that LLVM unrolls and packs
#: into vector instructions (8 doubles: one AVX-512 register), with no remainder.
LANE_WIDTH = np.uint64(8)


@njit(cache=True, inline="always")
def sincos(y, o, n, a, s, c):
    """s, c = a sin θ, a cos θ of the angles y[o:o+n] (a = weights)."""
    for j in range(n):
        s[j] = a[j] * sin(y[o + j])
        c[j] = a[j] * cos(y[o + j])


#: |δ| up to which sin/cos(θ + δ) (the RK4 stages 2–4 and the new θ of the tangent
#: kernels, the stage points of the chart formulation) come from the
#: angle-addition formula with the Taylor polynomials below instead of libm (beyond it:
#: libm).  At |δ| = 0.05 the first omitted terms, δ¹¹/11! (relative to sin δ ≈ δ: 2.4e-21)
#: and δ¹⁰/10! (2.7e-20), are far below an ulp, so the polynomials are exact to rounding; the
#: shifts are |δ| ≤ dt·|u| ≈ 0.01 at unit speed and dt = 0.01.  (libm at every stage
#: instead: 2× the cost per step, same exponents; docs/performance.md.)
SHIFT_MAX = 0.05
_S = (-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0)
_C = (-0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0)


@njit(cache=True, inline="always")
def shifted(sj, cj, d):
    """(a sin, a cos) of θ₀ + δ from sj, cj = a sin θ₀, a cos θ₀ by the angle-addition
    formula with the polynomials for |δ| ≤ `SHIFT_MAX` (linear in sj, cj: the weight a rides
    along)."""
    d2 = d * d
    sd = d + d * d2 * (_S[0] + d2 * (_S[1] + d2 * (_S[2] + d2 * _S[3])))
    cm = d2 * (_C[0] + d2 * (_C[1] + d2 * (_C[2] + d2 * _C[3])))
    return sj + (sj * cm + cj * sd), cj + (cj * cm - sj * sd)
