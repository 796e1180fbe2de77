"""A mechanism's pieces of a scene run (a ``[mechanism]`` table, ``charts.runs.scene_mechanism``):
its Mechanism, its compiled tangent flow with the settings of
``charts.analyses.mechanism_lyapunov.lyapunov_spectrum`` (so that a scene and that call give
the same numbers), its invariants, its curvature samples, its angle test and its own results;
``charts.runs.scene_kind`` hands them to the runner, the recorders and the result writers.

The Appendix's linkage (``[system] kind = "linkage"``) is a Mechanism on the same flow, with
the same invariants and angle test; what it has of its own is at the end: its construction
from [system], the linkage's words for a failed step (`LinkageSceneFlow`), its curvature
route (the Gauss equation, as ``charts.linkage_run``), its reference exponents (the paper's
N = 4, its ε → 0 limit) and its results (the disk's health, the cone points)."""
from __future__ import annotations

import numpy as np

from ..mechanism.tangent_flow import MechanismTangentFlow
from .plan import ticks

__all__ = ["mechanism_system", "mechanism_start", "scene_flow", "SceneFlow",
           "mechanism_invariants", "mechanism_curvature_sample", "mechanism_angles_pass",
           "mechanism_result", "linkage_system", "linkage_start", "LinkageSceneFlow",
           "linkage_curvature", "linkage_paper_exponents", "linkage_result"]


def mechanism_system(scene):
    """The scene's Mechanism (``charts.runs.scene_mechanism.mechanism_of``)."""
    from .scene_mechanism import mechanism_of

    return mechanism_of(scene.system)


class SceneFlow(MechanismTangentFlow):
    """`MechanismTangentFlow` as the kernel engine drives a flow: ``advance(nsteps,
    where=...)`` (a failure an ``IntegrationError`` naming the route), ``state`` /
    ``load_state`` for the checkpoints, ``project_every`` in steps."""

    @property
    def project_every(self) -> int:
        return self.project

    def advance(self, steps, *, where="mechanism RK4"):
        from ..mechanism.errors import MechanismError
        from ..solvers.status import IntegrationError

        try:
            super().advance(steps)
        except MechanismError as exc:
            raise IntegrationError(f"{where}: {exc}") from None

    def state(self) -> dict:
        """Copies of every array that decides the next step (for checkpoints)."""
        return {"Z": self.Z.copy(), "counter": self.counter.copy(),
                "logsum": self.logsum.copy()}

    def load_state(self, a) -> None:
        for key, arr in self.state().items():
            getattr(self, key)[...] = a[key]


def scene_flow(scene, system, q, v, k: int, cls=SceneFlow):
    """The flow (``cls``: `SceneFlow` or a subclass) of a mechanism's scene from (q, v) with
    ``k`` vectors: re-orthonormalised every ``reorth_every`` of the Lyapunov effect (every
    step without one, as the rotors'), projected every ``project_every``, in its
    ``inner_product``, seeded by the scene's seed — as ``lyapunov_spectrum`` and
    ``linkage_run``."""
    integ = scene.integrator
    dt = integ["dt"]
    ly = scene.effects.get("lyapunov", {})
    reorth = ticks(ly["reorth_every"], dt) if ly else 1
    project = 1 if integ["project"] else ticks(integ["project_every"] or 0.0, dt)
    return cls(system, q, v, k, dt=dt, reorth=reorth, project=project,
               inner=ly.get("inner_product", "theta"), seed=scene.initial["seed"] or 0)


def mechanism_start(scene, system, plan, cls=SceneFlow):
    """(positions per state n, initial state y0 = (q, v) drawn from the scene's seed at its
    speed (``random_state``), that speed, the `scene_flow` with ``plan.tangent_vectors``
    vectors)."""
    q, v = system.random_state(seed=scene.initial["seed"], speed=scene.system["speed"])
    flow = scene_flow(scene, system, q, v, plan.tangent_vectors, cls)
    return system.n, np.concatenate([q, v]), float(np.sqrt(2 * flow.energy())), flow


def mechanism_invariants(system, y, speed) -> list:
    """[the constraint Fᵢ largest in size, (J v)ᵢ largest in size, E/E₀ − 1] at y = (q, v)
    of ``system`` (a Mechanism) whose initial speed was ``speed``."""
    n = system.n
    q, v = y[:n], y[n:]
    F = system.constraint(q)
    Jv = system.jacobian(q) @ v
    return [float(F[np.argmax(np.abs(F))]), float(Jv[np.argmax(np.abs(Jv))]),
            float(2 * system.energy(q, v) / speed ** 2 - 1.0)]


