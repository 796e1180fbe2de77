"""Every public callable, every parameter, hostile values (docs/reliability.md, "Bad input").

The enumeration is real: ``charts.__all__`` is walked with `inspect.signature`, and a name
without an entry here fails `test_every_public_name_has_an_entry` (a new public function must
bring its valid base call).  The user-facing functions of the analyses' modules (those the
docs name for users) are covered too; every other callable in an analyses module's
``__all__`` is an internal step (a numba kernel, or a function that takes the library's own
settings objects) and must be listed as such.

For each entry, a valid base call with tiny integration lengths (t_final = 0.5, no
transient); each parameter in turn is replaced by each value of `FIXED` (and, for an array
parameter, its wrong shapes, a NaN entry, and a non-contiguous and a read-only copy of the
valid array), then by values a Hypothesis strategy draws.  Property:

* a refusal is a ValueError/TypeError or one of the library's own errors (``charts.*``,
  e.g. SceneError, SweepError, RunError) whose message names the parameter — never an error
  from NumPy, xarray, HDF5, json, the OS or numba, nor ZeroDivision/Index/Key/Attribute/
  Recursion errors;
* an accepted call returns finite numbers (no NaN, no inf anywhere in its result);
* nonsense for every parameter (NaN, ±inf, complex, an arbitrary object, an array holding a
  NaN) is refused, unless the parameter documents that it takes such a value.
"""
from __future__ import annotations

import atexit
import dataclasses
import functools
import importlib
import inspect
import math
import os
import pkgutil
import shutil
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import charts

S3 = charts.RotorSystem(3)
S4 = charts.RotorSystem(4)
THETA, U = S4.random_state(seed=3)
THETA3, U3 = S3.random_state(seed=3)
SHORT = {"t_final": 0.5, "t_transient": 0.0}
#: A NaN exponent (a failed estimate) makes the entropy and the dimension NaN: documented,
#: never dropped (tests/test_hostile_analyses.py).
NAN_EXPONENT = "NaN entries: the answer is NaN"

#: Examples of the generated test (derandomized: the same cases on every run).
EXAMPLES = 1500

#: A folder for every file the calls write (paths given as hostile strings are relative:
#: the tests run inside it).
WORK = Path(tempfile.mkdtemp(prefix="charts-hostile-"))
atexit.register(shutil.rmtree, WORK, ignore_errors=True)


class Fresh:
    """A base value made anew for each call (an output folder that must not exist yet)."""

    def __init__(self, make):
        self.make = make


def _fresh_dir():
    return Path(tempfile.mkdtemp(dir=WORK)) / "out"


@functools.cache
def linkage():
    return charts.LinkageSystem(0.1)


@functools.cache
def linkage_state():
    return linkage().random_state(seed=1)


@functools.cache
def lyapunov_result():
    return charts.lyapunov_spectrum(S4, THETA, U, 0.5, t_transient=0.0, n_batches=2)


@functools.cache
def angle_result():
    return charts.hyperbolicity_angles(S4, THETA, U, 0.5, t_transient=0.0)


@functools.cache
def angle_tally():
    return charts.hyperbolicity_tally(S4, 2, 0.5, workers=1, t_transient=0.0)


@functools.cache
def curvature_result():
    return charts.curvature_along_trajectory(S4, THETA, U, 0.5, t_transient=0.0)


@functools.cache
def covariant_result():
    return charts.covariant_lyapunov_vectors(S4, THETA, U, 1.0, t_transient=0.0)


@functools.cache
def ensemble_result():
    return charts.lyapunov_ensemble(S4, 2, 0.5, workers=1, t_transient=0.0, n_batches=2)


@functools.cache
def saved_file():
    path = WORK / "saved.nc"
    lyapunov_result().save(path)
    return path


SCENE = {"system": {"n": 4}, "run": {"t_final": 0.5, "t_transient": 0.0},
         "effects": {"lyapunov": {"n_batches": 2}}}
SWEEP = {"name": "h", "scene": SCENE, "sweep": {"seeds": [0], "parameters": {"level": [0.0]}}}


@functools.cache
def scene_file():
    path = WORK / "scene.toml"
    path.write_text('[system]\nn = 4\n[run]\nt_final = 0.5\nt_transient = 0.0\n'
                    '[effects.lyapunov]\nn_batches = 2\n')
    return path


@functools.cache
def sweep_file():
    path = WORK / "sweep.toml"
    path.write_text('name = "h"\n[scene.system]\nn = 4\n[scene.run]\nt_final = 0.5\n'
                    't_transient = 0.0\n[scene.effects.lyapunov]\nn_batches = 2\n'
                    '[sweep]\nseeds = [0]\n[sweep.parameters]\nlevel = [0.0]\n')
    return path


def _sphere():
    import sympy
    x, y, z = sympy.symbols("x y z")
    return {"coordinates": ["x", "y", "z"], "constraints": [x ** 2 + y ** 2 + z ** 2 - 1],
            "masses": [1.0, 1.0, 1.0]}


