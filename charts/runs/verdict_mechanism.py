"""The verdict of a 2-dimensional mechanism (``charts verdict --mechanism``; docs/mechanisms.md):
its configuration surface's integrals by the chart route and, for a constant metric, the Gauss
route (``charts.mechanism.surface``: the sheets in closed form, or by Newton's method from a
grid of seeds for a mechanism of one's own), χ read from Gauss–Bonnet, the range of K at the
nodes and the share of area with K > 0, λ₁ against the entropy bracket and optionally the
restricted angles, judged by `charts.runs.verdict.case_verdict`: χ > 0 is "not hyperbolic"
(Hopf), anything else "open", never "hyperbolic" (no certificate of K's sign exists for a
general mechanism).  The triple linkage's verdict (``charts.runs.verdict_linkage``) is this
one with its limit r → 0.

The mechanism is named as a scene's ``[mechanism]`` table names it, by the same code
(``charts.runs.scene_mechanism``): `resolve_mechanism`."""
from __future__ import annotations

import time
import tomllib
import warnings
from types import SimpleNamespace

import numpy as np

from .verdict import case_verdict, exponent_report

__all__ = ["resolve_mechanism", "surface_plan", "mechanism_verdict", "measure_surface",
           "PLAN_GRID"]

#: Nodes per axis of each angle chart in `surface_plan`'s check that the surface is regular.
PLAN_GRID = 16


def resolve_mechanism(spec, settings=()):
    """The Mechanism that ``spec`` names, as a scene's ``[mechanism]`` table names it
    (``charts.runs.scene_mechanism``, its one home): an instance (``triple_linkage``,
    ``rotors``, ``linkage``) or ``"package.module:factory"``, with ``settings`` its keyword
    parameters as ``KEY=VALUE`` strings (each VALUE a TOML value, as in the table); or the
    path of a TOML file (a scene) whose ``[mechanism]`` table is read.  ValueError (a
    SceneError) naming ``--mechanism`` and what fails: an unknown instance or module, a key
    the factory does not take, a value it refuses, a factory that returns no Mechanism."""
    from .scene_mechanism import mechanism_of, mechanism_system
    from .scene_schema import SceneError
    if not isinstance(spec, str) or not spec:
        raise SceneError(f"--mechanism must name a mechanism, got {spec!r}")
    if spec.endswith(".toml"):
        if settings:
            raise SceneError(f"--mechanism {spec}: the parameters are the file's [mechanism] "
                             "table; give no KEY=VALUE beside a file")
        try:
            with open(spec, "rb") as f:
                table = tomllib.load(f).get("mechanism")
        except (OSError, tomllib.TOMLDecodeError) as exc:
            raise SceneError(f"--mechanism {spec}: cannot be read as TOML "
                             f"({type(exc).__name__}: {exc})") from None
        if table is None:
            raise SceneError(f"--mechanism {spec}: the file has no [mechanism] table")
    else:
        table = dict(name=spec)
        for item in settings:
            key, eq, value = str(item).partition("=")
            key = key.strip()
            try:
                if not (eq and key):
                    raise tomllib.TOMLDecodeError("not KEY=VALUE")
                table[key] = tomllib.loads(f"v = {value.strip()}")["v"]
            except tomllib.TOMLDecodeError:
                raise SceneError(f"--mechanism {spec}: a parameter is KEY=VALUE with a TOML "
                                 f"value (r=0.2, name=\"x\"), got {item!r}") from None
            if key == "name":
                raise SceneError(f"--mechanism {spec}: name is the mechanism itself (the "
                                 "first word of --mechanism), not a parameter")
    problems = SimpleNamespace(messages=[])
    system = dict(speed=1.0)
    mechanism_system("--mechanism", dict(mechanism=table), system, {}, problems)
    if problems.messages:
        raise SceneError("; ".join(problems.messages))
    return mechanism_of(system)


def surface_plan(mech, what=None, at=""):
    """``mech`` checked before any long work: a Mechanism of dimension 2 with two periodic
    coordinates or more (the angle charts of ``charts.mechanism.surface``), points of its
    configuration surface above a `PLAN_GRID`² grid of each angle chart, and the surface
    regular there (finite area elements and curvatures); MechanismError (a ValueError)
    naming ``what`` (default the mechanism's name; ``at``: where, e.g. its parameters) and
    what fails otherwise."""
    from ..mechanism import Mechanism, MechanismError
    from ..mechanism.surface import curvatures, surface_nodes
    if not isinstance(mech, Mechanism):
        raise MechanismError(f"mech must be a charts.Mechanism, got {type(mech).__name__}")
    what = what or mech.name
    if mech.dim != 2:
        raise MechanismError(f"{what} has a {mech.dim}-dimensional configuration space: the "
                             "verdict of a mechanism reads chi from Gauss-Bonnet on a surface, "
                             "so it needs dimension 2 (the rotors of N >= 4: charts verdict "
                             "--n N)")
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")       # NaN at singular nodes: refused below
        q, dA = surface_nodes(mech, PLAN_GRID)
        K = curvatures(mech, q, "chart")
    if not (np.all(np.isfinite(dA)) and np.all(np.isfinite(K))):
        raise MechanismError(
            f"{what} is singular{at}: area elements or curvatures are not finite at points above "
            f"the {PLAN_GRID}^2 grid (the constraints lose rank there, or the kinetic metric "
            "degenerates on the tangent planes), so it is not a closed smooth Riemannian "
            "surface and no verdict applies")
    return mech


