"""Argument checks shared by every analysis: one message style, one rule for time grids.

Times are in time units of the flow everywhere.  A duration on the RK4 grid (``t_final``,
``t_transient``, ``sample_every``, ...) that the caller writes must be a whole number of steps
``dt``: it is never rounded silently.  A default the caller leaves (`Documented`: the
signatures' ``reorth_every=0.1``, ``sample_every=0.1``, ``t_transient=50.0``, …) follows
``dt`` instead: the nearest whole number of steps (at least one), and where it must divide
another duration, the largest count at most that which does (docs/reliability.md).
"""
from __future__ import annotations

from math import gcd

from ..geometry.checks import flag, integer, number, shown  # noqa: F401 - flag re-exported
from ..solvers.progress import progress_reporter
from ..solvers.status import MAX_STEPS, check_step
from ..solvers.tangent import largest_divisor

__all__ = ["flag", "inner_steps", "positive_time", "nonnegative_time", "steps_of", "positive_int", "progress_reporter",
           "project_steps", "samples_of", "start_state", "unstable_dimension", "rotor_system", "linkage_system", "seed_of", "Documented"]


class Documented(float):
    """A default duration as documented in a signature (``reorth_every=Documented(0.1)``
    shows as 0.1): `steps_of` makes it follow ``dt`` where a value the caller writes would be
    refused.  Any arithmetic on it gives a plain float."""
    __slots__ = ()

    def __repr__(self):
        return repr(float(self))


#: Largest seed: the members' seeds seed, seed + 1, … stay within an int64 (NumPy's and the
#: kernels' integers).
MAX_SEED = 2 ** 62
#: Most members of one ensemble: seeds and per-member arrays are sized by it before any work,
#: and 10⁹ members at the fastest measured member (~0.1 ms) is already a day of one core.
MAX_MEMBERS = 10 ** 9
#: Most worker processes one may ask for (never more are started than there are jobs).
MAX_WORKERS = 10 ** 6
#: Largest speed |u| of an ensemble's states: ½|u|² beyond it overflows a float.
MAX_SPEED = 1e150

#: Relative slack when checking that a duration is a whole number of steps (rounding of
#: decimal inputs such as 0.1 / 0.01 = 9.999999999999998).
GRID_RTOL = 1e-9


def positive_time(name, x) -> float:
    """``x`` as a float; ValueError naming ``name`` unless finite and > 0."""
    x = number(name, x)
    if not x > 0:
        raise ValueError(f"{name} must be positive, got {x!r}")
    return x


def nonnegative_time(name, x) -> float:
    """``x`` as a float; ValueError naming ``name`` unless finite and >= 0."""
    x = number(name, x)
    if x < 0:
        raise ValueError(f"{name} must be >= 0, got {x!r}")
    return x


def steps_of(name, t, dt, *, allow_zero=False, divides=0) -> int:
    """The number of steps ``dt`` in the duration ``t``; ValueError naming ``name`` if ``t``
    is not finite, negative (or zero unless ``allow_zero``), shorter than one step, more than
    `MAX_STEPS` steps, or not a whole number of steps.  A `Documented` default is not refused:
    it gives the nearest whole number of steps (at least one if t > 0), and with ``divides``
    (a step count) the largest count at most that which divides it."""
    documented = isinstance(t, Documented)
    t = nonnegative_time(name, t) if allow_zero else positive_time(name, t)
    ratio = t / dt
    if documented and ratio <= MAX_STEPS:
        k = max(1, round(ratio)) if t > 0 else 0
        return largest_divisor(int(divides), k) if divides and k else int(k)
    if ratio > MAX_STEPS:
        raise ValueError(f"{name}={t:g} is {ratio:.3g} steps of dt={dt:g}, more than "
                         f"{MAX_STEPS:.3g}; use a larger dt or a shorter {name}")
    k = round(ratio)
    if t > 0 and k == 0:
        raise ValueError(f"{name}={t:g} is shorter than one step dt={dt:g}; use a multiple of "
                         f"dt (e.g. {dt:g}) or a smaller dt")
    if abs(k * dt - t) > GRID_RTOL * t:
        example = max(k, 1) * dt
        # six digits unless they hide the difference (t and the example, or dt, would read
        # the same): then every digit
        short = f"{example:g}" != f"{t:g}" and float(f"{dt:g}") == dt
        t_, dt_, ex_ = (f"{t:g}", f"{dt:g}", f"{example:g}") if short else \
            (repr(t), repr(dt), repr(example))
        raise ValueError(f"{name}={t_} is not a whole number of steps dt={dt_}; use a multiple "
                         f"of dt (e.g. {ex_})")
    return int(k)


