"""Topology of the level sets S_c = {F = c} of F = Σ aᵢ cos θᵢ on the N-torus, by Morse theory.

F is a Morse function on Tᴺ (weights aᵢ > 0): its critical points are the 2ᴺ points with
every θᵢ ∈ {0, π}, with signs σᵢ = cos θᵢ = ±1, value Σ σᵢaᵢ and Hessian diag(−σᵢaᵢ), so the
Morse index (negative eigenvalues) is the number of σᵢ = +1.  For a regular level c the
sublevel set M_c = {F ≤ c} is a compact N-manifold with boundary S_c, and

    χ(M_c) = Σ over critical points below c of (−1)^index,

    χ(S_c) = 2 χ(M_c) for N odd (S_c has even dimension N − 1), 0 for N even.

For the paper's N = 3 surface (a = 1, c = 0): one minimum and three saddles of index 1 lie
below 0, χ(M) = 1 − 3 = −2 and χ(S) = −4: a closed surface of genus 3 (the Schwarz P
surface in the 3-torus).  A level set need not be connected (a = (1, 1, 5), c = 0: two tori,
χ = 0), so χ, not a genus, is what the count gives.  Independent of any metric: the Gauss–Bonnet test of
``charts.analyses.surface_integrals`` checks the curvature against it.
"""
from __future__ import annotations

import numpy as np

from .checks import finite_array, number, shown

__all__ = ["critical_points", "euler_characteristic", "check_weights", "critical_plan",
           "CRITICAL_RTOL", "MAX_CRITICAL_POINTS", "BYTES_PER_CRITICAL_POINT"]

#: |c − Σ ±aᵢ| below this (relative to Σ|aᵢ|) counts as the critical value itself.
CRITICAL_RTOL = 1e-12
#: Most critical points enumerated (2²⁴: N ≤ 24 weights).  Measured (tracemalloc) at N = 18,
#: 20 and 22: `euler_characteristic` holds `BYTES_PER_CRITICAL_POINT` bytes per point at its
#: peak and takes about 0.3 µs per point at N = 22 (N = 24: 768 MiB, some 5 s).
MAX_CRITICAL_POINTS = 1 << 24
#: Peak bytes per critical point: the pattern number, the value, the index and one
#: temporary of each (8 bytes each), measured 48.0–48.3.
BYTES_PER_CRITICAL_POINT = 48


def check_weights(weights, n=None) -> np.ndarray:
    """The weights aᵢ of F = Σ aᵢ cos θᵢ as a float array: 1-D (of length ``n`` if given),
    not empty, every entry finite and > 0; ValueError naming ``weights`` otherwise."""
    a = finite_array("weights", weights, shape=None if n is None else (n,),
                     ndim=1 if n is None else None)
    if a.size == 0:
        raise ValueError("weights must hold one weight per rotor, got none: []")
    if np.any(a <= 0):
        raise ValueError(f"weights must be finite and positive (a negative weight is the rotor "
                         f"turned by pi: theta -> theta + pi), got {shown(a)}")
    return a


def critical_plan(n) -> int:
    """The 2ᴺ critical points of N = ``n`` weights, refused (ValueError with the count and
    the memory) beyond `MAX_CRITICAL_POINTS`, before anything is allocated."""
    count = 1 << int(n)
    if count > MAX_CRITICAL_POINTS:
        need = count * BYTES_PER_CRITICAL_POINT
        raise ValueError(f"weights: N = {n} rotors have 2^{n} = {count} critical points to "
                         f"enumerate, {need / 2**30:.4g} GiB at {BYTES_PER_CRITICAL_POINT} bytes "
                         f"each; at most 2^{MAX_CRITICAL_POINTS.bit_length() - 1} = "
                         f"{MAX_CRITICAL_POINTS} are enumerated (N <= "
                         f"{MAX_CRITICAL_POINTS.bit_length() - 1}: "
                         f"{MAX_CRITICAL_POINTS * BYTES_PER_CRITICAL_POINT / 2**20:.0f} MiB)")
    return count


def critical_points(weights):
    """(values, indices) of the 2ᴺ critical points of F = Σ aᵢ cos θᵢ on Tᴺ: F = Σ σᵢaᵢ and
    the Morse index #{σᵢ = +1}, for every sign pattern σ ∈ {±1}ᴺ (in the order of
    ``itertools.product((1, -1), repeat=N)``).  ``weights``: `check_weights`; N at most
    `critical_plan`'s bound."""
    a = check_weights(weights)
    n = a.size
    pattern = np.arange(critical_plan(n), dtype=np.int64)
    values = np.zeros(pattern.size)
    index = np.zeros(pattern.size, dtype=np.int64)
    for i in range(n):                          # bit 1 of rotor i: σᵢ = −1
        minus = (pattern >> (n - 1 - i)) & 1
        values += a[i] * (1 - 2 * minus)
        index += 1 - minus
    return values, index


def euler_characteristic(weights, level) -> int:
    """χ of the level set Σ aᵢ cos θᵢ = level in Tᴺ by the Morse count above (the level must
    not be a critical value Σ ±aᵢ: there the set has cone points).  ``weights``: finite and
    positive (`check_weights`), at most 2^24 critical points (`critical_plan`); ``level`` a
    finite real number; ValueError naming the argument otherwise, before the count."""
    a = check_weights(weights)
    level = number("level", level)
    critical_plan(a.size)
    values, index = critical_points(a)
    total = float(np.sum(a))
    if np.any(np.abs(values - level) <= CRITICAL_RTOL * total):
        raise ValueError(f"level={level!r} is a critical value of sum(a cos theta): the level set "
                         "is not a manifold there (cone points), so it has no Euler "
                         "characteristic of a closed surface")
    if a.size % 2 == 0:
        return 0
    return 2 * int(np.sum((-1) ** index[values < level]))

