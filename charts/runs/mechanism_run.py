"""A mechanism's pieces of a scene run (a ``[mechanism]`` table on the generic route,
``charts.runs.scene_mechanism``): its Mechanism, its compiled tangent flow with the settings
of ``charts.analyses.mechanism_lyapunov.lyapunov_spectrum`` (so that a scene and that call
give the same numbers), its invariants and its own results; ``charts.runs.scene_kind`` hands
them to the runner, the recorders and the result writers."""
from __future__ import annotations

import numpy as np

from ..mechanism.tangent_flow import MechanismTangentFlow
from .plan import ticks

__all__ = ["mechanism_system", "mechanism_start", "SceneFlow", "mechanism_invariants",
           "mechanism_curvature_sample", "mechanism_angles_pass", "mechanism_result"]


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


def mechanism_start(scene, system, plan):
    """(positions per state n, initial state y0 = (q, v) drawn from the scene's seed at its
    speed, that speed, the `SceneFlow` with ``plan.tangent_vectors`` vectors): re-orthonormalised
    every ``reorth_every`` of the Lyapunov effect (every step without one), projected every
    ``project_every``, in its ``inner_product``, seeded by the scene's seed — as
    ``lyapunov_spectrum``."""
    seed = scene.initial["seed"] or 0
    q, v = system.random_state(seed=seed, speed=scene.system["speed"])
    integ = scene.integrator
    dt = integ["dt"]
    ly = scene.effects.get("lyapunov", {})
    reorth = ticks(ly["reorth_every"], dt) if ly else 1
    project = 1 if integ["project"] else ticks(integ["project_every"] or 0.0, dt)
    flow = SceneFlow(system, q, v, plan.tangent_vectors, dt=dt, reorth=reorth,
                     project=project, inner=ly.get("inner_product", "theta"), seed=seed)
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
    t = res.t - res.params["t_transient"]
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
