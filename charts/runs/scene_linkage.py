"""The linkage of the Appendix as a scene system: ``[system] kind = "linkage"``.

A linkage scene runs the exact four-rotor linkage (``charts.geometry.linkage``) through the
same runner, engine, checkpoints, recorders and result writers as a rotor scene; this module
holds only what differs, each part calling the linkage's API:

* validation: the keys ``eps``, ``rho``, ``disk_mass``, ``disk_inertia`` (the arguments of
  `LinkageSystem`), and which settings and effects a linkage can do (ambient RK4 with
  multipliers only; lyapunov, curvature (the Gauss equation, route "exact"), angles (the
  restricted variant, ``charts.analyses.linkage_angles``), waveforms, spectrum, drift);
* the run: the system, its seeded state (`LinkageSystem.random_state`), its tangent flow
  (`LinkageFlow` with the settings of `linkage_run`), its invariants, curvature samples
  (`frame_curvatures`), the angles pass (`linkage_angles`) and the linkage's own results.

The state is y = (q, v) with q = (θ₀…θ₃, x, y, α): the rotors' velocities sit at
``NQ + i``.
"""
from __future__ import annotations

import numpy as np

from .scene_checks import where
from .scene_schema import SceneError

__all__ = ["LINKAGE_KEYS", "ROTOR_KEYS", "is_linkage", "system_kind_problems",
           "check_linkage_system", "check_linkage_effects", "linkage_system", "linkage_flow",
           "linkage_invariants", "linkage_curvature", "linkage_angles_pass",
           "linkage_angles_plan", "linkage_result", "LINKAGE_EFFECTS"]

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
                f"{where(source, 'system', key)} = {raw_sys[key]!r} is not allowed with kind = "
                f"{kind!r} (the keys of kind = {kind!r}: {', '.join(own)}; docs/scenes.md)")
    if need not in raw_sys:
        what = ("the crank length ε of the linkage, 0 < eps < 0.5" if need == "eps"
                else "Number of rotors N (>= 3; the manifold has dimension N−1).")
        problems.messages.append(f"{where(source, 'system', need)} is required ({what})")


