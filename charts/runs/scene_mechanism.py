"""Mechanisms as scene systems: the ``[mechanism]`` table.

A scene names its mechanism by an instance and that instance's keyword parameters::

    [mechanism]
    name = "triple_linkage"        # or "linkage", "rotors", or "package.module:factory"
    r = 0.3                        # the factory's keyword arguments (unknown keys refused)

The named instances are `INSTANCES`: ``triple_linkage`` (``charts.triple_linkage``: r, l,
R, inertia, joint_mass, rod_mass), ``linkage`` (the Appendix's ``charts.LinkageSystem``:
eps, rho, disk_mass, disk_inertia) and ``rotors`` (N rotors: n, masses, weights, level);
any other name of the form ``"package.module:factory"`` is a user's factory, called with
the table's other keys, that returns a ``charts.Mechanism``.  A key the factory does not
take is refused naming it and the allowed ones; a value it refuses, with its message.

How each runs:

* ``rotors`` and ``linkage`` are the library's structured routes: their table is read as the
  ``[system]`` keys of those routes (``n``, ``masses``, … ; ``kind = "linkage"``, ``eps``, …),
  so that such a scene is the same scene, with the same point ids and numbers, as one written
  with ``[system]`` (which keeps loading: `translated`);
* every other mechanism runs on the generic route (``charts.runs.mechanism_run``: its
  compiled tangent flow ``MechanismTangentFlow``, the same steps as
  ``charts.analyses.mechanism_lyapunov.lyapunov_spectrum``), its scene's ``[system]``
  holding ``kind = "mechanism"``, the instance and its parameters (every default filled in),
  the coordinates' names and the manifold's dimension (`mechanism_system`).

What a scene of the generic route can do (`MECHANISM_EFFECTS`, `check_mechanism_start`):
ambient RK4 from a seeded state (``Mechanism.random_state``), the effects lyapunov,
waveforms and spectrum (of the coordinates' velocities), drift (the constraints, the
tangency J v and the energy), curvature (both routes of
``charts.analyses.mechanism_curvature`` at the samples of the scene's flow) and angles (the
restricted test of ``charts.analyses.mechanism_angles``).

The linkage's route (``[system] kind = "linkage"``; its run's pieces in
``charts.runs.mechanism_run``) has the same rules and a few of its own, at the end of this
module: its keys ``eps``, ``rho``, ``disk_mass``, ``disk_inertia`` (`LINKAGE_KEYS`); its
effects (`LINKAGE_EFFECTS`: lyapunov, curvature by the Gauss equation (route "exact"),
angles (the restricted variant, ``charts.analyses.linkage_angles``), waveforms, spectrum,
drift); its defaults, its calls' (`linkage_defaults`).  Its state is y = (q, v) with
q = (θ₀…θ₃, x, y, α): the rotors' velocities sit at ``NQ + i``.
"""
from __future__ import annotations

import importlib
import inspect

from ..geometry.checks import shown
from .scene_checks import unknown_key, where
from .scene_schema import SceneError

__all__ = ["INSTANCES", "STRUCTURED", "MECHANISM_EFFECTS", "MECHANISM_SYSTEM_KEYS",
           "factory_of", "factory_keys", "translated", "mechanism_system", "mechanism_of",
           "check_mechanism_start", "check_mechanism_effects", "check_own_effects",
           "LINKAGE_KEYS", "ROTOR_KEYS",
           "LINKAGE_EFFECTS", "system_kind_problems", "check_linkage_system",
           "check_linkage_effects", "linkage_defaults"]

#: The named instances: name → ``"module:factory"`` (imported when a scene names it).
INSTANCES = {
    "triple_linkage": "charts.mechanism.instances:triple_linkage",
    "linkage": "charts:LinkageSystem",
    "rotors": "charts.mechanism.instances:rotors",
}
#: The instances that run on their own structured route: the instance → its ``[system]``
#: kind (`translated`).
STRUCTURED = {"rotors": "rotors", "linkage": "linkage"}
#: The effects a scene of the generic route can request.
MECHANISM_EFFECTS = ("waveforms", "spectrum", "drift", "lyapunov", "curvature", "angles")
#: The keys of ``[system]`` a scene of the generic route may write.
MECHANISM_SYSTEM_KEYS = ("speed",)

_SECTION = "mechanism"
#: Built mechanisms by (instance, parameters): a sweep validates each point's scene, and its
#: worker reads it again.
_BUILT = {}


