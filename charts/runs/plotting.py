"""The figure style, for the runs layer: re-exported from its home :mod:`charts.plotting.style`."""
from ..plotting.style import DPI, new_figure, png_bytes, save_png

__all__ = ["new_figure", "png_bytes", "save_png", "DPI"]
