"""How a run ends, for every route (the integration loop and the tangent kernel alike):
status codes, their messages, the exceptions they raise, and the policy near singular points.

Policy.  A step never moves the point by more than a fraction of its distance to the nearest
singular point of the manifold (≈ √S, S = Σ sin²θ; fraction `CAP_FRACTION` of the method)
nor, in a chart, of its distance to the chart boundary (≈ |sin θₖ|, `DOMAIN_CAP_FRACTION`):
`step_cap`.  Within one step |Δ sin θₖ| ≤ |u|·h, so 0.5 keeps every stage strictly inside the
chart, and a trajectory aimed at a singular point approaches it geometrically until the
singular-point test (S < `SINGULAR_S`) catches it instead of stepping over it.  DOP853
controls its own error, so its cap only serves that safety.  RK4 has no error control, and
near a singular point the path turns by ~|u|h/√S per step; its local error ∝ (fraction)⁵
per step, and 0.03 keeps a close pass (S ≈ 1e-6) at an energy error ≈ 1e-8 (0.1 gave 3e-6).
For dt = 0.01 at unit speed it only binds where S < 0.1.  A fixed-step route (the tangent
kernel, the lanes) keeps its grid: a capped step is cut into equal sub-steps planned from the
cap at its start, and where the point comes closer than that plan allows, into sub-steps
each within the cap at its own start (`next_substep`), so a trajectory aimed at a singular
point approaches it geometrically on every route and stops there instead of stepping over it.  The test
S = Σ (aᵢ sin θᵢ)² < `SINGULAR_S` holds for every family member: the gradient of
Σ aᵢ cos θᵢ vanishes exactly where every sin θᵢ does, and such a point lies on the level set
only at a critical level c = Σ ±aᵢ (the paper's N = 4 at c = 0, N = 3 at c = ±1, …).
Near such a cone point the computed trajectory lives on a neighbouring level c + δ, δ its
drift from the constraint, whose neck has S ≈ 2aδ: a trajectory aimed at the cone point
passes through that neck or turns back by the sign of δ, not by the geometry.  So where a
step is capped the test is S < `singular_floor` (δ) = max(`SINGULAR_S`, `NECK_FACTOR`·a·|δ|),
a few neck radii: without projection (δ ≈ 1e-12 after a long pass) every route then stops
where the chart routes (δ = 0 by construction) and the projected ones stop.
"""
from __future__ import annotations

import warnings
from math import ceil, isfinite, sqrt

from ..jit import njit

__all__ = ["CAP_FRACTION", "DOMAIN_CAP_FRACTION", "CHART_MIN_RATIO", "SINGULAR_S", "step_cap", "sum_squares", "fixed_step_status", "substep_count", "substep_length", "next_substep", "singular_floor", "NECK_FACTOR", "RUNNING",
           "FINISHED", "OUT_FULL", "LOG_FULL", "SINGULAR", "DOMAIN", "UNDERFLOW", "NONFINITE",
           "STATUS_MESSAGES", "IntegrationError", "SingularPointError", "ChartDomainError",
           "status_error", "StepSizeWarning", "check_step", "check_duration", "MAX_STEP_LENGTH",
           "MAX_STEPS", "DT_SPEED"]

#: Largest step as a fraction of the distance √S to the nearest singular point, per method.
CAP_FRACTION = {"dop853": 0.5, "rk4": 0.03}
#: Largest step as a fraction of the distance |sin θₖ| to the boundary of chart k.
DOMAIN_CAP_FRACTION = 0.5
#: |sin θₖ| / maxᵢ |sin θᵢ| below which chart k is not used any further (a route that keeps it,
#: switching turned off, stops with the domain status): its metric's condition number is then
#: above 1 + (N − 1)·10⁸, and DOP853's error control would crawl towards the edge in steps
#: of ~1e-9 forever (measured at a ratio of 5e-5).  The switching rule (τ = 0.9) never gets
#: near it.
CHART_MIN_RATIO = 1e-4
#: Σ sin²θ below which a point counts as an N = 4 singular point (distance ≈ 1e-7): there
#: the sines carry a relative rounding error ≈ 1e-16/√S ≈ 1e-9, and the flow (whose
#: acceleration scales as 1/√S) cannot be continued meaningfully.
SINGULAR_S = 1e-14
#: S / (a·|F − c|) below which a capped step counts as singular (`singular_floor`): the
#: neck of the drifted level has S ≈ 2a|δ|, so 20 stops about three neck radii out.
NECK_FACTOR = 20.0