@dataclasses.dataclass
class Entry:
    """One public callable: ``fn`` called with ``base`` (keywords; `Fresh` values made anew),
    each parameter in turn made hostile.  ``takes``: {parameter: what it documents to take;
    ``"object"``: any object, so nonsense is not refused, `NAN_EXPONENT`: NaN entries};
    ``skip``: parameters not made hostile, with why."""
    fn: object
    base: dict
    takes: dict = dataclasses.field(default_factory=dict)
    skip: dict = dataclasses.field(default_factory=dict)
    signature_of: object = None
    #: {place in the result (".K"): why NaN there is the documented answer}
    nan_ok: dict = dataclasses.field(default_factory=dict)
    #: exceptions besides the documented ones this callable raises by design, with why
    raises: dict = dataclasses.field(default_factory=dict)
    #: file parameters: a message naming the file given (its path) names the parameter
    paths: tuple = ()
    #: {parameter: the word that names it in messages}, e.g. a scene's data is named by its
    #: source label ("<scene>: ...")
    aliases: dict = dataclasses.field(default_factory=dict)

    def parameters(self):
        sig = inspect.signature(self.signature_of or self.fn)
        return [p.name for p in sig.parameters.values()
                if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"
                and p.name not in self.skip]


def method(make, name):
    """``make().name`` called with the keywords (a result's method, its result built once)."""
    def call(**kw):
        return getattr(make(), name)(**kw)
    call.__name__ = name
    return call


LINKAGE = {"system": Fresh(linkage), "q0": Fresh(lambda: linkage_state()[0]),
           "v0": Fresh(lambda: linkage_state()[1])}
ENSEMBLE = {"n_trajectories": 2, "t_final": 0.5, "workers": 1, "t_transient": 0.0}
PROGRESS = {"progress": "bool or callable"}

