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
* a mechanism's configuration manifold from its symbolic model: ``Mechanism`` (its
  constrained equations, atlas, metric, curvature by two routes) and the triple linkage of
  Fig. 1a, ``triple_linkage`` (docs/mechanisms.md);
* the flat linkage of the Appendix (its exact constraint, eq (1) as its ε → 0 limit):
  ``LinkageSystem``, ``linkage_run``, ``linkage_trajectory`` (docs/linkage.md);
* declarative runs and sweeps: ``load_scene``/``run_scene``, ``load_sweep``/``run_sweep``;
* every result saves itself (``result.save(path)``, NetCDF) and ``load(path)`` reads it back
  as its own type (``charts.io.archive``; the extra ``charts[io]``); results plot themselves
  (``result.plot()``, ``charts.plotting``).
"""
import importlib

#: Where each public name lives.  ``import charts`` imports none of them: a name is imported
#: from its home on first use (PEP 562), so that ``import charts`` costs little more than the
#: package itself, and a Lyapunov run does not pay for scenes, sweeps or the linkage
#: (docs/performance.md, "Cold start").
_HOMES = {
    "RotorSystem": ".geometry.system",
    "IntegrationResult": ".solvers.integrate",
    "integrate": ".solvers.integrate",
    "ChartDomainError": ".solvers.status",
    "IntegrationError": ".solvers.status",
    "SingularPointError": ".solvers.status",
    "DeviceUnavailable": ".solvers.device",
    "EnsembleResult": ".analyses.ensemble",
    "ErrorBarWarning": ".analyses.ensemble",
    "LyapunovResult": ".analyses.lyapunov_result",
    "lyapunov_ensemble": ".analyses.lyapunov_members",
    "lyapunov_spectrum": ".analyses.lyapunov",
    "CurvatureResult": ".analyses.curvature",
    "curvature_along_trajectory": ".analyses.curvature",
    "gaussian_curvature_eq22": ".analyses.curvature",
    "SurfaceIntegrals": ".analyses.surface_integrals",
    "surface_integrals": ".analyses.surface_integrals",
    "euler_characteristic": ".geometry.topology",
    "AngleResult": ".analyses.hyperbolicity",
    "angle_statistics": ".analyses.hyperbolicity",
    "hyperbolicity_angles": ".analyses.hyperbolicity",
    "hyperbolicity_ensemble": ".analyses.hyperbolicity",
    "AngleTally": ".analyses.angle_tally",
    "hyperbolicity_tally": ".analyses.tally_run",
    "CovariantResult": ".analyses.covariant",
    "covariant_lyapunov_vectors": ".analyses.covariant",
    "covariant_ensemble": ".analyses.clv_ensemble",
    "PowerSpectrum": ".analyses.spectra",
    "Waveform": ".analyses.spectra",
    "power_spectrum": ".analyses.spectra",
    "waveform": ".analyses.spectra",
    "load": ".io.archive",
    "Mechanism": ".mechanism.model",
    "MechanismError": ".mechanism.model",
    "triple_linkage": ".mechanism.instances",
    "LinkageSystem": ".mechanism.linkage",
    "DegenerateMetricError": ".mechanism.linkage",
    "LinkageResult": ".analyses.linkage",
    "linkage_run": ".analyses.linkage",
    "linkage_ensemble": ".analyses.linkage",
    "linkage_trajectory": ".analyses.linkage",
    "Scene": ".runs.scene",
    "SceneError": ".runs.scene",
    "load_scene": ".runs.scene",
    "parse_scene": ".runs.scene",
    "RunError": ".runs.runner",
    "plan_scene": ".runs.runner",
    "run_scene": ".runs.runner",
    "Sweep": ".runs.sweep",
    "SweepError": ".runs.sweep",
    "load_sweep": ".runs.sweep",
    "parse_sweep": ".runs.sweep",
    "run_sweep": ".runs.sweep",
}

__all__ = list(_HOMES)

from .version import __version__  # noqa: E402


def __getattr__(name):
    """Import a public name from its home on first use, or a subpackage (``charts.runs``)."""
    home = _HOMES.get(name)
    if home is None:
        if name.startswith("_"):
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
        try:
            module = importlib.import_module(f".{name}", __name__)
        except ModuleNotFoundError as e:
            if e.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
        return module
    value = getattr(importlib.import_module(home, __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
