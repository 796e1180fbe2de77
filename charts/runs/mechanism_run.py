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
           "mechanism_result"]


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


def mechanism_result(st, out) -> None:
    """The mechanism's own entry of the results: its instance, parameter values, the names
    of its coordinates and the dimension of its configuration manifold."""
    s = st.scene.system
    out.results["mechanism"] = {"name": s["mechanism"], "label": st.system.name,
                                "parameters": dict(s["parameters"]),
                                "coordinates": list(s["coordinates"]),
                                "dimension": s["dimension"]}
