"""Events of ``integrate``, with SciPy's ``solve_ivp`` contract.

An event is a callable ``event(t, y) -> float`` whose zeros are wanted, where ``y`` is the
ambient state ``[θ₁…θ_N, u₁…u_N]`` (followed by the transported vectors p¹…pᵏ when
``transport`` is given; the same row as ``sol(t)``), θ continuous (not wrapped), for either
formulation.  Optional attributes, as in SciPy:

* ``terminal`` — False (default); True: stop at the first zero; an int k: stop at the k-th;
* ``direction`` — 0 (default): every zero; > 0: only where the function goes from negative
  to positive in the direction of integration; < 0: the other way.

After every accepted step the function is evaluated at both ends of the step's interpolant;
a sign change (or a zero end) brackets a zero, which ``scipy.optimize.brentq`` finds on the
interpolant to ``ROOT_XTOL`` in time — the interpolant's accuracy (``docs/integrators.md``),
not the root finder's, limits the event time.  A zero at both the end of one step and the
start of the next is reported once; a zero at t0 is reported, as in SciPy.
"""
from __future__ import annotations

import numpy as np

__all__ = ["check_events", "EventTracker", "ROOT_XTOL"]

#: Absolute time tolerance of the root finder (far below any interpolant's error).
ROOT_XTOL = 1e-14


def check_events(events):
    """``(function, terminal count or 0, direction)`` for each event; ValueError on bad ones."""
    if events is None:
        return []
    if callable(events):
        events = [events]
    if not isinstance(events, (list, tuple)):
        raise ValueError(f"events must be a callable or a list of callables, got {type(events).__name__}")
    out = []
    for i, ev in enumerate(events):
        if not callable(ev):
            raise ValueError(f"events[{i}] must be callable(t, y) -> float, got {type(ev).__name__}")
        term = getattr(ev, "terminal", False)
        if isinstance(term, (bool, np.bool_)):
            count = 1 if term else 0
        elif isinstance(term, (int, np.integer)) and term >= 0:
            count = int(term)
        else:
            raise ValueError(f"events[{i}].terminal must be a bool or an int >= 0, got {term!r}")
        direction = getattr(ev, "direction", 0)
        if isinstance(direction, bool) or not isinstance(direction, (int, float, np.integer, np.floating)) \
                or not np.isfinite(direction):
            raise ValueError(f"events[{i}].direction must be a number, got {direction!r}")
        out.append((ev, count, float(np.sign(direction))))
    return out


class EventTracker:
    """Finds the zeros of the events on the interpolants of the steps taken so far.

    ``t_of(s)``: the user's time at integration time s (t0 ± s).  ``sol``: the
    :class:`charts.solvers.dense.DenseSolution` being filled.  :meth:`scan` examines the
    segments added since its last call and returns the integration time of a terminal event
    (or None); ``t_events``/``y_events`` then hold, per event, the times (m,) and states
    (m, n_y) up to it, as in SciPy."""

    def __init__(self, events, sol, t_of):
        self.events = events
        self.sol = sol
        self.t_of = t_of
        self.found = [[] for _ in events]
        self.count = [0] * len(events)
        self._done = 0
        self.stop = None

    def _values(self, s, rows, k):
        return np.array([self._value(k, self.t_of(si), row) for si, row in zip(s, rows)])

    def _value(self, k, t, row):
        """events[k](t, row), checked: one finite real number, else a ValueError naming the
        event and the time (a NaN, None, a string, a complex number or an array would
        otherwise lose zeros silently)."""
        fn = self.events[k][0]
        v = fn(t, row)
        a = np.asarray(v) if isinstance(v, (np.ndarray, np.generic)) else None
        if a is not None and a.size == 1:
            v = a.reshape(()).item() if a.dtype.kind in "iuf" else v
        x = None
        if not isinstance(v, (bool, np.bool_)) and isinstance(v, (int, float)):
            try:
                x = float(v)
            except OverflowError:       # an int beyond a float's range
                x = None
        if x is None or not np.isfinite(x):
            name = getattr(fn, "__name__", type(fn).__name__)
            shown = repr(v) if len(repr(v)) <= 60 else repr(v)[:57] + "..."
            raise ValueError(f"events[{k}] ({name}) returned {shown} at t = {t:.17g}; an event "
                             "function must return one finite real number")
        return x

    def scan(self):
        if self.stop is not None or not self.events:
            return self.stop
        Seg, _ = self.sol.segments()
        lo, hi = self._done, len(Seg)
        if hi == lo:
            return None
        s0 = Seg[lo:hi, 0]
        s1 = s0 + Seg[lo:hi, 1]
        rows0 = self.sol.sample(s0)
        rows1 = self.sol.sample(s1)
        hits = []
        for k, (fn, count, direction) in enumerate(self.events):
            g0 = self._values(s0, rows0, k)
            g1 = self._values(s1, rows1, k)
            up = (g0 <= 0) & (g1 >= 0)
            down = (g0 >= 0) & (g1 <= 0)
            mask = (up & (direction >= 0)) | (down & (direction <= 0))
            for j in np.flatnonzero(mask):
                if g0[j] == 0 and g1[j] == 0:
                    continue  # identically zero over the step: no isolated crossing
                a, b = s0[j], s1[j]
                if g0[j] == 0:
                    root = a
                elif g1[j] == 0:
                    root = b
                else:
                    from scipy.optimize import brentq  # here: scipy.optimize is half of `import charts`

                    def g(s, k=k):
                        return self._value(k, self.t_of(s), self.sol.sample([s])[0])
                    root = brentq(g, a, b, xtol=ROOT_XTOL, rtol=4 * np.finfo(float).eps)
                hits.append((root, k))
        self._done = hi
        for root, k in sorted(hits):
            if self.stop is not None and root > self.stop:
                break
            if self.found[k] and root <= self.found[k][-1]:
                continue  # the same zero at the end of a step and the start of the next
            self.found[k].append(root)
            self.count[k] += 1
            if self.events[k][1] and self.count[k] >= self.events[k][1] and self.stop is None:
                self.stop = root
        return self.stop

    def results(self):
        """``(t_events, y_events)``: lists with one array per event, as in SciPy."""
        t_events, y_events = [], []
        for k in range(len(self.events)):
            s = np.array([r for r in self.found[k] if self.stop is None or r <= self.stop])
            t_events.append(np.array([self.t_of(si) for si in s], dtype=float))
            y_events.append(self.sol.sample(s) if s.size else np.zeros((0, self.sol.n_y)))
        return t_events, y_events
