"""charts: geodesic flows on the configuration manifolds of mechanically coupled rotators.

Kuznetsov, "Chaos and hyperchaos of geodesic flows on curved manifolds corresponding to
mechanically coupled rotators".  Public surface:

* ``RotorSystem(n, masses=None)`` — the manifold Σ cos θᵢ = 0, its charts and curvature.
"""
from .system import RotorSystem
from .lyapunov import LyapunovResult, lyapunov_ensemble, lyapunov_spectrum
from .curvature import CurvatureResult, curvature_along_trajectory, gaussian_curvature_eq22
from .hyperbolicity import AngleResult, angle_statistics, hyperbolicity_angles, hyperbolicity_ensemble
from .spectra import power_spectrum, waveform

__all__ = ["RotorSystem", "lyapunov_spectrum", "lyapunov_ensemble", "LyapunovResult",
           "curvature_along_trajectory", "CurvatureResult", "gaussian_curvature_eq22",
           "hyperbolicity_angles", "hyperbolicity_ensemble", "angle_statistics", "AngleResult",
           "waveform", "power_spectrum"]
from .integrate import IntegrationError, IntegrationResult, integrate; __all__ += ["integrate", "IntegrationResult", "IntegrationError"]  # noqa: E402,E702
from .scene import Scene, SceneError, load_scene, parse_scene; __all__ += ["Scene", "SceneError", "load_scene", "parse_scene"]  # noqa: E402,E702
from .runner import RunError, plan_scene, run_scene; __all__ += ["run_scene", "plan_scene", "RunError"]  # noqa: E402,E702
__version__ = "0.1.0"
from .sweep import Sweep, SweepError, load_sweep, parse_sweep, run_sweep; __all__ += ["Sweep", "SweepError", "load_sweep", "parse_sweep", "run_sweep"]  # noqa: E402,E702