@njit(cache=True, inline="always")
def step_cap(S, U, fraction):
    """Largest step allowed at a point with Σ sin²θ = S and speed² U = Σ u² (see above)."""
    if U == 0.0:
        return 1e300
    return fraction * sqrt(S / U)


@njit(cache=True, inline="always")
def sum_squares(x, o, n):
    """Σ x[o + j]² over j < n: the policy's S = Σ (a sin θ)² (from the weighted sines) and
    U = Σ u² (from the velocities), for the kernels that test the policy inline."""
    acc = 0.0
    for j in range(n):
        acc += x[o + j] * x[o + j]
    return acc


@njit(cache=True, inline="always")
def fixed_step_status(S, U, dt, fraction):
    """The policy for a fixed step ``dt`` from a point with Σ sin²θ = S and speed² U:
    (NONFINITE, 0) if S + U is not finite; (SINGULAR, cap) if the step is not capped and
    S < `SINGULAR_S`; else (RUNNING, cap), where cap < dt means: cut the step into equal
    sub-steps within the cap, each starting with the singular-point test."""
    if not isfinite(S + U):
        return NONFINITE, 0.0
    hc = step_cap(S, U, fraction)
    if hc >= dt and S < SINGULAR_S:
        return SINGULAR, hc
    return RUNNING, hc


@njit(cache=True)
def singular_floor(c, wts, n, level):
    """S below which a point counts as singular, from its weighted cosines c[:n]
    (a cos θ: Σ c − level is the drift δ from the constraint) and the weights wts[:n]:
    max(`SINGULAR_S`, `NECK_FACTOR`·max(a)·|δ|) (module doc)."""
    drift = -level
    amax = 0.0
    for j in range(n):
        drift += c[j]
        if wts[j] > amax:
            amax = wts[j]
    floor = NECK_FACTOR * amax * abs(drift)
    return floor if floor > SINGULAR_S else SINGULAR_S


@njit(cache=True, inline="always")
def substep_count(dt, hc):
    """The equal sub-steps planned for a fixed step ``dt`` capped at ``hc`` by
    `fixed_step_status` (1: the step itself; `next_substep` departs from the plan where the
    point comes closer)."""
    return 1 if hc >= dt else int(ceil(dt / hc))


@njit(cache=True)
def substep_length(left, S, U, fraction):
    """The next sub-step of a capped fixed step with ``left`` (> 0) of it still to take,
    from a point with Σ sin²θ = S and speed² U: its own cap, or what is left."""
    hc = step_cap(S, U, fraction)
    return left if hc >= left else hc


@njit(cache=True)
def next_substep(left, S, U, planned, adaptive, fraction):
    """(length, adaptive) of the next sub-step of a capped fixed step: the planned equal
    sub-step (`substep_count` of them) until the point comes closer than the plan allows (its
    own cap below half the planned length: a trajectory heading into a singular point), from
    then on each within its own cap (`substep_length`).  A close pass keeps its equal
    sub-steps (and so its bits, and the backward pass retraces them); a trajectory aimed at a
    singular point approaches it geometrically instead of stepping over it.  The caller tests
    S < `singular_floor` (stop) before each sub-step."""
    if not adaptive and step_cap(S, U, fraction) < 0.5 * planned:
        adaptive = True
    if adaptive:
        return substep_length(left, S, U, fraction), True
    return planned, False


#: Most steps one duration may hold (2⁴⁰ ≈ 1.1·10¹²: days of CPU time at the kernel's rate);
#: beyond it a duration is an input error (t_final = 1e300, or dt = 1e-300), not a run.
MAX_STEPS = 2.0 ** 40
#: The default fixed step in units of 1/|u|: dt = DT_SPEED/|u| (10⁻² of a radian of geodesic
#: length per step, the paper's dt = 0.01 at unit speed).
DT_SPEED = 0.01
#: Largest geodesic length per fixed step, dt·|u| (radians of the angles at unit masses).
#: Beyond it a run is refused: between two grid points the rotors turn by up to 16 turns, so
#: every sampled output (waveforms, spectra, curvature and angle samples) aliases the motion,
#: and the Lyapunov tangent vectors, re-orthonormalised at most once per step, grow by up to
#: e^(λ₁·dt) in between: measured for N = 4 at unit speed (λ₁ ≈ 0.39), λ₂ is within 1 s.e.
#: at dt = 100, 3 s.e. off at 200 and 16 s.e. off at 400 (rounding swamps the weaker vector).
MAX_STEP_LENGTH = 100.0