def inner_steps(name, t, dt, total, outer, outer_steps) -> int:
    """`steps_of` ``t`` for a period that must divide both the run (``total`` steps) and a
    coarser period ``outer`` (``outer_steps`` steps; e.g. reorth_every inside record_every):
    a default ``t`` divides ``total``, and also ``outer_steps`` when ``outer`` was written (a
    default ``outer`` is then placed on this period's multiples by the caller)."""
    return steps_of(name, t, dt, divides=total if isinstance(outer, Documented)
                    else gcd(total, outer_steps))


def seed_of(seed, name="seed") -> int:
    """``seed`` as an int in 0..`MAX_SEED`; ValueError naming ``name`` otherwise."""
    return integer(name, seed, 0, MAX_SEED)


def positive_int(name, x, minimum=1) -> int:
    """``x`` as an int; ValueError naming ``name`` unless an integer >= ``minimum`` (an
    integral float such as 4.0 counts, 2.7 and True do not: ``charts.geometry.checks``)."""
    return integer(name, x, minimum)


def project_steps(project_every, dt) -> int:
    """Steps between projections onto the invariants (0 for ``project_every=None``: never)."""
    return 0 if project_every is None else steps_of("project_every", project_every, dt)


def samples_of(total, sample, t_final, sample_every) -> int:
    """Samples in ``total`` steps, one every ``sample`` steps; ValueError unless whole."""
    if total % sample:
        raise ValueError(f"t_final={t_final:g} must be a multiple of sample_every={sample_every:g}")
    return total // sample


def unstable_dimension(n, n_unstable) -> int:
    """m, the dimension of the expanding subspace: N−2 for None, else 1..N−2 (ValueError)."""
    m = n - 2 if n_unstable is None else positive_int("n_unstable", n_unstable)
    if not 1 <= m <= n - 2:
        raise ValueError(f"n_unstable must be in 1..{n - 2} (the positive exponents), got {m}")
    return m


def start_state(system, theta0, u0, dt=None):
    """``system.check_state(theta0, u0)`` for a flow: the velocity must not be zero; with a
    fixed step ``dt``, the step is checked against the speed (``status.check_step``: refused
    when meaningless, a StepSizeWarning when every step is cut by the step cap)."""
    theta0, u0 = rotor_system(system).check_state(theta0, u0, ("theta0", "u0"))
    speed = float(system.speed(u0))
    if not speed > 0:
        raise ValueError("u0 is zero: the geodesic flow needs a nonzero speed")
    if dt is not None:
        check_step(dt, speed, system.n)
    return theta0, u0


def rotor_system(system):
    """``system`` if it is a ``charts.RotorSystem``; TypeError naming ``system`` otherwise
    (called first by every analysis of the rotors, before the system is used)."""
    from ..geometry.system import RotorSystem
    if not isinstance(system, RotorSystem):
        raise TypeError(f"system must be a charts.RotorSystem, got {shown(system)}")
    return system


def linkage_system(system):
    """``system`` if it is a ``charts.LinkageSystem``; TypeError naming ``system`` otherwise
    (called first by every analysis of the linkage)."""
    from ..mechanism.linkage import LinkageSystem
    if not isinstance(system, LinkageSystem):
        raise TypeError(f"system must be a charts.LinkageSystem, got {shown(system)}")
    return system