#: Valid base calls, by public name ("Class.method" for a method).
TABLE = {
    "RotorSystem": Entry(charts.RotorSystem, {"n": 4}),
    "integrate": Entry(charts.integrate, {"system": S4, "theta0": THETA, "u0": U, "t_final": 0.5},
                       takes={"events": "callable", "progress": "bool or callable"}),
    "lyapunov_spectrum": Entry(charts.lyapunov_spectrum,
                               {"system": S4, "theta0": THETA, "u0": U, "n_batches": 2, **SHORT},
                               takes=PROGRESS),
    "lyapunov_ensemble": Entry(charts.lyapunov_ensemble, {"system": S4, "n_batches": 2, **ENSEMBLE},
                               takes=PROGRESS),
    "curvature_along_trajectory": Entry(charts.curvature_along_trajectory,
                                        {"system": S4, "theta0": THETA, "u0": U, **SHORT},
                                        takes=PROGRESS),
    "gaussian_curvature_eq22": Entry(charts.gaussian_curvature_eq22, {"theta": THETA3}),
    "surface_integrals": Entry(charts.surface_integrals, {"system": S3, "n_grid": 16}),
    "euler_characteristic": Entry(charts.euler_characteristic,
                                  {"weights": [1.0, 1.0, 1.0], "level": 0.5}),
    "angle_statistics": Entry(charts.angle_statistics,
                              {"phi": np.linspace(0.01, 1.0, 50), "small": 0.05}),
    "hyperbolicity_angles": Entry(charts.hyperbolicity_angles,
                                  {"system": S4, "theta0": THETA, "u0": U, **SHORT},
                                  takes=PROGRESS),
    "hyperbolicity_ensemble": Entry(charts.hyperbolicity_ensemble, {"system": S4, **ENSEMBLE},
                                    takes=PROGRESS),
    "hyperbolicity_tally": Entry(charts.hyperbolicity_tally, {"system": S4, **ENSEMBLE},
                                 takes=PROGRESS),
    "covariant_lyapunov_vectors": Entry(charts.covariant_lyapunov_vectors,
                                        {"system": S4, "theta0": THETA, "u0": U, **SHORT},
                                        takes=PROGRESS),
    "covariant_ensemble": Entry(charts.covariant_ensemble, {"system": S4, **ENSEMBLE},
                                takes=PROGRESS),
    "power_spectrum": Entry(charts.power_spectrum, {"signal": np.sin(np.arange(400) * 0.05),
                                                    "dt_sample": 0.05, "segment_time": 5.0}),
    "waveform": Entry(charts.waveform, {"system": S4, "theta0": THETA, "u0": U, "t_final": 0.5},
                      takes=PROGRESS),
    "load": Entry(charts.load, {"path": Fresh(saved_file)}, paths=("path",),
                  raises={FileNotFoundError: "a missing file (tests/test_archive.py)"}),
    "Mechanism": Entry(charts.Mechanism, _sphere()),
    "triple_linkage": Entry(charts.triple_linkage, {"r": 0.3}),
    "LinkageSystem": Entry(charts.LinkageSystem, {"eps": 0.1}),
    "linkage_run": Entry(charts.linkage_run, {**LINKAGE, "t_final": 0.5, "t_transient": 0.0,
                                              "n_batches": 2, "sample_every": 0.5},
                         takes=PROGRESS,
                         nan_ok={".K": "curvature=False: K is NaN, not computed (docstring)"}),
    "linkage_ensemble": Entry(charts.linkage_ensemble,
                              {"system": Fresh(linkage), "n_batches": 2, "sample_every": 0.5,
                               **ENSEMBLE}, takes=PROGRESS),
    "linkage_trajectory": Entry(charts.linkage_trajectory, {**LINKAGE, "t_final": 0.5}),
    "LinkageSystem.check_state": Entry(lambda **k: linkage().check_state(**k),
                                       {"q": Fresh(lambda: linkage_state()[0]),
                                        "v": Fresh(lambda: linkage_state()[1])},
                                       signature_of=charts.LinkageSystem.check_state),
    "load_scene": Entry(charts.load_scene, {"path": Fresh(scene_file)}, paths=("path",)),
    "parse_scene": Entry(charts.parse_scene, {"data": SCENE}, aliases={"data": "<scene>"}),
    "plan_scene": Entry(charts.plan_scene, {"scene": Fresh(lambda: charts.parse_scene(SCENE))}),
    "run_scene": Entry(charts.run_scene, {"scene": Fresh(lambda: charts.parse_scene(SCENE)),
                                          "outdir": Fresh(_fresh_dir), "quiet": True},
                       ),
    "load_sweep": Entry(charts.load_sweep, {"path": Fresh(sweep_file)}, paths=("path",)),
    "parse_sweep": Entry(charts.parse_sweep, {"data": SWEEP}, aliases={"data": "<sweep>"}),
    "run_sweep": Entry(charts.run_sweep, {"sweep": Fresh(lambda: charts.parse_sweep(SWEEP)),
                                          "outdir": Fresh(_fresh_dir), "workers": 1,
                                          "quiet": True, "plots": False},
                       ),
    # the methods of the results that take arguments
    "LyapunovResult.localised_fraction": Entry(
        method(lyapunov_result, "localised_fraction"), {"share": 0.4},
        signature_of=charts.LyapunovResult.localised_fraction),
    "LyapunovResult.save": Entry(
        method(lyapunov_result, "save"), {"path": Fresh(lambda: WORK / "r.nc")},
        signature_of=charts.LyapunovResult.save),
    "EnsembleResult.localised_fractions": Entry(
        method(ensemble_result, "localised_fractions"), {"share": 0.4},
        signature_of=charts.EnsembleResult.localised_fractions),
    "EnsembleResult.concatenate": Entry(
        method(ensemble_result, "concatenate"), {"attribute": "exponents"},
        signature_of=charts.EnsembleResult.concatenate),
    "AngleResult.statistics": Entry(method(angle_result, "statistics"), {},
                                    signature_of=charts.AngleResult.statistics),
    "CurvatureResult.diagonal": Entry(method(curvature_result, "diagonal"), {},
                                      signature_of=charts.CurvatureResult.diagonal),
    "CurvatureResult.fraction_positive": Entry(
        method(curvature_result, "fraction_positive"), {},
        signature_of=charts.CurvatureResult.fraction_positive),
    "CovariantResult.domination": Entry(method(covariant_result, "domination"),
                                        {"windows": [0.5]},
                                        signature_of=charts.CovariantResult.domination),
    "CovariantResult.finite_time": Entry(method(covariant_result, "finite_time"),
                                         {"windows": [0.5]},
                                         signature_of=charts.CovariantResult.finite_time),
}
for _name in ("metric", "christoffel", "riemann", "metric_inverse", "check_point",
              "project_point", "best_chart"):
    TABLE[f"RotorSystem.{_name}"] = Entry(getattr(S4, _name), {"theta": THETA})
for _name in ("check_state", "project_tangent", "check_tangent"):
    TABLE[f"RotorSystem.{_name}"] = Entry(getattr(S4, _name), {"theta": THETA, "u": U})
for _name in ("energy", "speed"):
    TABLE[f"RotorSystem.{_name}"] = Entry(getattr(S4, _name), {"u": U})
TABLE["RotorSystem.random_state"] = Entry(S4.random_state, {})
TABLE["RotorSystem.inner"] = Entry(S4.inner, {"theta": THETA, "a": U, "b": U})
W = S4.project_tangent(THETA, np.ones(4))
Q, V = S4.to_chart(THETA, U, 0)
for _name in ("christoffel_contract", "curvature_operator", "sectional_curvature_gauss"):
    _a, _b = ("x", "y") if _name == "curvature_operator" else ("v", "w")
    TABLE[f"RotorSystem.{_name}"] = Entry(getattr(S4, _name), {"theta": THETA, _a: U, _b: W})
TABLE["RotorSystem.to_chart"] = Entry(S4.to_chart, {"theta": THETA, "u": U, "chart": 0})
TABLE["RotorSystem.from_chart"] = Entry(S4.from_chart, {"q": Q, "v": V, "chart": 0,
                                                        "branch": int(np.sign(np.sin(THETA[0])))})
