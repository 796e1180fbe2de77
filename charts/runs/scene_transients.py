"""A scene's transients named by a rule (``t_transient = "scaled"`` or ``"auto"``, in [run],
[effects.angles] or [effects.clv]; ``charts.analyses.transients``), turned into durations
when the scene is read, so that every pass, checkpoint and sweep worker sees a number: the
same duration the API call with that rule would use.  A mechanism's scene (``[mechanism]``,
the generic route) takes "auto", its pilot the mechanism's own
(``charts.analyses.mechanism_lyapunov.resolve_transient``, which refuses "scaled")."""
from __future__ import annotations

from functools import lru_cache

from ..geometry.checks import shown
from .scene_checks import where
from .scene_schema import SceneError

__all__ = ["scene_transients", "refuse_linkage_rules"]


def _named(run, effects):
    """(section, table) of each transient that names a rule."""
    return [(sect, table) for sect, table in
            [("run", run)] + [(f"effects.{e}", effects[e]) for e in ("angles", "clv")
                              if e in effects]
            if isinstance(table.get("t_transient"), str)]


def refuse_linkage_rules(source, run, effects):
    """SceneError where a linkage's transient names a rule (the rules are the rotors')."""
    named = _named(run, effects)
    if named:
        sect, table = named[0]
        raise SceneError(f"{where(source, sect, 't_transient')} = {shown(table['t_transient'])} "
                         "is not allowed for the linkage: the transient rules are the rotors' "
                         "(their exponents); give the transient in time units")


def scene_transients(source, linkage, system, initial, integ, run, effects):
    """Replace each transient of ``run`` and the angles and CLV effects that names a rule
    by its duration (the nearest whole number of steps; [run]'s of its sample_dt), from the
    scene's system and initial state (given, or drawn from its seed); "auto" runs its pilot
    with the scene's step, exponents, product and seed.  Returns the rules' texts (None
    where every transient is a number).  SceneError for a rule on the linkage, or an
    "auto" whose pilot fails."""
    named = _named(run, effects)
    if not named:
        return None
    if linkage:
        refuse_linkage_rules(source, run, effects)
    dt = integ.get("dt") or 0.01
    ly = effects.get("lyapunov", {})
    mechanical = system.get("kind") == "mechanism"
    if mechanical:
        import json
        project = dt if integ.get("project") else (integ.get("project_every") or None)
        key = (json.dumps([system["mechanism"], system["parameters"]], sort_keys=True),
               float(system["speed"]), initial.get("seed"), float(dt), ly.get("n_exponents"),
               ly.get("inner_product", "theta"), project)
    else:
        masses = system.get("masses")
        weights = system.get("weights")
        key = (system["n"], tuple(masses) if masses else None,
               tuple(weights) if weights else None, float(system.get("level", 0.0)),
               float(system["speed"]), initial.get("seed"),
               tuple(initial["theta"]) if initial.get("theta") is not None else None,
               tuple(initial["u"]) if initial.get("u") is not None else None, float(dt),
               ly.get("n_exponents"), ly.get("inner_product", "theta"))
    texts = []
    for sect, table in named:
        try:
            duration, text = (_mechanism_resolved if mechanical else _resolved)(
                table["t_transient"], key)
        except ValueError as exc:
            raise SceneError(f"{where(source, sect, 't_transient')} = "
                             f"{shown(table['t_transient'])}: {exc}") from None
        grid = run["sample_dt"] if sect == "run" else dt
        if mechanical and sect == "effects.angles":       # mechanism_angles's grid
            grid = table["sample_every"]
        table["t_transient"] = max(1, round(float(duration) / grid)) * grid
        if text not in texts:
            texts.append(text)
    return "; ".join(texts)


@lru_cache(maxsize=64)
def _resolved(rule, key):
    """(duration, rule text) of ``rule`` for the scene whose system, state and pilot
    settings ``key`` holds (cached: a sweep's worker reads its point's scene again)."""
    import numpy as np

    from ..analyses.lyapunov import resolve_transient
    from ..geometry.system import RotorSystem
    n, masses, weights, level, speed, seed, theta, u, dt, k, inner = key
    system = RotorSystem(n, None if masses is None else list(masses),
                         None if weights is None else list(weights), level)
    if theta is not None:
        theta, u = np.array(theta), np.array(u)
    else:
        theta, u = system.random_state(seed=seed, speed=speed)
    return resolve_transient(rule, system, theta, u, dt=dt, n_exponents=k, inner=inner,
                             space="restricted", seed=seed or 0)


@lru_cache(maxsize=64)
def _mechanism_resolved(rule, key):
    """(duration, rule text) of ``rule`` for a mechanism's scene whose mechanism, state and
    pilot settings ``key`` holds (cached as `_resolved`): the pilot of
    ``lyapunov_spectrum(mech, q, v, ..., t_transient=rule)`` from the scene's seeded state."""
    import json

    from ..analyses.mechanism_lyapunov import resolve_transient
    from .scene_mechanism import mechanism_of
    instance, speed, seed, dt, k, inner, project = key
    name, parameters = json.loads(instance)
    mech = mechanism_of({"mechanism": name, "parameters": parameters})
    q, v = mech.random_state(seed=seed, speed=speed)
    return resolve_transient(rule, mech, q, v, dt=dt, n_exponents=k, inner=inner,
                             project_every=project, seed=seed or 0)
