"""A trajectory of N = 3 three ways: angles against time (wrapped, chart switches marked), the
path on the surface cos θ₁ + cos θ₂ + cos θ₃ = 0, and an animation of the rotors (GIF).

    python examples/trajectory_figures.py [T]      # T: integration time (default 40)
"""
import sys

import charts
from charts.plotting import save_animation, save_png

T = float(sys.argv[1]) if len(sys.argv) > 1 else 40.0

system = charts.RotorSystem(3)
theta, u = system.random_state(seed=3)
res = charts.integrate(system, theta, u, T, t_eval=[i * 0.05 for i in range(int(T / 0.05) + 1)])

fig, ax = res.plot("angles")
save_png(fig, "angles.png")
fig, ax = res.plot("surface")
save_png(fig, "surface.png")
anim = res.plot("animation", every=2)
save_animation(anim, "rotors.gif", fps=20)       # pillow; "rotors.mp4" needs ffmpeg
print(f"wrote angles.png, surface.png, rotors.gif ({len(res.switches)} chart switches)")