def factory_of(source, name):
    """The factory that ``[mechanism] name`` names: a key of `INSTANCES`, or
    ``"package.module:factory"``; SceneError naming the key otherwise."""
    loc = where(source, _SECTION, "name")
    if not isinstance(name, str) or not name:
        raise SceneError(f"{loc} = {shown(name)} is not allowed: expected one of "
                         f"{', '.join(map(repr, INSTANCES))} or \"package.module:factory\"")
    path = INSTANCES.get(name, name)
    module, _, attr = path.partition(":")
    if not module or not attr:
        import difflib
        hint = difflib.get_close_matches(name, list(INSTANCES), n=1, cutoff=0.6)
        did = f" — did you mean {shown(hint[0])}?" if hint else ""
        raise SceneError(f"{loc} = {shown(name)} is not allowed{did} (the instances: "
                         f"{', '.join(map(repr, INSTANCES))}; a factory of your own as "
                         "\"package.module:factory\")")
    try:
        factory = getattr(importlib.import_module(module), attr)
    except ImportError as exc:
        raise SceneError(f"{loc} = {shown(name)}: the module {module!r} cannot be imported "
                         f"({type(exc).__name__}: {exc})") from None
    except AttributeError:
        raise SceneError(f"{loc} = {shown(name)}: the module {module!r} has no {attr!r}") from None
    if not callable(factory):
        raise SceneError(f"{loc} = {shown(name)}: {attr!r} is not callable (a factory returning "
                         "a charts.Mechanism)")
    return factory


def factory_keys(factory):
    """(the keyword parameters of ``factory`` → their defaults, ``inspect.Parameter.empty``
    for a required one; whether it takes any keyword, ``**kwargs``)."""
    try:
        sig = inspect.signature(factory)
    except (TypeError, ValueError):
        return {}, True
    keys, anything = {}, False
    for p in sig.parameters.values():
        if p.kind is p.VAR_KEYWORD:
            anything = True
        elif p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY):
            keys[p.name] = p.default
    return keys, anything


def _table(source, data):
    """(the instance's name, its factory, its keyword arguments) of the scene's [mechanism]
    table, every key checked against the factory's parameters."""
    raw = data["mechanism"]
    if not isinstance(raw, dict):
        raise SceneError(f"{source}: [mechanism] must be a table (name = \"...\" and the "
                         f"mechanism's parameters), got {shown(raw)}")
    if "name" not in raw:
        raise SceneError(f"{where(source, _SECTION, 'name')} is required: the instance "
                         f"({', '.join(map(repr, INSTANCES))}) or \"package.module:factory\"")
    name = raw["name"]
    factory = factory_of(source, name)
    keys, anything = factory_keys(factory)
    kwargs = {k: v for k, v in raw.items() if k != "name"}
    if not anything:
        for key in kwargs:
            if key not in keys:
                raise unknown_key(source, _SECTION, key, ["name", *keys])
    missing = [k for k, d in keys.items() if d is inspect.Parameter.empty and k not in kwargs]
    if missing:
        raise SceneError(f"{where(source, _SECTION, missing[0])} is required: a parameter of "
                         f"{name} without a default (its parameters: {', '.join(keys)})")
    return name, factory, kwargs, keys


def translated(source, data):
    """The scene ``data`` with a ``[mechanism]`` table of a structured instance (`STRUCTURED`:
    rotors, linkage) written as that route's ``[system]`` keys (``kind = "linkage"`` for the
    linkage); ``data`` itself for a scene without one or of the generic route.  A key given in
    both tables is refused."""
    if not isinstance(data, dict) or "mechanism" not in data:
        return data
    name, factory, kwargs, _ = _table(source, data)
    if name not in STRUCTURED:
        return data
    system = data.get("system", {})
    if not isinstance(system, dict):
        return data                                   # reported by the [system] checks
    for key in kwargs:
        if key in system:
            raise SceneError(f"{where(source, 'system', key)} is not allowed beside "
                             f"[mechanism] {key}: give it once, in [mechanism]")
    if "kind" in system:
        raise SceneError(f"{where(source, 'system', 'kind')} is not allowed beside a "
                         "[mechanism] table (the table names the mechanism)")
    out = {k: v for k, v in data.items() if k != "mechanism"}
    out["system"] = {**system, **kwargs}
    if STRUCTURED[name] != "rotors":
        out["system"]["kind"] = STRUCTURED[name]
    return out


def mechanism_of(system: dict):
    """The Mechanism of a generic-route scene's ``[system]`` (built once per process for each
    instance and parameter values)."""
    import json

    key = json.dumps([system["mechanism"], system["parameters"]], sort_keys=True)
    if key not in _BUILT:
        factory = factory_of("<scene>", system["mechanism"])
        _BUILT[key] = factory(**system["parameters"])
    return _BUILT[key]


