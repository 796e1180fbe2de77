"""A Poincaré section of N = 3 in one call: the crossings of θ₁ ≡ 0 (mod 2π) with u₁ > 0,
plotted in the (θ₂, u₂) plane, and the run saved as NetCDF.  The event sin θ₁ = 0 with sin θ₁
increasing holds on two sheets (θ₁ ≡ 0 with u₁ > 0, θ₁ ≡ π with u₁ < 0): ``select`` keeps one.

    python examples/poincare_section.py [T]        # T: integration time (default 2000)
"""
import sys

import numpy as np

import charts
from charts.plotting import save_png

T = float(sys.argv[1]) if len(sys.argv) > 1 else 2000.0


def section(t, y):
    """y = [θ₁, θ₂, θ₃, u₁, u₂, u₃] (ambient; θ not wrapped)."""
    return np.sin(y[0])


section.direction = 1        # only upward crossings

system = charts.RotorSystem(3)
theta, u = system.random_state(seed=3)
res = charts.integrate(system, theta, u, T, rtol=1e-10, events=section)
print(f"{len(res.t_events[0])} crossings in t = {T:g}, {len(res.switches)} chart switches")

fig, ax = res.plot("poincare", coords=(1, 4),     # θ₂ against u₂, the sheet θ₁ ≡ 0
                   select=lambda Y: np.cos(Y[:, 0]) > 0)
save_png(fig, "poincare.png")
res.save("poincare.nc")                           # charts.load("poincare.nc") reads it back
print("wrote poincare.png, poincare.nc")
