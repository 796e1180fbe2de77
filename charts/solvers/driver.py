"""The one time loop of the rotors' fixed-step flows: the stacked flow (state and tangent or
adjoint vectors, ``charts.solvers.tangent``) and its lanes (``charts.solvers.lanes``).  A
mechanism without the rotors' structured kernels (the linkages) runs on the generic route,
``charts.mechanism.tangent_flow.MechanismTangentFlow``.  The loop owns the step count and
the phases of what happens after a step — projection of the state, re-orthonormalisation of
the vectors (eq 18), the log-norm sums at event steps, records — and nothing else: the
formulation's named state ``flow`` (a named tuple) and its hooks do the work.

Phases follow the global step counter (`countdowns`), so a run advanced in one call or in
any number of chunks takes the same steps in the same order: bit-identical numbers.

Hooks, all compile-time arguments, inlined into the caller's kernel (so each kernel compiles
one loop with its own hooks, and no call or reference count per step is added):

* ``step(flow, rate) -> status``: one step of the flow (its sub-steps near a singular point
  included); ``rate`` is passed through untouched (the rotors' vectors hook);
* ``project(flow) -> status``: the state back onto its invariants;
* ``reorth(flow) -> status``: the vectors re-orthonormalised, their logs added to the flow's
  sums (and what else the formulation samples then);
* ``log_event(flow, e)``: the log-norm sums into row e of the flow's event logs;
* ``record(flow, row)``: the flow's record row.

A hook's status other than `RUNNING` stops the loop: (status, steps done) with the state
where the hook left it (a failing step: at its start).
"""
from __future__ import annotations

from collections import namedtuple

from ..jit import njit
from ..jit.borrowed import borrowed, keep_alive

from .status import RUNNING

__all__ = ["phased_loop", "Phases", "countdowns", "no_record", "borrowed", "keep_alive",
           "log_sums"]


#: Steps between projections of the state (0: never) and between re-orthonormalisations;
#: the first recorded global step and the steps between records (0: no records).
Phases = namedtuple("Phases", ["project_every", "reorth_every", "rec_start", "rec_every"])


@njit(cache=True, inline="always")
def countdowns(i0, project_every, reorth_every, events):
    """(steps to the next projection (−1: never), to the next re-orthonormalisation, index
    of the next event) after global step i0: the phases follow the global step counter, so
    they do not depend on how the steps are chunked."""
    to_proj = project_every - i0 % project_every if project_every > 0 else -1
    to_reorth = reorth_every - i0 % reorth_every
    ev = 0
    while ev < events.size and events[ev] <= i0:
        ev += 1
    return to_proj, to_reorth, ev


@njit(cache=True, inline="always")
def log_sums(flow, e):
    """The log-event hook of a flow whose vectors keep log-norm sums: ``flow.logsum`` into
    row e of ``flow.event_logs`` (as many entries as both hold)."""
    logsum = flow.logsum
    event_logs = flow.event_logs
    k = logsum.size
    if event_logs.shape[1] < k:         # (not min(): numba-cuda fails to type min of two ints)
        k = event_logs.shape[1]
    for r in range(k):
        event_logs[e, r] = logsum[r]


@njit(cache=True, inline="always")
def no_record(flow, row):
    """The record hook of a flow that records nothing."""
    return


@njit(cache=True, inline="always")
def _phase(countdown, every, hook, flow):
    """One step of a phase's countdown: at zero, ``hook(flow)`` and the countdown anew.
    Returns (countdown, the hook's status or RUNNING)."""
    countdown -= 1
    if countdown == 0:
        return every, hook(flow)
    return countdown, RUNNING


@njit(cache=True, inline="always")
def phased_loop(flow, nsteps, counter, phases, events, step, rate, project, reorth, log_event,
                record):
    """Advance ``flow`` by ``nsteps`` steps of ``step``; after global step i (``counter``
    (1,), incremented here): ``project`` when i % project_every == 0 (project_every = 0:
    never), ``reorth`` when i % reorth_every == 0, ``log_event(flow, e)`` when i = events[e]
    (a sorted array of global steps), ``record(flow, row)`` when i ≥ rec_start and
    (i − rec_start) % rec_every == 0, row = (i − rec_start) // rec_every.  Returns (status,
    steps done)."""
    project_every, reorth_every, rec_start, rec_every = phases
    i0 = counter[0]
    to_proj, to_reorth, ev = countdowns(i0, project_every, reorth_every, events)
    to_rec = -1
    if rec_every > 0:
        to_rec = rec_start - i0 if i0 < rec_start else rec_every - (i0 - rec_start) % rec_every
    for it in range(nsteps):
        code = step(flow, rate)
        if code != RUNNING:
            return code, it
        counter[0] += 1
        to_proj, code = _phase(to_proj, project_every, project, flow)
        if code != RUNNING:
            return code, it + 1
        to_reorth, code = _phase(to_reorth, reorth_every, reorth, flow)
        if code != RUNNING:
            return code, it + 1
        if ev < events.size and counter[0] == events[ev]:
            log_event(flow, ev)
            ev += 1
        to_rec -= 1
        if to_rec == 0:
            to_rec = rec_every
            record(flow, (counter[0] - rec_start) // rec_every)
    return RUNNING, nsteps
