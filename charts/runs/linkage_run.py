"""The linkage's pieces of a scene run (``[system] kind = "linkage"``): its system, its
flow (the mechanism's), its invariants, its curvature samples, its angle pass and its own results;
the runner, the recorders and the result writers call them where a rotor scene calls the
tangent kernel's (the checks of a linkage scene: ``charts.runs.scene_mechanism``)."""
from __future__ import annotations

import numpy as np

from .mechanism_run import SceneFlow
from .plan import ticks

__all__ = ["linkage_system", "linkage_start", "linkage_flow", "linkage_invariants",
           "linkage_curvature", "linkage_angles_pass", "linkage_paper_exponents",
           "linkage_result"]


def linkage_system(scene):
    """The scene's `LinkageSystem`."""
    from ..mechanism.linkage import LinkageSystem

    s = scene.system
    return LinkageSystem(s["eps"], s["rho"], disk_mass=s["disk_mass"],
                         disk_inertia=s["disk_inertia"])


def linkage_start(scene, system, plan):
    """(positions per state nq = 7, initial state y0 = (q, v) drawn from the scene's seed,
    its speed, the flow, `linkage_flow`)."""
    q, v = system.random_state(seed=scene.initial["seed"], speed=scene.system["speed"])
    return (q.size, np.concatenate([q, v]), float(system.speed(v)),
            linkage_flow(scene, system, q, v, plan.tangent_vectors))


def linkage_flow(scene, system, q, v, k: int):
    """The flow of a linkage scene, the mechanism's (`LinkageSceneFlow`): ``k`` vectors with
    the settings of `linkage_run` (re-orthonormalised every step without a Lyapunov effect,
    as the rotors')."""
    from ..analyses.arguments import project_steps

    integ = scene.integrator
    dt = integ["dt"]
    ly = scene.effects.get("lyapunov")
    reorth = ticks(ly["reorth_every"], dt) if ly else 1
    project = 1 if integ["project"] else project_steps(integ["project_every"] or None, dt)
    return LinkageSceneFlow(system, q, v, k, dt=dt, reorth=reorth, project=project,
                            inner="theta", seed=scene.initial["seed"] or 0)


class LinkageSceneFlow(SceneFlow):
    """A mechanism's `SceneFlow` whose failures are the linkage's (``advance_linkage``: a
    `DegenerateMetricError` where a massless disk's metric degenerates), as `linkage_run`'s."""

    def advance(self, steps, *, where="linkage RK4"):
        from ..analyses.linkage import advance_linkage

        advance_linkage(self.mech, self, steps, where)


def linkage_invariants(system, y, speed) -> list:
    """[the constraint Fᵢ largest in size, (J v)ᵢ largest in size, E/E₀ − 1] at y = (q, v)."""
    from ..mechanism.linkage import NQ

    q, v = y[:NQ], y[NQ:]
    F = system.constraints(q)
    Jv = system.jacobian(q) @ v
    return [float(F[np.argmax(np.abs(F))]), float(Jv[np.argmax(np.abs(Jv))]),
            float((system.speed(v) / speed) ** 2 - 1.0)]


def linkage_curvature(st, kdir: int, routes=None):
    """(None, K(v̂, eᵢ)), i = 1…kdir, at the current state and vectors (`frame_curvatures`:
    the Gauss equation, the linkage's one route, whatever ``routes`` asks)."""
    from ..analyses.linkage import frame_curvatures

    return None, frame_curvatures(st.system, st.flow.Z.ravel(), kdir)


def linkage_paper_exponents(st, k: int):
    """(the paper's N = 4 exponents, the linkage's ε → 0 limit, scaled by the run's speed,
    where they come from)."""
    from .paper import PAPER_EXPONENTS

    return ([round(float(p) * st.speed, 12) for p in PAPER_EXPONENTS[4][:k]],
            "section 2, N = 4: the linkage's limit ε → 0 (Σ cos θᵢ = 0), unit speed; scaled "
            "by the speed")


def linkage_angles_pass(st) -> None:
    """The section-4 angle test of the linkage from the initial state (`linkage_angles`),
    recorded as the rotors' pass is: rows [t, nan (no full variant), φ]."""
    from ..analyses.linkage_angles import linkage_angles
    from ..mechanism.linkage import NQ

    sc = st.scene
    dt = sc.integrator["dt"]
    res = linkage_angles(st.system, st.y0[:NQ], st.y0[NQ:], sc.run["t_final"], dt=dt,
                         t_transient=sc.effects["angles"]["t_transient"],
                         sample_every=sc.effects["angles"]["sample_every"],
                         project_every=st.flow.project * dt or None,
                         seed=sc.initial["seed"] or 0)
    st.rec["angles"] = [[t, np.nan, p] for t, p in zip(res.t, res.phi)]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.backward_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += st.plan.angles["steps"]


def linkage_result(st, out) -> None:
    """The linkage's own numbers: its parameters, the smallest health det(C̃ᵀC̃) of its disk
    (``charts.analyses.linkage.disk_health``) and the smallest Σ sin²θᵢ at the curvature samples
    (0 at a cone point of Σ cos θ = 0) and the distances of M from the six cone points
    (`cone_distance`, θ-metric; 0 for the two that stay on M)."""
    from ..analyses.linkage import CONE_POINTS, cone_distance, disk_health

    system = st.system
    res = {"eps": system.eps, "rho": system.rho, "disk_mass": system.disk_mass,
           "disk_inertia": system.disk_inertia, "min_kkt_health": None}
    Y = np.array(st.rec["curvature_y"])
    if len(Y):
        res["min_sin2"] = float(np.min(np.sum(np.sin(Y[:, :4]) ** 2, axis=1)))
        res["min_kkt_health"] = float(np.min(disk_health(system, Y)))
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