class StepSizeWarning(UserWarning):
    """A fixed step longer than any step the singular-point cap lets through (see
    :func:`check_step`): the grid is coarser than the integration."""


def check_step(dt: float, speed: float, n: int) -> float:
    """Check a fixed (RK4) step ``dt`` for a flow of speed ``speed`` on N = ``n`` rotors, once
    per call (never per step).

    Refused (ValueError) when dt·|u| > `MAX_STEP_LENGTH` (the run would be meaningless, see
    there).  Warned (`StepSizeWarning`) when dt·|u| > CAP_FRACTION['rk4']·√n: the step cap
    `step_cap` (≤ 0.03·√S/|u| with S = Σ sin²θ ≤ n) then cuts every step into sub-steps, so
    the integration is as accurate as with the capped step (measured: the N = 4 exponents at
    dt = 1, 10, 100 agree with dt = 0.01 within 2 s.e.), but the grid (samples,
    re-orthonormalisation, projection) is dt and the cost is that of the sub-steps.
    """
    length = dt * speed
    if length > MAX_STEP_LENGTH:
        raise ValueError(f"dt={dt:g} is too large for the speed |u|={speed:g}: dt·|u| = "
                         f"{length:g} > {MAX_STEP_LENGTH:g} radians per step, so the samples "
                         "alias the motion and the tangent vectors outgrow double precision "
                         f"between re-orthonormalisations; use dt <= {DT_SPEED / speed:.3g}")
    limit = CAP_FRACTION["rk4"] * sqrt(n)
    if length > limit:
        warnings.warn(
            f"dt={dt:g} is too large for the speed |u|={speed:g} and the curvature near "
            f"singular points: dt·|u| = {length:.3g} > {limit:.3g}, so the step cap "
            f"(0.03·√(Σsin²θ)/|u|) cuts every step into at least {int(length / limit) + 1} "
            f"sub-steps and only the samples stay on the dt grid; dt={DT_SPEED / speed:.3g} "
            "makes the step the step", StepSizeWarning, stacklevel=3)
    return dt


def check_duration(t_final: float, speed: float, dt: float | None = None) -> float:
    """Refuse (ValueError naming t_final) a run of more than `MAX_STEPS` steps: ``dt``, or
    for an adaptive method the default fixed step DT_SPEED/|u| (a bound on its output)."""
    step = dt if dt else DT_SPEED / speed
    if t_final / step > MAX_STEPS:
        raise ValueError(f"t_final={t_final:g} is {t_final / step:.3g} steps of {step:g}, more "
                         f"than {MAX_STEPS:.3g}; use a shorter t_final"
                         + (" or a larger dt" if dt else ""))
    return t_final


RUNNING, FINISHED, OUT_FULL, LOG_FULL = 0, 1, 2, 3
SINGULAR, DOMAIN, UNDERFLOW, NONFINITE = -1, -2, -3, -4

STATUS_MESSAGES = {
    SINGULAR: "the trajectory reached a singular point of the manifold (all θᵢ ∈ {{0, π}}, "
              "sum((a sin θ)²) < {s_sing:.1e}: a critical level) at t = {t:.17g}; the geodesic "
              "cannot be continued "
              "through it. Start from a different state (the part computed up to t is in "
              "err.result).",
    DOMAIN: "a step left the domain of the current chart at t = {t:.17g}, or came so close to its "
            "boundary that the chart is ill-conditioned beyond use (|sin θₖ| < 1e-4·max|sin θ|); "
            "reduce dt, use method='dop853' (which shrinks such steps automatically), or let "
            "the chart switch (tau close to the default 0.9).",
    UNDERFLOW: "the step size underflowed at t = {t:.17g}; the solution is not resolvable at "
               "this tolerance. Loosen rtol/atol or check the initial state.",
    NONFINITE: "the state became non-finite at t = {t:.17g}; reduce dt or tighten rtol.",
}


class IntegrationError(RuntimeError):
    """The run could not be completed; ``err.result`` holds what was computed so far."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result


class SingularPointError(IntegrationError):
    """The trajectory reached a singular point of the manifold (N = 4)."""


class ChartDomainError(IntegrationError):
    """A fixed step left the domain of the current chart."""


def status_error(status: int, t: float, where: str, result=None) -> IntegrationError:
    """The exception for a negative status code at time ``t``; ``where`` names the route."""
    msg = STATUS_MESSAGES[status].format(t=t, s_sing=SINGULAR_S)
    exc = {SINGULAR: SingularPointError, DOMAIN: ChartDomainError}.get(status, IntegrationError)
    return exc(f"{where}: {msg}", result)
