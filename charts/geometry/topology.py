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

import itertools

import numpy as np

__all__ = ["critical_points", "euler_characteristic", "CRITICAL_RTOL"]

#: |c − Σ ±aᵢ| below this (relative to Σ|aᵢ|) counts as the critical value itself.
CRITICAL_RTOL = 1e-12


def critical_points(weights):
    """(values, indices) of the 2ᴺ critical points of F = Σ aᵢ cos θᵢ on Tᴺ: F = Σ σᵢaᵢ and
    the Morse index #{σᵢ = +1}, for every sign pattern σ ∈ {±1}ᴺ."""
    a = np.asarray(weights, dtype=float)
    signs = np.array(list(itertools.product((1.0, -1.0), repeat=a.size)))
    return signs @ a, (signs > 0).sum(axis=1)


def euler_characteristic(weights, level) -> int:
    """χ of the level set Σ aᵢ cos θᵢ = level in Tᴺ by the Morse count above (the level must
    not be a critical value Σ ±aᵢ: there the set has cone points)."""
    values, index = critical_points(weights)
    total = float(np.sum(weights))
    if np.any(np.abs(values - level) <= CRITICAL_RTOL * total):
        raise ValueError(f"level={level!r} is a critical value of sum(a cos theta): the level set "
                         "is not a manifold there (cone points), so it has no Euler "
                         "characteristic of a closed surface")
    if len(weights) % 2 == 0:
        return 0
    return 2 * int(np.sum((-1) ** index[values < level]))

