"""The rotors' tolerances: when input lies on the manifold and in a chart's domain, how many
Newton steps a projection may take, and a Mechanism's ``tol=`` argument checked."""
from __future__ import annotations

from .checks import number

__all__ = ["TOL", "MAX_ITERATIONS", "positive_tolerance"]

#: Tolerances used to decide whether input lies on the manifold.  Points produced by
#: the integrators satisfy the constraint to ~1e-13; 1e-8 accepts user input rounded
#: to ~8 digits and rejects anything visibly off the manifold.
TOL = {"constraint": 1e-8, "tangency": 1e-8, "chart_domain": 1e-10}
#: Most Newton steps ``project_point`` may take (it converges in a handful; the cap keeps a
#: count the int64 loop of ``project_constraint`` can hold).
MAX_ITERATIONS = 10 ** 6


def positive_tolerance(tol) -> float:
    """``tol`` (a Mechanism's absolute tolerance) as a positive float; ValueError naming it."""
    tol = number("tol", tol)
    if not tol > 0:
        raise ValueError(f"tol must be positive, got {tol!r}")
    return tol
