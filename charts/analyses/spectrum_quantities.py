"""The quantities computed next from a Lyapunov spectrum: the Kolmogorov–Sinai entropy (Pesin's
formula: the sum of the positive exponents, for the smooth invariant measure of a geodesic
flow) and the Kaplan–Yorke dimension, with standard errors from the independent estimates
behind a spectrum (the batches of one run, or the members of an ensemble).

For a geodesic flow the spectrum comes in pairs ±λ with two zeros (the flow direction and the
speed), so the exponents sum to zero and the Kaplan–Yorke dimension is that of the whole
space the spectrum lives on (2N − 2 for the restricted tangent space): a check of the
spectrum rather than a measure of an attractor.
"""
from __future__ import annotations

from functools import partial

import numpy as np

from ..geometry.checks import shown
from .statistics import standard_error

__all__ = ["kolmogorov_sinai_entropy", "kaplan_yorke_dimension", "with_error",
           "entropy_with_error", "leading_entropy_with_error", "reconstructed_spectra",
           "SpectrumQuantities"]


def kolmogorov_sinai_entropy(spectrum, positive=None) -> float:
    """Σ max(λᵢ, 0): the Kolmogorov–Sinai entropy by Pesin's formula (1/time).

    ``positive``: which exponents count (a boolean mask over ``spectrum``; default those
    > 0 of ``spectrum`` itself).  An estimate of a spectrum (a batch of a run, a member of
    an ensemble) is summed over the exponents positive in the mean (`entropy_with_error`),
    each with its own sign: an exponent consistent with zero counts in every estimate or in
    none, never only where it came out positive.  A NaN exponent (a failed estimate) makes
    the entropy NaN, whether or not it would count: it is never dropped as "not positive"."""
    lam = exponents(spectrum)
    if positive is not None:
        positive = np.asarray(positive)
        if positive.dtype != bool or positive.shape != lam.shape:
            raise ValueError(f"positive must be a boolean mask of the spectrum's shape "
                             f"{lam.shape}, got {positive.dtype} of shape {positive.shape}")
    if np.isnan(lam).any():
        return float("nan")
    mask = lam > 0 if positive is None else positive
    return float(lam[mask].sum())


def kaplan_yorke_dimension(spectrum) -> float:
    """j + (λ₁ + … + λⱼ)/|λⱼ₊₁| with j the largest index whose partial sum is ≥ 0 (exponents
    sorted decreasing); 0 if λ₁ < 0, the number of exponents if every partial sum is ≥ 0;
    NaN if an exponent is NaN (never sorted to the end and dropped)."""
    lam = np.sort(exponents(spectrum))[::-1]
    if np.isnan(lam).any():
        return float("nan")
    if lam.size == 0 or lam[0] < 0:
        return 0.0
    partial = np.cumsum(lam)
    # partial sums that vanish to rounding count as ≥ 0 (a spectrum in ± pairs sums to 0)
    tol = 1e-12 * np.abs(lam).sum()
    j = int(np.nonzero(partial >= -tol)[0][-1]) + 1
    if j == lam.size:
        return float(j)
    return float(j + partial[j - 1] / abs(lam[j]))


def exponents(spectrum) -> np.ndarray:
    """``spectrum`` as a 1-D float array of exponents: real numbers, NaN allowed (a failed
    estimate, kept), ±inf not; ValueError naming ``spectrum`` otherwise."""
    a = spectrum if isinstance(spectrum, np.ndarray) else None
    if a is None:
        try:
            a = np.asarray(spectrum)
        except (TypeError, ValueError, OverflowError):
            a = np.asarray(None)
    if a.ndim != 1 or a.dtype.kind not in "iuf":
        raise ValueError(f"spectrum must be a 1-D array of real numbers, got {shown(spectrum)}")
    a = a.astype(float)
    if np.isinf(a).any():
        raise ValueError(f"spectrum has infinite entries: {shown(a)}")
    return a


def reconstructed_spectra(exponents, n_positive, total):
    """Spectra of ``total`` exponents from rows of the ``n_positive`` leading (positive)
    exponents of a geodesic flow: (λ…, zeros, −λ… reversed); rows (m, n_positive) → (m, total)."""
    E = np.atleast_2d(np.asarray(exponents, dtype=float))[:, :n_positive]
    zeros = np.zeros((E.shape[0], total - 2 * n_positive))
    return np.hstack([E, zeros, -E[:, ::-1]])


def with_error(quantity, spectrum, rows):
    """(``quantity`` of ``spectrum``, its standard error from the independent estimates
    ``rows`` of the spectrum: the batches of one run, or the members of an ensemble)."""
    rows = np.atleast_2d(np.asarray(rows, dtype=float))
    values = np.array([quantity(row) for row in rows])
    return float(quantity(spectrum)), float(standard_error(values))


def entropy_with_error(spectrum, rows):
    """(h_KS of ``spectrum``, its standard error from the independent estimates ``rows``):
    `with_error` of `kolmogorov_sinai_entropy` with the exponents that count decided once,
    by ``spectrum`` (the mean), for every row alike (a NaN in the mean or in a row gives a
    NaN entropy or error, not a smaller sum)."""
    positive = np.asarray(spectrum, dtype=float) > 0
    return with_error(partial(kolmogorov_sinai_entropy, positive=positive), spectrum, rows)


def leading_entropy_with_error(exponents, rows, n_positive):
    """(h_KS, standard error) of a geodesic flow from its leading exponents: ``exponents``
    (a run's, or the mean of an ensemble's members) and their independent estimates
    ``rows`` (a run's batches, an ensemble's members), each with at least ``n_positive``
    (N − 2) exponents.  Only the leading ``n_positive`` can count, the positive half of the
    pairs ±λ: the two zeros of the flow direction and the energy shift, and the negative
    partners, never count, even where they were computed; of the leading ones, those
    positive in ``exponents`` count in every row (`entropy_with_error`)."""
    lead = np.atleast_2d(np.asarray(exponents, dtype=float))[0, :n_positive]
    return entropy_with_error(lead, np.atleast_2d(np.asarray(rows, dtype=float))[:, :n_positive])


class SpectrumQuantities:
    """The entropy and the dimension as methods of a result: a result class supplies
    ``_spectra()`` -> (its spectrum, the independent estimates behind it as spectra)."""

    def _spectra(self):  # pragma: no cover - contract
        raise NotImplementedError

    def kolmogorov_sinai_entropy(self):
        """(h_KS, standard error): Pesin's sum of the positive exponents (1/time), its error
        from the independent estimates (a run's batches, an ensemble's members), each summed
        over the exponents positive in the spectrum (`entropy_with_error`)."""
        return entropy_with_error(*self._spectra())

    def kaplan_yorke_dimension(self):
        """(D_KY, standard error) of the relevant spectrum (for a geodesic flow, whose
        exponents sum to zero, the dimension of the whole space: a check)."""
        return with_error(kaplan_yorke_dimension, *self._spectra())
