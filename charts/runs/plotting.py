"""The one figure style of the project: pyplot-free figures (no global state, no GUI
backend is ever selected), PNG bytes or files written atomically."""
from __future__ import annotations

import io

from .io import atomic_write

__all__ = ["new_figure", "png_bytes", "save_png", "DPI"]

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