for _name in ("constraints", "jacobian", "disk_margin", "constraint_rank_margin"):
    TABLE[f"LinkageSystem.{_name}"] = Entry(method(linkage, _name),
                                            {"q": Fresh(lambda: linkage_state()[0])},
                                            signature_of=getattr(charts.LinkageSystem, _name))
TABLE["LinkageSystem.project"] = Entry(method(linkage, "project"),
                                       {"q": Fresh(lambda: linkage_state()[0]),
                                        "v": Fresh(lambda: linkage_state()[1])},
                                       signature_of=charts.LinkageSystem.project)
TABLE["LinkageSystem.speed"] = Entry(method(linkage, "speed"),
                                     {"v": Fresh(lambda: linkage_state()[1])},
                                     signature_of=charts.LinkageSystem.speed)
TABLE["LinkageSystem.random_state"] = Entry(method(linkage, "random_state"), {},
                                            signature_of=charts.LinkageSystem.random_state)
TABLE["LinkageSystem.first_order_disk"] = Entry(method(linkage, "first_order_disk"),
                                                {"theta": THETA},
                                                signature_of=charts.LinkageSystem.first_order_disk)
TABLE["LinkageSystem.from_rotor_state"] = Entry(method(linkage, "from_rotor_state"),
                                                {"theta": THETA, "u": U},
                                                signature_of=charts.LinkageSystem.from_rotor_state)


@functools.cache
def sphere():
    return charts.Mechanism(**_sphere())


@functools.cache
def sphere_state():
    return sphere().random_state(seed=1)


SPHERE_Q = Fresh(lambda: sphere_state()[0])
SPHERE_V = Fresh(lambda: sphere_state()[1])
for _name, _base in (("random_state", {}), ("metric", {"q": SPHERE_Q}),
                     ("check_point", {"q": SPHERE_Q}), ("project_point", {"q": SPHERE_Q}),
                     ("check_tangent", {"q": SPHERE_Q, "u": SPHERE_V}),
                     ("project_velocity", {"q": SPHERE_Q, "v": SPHERE_V}),
                     ("project_tangent", {"q": SPHERE_Q, "u": SPHERE_V}),
                     ("energy", {"q": SPHERE_Q, "v": SPHERE_V}),
                     ("gaussian_curvature", {"q": SPHERE_Q}), ("christoffel", {"q": SPHERE_Q}),
                     ("constraint", {"q": SPHERE_Q}), ("jacobian", {"q": SPHERE_Q}),
                     ("inner", {"q": SPHERE_Q, "a": SPHERE_V, "b": SPHERE_V})):
    TABLE[f"Mechanism.{_name}"] = Entry(method(sphere, _name), _base,
                                        signature_of=getattr(charts.Mechanism, _name))
TABLE["Scene.wants"] = Entry(method(lambda: charts.parse_scene(SCENE), "wants"),
                             {"effect": "lyapunov"}, signature_of=charts.Scene.wants)
TABLE["AngleTally.statistics"] = Entry(method(angle_tally, "statistics"), {},
                                       signature_of=charts.AngleTally.statistics)
TABLE["RotorSystem.sectional_curvature"] = Entry(
    S4.sectional_curvature, {"theta": THETA, "v": U, "w": W})
#: A Mechanism's atlas on a RotorSystem, with a chart in either form (its other Mechanism
#: methods are its generic twin's, ``RotorSystem.mechanism``: the sphere's entries above).
TABLE["RotorSystem.lift"] = Entry(S4.lift, {"s": THETA[1:], "chart": 0, "near": THETA})
TABLE["RotorSystem.embedding_jets"] = Entry(S4.embedding_jets, {"q": THETA, "chart": 0})
TABLE["RotorSystem.chart_names"] = Entry(S4.chart_names, {"chart": 0})
TABLE["RotorSystem.gaussian_curvature"] = Entry(S3.gaussian_curvature, {"theta": THETA3})


@functools.cache
def rotor_mechanism():
    return charts.mechanism.rotors(3)


@functools.cache
def rotor_state():
    return rotor_mechanism().random_state(seed=3)


def _analyses(module, name):
    return getattr(importlib.import_module(f"charts.analyses.{module}"), name)


