"""The one figure style of the project: pyplot-free figures (no global state, no GUI
backend is ever selected), PNG bytes or files written atomically, axes given or new, angle
wrapping for plots.  No imports from the package's layers but the atomic write and the words
for a system that the results' reprs use too (``charts.io.result_words.system_label``)."""
from __future__ import annotations

import io

import numpy as np

from ..io.result_words import system_label
from ..io.atomic import atomic_write

__all__ = ["new_figure", "png_bytes", "save_png", "DPI", "figure_axes", "wrap", "broken_at_wraps",
           "TIME", "time_window", "MAX_POINTS", "system_label"]

#: Most samples drawn per line of a time series (a longer series is thinned evenly).
MAX_POINTS = 20000


def time_window(t, values, window=None, max_points=MAX_POINTS):
    """(t, values, stride): the samples of a time series inside ``window`` = (t0, t1) (all
    if None; ValueError naming the span if none is inside), then every ``stride``-th so that
    at most ``max_points`` remain (a long run drawn whole smears into a block)."""
    t = np.asarray(t, dtype=float)
    values = np.asarray(values)
    if window is not None:
        t0, t1 = (float(x) for x in window)
        keep = (t >= t0) & (t <= t1)
        if not keep.any():
            raise ValueError(f"window={tuple(window)} holds no sample: the samples span "
                             f"t = {t[0]:g} … {t[-1]:g}")
        t, values = t[keep], values[keep]
    stride = max(1, -(-t.size // int(max_points)))
    return t[::stride], values[::stride], stride

#: The time axis label of every figure.
TIME = "t (time units of the flow)"

#: Resolution of every PNG the project writes.
DPI = 110


def new_figure(nrows=1, ncols=1, *, figsize=(6, 3.5), layout="constrained", **subplots_kw):
    """``(fig, axes)`` as ``plt.subplots`` would return, on a bare ``matplotlib.figure.Figure``
    (Agg canvas on save; the process's matplotlib backend is left alone)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, layout=layout)
    if nrows == 0:
        return fig, None
    return fig, fig.subplots(nrows, ncols, **subplots_kw)


def png_bytes(fig) -> bytes:
    """The figure as PNG bytes."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI)
    return buf.getvalue()


def save_png(fig, path) -> None:
    """Write the figure to ``path`` as PNG, atomically."""
    atomic_write(path, png_bytes(fig))


def figure_axes(ax=None, **new_kw):
    """``(fig, ax)``: the figure of the given axes, or a new figure with one axes."""
    if ax is not None:
        return ax.figure, ax
    return new_figure(**new_kw)


def line_colors(k):
    """``k`` distinct line colours: matplotlib's ten-colour cycle up to ten lines; up to 20
    the ten hues of ``tab20`` dark, then the same ten light (so that neighbours differ in hue,
    where a continuous map made λ₁ and λ₂ look alike); beyond that evenly spaced colours of
    the viridis map (the cycle would repeat its colours)."""
    if k <= 10:
        return [f"C{i}" for i in range(k)]
    from matplotlib import colormaps
    if k <= 20:
        tab = colormaps["tab20"].colors
        return [tab[2 * i] for i in range(10)] + [tab[2 * i + 1] for i in range(k - 10)]
    cmap = colormaps["viridis"]
    return [cmap(x) for x in np.linspace(0.0, 0.92, k)]


def wrap(theta):
    """Angles wrapped to (−π, π]."""
    return np.pi - np.mod(np.pi - np.asarray(theta, dtype=float), 2 * np.pi)


def broken_at_wraps(angles, extra=()):
    """Wrapped copies of the angle columns ``angles`` (a list of equal-length arrays) and
    copies of the ``extra`` columns (e.g. time), with NaN inserted wherever an angle jumps by
    more than π between samples, so that lines are not drawn across the edge of (−π, π]."""
    W = [wrap(c) for c in angles]
    jump = np.zeros(max(len(W[0]) - 1, 0), dtype=bool)
    for w in W:
        jump |= np.abs(np.diff(w)) > np.pi
    where = np.flatnonzero(jump) + 1
    return ([np.insert(w, where, np.nan) for w in W] +
            [np.insert(np.asarray(e, dtype=float), where, np.nan) for e in extra])
