"""Lyapunov exponents of N = 4 with their convergence plot (running estimates on a log time
axis, ± standard-error bands, the paper's values dotted), saved and loaded back.

    python examples/lyapunov_convergence.py [T]    # T: averaging time (default 2000)
"""
import sys

import numpy as np

import charts
from charts.plotting import save_png

T = float(sys.argv[1]) if len(sys.argv) > 1 else 2000.0

system = charts.RotorSystem(4)
theta, u = system.random_state(seed=0)
lyap = charts.lyapunov_spectrum(system, theta, u, T, progress=True)
print(lyap)

fig, ax = lyap.plot(paper=[0.385, 0.230])        # the paper's section 2 values, unit speed
save_png(fig, "lyapunov.png")
lyap.save("lyapunov.nc")
back = charts.load("lyapunov.nc")
assert np.array_equal(back.exponents, lyap.exponents) and back.params == lyap.params
print("wrote lyapunov.png, lyapunov.nc (loaded back identical)")