#: The user-facing functions of the analyses' modules (named for users in the docs).
ANALYSES = {
    "flat_tori.certify_flat_torus": Entry(_analyses("flat_tori", "certify_flat_torus"),
                                          {"system": S4, "steps": 64}),
    "curvature_certificate.certify_curvature_sign": Entry(
        _analyses("curvature_certificate", "certify_curvature_sign"),
        {"system": S3, "max_boxes": 2000}),
    "spectrum_quantities.kolmogorov_sinai_entropy": Entry(
        _analyses("spectrum_quantities", "kolmogorov_sinai_entropy"),
        {"spectrum": [0.5, 0.1, -0.1, -0.5]}, takes={"spectrum": NAN_EXPONENT},
        nan_ok={"": NAN_EXPONENT}),
    "spectrum_quantities.kaplan_yorke_dimension": Entry(
        _analyses("spectrum_quantities", "kaplan_yorke_dimension"),
        {"spectrum": [0.5, 0.1, -0.1, -0.8]}, takes={"spectrum": NAN_EXPONENT},
        nan_ok={"": NAN_EXPONENT}),
    "tangency.sign_changes": Entry(_analyses("tangency", "sign_changes"),
                                   {"t": [0.0, 1.0, 2.0], "v": [1.0, -1.0, 2.0]}),
    "finite_time.domination": Entry(
        _analyses("finite_time", "domination"),
        {"growth": np.linspace(-1.0, 1.0, 40).reshape(10, 4)[:, ::-1].copy(), "m": 1,
         "sample_every": 0.1, "windows": [0.5]}),
    "finite_time.finite_time_statistics": Entry(
        _analyses("finite_time", "finite_time_statistics"),
        {"rates": np.linspace(-1.0, 1.0, 40).reshape(10, 4), "sample_every": 0.1,
         "windows": [0.5]}),
    "statistics.small_value_law": Entry(
        _analyses("statistics", "small_value_law"),
        {"samples": np.random.default_rng(0).uniform(0.01, 1.0, 200), "x0": 0.1,
         "n_batches": 4},
        nan_ok={k: "NaN where undefined: no sample below x0, or fewer than two batches "
                   "holding one (docstring)" for k in (".exponent", ".coef2")}),
    "covariant.sample_bytes": Entry(_analyses("covariant", "sample_bytes"),
                                    {"n": 4, "variant": "restricted"}),
    "mechanism_angles.mechanism_angles": Entry(
        _analyses("mechanism_angles", "mechanism_angles"),
        {"mech": Fresh(lambda: rotor_mechanism()), "q0": Fresh(lambda: rotor_state()[0]),
         "v0": Fresh(lambda: rotor_state()[1]), **SHORT}),
    "mechanism_curvature.mechanism_curvature": Entry(
        _analyses("mechanism_curvature", "mechanism_curvature"),
        {"mech": Fresh(lambda: rotor_mechanism()), "q0": Fresh(lambda: rotor_state()[0]),
         "v0": Fresh(lambda: rotor_state()[1]), **SHORT}),
    "mechanism_covariant.mechanism_clvs": Entry(
        _analyses("mechanism_covariant", "mechanism_clvs"),
        {"mech": Fresh(lambda: rotor_mechanism()), "q0": Fresh(lambda: rotor_state()[0]),
         "v0": Fresh(lambda: rotor_state()[1]), **SHORT}),
    **{f"mechanism_ensemble.{name}": Entry(
        _analyses("mechanism_ensemble", name),
        {"mech": Fresh(lambda: rotor_mechanism()), "n_batches": 2, **ENSEMBLE}
        if name == "lyapunov_ensemble" else {"mech": Fresh(lambda: rotor_mechanism()), **ENSEMBLE},
        takes=PROGRESS)
       for name in ("lyapunov_ensemble", "hyperbolicity_ensemble", "hyperbolicity_tally",
                    "covariant_ensemble")},
    "mechanism_surface.mechanism_surface_integrals": Entry(
        _analyses("mechanism_surface", "mechanism_surface_integrals"),
        {"mech": Fresh(lambda: charts.triple_linkage(0.2)), "n_grid": 8}),
    "linkage_angles.linkage_angles": Entry(_analyses("linkage_angles", "linkage_angles"),
                                           {**LINKAGE, "t_final": 0.5, "t_transient": 0.5}),
}

#: What ``charts.__all__`` holds besides callables with an entry: the documented exceptions
#: and warnings (raised, never called by users with arguments) and the result classes, built
#: by the library (their methods that take arguments have entries above).
EXCEPTIONS = {"ChartDomainError", "IntegrationError", "SingularPointError", "DeviceUnavailable",
              "ErrorBarWarning", "MechanismError", "DegenerateMetricError", "SceneError",
              "RunError", "SweepError"}
RESULTS = {"IntegrationResult", "EnsembleResult", "LyapunovResult", "CurvatureResult",
           "SurfaceIntegrals", "AngleResult", "AngleTally", "CovariantResult", "PowerSpectrum",
           "Waveform", "LinkageResult", "Scene", "Sweep"}

