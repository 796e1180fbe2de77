"""Figures: the one figure style (``style``) and the pictures of trajectories and analyses.

Imported lazily by the results' ``plot()`` methods; every function returns matplotlib
``(fig, ax)`` on a pyplot-free figure (never selecting or switching a backend), or draws on
the axes it is given.  Sits below the analyses in the layers: it imports only the style,
the atomic write, the results' words for a system and (for the N = 3 surface)
``charts.geometry``."""
from .analyses import (CURVATURE_QUANTILES, LOG_FLOOR, plot_angle_law, plot_angles,
                       plot_angles_series,
                       plot_curvature, plot_drift, plot_ensemble_exponents, plot_lyapunov,
                       plot_lyapunov_spectrum, plot_spectrum)
from .style import DPI, TIME, new_figure, png_bytes, save_png, system_label
from .trajectory import (animate_rotors, plot_angles_time, plot_poincare, plot_surface,
                         plot_trajectory, plot_velocities_time, save_animation)

__all__ = ["plot_lyapunov", "plot_lyapunov_spectrum", "plot_ensemble_exponents", "plot_curvature",
           "plot_angles", "plot_angle_law",
           "plot_angles_series", "plot_spectrum", "plot_drift",
           "plot_angles_time", "plot_velocities_time", "plot_surface", "plot_poincare", "animate_rotors", "save_animation",
           "plot_trajectory", "new_figure", "png_bytes", "save_png", "system_label", "DPI", "TIME",
           "CURVATURE_QUANTILES", "LOG_FLOOR"]