def check_linkage_system(source, system, raw_sys, initial, raw_init, integ, raw_int) -> None:
    """The joined rules of a linkage scene's [system], [initial] and [integrator]; fills
    ``n = 4``, ``rho`` (default 2ε), the unit rotor moments ``masses``."""
    from ..geometry.linkage import LinkageSystem

    if "n" in raw_sys and system["n"] != 4:
        raise SceneError(f"{where(source, 'system', 'n')} = {system['n']!r} is not allowed with "
                         "kind = 'linkage': the linkage of the Appendix has 4 rotors (omit n)")
    try:
        L = LinkageSystem(system["eps"], system["rho"], disk_mass=system["disk_mass"],
                          disk_inertia=system["disk_inertia"])
    except ValueError as exc:
        key = "rho" if "rho" in raw_sys and str(exc).startswith("rho") else "eps"
        raise SceneError(f"{where(source, 'system', key)} = {system[key]!r} is not allowed: "
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
            raise SceneError(f"{where(source, 'integrator', key)} = {integ[key]!r} is not "
                             f"allowed with kind = 'linkage': the linkage is integrated by "
                             f"multipliers in its 7 coordinates with fixed-step RK4 "
                             f"({key} = {only!r}; docs/linkage.md)")


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
            raise SceneError(f"{where(source, sect(eff), key)} = {given!r} is not allowed with "
                             f"kind = 'linkage': only {only!r} ({why})")
        effects[eff][key] = only
    if "angles" in effects:
        a = effects["angles"]
        if a["n_vectors"] not in (None, 2):
            raise SceneError(f"{where(source, sect('angles'), 'n_vectors')} = "
                             f"{a['n_vectors']!r} is not allowed with kind = 'linkage': the "
                             "linkage's test follows 2 vectors (its 2 positive exponents)")
        from .scene_checks import multiple_of
        for key in ("t_final", "t_transient"):
            if run[key] > 0:
                multiple_of(source, "run", key, run[key], a["sample_every"],
                            "[effects.angles] sample_every")


# ------------------------------------------------------------------------------- runs
def linkage_system(scene):
    """The scene's `LinkageSystem`."""
    from ..geometry.linkage import LinkageSystem

    s = scene.system
    return LinkageSystem(s["eps"], s["rho"], disk_mass=s["disk_mass"],
                         disk_inertia=s["disk_inertia"])


def linkage_flow(scene, system, q, v, k: int):
    """The `LinkageFlow` of a linkage scene: ``k`` vectors with the settings of
    `linkage_run` (re-orthonormalised every step without a Lyapunov effect, as the rotors')."""
    from ..analyses.arguments import project_steps
    from ..solvers.linkage import LinkageFlow
    from .plan import ticks

    integ = scene.integrator
    dt = integ["dt"]
    ly = scene.effects.get("lyapunov")
    reorth = ticks(ly["reorth_every"], dt) if ly else 1
    project = 1 if integ["project"] else project_steps(integ["project_every"] or None, dt)
    return LinkageFlow(system, q, v, k, dt=dt, reorth_every=reorth, project_every=project,
                       seed=scene.initial["seed"] or 0)


def linkage_invariants(system, y, speed) -> list:
    """[the constraint Fᵢ largest in size, (J v)ᵢ largest in size, E/E₀ − 1] at y = (q, v)."""
    from ..geometry.linkage import NQ

    q, v = y[:NQ], y[NQ:]
    F = system.constraints(q)
    Jv = system.jacobian(q) @ v
    return [float(F[np.argmax(np.abs(F))]), float(Jv[np.argmax(np.abs(Jv))]),
            float((system.speed(v) / speed) ** 2 - 1.0)]


def linkage_curvature(st, kdir: int):
    """K(v̂, eᵢ), i = 1…kdir, at the current state and vectors (`frame_curvatures`)."""
    from ..analyses.linkage import frame_curvatures

    return frame_curvatures(st.system, st.flow.Z.ravel(), kdir)


def linkage_angles_plan(scene) -> dict:
    """The angles pass of `linkage_angles`: forward t_transient + t_final + t_transient,
    backward t_final + t_transient, two vectors each, re-orthonormalised every step."""
    from .plan import ticks

    dt = scene.integrator["dt"]
    n_tr, total = ticks(scene.run["t_transient"], dt), ticks(scene.run["t_final"], dt)
    steps = (2 * n_tr + total) + (n_tr + total)
    return {"forward_vectors": 2, "adjoint_vectors": 2, "steps": steps,
            "rhs_evaluations": 4 * steps, "stored_trajectory_checkpoints": 0,
            "stored_samples": ticks(scene.run["t_final"],
                                    scene.effects["angles"]["sample_every"]) + 1}


def linkage_angles_pass(st) -> None:
    """The section-4 angle test of the linkage from the initial state (`linkage_angles`),
    recorded as the rotors' pass is: rows [t, nan (no full variant), φ]."""
    from ..analyses.linkage_angles import linkage_angles
    from ..geometry.linkage import NQ

    sc = st.scene
    dt = sc.integrator["dt"]
    res = linkage_angles(st.system, st.y0[:NQ], st.y0[NQ:], sc.run["t_final"], dt=dt,
                         t_transient=sc.run["t_transient"],
                         sample_every=sc.effects["angles"]["sample_every"],
                         project_every=st.flow.project_every * dt or None,
                         seed=sc.initial["seed"] or 0)
    st.rec["angles"] = [[t, np.nan, p] for t, p in zip(res.t, res.phi)]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.backward_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += st.plan.angles["steps"]


def linkage_result(st, out) -> None:
    """The linkage's own numbers: its parameters, the smallest KKT health det(C̃ᵀC̃) met
    (``charts.solvers.linkage.GRAM_MIN``), the smallest Σ sin²θᵢ at the curvature samples
    (0 at a cone point of Σ cos θ = 0) and the distances of M from the six cone points
    (`cone_distance`, θ-metric; 0 for the two that stay on M)."""
    from ..analyses.linkage import CONE_POINTS, cone_distance

    system = st.system
    res = {"eps": system.eps, "rho": system.rho, "disk_mass": system.disk_mass,
           "disk_inertia": system.disk_inertia,
           "min_kkt_health": float(st.flow.health[0]) if st.flow.steps else None}
    Y = np.array(st.rec["curvature_y"])
    if len(Y):
        res["min_sin2"] = float(np.min(np.sum(np.sin(Y[:, :4]) ** 2, axis=1)))
    d = []
    for p in CONE_POINTS:
        try:
            d.append(cone_distance(system, p, 1)[0])
        except RuntimeError:
            d.append(None)
    res["cone_distances"] = d
    found = [x for x in d if x is not None]
    res["cone_points_on_manifold"] = sum(x < 1e-6 for x in found)
    avoided = [x for x in found if x >= 1e-6]
    res["cone_distance_min"] = min(avoided) if avoided else None
    out.results["linkage"] = res