#: The other callables of the analyses' ``__all__`` that are not numba kernels: internal
#: steps of the analyses above (they take the library's own settings objects, plans or
#: member jobs, or already-checked arrays), not called by users.
INTERNAL = {
    "angle_blocks": {"block_plan", "block_bytes", "angle_states", "angles_on_device",
                     "kernel_functions"},
    "angle_tally": {"carries", "member_bytes"},
    "arguments": {"flag", "rotor_system", "linkage_system", "seed_of", "inner_steps", "positive_time", "nonnegative_time", "steps_of",
                  "positive_int", "progress_reporter", "project_steps", "samples_of",
                  "start_state", "unstable_dimension"},
    "cluster": {"cluster_pool", "cluster_device", "dask_client", "check_scheduler_address",
                "sigint_held"},
    "clv_ensemble": {"clv_ensemble_settings", "clvs_on_device", "clv_block_plan",
                     "clv_block_bytes", "clv_states", "kernel_function"},
    "covariant": {"clv_dimension", "clv_settings", "clv_flow", "ginelli_start", "clv_samples",
                  "covariant_result", "forward_members", "result_bytes"},
    "curvature": {"exact_curvature_matrix", "exact_curvatures"},
    "curvature_certificate": {"sign_polynomials"},
    "ensemble": {"run_ensemble", "ensemble_arguments", "map_jobs", "stream_jobs",
                 "ensemble_result", "error_ratio_of", "warn_understated", "member_states_of",
                 "resolved_settings", "system_settings"},
    "exact_curvature": {"exact_curvatures", "exact_curvature_matrix"},
    "finite_time": {"window_means"},
    "flat_tori": {"antipodal_torus", "torus_plan"},
    "forward_pass": {"angle_settings", "angle_flow", "adjoint_start", "forward_kernel"},
    "hyperbolicity": {"angle_result", "angle_members", "angle_params", "short_settings",
                      "check_cpu_store"},
    "tally_run": {"tally_on_device", "tally_on_cpu"},
    "linkage": {"run_steps", "gauss_curvature", "frame_curvatures", "cone_distance"},
    "linkage_angles": {"angle_steps", "sin_angle"},
    "mechanism_arguments": {"mechanism_of", "mechanism_state", "unstable_of"},
    "mechanism_curvature": {"jacobi_frame", "jacobi_curvature", "riemann_curvature"},
    "mechanism_route": {"generic_mechanism", "mechanism_route"},
    "mechanism_ensemble": {"mechanism_ensemble", "member_settings", "step_of",
                           "ensemble_transient"},
    "mechanism_lyapunov": {"mechanism_rule", "resolve_transient", "auto_transient",
                           "settings_before_pilot"},
    "mechanism_covariant": {"gram_schmidt_factor"},
    "mechanism_angles": {"sin_angle", "root_metric", "angle_grid"},
    "lyapunov": {"resolve_transient", "lyapunov_settings", "lyapunov_flow", "lyapunov_schedule", "lyapunov_result",
                 "chunk_sizes", "averaging_logs", "end_transient", "reconstruct_spectrum",
                 "auto_transient", "transient_rule", "identify_nonphysical",
                 "exponents_from_marks"},
    "lyapunov_members": {"lyapunov_lanes", "lyapunov_device", "member_states", "members_pay",
                         "plan_memory", "result_bytes"},
    "singular_values": {"smallest_singular_values", "smallest_singular_values_into",
                        "sin_to_angle"},
    "spectrum_quantities": {"with_error", "entropy_with_error", "leading_entropy_with_error",
                            "reconstructed_spectra"},
    "statistics": {"standard_error", "batch_ends", "batch_estimates", "pool_small_value_laws",
                   "block_minima", "law_from_batches", "jackknife_slopes"},
    "tally_checkpoint": {"check_resumed"},
    "surface_integrals": {"surface_plan", "surface_nodes", "tangent_frames"},
    "tangency": {"oriented_volume", "closest_passage"},
    "adjoint_pass": {"backward_kernel"},
    "transients": {"transient_rule", "scaled_transient", "resolve_transient", "kinetic_speed",
                   "auto_duration"},
    "worker_pool": {"worker_pool", "pool_workers", "workers_of"},
}

ALL = {**TABLE, **ANALYSES}


class Opaque:
    """An object of no type any parameter documents."""

    def __repr__(self):
        return "Opaque()"


#: Hostile values tried on every parameter: (label, value).  NaN, ±inf, a complex number, an
#: opaque object and a list holding a NaN are nonsense for every parameter (`NONSENSE`).
FIXED = [("0", 0), ("-1", -1), ("-2.5", -2.5), ("0.3", 0.3), ("1e300", 1e300),
         ("10**400", 10 ** 400), ("2**63", 2 ** 63), ("nan", math.nan), ("inf", math.inf),
         ("-inf", -math.inf), ("True", True), ("False", False), ("'x'", "x"), ("''", ""),
         ("None", None), ("1j", 1j), ("Opaque()", Opaque()), ("[]", []), ("[nan]", [math.nan]),
         ("{'a': 1}", {"a": 1}), ("zeros(2, 3)", np.zeros((2, 3))),
         ("float32 nan", np.float32("nan"))]
NONSENSE = {"nan", "inf", "-inf", "1j", "Opaque()", "[nan]", "float32 nan", "NaN entry"}


