"""The pictures of the notebook interface in the docs: a Poincaré section of N = 3 found by
``integrate(..., events=...)`` (docs/figures/poincare_n3.png) and a gallery of the results'
own ``plot()`` methods (docs/figures/plotting_gallery.png), plus the numbers quoted with them.

    python scripts/notebook_figures.py
"""
from __future__ import annotations

import time

import numpy as np

import charts
from charts.plotting import new_figure, save_png

OUT = "docs/figures"


def section(t, y):
    """θ₀ ≡ 0 (mod π) crossed with sin θ₀ increasing."""
    return np.sin(y[0])


section.direction = 1


def main():
    system = charts.RotorSystem(3)
    theta, u = system.random_state(seed=3, speed=1.0)
    t0 = time.perf_counter()
    res = charts.integrate(system, theta, u, 5000.0, rtol=1e-10, events=section)
    wall = time.perf_counter() - t0
    pts = res.y_events[0]
    print(f"Poincaré section N = 3, t = 5000, rtol 1e-10: {len(pts)} crossings, {res.n_steps} steps, "
          f"{len(res.switches)} chart switches, {wall:.2f} s; max |sin θ₀| at the crossings "
          f"{np.abs(np.sin(pts[:, 0])).max():.1e}")
    sheet = np.cos(pts[:, 0]) > 0             # sin θ₀ = 0 upwards: θ₀ ≡ 0 (u₀ > 0) or π (u₀ < 0)
    fig, ax = res.plot("poincare", coords=(1, 4), s=1.5, select=lambda Y: np.cos(Y[:, 0]) > 0)
    ax.set_title(f"N = 3, section θ₀ ≡ 0, u₀ > 0: {int(sheet.sum())} of {len(pts)}\n"
                 "crossings of sin θ₀ = 0 upwards, t = 5000", fontsize=9)
    fig.set_size_inches(5.2, 4.6)
    save_png(fig, f"{OUT}/poincare_n3.png")

    fig, _ = new_figure(0, figsize=(11, 8))
    gs = fig.add_gridspec(2, 2)
    short = charts.integrate(system, theta, u, 40.0, dense_output=True)
    short.plot("angles", ax=fig.add_subplot(gs[0, 0]))
    short.plot("surface", ax=fig.add_subplot(gs[0, 1], projection="3d"))
    res.plot("poincare", ax=fig.add_subplot(gs[1, 0]), coords=(1, 4), s=1.0,
             select=lambda Y: np.cos(Y[:, 0]) > 0)
    th4, u4 = charts.RotorSystem(4).random_state(seed=0)
    lyap = charts.lyapunov_spectrum(charts.RotorSystem(4), th4, u4, 2000.0)
    lyap.plot(ax=fig.add_subplot(gs[1, 1]), paper=[0.385, 0.230])
    print(f"Lyapunov N = 4, T = 2000: {lyap}")
    save_png(fig, f"{OUT}/plotting_gallery.png")
    print(f"wrote {OUT}/poincare_n3.png, {OUT}/plotting_gallery.png")


if __name__ == "__main__":
    main()