def measure_surface(mech, *, n_grid, t_final, seeds, angles_window, say) -> dict:
    """The measured pieces of a surface's verdict as JSON-ready entries: ``routes`` (the
    integrals of each curvature route on ``n_grid``² nodes per angle chart, χ the integer
    nearest ∫K dA / 2π, the smallest K at the nodes), ``bracket`` (the chart route's entropy
    bracket), ``exponents`` (λ₁ at unit speed over ``t_final`` from each seed's random state,
    ``charts.analyses.mechanism_lyapunov``) and, with ``angles_window``, ``angles`` (the
    restricted-angle test from each seed's state, ``charts.analyses.mechanism_angles``).
    ``say`` is given a line before each step."""
    from dataclasses import replace

    from ..analyses.mechanism_lyapunov import lyapunov_spectrum as mechanism_lyapunov
    from ..geometry.surface_quadrature import integrals_from_nodes
    from ..mechanism.surface import curvatures, surface_nodes
    route_names = ("chart", "gauss") if mech.constant_metric else ("chart",)
    say(f"surface integrals on {n_grid}^2 nodes per angle chart (the "
        f"{' and '.join(route_names)} route{'s' if len(route_names) > 1 else ''})")
    q, dA = surface_nodes(mech, n_grid)
    routes = {}
    for route in route_names:
        K = curvatures(mech, q, route)
        s = integrals_from_nodes(K, dA, 0, n_grid, route,
                                 dict(mech.parameter_values, mechanism=mech.name))
        s = replace(s, euler_characteristic=int(round(s.total_curvature / (2 * np.pi))))
        routes[route] = dict(s.to_dict(), min_curvature=float(K.min()),
                             euler_characteristic_from="nearest integer to int K dA / 2 pi")
    bracket = routes["chart"]["entropy_bracket"]
    exponents = []
    for seed in seeds:
        say(f"lambda1 at unit speed, seed {seed}, T = {t_final:g}")
        exponents.append(exponent_report(mechanism_lyapunov(mech, *mech.random_state(seed),
                                                            t_final, seed=seed),
                                         seed, t_final, bracket))
    out = dict(routes=routes, bracket=bracket, exponents=exponents)
    if angles_window is not None:
        from ..analyses.mechanism_angles import mechanism_angles
        out["angles"] = []
        for seed in seeds:
            say(f"restricted angles, seed {seed}, T = {angles_window:g}")
            a = mechanism_angles(mech, *mech.random_state(seed), angles_window, seed=seed)
            st = a.statistics()
            out["angles"].append(dict(seed=int(seed), t_final=float(angles_window),
                                      **{k: st[k] for k in ("min", "median", "frac_small",
                                                            "small", "n")}))
    return out


def check_settings(n_grid, t_final, seeds, angles_window, names=None) -> None:
    """The settings of a verdict checked before any work (ValueError naming each): the grid
    (8 … 4096), the exponents' ``t_final`` and the angles' window (whole numbers of the
    step 0.01), the seeds (integers ≥ 0).  ``names``: how the messages call the four
    (default the keywords of `mechanism_verdict`)."""
    from ..analyses.arguments import steps_of
    from ..geometry.checks import integer
    names = names or ("n_grid", "t_final", "seeds", "angles_window")
    integer(names[0], n_grid, 8, 1 << 12)
    steps_of(names[1], t_final, 0.01)                  # the exponent's RK4 step
    if angles_window is not None:
        steps_of(names[3], angles_window, 0.01)
    if isinstance(seeds, (str, bytes)) or not hasattr(seeds, "__iter__"):
        raise ValueError(f"{names[2]} must be a sequence of integers >= 0, got {seeds!r}")
    for seed in seeds:
        integer(names[2], seed, 0)


def mechanism_verdict(mech, *, n_grid=96, t_final=3000.0, seeds=(1, 2), angles_window=None,
                      progress=None, spec=None) -> dict:
    """Every piece of the verdict of a 2-dimensional mechanism ``mech`` (`surface_plan`) as
    one JSON-ready dict, without a certificate: ``system`` (kind "mechanism", its name, the
    ``spec`` that named it when given, parameters, coordinates, dimension), ``n_grid`` and
    `measure_surface`'s entries, then ``seconds`` and `case_verdict`'s verdict, evidence and
    reason.  ``progress``: a callable given a line before each step."""
    check_settings(n_grid, t_final, seeds, angles_window)
    if progress is not None and not callable(progress):
        raise ValueError(f"progress must be a callable given a line, or None, got "
                         f"{type(progress).__name__}")
    say = progress or (lambda line: None)
    t0 = time.perf_counter()
    surface_plan(mech)
    system = dict(kind="mechanism", name=mech.name, mechanism=spec,
                  parameters={str(k): float(v) for k, v in mech.parameter_values.items()},
                  coordinates=[s.name for s in mech.q], dimension=int(mech.dim))
    rep = dict(system=system, n_grid=int(n_grid),
               **measure_surface(mech, n_grid=n_grid, t_final=t_final, seeds=seeds,
                                 angles_window=angles_window, say=say))
    rep["seconds"] = time.perf_counter() - t0
    return dict(rep, **case_verdict(rep))