def mechanism_system(source, data, system, raw_sys, problems) -> None:
    """Fill ``system`` (the validated [system] of a generic-route scene) in place: ``kind =
    "mechanism"``, ``mechanism`` (the instance), ``parameters`` (every keyword of the factory,
    the defaults filled in), ``coordinates`` (the names of q), ``dimension`` (of the
    configuration manifold) and ``speed``.  Problems: a [system] key other than speed, a
    [mechanism] key or value the factory refuses, a factory that returns no Mechanism."""
    from ..mechanism.model import Mechanism

    for key in raw_sys if isinstance(raw_sys, dict) else ():
        if key not in MECHANISM_SYSTEM_KEYS:
            problems.messages.append(
                f"{where(source, 'system', key)} is not allowed with a [mechanism] table (the "
                f"[system] of a mechanism takes {', '.join(MECHANISM_SYSTEM_KEYS)}; the "
                "mechanism's parameters go in [mechanism])")
    try:
        name, factory, kwargs, keys = _table(source, data)
    except SceneError as exc:
        problems.messages.append(str(exc))
        return
    params = {k: kwargs.get(k, d) for k, d in keys.items()
              if k in kwargs or d is not inspect.Parameter.empty}
    params.update(kwargs)                       # (the factory's order, then any **kwargs)
    speed = system["speed"]
    system.clear()
    system.update(kind="mechanism", mechanism=name, parameters=params, speed=speed)
    try:
        mech = mechanism_of(system)
    except (ValueError, TypeError) as exc:
        key = next((k for k in kwargs if str(exc).startswith(k)), None)
        if key is None:           # not a value it refused: the factory's own failure, below
            problems.messages.append(f"{where(source, _SECTION, 'name')} = {shown(name)}: the "
                                     f"factory failed ({type(exc).__name__}: {exc})")
            return
        problems.messages.append(f"{where(source, _SECTION, key)} = {shown(kwargs[key])} is "
                                 f"not allowed: {exc}")
        return
    except Exception as exc:      # noqa: BLE001 - a user's factory may raise anything
        problems.messages.append(f"{where(source, _SECTION, 'name')} = {shown(name)}: the "
                                 f"factory failed ({type(exc).__name__}: {exc})")
        return
    if not isinstance(mech, Mechanism):
        problems.messages.append(f"{where(source, _SECTION, 'name')} = {shown(name)}: the factory "
                                 f"returned {type(mech).__name__}, not a charts.Mechanism")
        return
    if mech.dim < 2:
        problems.messages.append(f"{where(source, _SECTION, 'name')} = {shown(name)}: "
                                 f"{mech.name} has a {mech.dim}-dimensional configuration space; "
                                 "a scene's analyses need 2 or more dimensions")
        return
    system.update(coordinates=[s.name for s in mech.q], dimension=int(mech.dim))


def check_mechanism_start(source, raw_init, integ, context="a [mechanism] table",
                          cls="Mechanism", doc="docs/mechanisms.md") -> None:
    """A mechanism's [initial] (a seed: ``<cls>.random_state``) and [integrator] (ambient
    RK4 with multipliers, its tangent flow's); ``context`` names the scene's kind in the
    messages, ``doc`` the page that says why."""
    for key in ("theta", "u"):
        if key in raw_init:
            raise SceneError(f"{where(source, 'initial', key)} is not allowed with {context}: "
                             f"its state is seeded ({cls}.random_state); give [initial] seed")
    for key, only in (("formulation", "ambient"), ("method", "rk4")):
        if integ[key] != only:
            raise SceneError(f"{where(source, 'integrator', key)} = {shown(integ[key])} is not "
                             f"allowed with {context}: a mechanism is integrated by its "
                             f"multipliers in its ambient coordinates with fixed-step RK4 "
                             f"({key} = {shown(only)}; {doc})")


def check_mechanism_effects(source, run, effects, raw_eff) -> None:
    """The effects the generic route can do (`MECHANISM_EFFECTS`), with their settings:
    the angle test's variant "restricted" (the mechanism's TC), its t_final and
    t_transient multiples of its sample_every."""
    check_own_effects(source, run, effects, raw_eff, MECHANISM_EFFECTS,
                      (("angles", "variant", "restricted", "the tangent bundle TC of the "
                        "mechanism: charts.analyses.mechanism_angles"),),
                      "a [mechanism] table")


def check_own_effects(source, run, effects, raw_eff, allowed, fixed, context) -> None:
    """The effects a mechanism's route can do (``allowed``), the settings it takes one value
    of (``fixed``: (effect, key, the value, why)), filled in; the angle test's t_final and
    t_transient multiples of its sample_every.  ``context`` names the route in messages."""
    sect = "effects.{}".format
    bad = [e for e in effects if e not in allowed]
    if bad:
        raise SceneError(f"{source}: [effects] {', '.join(bad)} is not allowed with "
                         f"{context} (its effects: {', '.join(allowed)})")
    for eff, key, only, why in fixed:
        if eff not in effects:
            continue
        given = raw_eff[eff].get(key, only) if isinstance(raw_eff[eff], dict) else only
        if given != only:
            raise SceneError(f"{where(source, sect(eff), key)} = {shown(given)} is not allowed "
                             f"with {context}: only {shown(only)} ({why})")
        effects[eff][key] = only
    if "angles" in effects:
        from .scene_checks import multiple_of
        a = effects["angles"]
        for sec, key, value in (("run", "t_final", run["t_final"]),
                                ("effects.angles", "t_transient", a["t_transient"])):
            if value > 0:
                multiple_of(source, sec, key, value, a["sample_every"],
                            "[effects.angles] sample_every")


