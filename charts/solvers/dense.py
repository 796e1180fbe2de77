"""Dense output of ``integrate``: the solution as a function of time, ``sol(t)``.

Every accepted step of the integration loop leaves its interpolant (``charts.solvers.loop``):
for DOP853 its own 7th-order interpolant (``charts.solvers.rk.dop853_dense``, built from the
step's stages plus three more, as SciPy's ``DOP853`` dense output); for RK4 the cubic Hermite
interpolant of the step's end values and slopes (``charts.solvers.rk.hermite_dense``).

**Across chart switches.**  An interpolant lives in the coordinates of its step: the chart in
use during that step (the chart formulation) or the ambient angles (the ambient one).  Each
step's interpolant is evaluated in those coordinates and then mapped to ambient (θ, u) by the
formulation's own ``to_ambient`` with the chart parameters of that step, which are stored with
it.  A switch happens between steps (``charts.solvers.chart_formulation``), so no interpolant
spans two charts, and the ambient θ, u — continuous along the geodesic — are continuous in t
up to rounding at the switch (up to the projection's correction with ``project=True``).
Interpolating ambient samples instead would lose the interpolant's order at every switch.
"""
from __future__ import annotations

import numpy as np

from .loop import dense_sample, segment_layout

__all__ = ["DenseSolution"]


class DenseSolution:
    """The ambient state along an integrated geodesic as a function of time.

    ``sol(t)`` → ``[θ, u, p¹, …, pᵏ]``, shape ``(n_y,)`` for a scalar t or ``(n_y, m)`` for
    an array of m times (SciPy's ``OdeSolution`` convention), with n_y = (2 + k)·n;
    ``sol.theta(t)``, ``sol.u(t)``: the angles and velocities alone, shape (n,) or (m, n).
    Valid for t in ``[t_min, t_max]`` (the interval integrated; a ValueError outside).
    ``ts``: the step boundaries, in the direction of integration.  Accuracy: that of the
    method's interpolant (7th order for DOP853, 3rd for RK4), see ``docs/integrators.md``.
    """

    def __init__(self, to_ambient, ny: int, npar: int, n: int, na: int, t0: float, sign: float):
        self._to_ambient = to_ambient
        self._ny = int(ny)
        self._width = segment_layout(ny, npar)[3]
        self.n = int(n)
        self.n_y = int(na)
        self._t0 = float(t0)
        self._sign = float(sign)
        self._parts, self._iparts = [], []
        self._seg = None
        self._s_end = 0.0

    def extend(self, Seg, ISeg, count: int):
        """Append the first ``count`` segment rows written by the loop (copied)."""
        if count:
            self._parts.append(Seg[:count].copy())
            self._iparts.append(ISeg[:count].copy())
            self._seg = None

    def segments(self):
        """``(Seg, ISeg)``: the rows of every step recorded so far (``segment_layout``)."""
        if self._seg is None:
            self._seg = (np.concatenate(self._parts) if self._parts else np.zeros((0, self._width)))
            self._iseg = (np.concatenate(self._iparts) if self._iparts
                          else np.zeros((0, 1), dtype=np.int64))
            self._parts, self._iparts = [self._seg], [self._iseg]
        return self._seg, self._iseg

    def close(self, s_end: float):
        """Fix the end of the valid interval at integration time ``s_end`` (≥ 0, measured from
        t0 in the direction of integration), dropping the segments that start after it."""
        Seg, ISeg = self.segments()
        keep = int(np.searchsorted(Seg[:, 0], s_end, side="left")) if s_end > 0 else min(1, len(Seg))
        keep = max(keep, min(1, len(Seg)))
        self._seg, self._iseg = Seg[:keep], ISeg[:keep]
        self._parts, self._iparts = [self._seg], [self._iseg]
        self._s_end = float(s_end)

    @property
    def t_min(self):
        return min(self._t0, self._t0 + self._sign * self._s_end)

    @property
    def t_max(self):
        return max(self._t0, self._t0 + self._sign * self._s_end)

    @property
    def ts(self):
        Seg, _ = self.segments()
        s = np.append(Seg[:, 0], self._s_end) if len(Seg) else np.array([0.0])
        return self._t0 + self._sign * s

    def sample(self, s) -> np.ndarray:
        """Rows (m, n_y) at integration times ``s`` ≥ 0 (measured from t0 in the direction of
        integration; t = t0 ± s)."""
        Seg, ISeg = self.segments()
        s = np.ascontiguousarray(np.atleast_1d(np.asarray(s, dtype=float)))
        out = np.zeros((s.size, self.n_y))
        if s.size == 0:
            return out
        if len(Seg) == 0:
            raise ValueError("the integration took no step; the dense output is empty")
        idx = np.clip(np.searchsorted(Seg[:, 0], s, side="right") - 1, 0, len(Seg) - 1)
        x = (s - Seg[idx, 0]) / Seg[idx, 1]
        dense_sample(self._to_ambient, Seg, ISeg, self._ny, idx.astype(np.int64), x, out)
        if self._sign < 0:
            out[:, self.n:2 * self.n] *= -1.0  # integrated forwards from (θ, −u)
        return out

    def _rows(self, t):
        raw = np.asarray(t)
        if raw.dtype.kind not in "iuf" or raw.ndim > 1:
            raise ValueError(f"t must be a real number or a 1-D array of real numbers, got "
                             f"{type(t).__name__} of dtype {raw.dtype} and shape {raw.shape}")
        t_arr = raw.astype(float)
        if not np.all(np.isfinite(t_arr)):
            raise ValueError("t must be finite")
        slack = 1e-12 * max(1.0, abs(self.t_min), abs(self.t_max))
        if np.any(t_arr < self.t_min - slack) or np.any(t_arr > self.t_max + slack):
            raise ValueError(f"t outside the integrated interval [{self.t_min:g}, {self.t_max:g}]")
        s = np.clip(self._sign * (t_arr.ravel() - self._t0), 0.0, self._s_end)
        rows = self.sample(s)
        return t_arr.ndim == 0, rows

    def __call__(self, t):
        scalar, rows = self._rows(t)
        return rows[0] if scalar else rows.T

    def theta(self, t):
        scalar, rows = self._rows(t)
        return rows[0, :self.n] if scalar else rows[:, :self.n]

    def u(self, t):
        scalar, rows = self._rows(t)
        return rows[0, self.n:2 * self.n] if scalar else rows[:, self.n:2 * self.n]

    def __repr__(self):
        return f"DenseSolution(t in [{self.t_min:g}, {self.t_max:g}], {max(len(self.ts) - 1, 0)} steps)"
