"""Scenes: declarative TOML descriptions of one run, validated before anything runs.

A scene names the system (N, masses, speed), the initial state (a seed, or explicit θ and
u), the integrator, the duration and sampling, and the **effects** wanted (waveforms, power
spectrum, Lyapunov spectrum, curvature, hyperbolicity angles, covariant Lyapunov vectors, chart-switch log, invariant
drift).  ``load_scene(path)`` / ``parse_scene(dict)`` return a frozen :class:`Scene`; every
problem is reported as one :class:`SceneError` naming the key, the value and what is allowed
(a misspelt key suggests the right one).  Every key is documented in ``docs/scenes.md``,
whose content is checked against :data:`SCHEMA` by the tests.

Layout (all tables optional except ``[system]`` and ``[run]``)::

    name = "fig2-n5"                  # optional, defaults to the file name
    description = "..."
    [system]     n, masses, speed
    [mechanism]  name + the mechanism's parameters (charts.runs.scene_mechanism), instead of
                 [system] n, masses, ...
    [initial]    seed | theta + u
    [integrator] formulation, method, dt | rtol + atol, project
    [run]        t_final, t_transient, sample_dt, checkpoint_every
    [effects.<name>]  one table per effect; ``<name> = true`` is the table with defaults
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..analyses.arguments import Documented, steps_of
from ..solvers.status import check_step
from .input_files import read_toml
from ..geometry.checks import path as file_path
from ..geometry.checks import shown
from .scene_checks import (Problems, source_names, multiple_of, section_values, table_values, unknown_key,
                           where)
from .scene_mechanism import (check_linkage_effects, check_linkage_system,
                              check_mechanism_effects, check_mechanism_start, linkage_defaults,
                              mechanism_system, system_kind_problems, translated)
from .scene_rotors import check_rotors
from .scene_schema import EFFECTS, SCHEMA, TANGENT_EFFECTS, TOP_KEYS, SceneError, api_default
from .scene_transients import refuse_linkage_rules, scene_transients

__all__ = ["Scene", "SceneError", "SCHEMA", "EFFECTS", "load_scene", "parse_scene",
           "scene_to_dict", "positive_exponents"]


# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Scene:
    """A validated scene.  ``effects`` maps each requested effect to its full option dict."""

    name: str
    description: str
    system: dict
    initial: dict
    integrator: dict
    run: dict
    effects: dict = field(default_factory=dict)
    source: str = "<dict>"
    #: the rule that gave the transients ("scaled", "auto": its text), None where written
    transient_rule: str | None = None

    def wants(self, effect: str) -> bool:
        """Whether the scene asks for ``effect``, one of the known effects (`EFFECTS`;
        SceneError naming ``effect`` otherwise)."""
        if not isinstance(effect, str) or effect not in EFFECTS:
            raise SceneError(f"effect must be one of {', '.join(EFFECTS)}, got {shown(effect)}")
        return effect in self.effects


def positive_exponents(scene: Scene) -> int:
    """The number of positive Lyapunov exponents of the scene's system: d − 1 on its
    d-dimensional configuration manifold (N − 2 for N rotors and for the linkage's N = 4)."""
    s = scene.system
    return s["dimension"] - 1 if s.get("kind") == "mechanism" else s["n"] - 2


def scene_to_dict(scene: Scene) -> dict:
    """The scene as run (every default filled in), JSON/TOML-serialisable."""
    return {"name": scene.name, "description": scene.description, "system": dict(scene.system),
            "initial": dict(scene.initial), "integrator": dict(scene.integrator),
            "run": dict(scene.run), "effects": {k: dict(v) for k, v in scene.effects.items()}}


def load_scene(path) -> Scene:
    """Read and validate a TOML scene file.  Raises :class:`SceneError` (ValueError for a
    ``path`` that is not a path)."""
    path = file_path("path", path)
    data = read_toml(path, "scene", SceneError, " (bundled scenes: `charts scenes`)")
    return parse_scene(data, source=str(path), default_name=path.stem)


# ---------------------------------------------------------------------------------------
def parse_scene(data: dict, *, source: str = "<scene>", default_name: str = "scene") -> Scene:
    """Validate a scene given as a dict (as read from TOML).  Raises :class:`SceneError`."""
    source_names(source, default_name, SceneError)
    if not isinstance(data, dict):
        raise SceneError(f"{source}: a scene is a TOML table, got {type(data).__name__}")
    read = translated(source, data)  # [mechanism] of the rotors or the linkage: their [system]
    if read is data:
        return _parse_scene(data, source, default_name)
    moved = [k for k in data["mechanism"] if k != "name"]
    try:
        return _parse_scene(read, source, default_name)
    except SceneError as exc:         # a problem of a key the [mechanism] table gave
        text = str(exc)
        for key in moved:
            text = text.replace(f"[system] {key} ", f"[mechanism] {key} ")
        raise SceneError(text) from None


def _parse_scene(data, source, default_name) -> Scene:
    """`parse_scene` of a scene whose [mechanism] table, if any, is of the generic route."""
    problems = Problems(source)      # key-level problems of every section, reported together
    top = table_values(source, data, None, TOP_KEYS, problems,
                       allowed=set(TOP_KEYS) | set(SCHEMA) | {"effects", "mechanism"})
    name = top["name"] or default_name

    system, _ = section_values(source, data, "system", SCHEMA["system"], problems)
    initial, raw_init = section_values(source, data, "initial", SCHEMA["initial"], problems)
    integ, raw_int = section_values(source, data, "integrator", SCHEMA["integrator"], problems)
    run, raw_run = section_values(source, data, "run", SCHEMA["run"], problems)
    raw_eff = data.get("effects", {})
    effects = {}
    if not isinstance(raw_eff, dict):
        problems.messages.append(f"{source}: [effects] must be a table of effect tables, "
                                 f"got {shown(raw_eff)}")
        raw_eff = {}
    for ename, eraw in raw_eff.items():
        if ename not in EFFECTS:
            problems.messages.append(str(unknown_key(source, "effects", ename, EFFECTS)))
            continue
        if eraw is False:
            continue
        if eraw is True:
            eraw = {}
        if not isinstance(eraw, dict):
            problems.messages.append(f"{source}: [effects] {ename} = {shown(eraw)} is not allowed: "
                                     f"expected true, false or a table [effects.{ename}]")
            continue
        effects[ename] = section_values(source, {ename: eraw}, ename, EFFECTS[ename], problems,
                                  label=f"effects.{ename}")[0]
    raw_sys = data.get("system", {})
    mechanical = "mechanism" in data      # a mechanism on the generic route
    if mechanical:
        mechanism_system(source, data, system, raw_sys, problems)
    else:
        system_kind_problems(source, raw_sys, system["kind"], problems)
    problems.raise_all()              # the checks below relate keys that must be valid first
    linkage = system["kind"] == "linkage"
    if linkage:                       # the exact linkage of the Appendix (docs/linkage.md)
        check_linkage_system(source, system, raw_sys, initial, raw_init, integ, raw_int)
        linkage_defaults(effects, raw_eff)
    elif mechanical:
        check_mechanism_start(source, raw_init, integ)
    else:
        check_rotors(source, system, raw_sys, initial, raw_init)
    n = system.get("n")

    # -- integrator --------------------------------------------------------------------------
    method = integ["method"]
    if method == "rk4":
        for key in ("rtol", "atol"):
            if key in raw_int:
                raise SceneError(f"{where(source, 'integrator', key)} = {shown(raw_int[key])} is not "
                                 "allowed with method = 'rk4' (fixed step: set dt, or use "
                                 "method = 'dop853')")
        integ["dt"] = integ["dt"] if integ["dt"] is not None else api_default("lyapunov", "dt")
        try:                # the API's step-size policy (status.check_step): the rotors' cap
            if not (linkage or mechanical):
                check_step(integ["dt"], system["speed"], n)
        except ValueError as exc:
            raise SceneError(f"{where(source, 'integrator', 'dt')}: {exc}") from None
    else:
        if "dt" in raw_int:
            raise SceneError(f"{where(source, 'integrator', 'dt')} = {shown(raw_int['dt'])} is not "
                             "allowed with method = 'dop853' (adaptive: set rtol/atol, or use "
                             "method = 'rk4')")
        integ["rtol"] = integ["rtol"] if integ["rtol"] is not None else 1e-10
        # atol: None = integrate's default, rtol·min(1, speed)

    _transients(system.get("kind", "rotors"), run, "t_transient" in raw_run, effects)
    if linkage:
        refuse_linkage_rules(source, run, effects)
    if method == "rk4":
        _follow_dt(system.get("kind", "rotors"), run, integ, effects, integ["dt"])

    # -- run: times on the grids ---------------------------------------------------------------
    grid = integ["dt"] if method == "rk4" else None
    if run["sample_dt"] is None:
        run["sample_dt"] = grid if grid is not None else 0.01
    elif grid is not None:
        multiple_of(source, "run", "sample_dt", run["sample_dt"], grid, "[integrator] dt")
    sdt = run["sample_dt"]
    n_samples = multiple_of(source, "run", "t_final", run["t_final"], sdt, "[run] sample_dt")
    # the transients a rule names, once t_final and the steps are known good ("auto" pilots)
    rule = scene_transients(source, linkage, system, initial, integ, run, effects)
    if run["t_transient"] > 0:
        multiple_of(source, "run", "t_transient", run["t_transient"], sdt, "[run] sample_dt")
    if run["checkpoint_every"] is None:
        per = max(1, n_samples // 20)
        run["checkpoint_every"] = per * sdt
    else:
        multiple_of(source, "run", "checkpoint_every", run["checkpoint_every"], sdt,
                  "[run] sample_dt")

    # -- effects -----------------------------------------------------------------------------------
    if linkage:
        check_linkage_effects(source, run, effects, raw_eff)
    if mechanical:
        check_mechanism_effects(source, run, effects, raw_eff)
        d = system["dimension"]
        _check_effects(source, len(system["coordinates"]), integ, run, effects,
                       exponents=(d - 1, d, 2 * d))
    else:
        _check_effects(source, n, integ, run, effects)
    if not effects:
        raise SceneError(f"{source}: the scene requests no effect: add at least one "
                         f"[effects.<name>] table (effects: {', '.join(EFFECTS)})")

    return Scene(name=name, description=top["description"], system=system, initial=initial,
                 integrator=integ, run=run, effects=effects, source=source, transient_rule=rule)


#: Defaults that must divide t_final (the API's ``divides``): per effect table, the keys.
_DIVIDE_T_FINAL = {"lyapunov": ("reorth_every",), "curvature": ("sample_every",),
                   "clv": ("sample_every",), "angles": ("sample_every",)}


def _follow_dt(kind, run, integ, effects, dt):
    """Each duration the scene leaves to the API's default (a `Documented` value of its
    signature: ``[integrator] project_every``, the transients, reorth_every, the
    sample_every of the effects) put on the step grid as the API puts it
    (``charts.analyses.arguments.steps_of``): the nearest whole number of steps, dividing
    t_final where it must — so that a scene that only sets dt runs where the API call does,
    with the same steps.  A value the scene writes is left as written (checked strictly
    below).  A linkage places its defaults as its calls do: reorth_every and the curvature's
    sample_every as `linkage_run` (`run_steps`: the samples a multiple of reorth_every, with
    linkage_run's reorth_every where the scene has no Lyapunov effect), the angle pass as
    `linkage_angles` (its t_transient a multiple of its sample_every: `angle_steps`), and so
    does a mechanism's (``kind`` "mechanism": `mechanism_angles`, whose transient is too)."""
    linkage = kind == "linkage"
    total = int(round(run["t_final"] / dt)) if run["t_final"] else 0   # checked below
    if linkage and ("lyapunov" in effects or "curvature" in effects):
        from ..analyses.linkage import run_steps
        ly, c = effects.get("lyapunov", {}), effects.get("curvature", {})
        try:
            _, reorth, sample = run_steps(
                dt, run["t_final"], ly.get("reorth_every", api_default("linkage", "reorth_every")),
                c.get("sample_every", api_default("linkage", "sample_every")))
        except ValueError:
            pass                        # a written value off the grid: refused below, by key
        else:
            for table, key, steps in ((ly, "reorth_every", reorth), (c, "sample_every", sample)):
                if isinstance(table.get(key), Documented):
                    table[key] = steps * dt
    if kind in ("linkage", "mechanism") and "angles" in effects:
        from ..analyses.linkage_angles import angle_steps
        a = effects["angles"]
        try:
            _, transient, sample = angle_steps(dt, run["t_final"], a["t_transient"],
                                               a["sample_every"])
        except ValueError:
            pass                        # a written value off the grid: refused below, by key
        else:
            for key, steps in (("t_transient", transient), ("sample_every", sample)):
                if isinstance(a[key], Documented):
                    a[key] = steps * dt
    tables = [("run", run), ("integrator", integ)] + list(effects.items())
    for name, table in tables:
        for key, value in table.items():
            if isinstance(value, Documented):
                divides = total if key in _DIVIDE_T_FINAL.get(name, ()) else 0
                table[key] = steps_of(key, value, dt, allow_zero=True, divides=divides) * dt


def _transients(kind, run, written, effects):
    """Fill in the transients left out: each pass gets the default of the API call it
    mirrors (``scene_schema.API``; ``kind``: the system's); a written ``[run] t_transient``
    is every pass's."""
    linkage = kind == "linkage"
    passes = {"angles": {"linkage": "linkage_angles", "mechanism": "mechanism_angles"}.get(
        kind, "angles"), "clv": "clv"}
    for name, api in passes.items():
        if name in effects and effects[name]["t_transient"] is None:
            effects[name]["t_transient"] = (run["t_transient"] if written
                                            else api_default(api, "t_transient"))
    if written:
        return
    main = [e for e in ("lyapunov", "curvature") if e in effects]
    if main:
        own = {"linkage": "linkage", "mechanism": "mechanism"}.get(kind, main[0])
        run["t_transient"] = api_default(own, "t_transient")
    elif any(e not in passes for e in effects):    # waveforms, spectrum, drift, switches
        run["t_transient"] = api_default("waveforms", "t_transient")
    else:                                          # only the passes: the first one's
        run["t_transient"] = next((effects[e]["t_transient"] for e in passes if e in effects),
                                  0.0)


def _check_effects(source, n, integ, run, effects, exponents=None):
    """The effects' settings against the system: ``n`` coordinates (the rotors' N) whose
    velocities waveforms and spectrum may record; ``exponents``: (positive, most with the
    θ product, most with the full product) of the Lyapunov exponents (default N − 2,
    N − 1, 2N − 2: the rotors')."""
    sect = "effects.{}".format
    positive, theta_max, full_max = exponents or (n - 2, n - 1, 2 * n - 2)
    tangent = [e for e in TANGENT_EFFECTS if e in effects]
    if tangent and (integ["formulation"] != "ambient" or integ["method"] != "rk4"):
        raise SceneError(
            f"{source}: [effects] {', '.join(tangent)} is not allowed with formulation = "
            f"{shown(integ['formulation'])}, method = {shown(integ['method'])}: tangent vectors follow the "
            "variational equations (17) with fixed-step RK4 and re-orthonormalisation (18); "
            "set [integrator] formulation = 'ambient', method = 'rk4'")
    if "switches" in effects and integ["formulation"] != "chart":
        raise SceneError(f"{source}: [effects] switches is not allowed with formulation = "
                         f"{shown(integ['formulation'])}: only the chart formulation switches charts; "
                         "set [integrator] formulation = 'chart'")
    if "waveforms" in effects:
        w = effects["waveforms"]
        rotors = w["rotors"] if w["rotors"] is not None else list(range(n))
        if not rotors or any(not 0 <= r < n for r in rotors) or len(set(rotors)) != len(rotors):
            raise SceneError(f"{where(source, sect('waveforms'), 'rotors')} = {shown(rotors)} is not "
                             f"allowed: expected distinct rotor indices in 0..{n - 1}")
        w["rotors"] = list(rotors)
        w["t_window"] = min(w["t_window"], run["t_final"])
        multiple_of(source, sect("waveforms"), "t_window", w["t_window"], run["sample_dt"],
                  "[run] sample_dt")
    if "spectrum" in effects:
        s = effects["spectrum"]
        if not 0 <= s["rotor"] < n:
            raise SceneError(f"{where(source, sect('spectrum'), 'rotor')} = {shown(s['rotor'])} is not "
                             f"allowed: expected a rotor index in 0..{n - 1}")
        n_samples = round(run["t_final"] / run["sample_dt"])
        if s["nperseg"] > n_samples:
            raise SceneError(f"{where(source, sect('spectrum'), 'nperseg')} = {shown(s['nperseg'])} is "
                             f"not allowed: expected at most the number of samples, {n_samples} "
                             "(lengthen [run] t_final or shorten the segments)")
    if integ["formulation"] == "ambient" and integ["method"] == "rk4" and integ["project_every"]:
        multiple_of(source, "integrator", "project_every", integ["project_every"], integ["dt"],
                  "[integrator] dt")
    if "lyapunov" in effects:
        ly = effects["lyapunov"]
        if ly["n_exponents"] is None:
            ly["n_exponents"] = positive
        multiple_of(source, sect("lyapunov"), "reorth_every", ly["reorth_every"], integ["dt"],
                  "[integrator] dt")
        multiple_of(source, "run", "t_final", run["t_final"], ly["reorth_every"],
                  "[effects.lyapunov] reorth_every")
        # the vectors stay in the 2N−2-dim. constraint-preserving subspace; the θ-only
        # product sees only its N−1 θ-directions (more vectors would be degenerate)
        kmax = theta_max if ly["inner_product"] == "theta" else full_max
        if ly["n_exponents"] > kmax:
            more = (" (use inner_product = 'full' for up to "
                    f"{'2N−2' if exponents is None else full_max})" if kmax == theta_max else "")
            raise SceneError(f"{where(source, sect('lyapunov'), 'n_exponents')} = "
                             f"{shown(ly['n_exponents'])} is not allowed with inner_product = "
                             f"{shown(ly['inner_product'])}: expected 1..{kmax}{more}")
    if "curvature" in effects:
        c = effects["curvature"]
        if c["n_directions"] is None:
            c["n_directions"] = positive
        if c["n_directions"] > positive:
            raise SceneError(f"{where(source, sect('curvature'), 'n_directions')} = "
                             f"{shown(c['n_directions'])} is not allowed: expected 1..{positive} "
                             "(the directions orthogonal to the velocity in the manifold)")
        multiple_of(source, sect("curvature"), "sample_every", c["sample_every"], integ["dt"],
                  "[integrator] dt")
    for name in ("angles", "clv"):        # the two routes to the angles of section 4
        if name not in effects:
            continue
        a = effects[name]
        if a["n_vectors"] is None:
            a["n_vectors"] = positive
        if a["n_vectors"] > positive:
            raise SceneError(f"{where(source, sect(name), 'n_vectors')} = {shown(a['n_vectors'])} "
                             f"is not allowed: expected 1..{positive} (at most the number of "
                             "positive exponents)")
        multiple_of(source, sect(name), "sample_every", a["sample_every"], integ["dt"],
                  "[integrator] dt")
        if a["t_transient"] > 0:
            multiple_of(source, sect(name), "t_transient", a["t_transient"], integ["dt"],
                        "[integrator] dt")
    if "clv" in effects:
        c = effects["clv"]
        multiple_of(source, "run", "t_final", run["t_final"], c["sample_every"],
                  "[effects.clv] sample_every")
        if c["windows"] is None:
            c["windows"] = [1.0, 10.0]
        for w in c["windows"]:
            multiple_of(source, sect("clv"), "windows", w, c["sample_every"],
                      "[effects.clv] sample_every")
    if "drift" in effects:
        d = effects["drift"]
        multiple_of(source, sect("drift"), "sample_every", d["sample_every"], run["sample_dt"],
                  "[run] sample_dt")
