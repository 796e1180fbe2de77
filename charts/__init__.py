"""charts: geodesic flows on the configuration manifolds of mechanically coupled rotators.

Kuznetsov, "Chaos and hyperchaos of geodesic flows on curved manifolds corresponding to
mechanically coupled rotators".  The public surface, by concept:

* the manifold (eqs 1-13, 22): ``RotorSystem``;
* trajectories (eqs 8, 14, 16, 19): ``integrate``;
* the paper's analyses (times in time units, ensembles as ``EnsembleResult``):
  ``lyapunov_spectrum`` (eqs 17-18), ``curvature_along_trajectory``
  (eqs 19-21 and the exact Riemann tensor), ``hyperbolicity_angles`` (section 4) and
  ``covariant_lyapunov_vectors`` (the same test by a second route, finite-time exponents),
  ``waveform`` and ``power_spectrum`` (figures 2-3);
* the flat linkage of the Appendix (its exact constraint, eq (1) as its ε → 0 limit):
  ``LinkageSystem``, ``linkage_run``, ``linkage_trajectory`` (docs/linkage.md);
* declarative runs and sweeps: ``load_scene``/``run_scene``, ``load_sweep``/``run_sweep``;
* every result saves itself (``result.save(path)``, NetCDF) and ``load(path)`` reads it back
  as its own type (``charts.archive``; the extra ``charts[io]``); results plot themselves
  (``result.plot()``, ``charts.plotting``).
"""
from .geometry.system import RotorSystem
from .solvers.integrate import IntegrationResult, integrate
from .solvers.status import ChartDomainError, IntegrationError, SingularPointError
from .analyses.ensemble import EnsembleResult
from .analyses.lyapunov import LyapunovResult, lyapunov_ensemble, lyapunov_spectrum
from .analyses.curvature import CurvatureResult, curvature_along_trajectory, gaussian_curvature_eq22
from .analyses.hyperbolicity import AngleResult, angle_statistics, hyperbolicity_angles, hyperbolicity_ensemble
from .analyses.covariant import CovariantResult, covariant_lyapunov_vectors
from .analyses.spectra import PowerSpectrum, Waveform, power_spectrum, waveform
from .archive import load
from .geometry.linkage import LinkageSystem
from .solvers.linkage import DegenerateMetricError
from .analyses.linkage import LinkageResult, linkage_run, linkage_trajectory
from .runs.scene import Scene, SceneError, load_scene, parse_scene
from .runs.runner import RunError, plan_scene, run_scene
from .runs.sweep import Sweep, SweepError, load_sweep, parse_sweep, run_sweep

__all__ = [
    "RotorSystem",
    "integrate", "IntegrationResult", "IntegrationError", "SingularPointError", "ChartDomainError",
    "EnsembleResult",
    "lyapunov_spectrum", "lyapunov_ensemble", "LyapunovResult",
    "curvature_along_trajectory", "CurvatureResult", "gaussian_curvature_eq22",
    "hyperbolicity_angles", "hyperbolicity_ensemble", "angle_statistics", "AngleResult",
    "covariant_lyapunov_vectors", "CovariantResult",
    "waveform", "power_spectrum", "Waveform", "PowerSpectrum", "load",
    "LinkageSystem", "linkage_run", "linkage_trajectory", "LinkageResult", "DegenerateMetricError",
    "Scene", "SceneError", "load_scene", "parse_scene", "run_scene", "plan_scene", "RunError",
    "Sweep", "SweepError", "load_sweep", "parse_sweep", "run_sweep",
]
from .version import __version__  # noqa: E402
