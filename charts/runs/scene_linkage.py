"""The linkage of the Appendix as a scene system: ``[system] kind = "linkage"``.

A linkage scene runs the exact four-rotor linkage (``charts.geometry.linkage``) through the
same runner, engine, checkpoints, recorders and result writers as a rotor scene; this module
holds only what differs, each part calling the linkage's API:

* validation: the keys ``eps``, ``rho``, ``disk_mass``, ``disk_inertia`` (the arguments of
  `LinkageSystem`), and which settings and effects a linkage can do (ambient RK4 with
  multipliers only; lyapunov, curvature (the Gauss equation, route "exact"), angles (the
  restricted variant, ``charts.analyses.linkage_angles``), waveforms, spectrum, drift);
* the run's pieces are in ``charts.runs.linkage_run``, the angle pass's plan in
  ``charts.runs.plan``.

The state is y = (q, v) with q = (θ₀…θ₃, x, y, α): the rotors' velocities sit at
``NQ + i``.
"""
from __future__ import annotations

from ..geometry.checks import shown
from .scene_checks import where
from .scene_schema import SceneError

__all__ = ["LINKAGE_KEYS", "ROTOR_KEYS", "is_linkage", "system_kind_problems",
           "check_linkage_system", "check_linkage_effects", "linkage_defaults",
           "LINKAGE_EFFECTS"]

#: [system] keys of the linkage only / of the rotors only.
LINKAGE_KEYS = ("eps", "rho", "disk_mass", "disk_inertia")
ROTOR_KEYS = ("masses", "weights", "level")
#: The effects a linkage scene can request.
LINKAGE_EFFECTS = ("waveforms", "spectrum", "drift", "lyapunov", "curvature", "angles")


def is_linkage(scene) -> bool:
    return scene.system.get("kind") == "linkage"


# ------------------------------------------------------------------------- validation
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
    from ..mechanism.linkage import LinkageSystem

    if "n" in raw_sys and system["n"] != 4:
        raise SceneError(f"{where(source, 'system', 'n')} = {shown(system['n'])} is not allowed with "
                         "kind = 'linkage': the linkage of the Appendix has 4 rotors (omit n)")
    try:
        L = LinkageSystem(system["eps"], system["rho"], disk_mass=system["disk_mass"],
                          disk_inertia=system["disk_inertia"])
    except ValueError as exc:
        key = "rho" if "rho" in raw_sys and str(exc).startswith("rho") else "eps"
        raise SceneError(f"{where(source, 'system', key)} = {shown(system[key])} is not allowed: "
                         f"{exc}") from None
    system.update(n=4, rho=L.rho, masses=[1.0] * 4)
    for key in ROTOR_KEYS[1:]:
        system.pop(key, None)
    for key in ("theta", "u"):
        if key in raw_init:
            raise SceneError(f"{where(source, 'initial', key)} is not allowed with kind = "
                             "'linkage': its state is seeded (LinkageSystem.random_state); "
                             "give [initial] seed")
    for key, only in (("formulation", "ambient"), ("method", "rk4")):
        if integ[key] != only:
            raise SceneError(f"{where(source, 'integrator', key)} = {shown(integ[key])} is not "
                             f"allowed with kind = 'linkage': the linkage is integrated by "
                             f"multipliers in its 7 coordinates with fixed-step RK4 "
                             f"({key} = {shown(only)}; docs/linkage.md)")


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
    sect = "effects.{}".format
    bad = [e for e in effects if e not in LINKAGE_EFFECTS]
    if bad:
        raise SceneError(f"{source}: [effects] {', '.join(bad)} is not allowed with kind = "
                         f"'linkage' (its effects: {', '.join(LINKAGE_EFFECTS)})")
    fixed = (("lyapunov", "inner_product", "theta",
              "the product of the kinetic metric on positions, Σ δθᵢ² for a massless disk"),
             ("curvature", "route", "exact", "the Gauss equation of the linkage's manifold"),
             ("angles", "variant", "restricted", "the invariant subspace T_r of the linkage"))
    for eff, key, only, why in fixed:
        if eff not in effects:
            continue
        given = raw_eff[eff].get(key, only) if isinstance(raw_eff[eff], dict) else only
        if given != only:
            raise SceneError(f"{where(source, sect(eff), key)} = {shown(given)} is not allowed with "
                             f"kind = 'linkage': only {shown(only)} ({why})")
        effects[eff][key] = only
    if "angles" in effects:
        a = effects["angles"]
        if a["n_vectors"] not in (None, 2):
            raise SceneError(f"{where(source, sect('angles'), 'n_vectors')} = "
                             f"{shown(a['n_vectors'])} is not allowed with kind = 'linkage': the "
                             "linkage's test follows 2 vectors (its 2 positive exponents)")
        from .scene_checks import multiple_of
        for sec, key, value in (("run", "t_final", run["t_final"]),
                                ("effects.angles", "t_transient", a["t_transient"])):
            if value > 0:
                multiple_of(source, sec, key, value, a["sample_every"],
                            "[effects.angles] sample_every")