# ------------------------------------------------------------------ the linkage's route
#: [system] keys of the linkage only / of the rotors only.
LINKAGE_KEYS = ("eps", "rho", "disk_mass", "disk_inertia")
ROTOR_KEYS = ("masses", "weights", "level")
#: The effects a linkage scene can request.
LINKAGE_EFFECTS = ("waveforms", "spectrum", "drift", "lyapunov", "curvature", "angles")


def system_kind_problems(source, raw_sys, kind, problems) -> None:
    """Keys of [system] that belong to the other kind, and a missing ``n``/``eps``: added to
    ``problems`` (reported with every other per-key problem)."""
    if not isinstance(raw_sys, dict) or raw_sys.get("kind", kind) != kind:
        return                         # a bad kind is a problem of its own
    own, other, need = ((LINKAGE_KEYS, ROTOR_KEYS, "eps") if kind == "linkage"
                        else (ROTOR_KEYS, LINKAGE_KEYS, "n"))
    for key in other:
        if key in raw_sys:
            problems.messages.append(
                f"{where(source, 'system', key)} = {shown(raw_sys[key])} is not allowed with kind = "
                f"{shown(kind)} (the keys of kind = {shown(kind)}: {', '.join(own)}; docs/scenes.md)")
    if need not in raw_sys:
        what = ("the crank length ε of the linkage, 0 < eps < 0.5" if need == "eps"
                else "Number of rotors N (>= 3; the manifold has dimension N−1).")
        problems.messages.append(f"{where(source, 'system', need)} is required ({what})")


def check_linkage_system(source, system, raw_sys, initial, raw_init, integ, raw_int) -> None:
    """The joined rules of a linkage scene's [system], [initial] and [integrator]; fills
    ``n = 4``, ``rho`` (default 2ε), the unit rotor moments ``masses``."""
    if "n" in raw_sys and system["n"] != 4:
        raise SceneError(f"{where(source, 'system', 'n')} = {shown(system['n'])} is not allowed with "
                         "kind = 'linkage': the linkage of the Appendix has 4 rotors (omit n)")
    try:
        L = factory_of(source, "linkage")(system["eps"], system["rho"],
                                          disk_mass=system["disk_mass"],
                                          disk_inertia=system["disk_inertia"])
    except ValueError as exc:
        key = "rho" if "rho" in raw_sys and str(exc).startswith("rho") else "eps"
        raise SceneError(f"{where(source, 'system', key)} = {shown(system[key])} is not allowed: "
                         f"{exc}") from None
    system.update(n=4, rho=L.rho, masses=[1.0] * 4)
    for key in ROTOR_KEYS[1:]:
        system.pop(key, None)
    check_mechanism_start(source, raw_init, integ, "kind = 'linkage'", "LinkageSystem",
                          "docs/linkage.md")


def linkage_defaults(effects, raw_eff) -> None:
    """Fill the keys a linkage scene leaves out whose default is another call's than a rotor
    scene's (the schema's ``Key.linkage``: curvature's ``sample_every`` is `linkage_run`'s),
    before the defaults are placed on the grid of dt."""
    from .scene_schema import EFFECTS

    for name, table in effects.items():
        written = raw_eff.get(name) if isinstance(raw_eff.get(name), dict) else {}
        for key, spec in EFFECTS[name].items():
            if spec.linkage is not None and key not in written:
                table[key] = spec.linkage.value


def check_linkage_effects(source, run, effects, raw_eff) -> None:
    """The effects a linkage can do, with its settings; fills its defaults (curvature
    route "exact", angles variant "restricted")."""
    fixed = (("lyapunov", "inner_product", "theta",
              "the product of the kinetic metric on positions, Σ δθᵢ² for a massless disk"),
             ("curvature", "route", "exact", "the Gauss equation of the linkage's manifold"),
             ("angles", "variant", "restricted", "the invariant subspace T_r of the linkage"))
    if "angles" in effects and effects["angles"]["n_vectors"] not in (None, 2):
        raise SceneError(f"{where(source, 'effects.angles', 'n_vectors')} = "
                         f"{shown(effects['angles']['n_vectors'])} is not allowed with kind = "
                         "'linkage': the linkage's test follows 2 vectors (its 2 positive "
                         "exponents)")
    check_own_effects(source, run, effects, raw_eff, LINKAGE_EFFECTS, fixed,
                      "kind = 'linkage'")