def _variants(base):
    """The hostile variants of a valid array argument: wrong shapes, a NaN entry, and two
    valid copies (non-contiguous, read-only) that must be accepted like the original."""
    try:
        a = np.asarray(base, dtype=float) if isinstance(base, (list, tuple, np.ndarray)) \
            else None
    except (TypeError, ValueError):         # not an array of numbers (names, expressions)
        a = None
    if a is None or a.size == 0:
        return []
    nan = a.copy()
    nan.flat[a.size // 2] = math.nan
    strided = np.repeat(a, 2, axis=-1)[..., ::2]
    frozen = a.copy()
    frozen.flags.writeable = False
    return [("wrong shape (extra axis)", a[None]), ("wrong shape (one less)", a.ravel()[:-1]),
            ("NaN entry", nan), ("non-contiguous", strided), ("read-only", frozen),
            ("int dtype", np.ones(a.shape, dtype=np.int64))]


#: Error types a refusal may have: these, and the library's own (defined in ``charts``).
DOCUMENTED = (ValueError, TypeError)


def _documented(exc) -> bool:
    cls = type(exc)
    return cls in DOCUMENTED or cls.__module__.startswith("charts")


def _nonfinite(out, seen=None, depth=0):
    """Where ``out`` holds a non-finite number (a path such as ".exponents[2]"), or None."""
    seen = set() if seen is None else seen
    if id(out) in seen or depth > 6:
        return None
    seen.add(id(out))
    if out is None or isinstance(out, (str, bytes, bool, np.bool_, Path, type)):
        return None
    if isinstance(out, (int, np.integer)):
        return None
    if isinstance(out, (float, complex, np.floating, np.complexfloating)):
        return None if np.isfinite(out) else ""
    if isinstance(out, np.ndarray):
        if out.dtype.kind in "fc":
            return None if np.all(np.isfinite(out)) else f"[{np.flatnonzero(~np.isfinite(out))[:3]}]"
        if out.dtype.kind == "O":
            return _nonfinite(list(out.ravel()), seen, depth + 1)
        return None
    if isinstance(out, dict):
        items = out.items()
    elif isinstance(out, (list, tuple)):
        items = enumerate(out)
    elif dataclasses.is_dataclass(out):
        items = ((f.name, getattr(out, f.name)) for f in dataclasses.fields(out))
    else:
        return None
    for key, value in items:
        where = _nonfinite(value, seen, depth + 1)
        if where is not None:
            return f".{key}{where}"
    return None


def _base(entry):
    return {k: (v.make() if isinstance(v, Fresh) else v) for k, v in entry.base.items()}


def check(name, param, label, value):
    """One call of ``ALL[name]`` with ``param`` set to ``value``; the property of the module
    docstring, or an AssertionError saying what escaped."""
    entry = ALL[name]
    kwargs = {**_base(entry), param: value}
    what = f"{name}({param}={label})"
    cwd = os.getcwd()
    os.chdir(WORK)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = entry.fn(**kwargs)
    except Exception as exc:            # noqa: BLE001 - the property is about every exception
        assert _documented(exc) or type(exc) in entry.raises, \
            f"{what}: {type(exc).__module__}.{type(exc).__name__}: {exc}"
        named = param in str(exc) or entry.aliases.get(param, param) in str(exc) or (
            param in entry.paths and isinstance(value, str)
                                      and value != "" and value in str(exc))
        assert named, f"{what}: the message does not name {param!r}: {exc}"
        return "refused"
    finally:
        os.chdir(cwd)
    takes = entry.takes.get(param, "")
    if label in NONSENSE and not (takes == NAN_EXPONENT and "nan" in label.lower()):
        assert "object" in takes, \
            f"{what}: accepted nonsense silently, returned {type(out).__name__}"
    where = _nonfinite(out)
    assert where is None or any(where.startswith(p) for p in entry.nan_ok), \
        f"{what}: returned non-finite numbers at {where!r}"
    return "accepted"


def _valid(entry, param, value) -> bool:
    """``value`` is a documented setting of ``param``, not a hostile one: None where the
    signature's default is None, True/False/1/0 where it is a bool (their runs are the
    entry's own tests)."""
    sig = inspect.signature(entry.signature_of or entry.fn).parameters
    default = sig[param].default if param in sig else inspect.Parameter.empty
    if value is None:
        return default is None
    if param == "dt" and _whole_steps(entry, value):
        return True
    return isinstance(default, bool) and isinstance(value, int) and value in (0, 1)


def _whole_steps(entry, dt) -> bool:
    """A step ``dt`` in (0, 1] that divides the entry's t_final into a whole number of steps
    (as the library's grid check reads it): a valid run, only long (4.3e-10 is 1.2e9 steps of
    a t_final of 0.5), not a hostile value — as a t_final of 10⁴ is left out of `HOSTILE`."""
    t_final = entry.base.get("t_final")
    if isinstance(dt, bool) or not isinstance(dt, (float, np.floating)) \
            or not isinstance(t_final, (int, float)) or not 0.0 < dt <= 1.0:
        return False
    k = round(t_final / dt)
    return 0 < k <= 2.0 ** 40 and abs(k * dt - t_final) <= 1e-9 * t_final


def cases(name):
    entry = ALL[name]
    for param in entry.parameters():
        base = entry.base.get(param)
        for label, value in FIXED + _variants(base if not isinstance(base, Fresh) else None):
            if not _valid(entry, param, value):
                yield param, label, value


def test_every_public_name_has_an_entry():
    """A new public name fails here until it has a base call (or is an exception, a warning
    or a result class, whose methods with arguments have entries)."""
    public = set(charts.__all__)
    missing = public - set(TABLE) - EXCEPTIONS - RESULTS
    assert missing == set(), f"public names without a hostile-input entry: {sorted(missing)}"
    for name in EXCEPTIONS:
        assert issubclass(getattr(charts, name), (Exception, Warning)), name
    for name in RESULTS:
        assert isinstance(getattr(charts, name), type), name
    assert not (set(TABLE) | RESULTS | EXCEPTIONS) - public - {
        n for n in TABLE if "." in n}, "entries for names that are no longer public"


def test_every_callable_of_the_analyses_modules_is_covered_or_internal():
    from numba.core.registry import CPUDispatcher
    import charts.analyses as analyses
    unclassified = []
    for info in pkgutil.iter_modules(analyses.__path__):
        module = importlib.import_module(f"charts.analyses.{info.name}")
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name)
            if (not callable(obj) or isinstance(obj, (type, CPUDispatcher))
                    or type(obj).__name__ == "CallsKernel" or name in charts.__all__):
                continue
            if f"{info.name}.{name}" not in ANALYSES and name not in INTERNAL.get(info.name, ()):
                unclassified.append(f"{info.name}.{name}")
    assert unclassified == [], f"add a hostile-input entry or list as internal: {unclassified}"