def mechanism_curvature_sample(st, kdir: int, routes: str):
    """(K(v̂, eᵢ) by route (a), the Jacobi fields moved by ±dt; by route (b), the Riemann
    tensor in a chart), i = 1…kdir, each None where ``routes`` leaves it out: the frame of
    ``charts.analyses.mechanism_curvature`` (the velocity and the position parts of the first
    ``kdir`` vectors, M-orthonormal) at the current state put on TC, as that analysis
    evaluates its samples."""
    from ..analyses.mechanism_curvature import (jacobi_curvature, jacobi_frame,
                                                riemann_curvature)

    mech, n = st.system, st.nq
    q = mech.project_point(st.y[:n])
    v = mech.project_velocity(q, st.y[n:])
    X = np.array([np.concatenate(mech.project_phase_tangent(q, v, x[:n], x[n:]))
                  for x in st.X[:kdir]])
    J, P = jacobi_frame(mech, q, v, X)
    Kn = Ke = None
    if routes in ("numerical", "both"):
        Kn = np.diagonal(jacobi_curvature(mech, q, v, J, P, st.scene.integrator["dt"])).copy()
    if routes in ("exact", "both"):
        Ke = np.diagonal(riemann_curvature(mech, q, P)).copy()
    return Kn, Ke


def mechanism_angles_pass(st) -> None:
    """The restricted angle test (section 4, ``charts.analyses.mechanism_angles``) from the
    initial state with the scene's settings, recorded as the linkage's pass is: rows [t from
    the window's start, nan (no full variant), φ]."""
    from ..analyses.mechanism_angles import mechanism_angles

    sc, n = st.scene, st.nq
    a, dt = sc.effects["angles"], sc.integrator["dt"]
    res = mechanism_angles(st.system, st.y0[:n], st.y0[n:], sc.run["t_final"], dt=dt,
                           n_unstable=a["n_vectors"], t_transient=a["t_transient"],
                           sample_every=a["sample_every"],
                           project_every=st.flow.project * dt or None,
                           seed=sc.initial["seed"] or 0)
    sample = ticks(a["sample_every"], dt)         # (the times as the linkage's test gives them)
    t = np.arange(len(res.t)) * sample * dt
    st.rec["angles"] = [[ti, np.nan, p] for ti, p in zip(t, res.phi_restricted)]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.adjoint_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += st.plan.angles["steps"]


def mechanism_result(st, out) -> None:
    """The mechanism's own entry of the results: its instance, parameter values, the names
    of its coordinates and the dimension of its configuration manifold."""
    s = st.scene.system
    out.results["mechanism"] = {"name": s["mechanism"], "label": st.system.name,
                                "parameters": dict(s["parameters"]),
                                "coordinates": list(s["coordinates"]),
                                "dimension": s["dimension"]}


# ------------------------------------------------------------------------- the linkage
def linkage_system(scene):
    """The scene's `LinkageSystem` (the instance ``linkage`` of
    ``charts.runs.scene_mechanism``)."""
    from .scene_mechanism import factory_of

    s = scene.system
    return factory_of(scene.source, "linkage")(s["eps"], s["rho"], disk_mass=s["disk_mass"],
                                               disk_inertia=s["disk_inertia"])


class LinkageSceneFlow(SceneFlow):
    """The `SceneFlow` whose failures are the linkage's (``advance_linkage``: a
    ``DegenerateMetricError`` where a massless disk's metric degenerates), as `linkage_run`'s."""

    def advance(self, steps, *, where="linkage RK4"):
        from ..analyses.linkage import advance_linkage

        advance_linkage(self.mech, self, steps, where)


def linkage_start(scene, system, plan):
    """`mechanism_start` with the `LinkageSceneFlow` (q = (θ₀…θ₃, x, y, α), nq = 7)."""
    return mechanism_start(scene, system, plan, LinkageSceneFlow)


def linkage_curvature(st, kdir: int, routes=None):
    """(None, K(v̂, eᵢ)), i = 1…kdir, at the current state and vectors (`frame_curvatures`:
    the Gauss equation, the linkage's one route and `linkage_run`'s, whatever ``routes``
    asks)."""
    from ..analyses.linkage import frame_curvatures

    return None, frame_curvatures(st.system, st.flow.Z.ravel(), kdir)


def linkage_paper_exponents(st, k: int):
    """(the paper's N = 4 exponents, the linkage's ε → 0 limit, scaled by the run's speed,
    where they come from)."""
    from .paper import PAPER_EXPONENTS

    return ([round(float(p) * st.speed, 12) for p in PAPER_EXPONENTS[4][:k]],
            "section 2, N = 4: the linkage's limit ε → 0 (Σ cos θᵢ = 0), unit speed; scaled "
            "by the speed")


def linkage_result(st, out) -> None:
    """The linkage's own numbers: its parameters, the smallest health det(C̃ᵀC̃) of its disk
    (``charts.analyses.linkage.disk_health``) and the smallest Σ sin²θᵢ at the curvature
    samples (0 at a cone point of Σ cos θ = 0), and the distances of M from the six cone
    points (`cone_distance`, θ-metric; 0 for the two that stay on M)."""
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
