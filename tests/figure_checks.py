"""What every figure's axes must have (tests/test_figures.py, tests/test_accuracy_study.py)."""
import io

import numpy as np


def _draw(fig):
    fig.savefig(io.BytesIO(), format="png")


def check_axes(ax, *, z=False):
    """Labels, at least two visible non-empty tick labels per axis, finite limits."""
    _draw(ax.figure)
    axes = ("x", "y", "z") if z else ("x", "y")
    for name in axes:
        label = getattr(ax, f"get_{name}label")()
        assert label.strip(), f"no {name} label"
        lo, hi = getattr(ax, f"get_{name}lim")()
        assert np.isfinite(lo) and np.isfinite(hi) and hi > lo, (name, lo, hi)
        if getattr(ax, f"get_{name}scale")() == "log":
            assert lo > 1e-30, f"log {name} axis reaches {lo:g}"
        if not z:
            axis = getattr(ax, f"{name}axis")
            ticks = [t for minor in (False, True)
                     for t, v in zip(axis.get_ticklabels(minor=minor), axis.get_ticklocs(minor=minor))
                     if t.get_text().strip() and min(lo, hi) <= v <= max(lo, hi)]
            assert len(ticks) >= 2, f"{name}: tick labels {[t.get_text() for t in axis.get_ticklabels()]}"


def legend_off_data(ax, legend):
    """True if the legend's box does not overlap the axes' data area."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    r = FigureCanvasAgg(ax.figure).get_renderer()
    ax.figure.draw(r)
    lb, ab = legend.get_window_extent(r), ax.get_window_extent(r)
    return not lb.overlaps(ab)