def test_every_parameter_of_every_entry_exists():
    for name, entry in ALL.items():
        sig = inspect.signature(entry.signature_of or entry.fn)
        params = set(sig.parameters)
        forwarded = any(p.kind == p.VAR_KEYWORD for p in sig.parameters.values())
        assert forwarded or set(entry.base) <= params, name
        assert set(entry.takes) <= params, name
        assert set(entry.skip) <= params, name


@pytest.mark.parametrize("name", sorted(ALL))
def test_every_parameter_times_every_fixed_hostile_value(name):
    failures = []
    for param, label, value in cases(name):
        try:
            check(name, param, label, value)
        except AssertionError as exc:
            failures.append(str(exc).splitlines()[0][:300])
    assert not failures, "\n".join(failures)


def _nonsense(value) -> bool:
    """NaN, ±inf or complex anywhere in ``value`` (a number, or an array or list of them)."""
    try:
        a = np.asarray(value)
    except Exception:                   # noqa: BLE001 - ragged lists: not numbers
        return False
    if a.dtype.kind == "c":
        return True
    if a.dtype.kind == "f":
        return bool(a.size) and not np.all(np.isfinite(a))
    if a.dtype.kind == "O" and a.ndim == 1:
        return any(_nonsense(v) for v in a.tolist() if isinstance(v, (float, complex)))
    return False


def _odd_layouts(a):
    """``a`` as it is, non-contiguous (every other entry of a doubled array) and read-only."""
    strided = np.repeat(a, 2, axis=-1)[..., ::2] if a.ndim else a
    frozen = a.copy()
    frozen.flags.writeable = False
    return st.sampled_from([a, strided, frozen])


#: Hostile values drawn by Hypothesis: floats in [-1, 1] and at the edges of the float range,
#: integers near zero and far beyond int64, bools, text, None, and arrays of any shape and
#: dtype, also non-contiguous and read-only.  (Magnitudes between are left out: a t_final of
#: 10⁴ is a valid, long run, not a hostile one.)
HOSTILE = st.one_of(
    st.floats(-1.0, 1.0),
    st.sampled_from([math.nan, math.inf, -math.inf, 1e300, -1e300, 5e-324, 1e-300]),
    st.integers(-3, 1), st.integers(2 ** 63, 10 ** 400), st.integers(-10 ** 400, -2 ** 63),
    st.booleans(), st.text(max_size=3), st.none(), st.complex_numbers(max_magnitude=2.0),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=4),
    hnp.arrays(dtype=st.sampled_from([np.float64, np.float32, np.int64, np.complex128,
                                      np.bool_]),
               shape=hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=5),
               elements=None).flatmap(_odd_layouts))

#: (name, parameter) pairs the generated test draws from: every parameter of every entry.
PAIRS = [(name, param) for name in sorted(ALL) for param in ALL[name].parameters()]


@settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(data=st.data())
def test_every_parameter_given_generated_hostile_values(data):
    name, param = data.draw(st.sampled_from(PAIRS), label="parameter")
    value = data.draw(HOSTILE.filter(lambda v: not _valid(ALL[name], param, v)), label="value")
    check(name, param, "NaN entry" if _nonsense(value) else repr(value)[:60], value)
