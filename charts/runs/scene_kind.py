"""What a scene's kind of system decides — the rotors (``charts.runs.rotor_run``), the
Appendix's linkage or any other mechanism (``charts.runs.mechanism_run``; the
``[mechanism]`` table, ``charts.runs.scene_mechanism``):
one record of its pieces per kind, so that the runner, the recorders and the result writers
ask the scene's kind instead of branching on it."""
from __future__ import annotations

from typing import Callable, NamedTuple

from . import mechanism_run, rotor_run

__all__ = ["SceneKind", "scene_kind", "ROTORS", "LINKAGE", "MECHANISM", "KINDS"]


class SceneKind(NamedTuple):
    """The pieces of a scene run that depend on the kind of system."""
    #: "rotors", "linkage" or "mechanism" (``[system] kind``)
    name: str
    #: the names of a state's positions and velocities in result.json
    state_keys: tuple
    #: scene → the system
    system: Callable
    #: (scene, system, plan) → (positions per state, y0, speed, the tangent flow or None)
    start: Callable
    #: run state → [constraint, tangency, E/E₀ − 1] of its current state
    invariants: Callable
    #: (run state, directions, routes) → (numerical K(v̂, eᵢ) or None, exact or None)
    curvature: Callable
    #: run state → None: the section-4 angle test, recorded in the run state
    angles_pass: Callable
    #: (run state, k) → (the paper's first k exponents, their source) or None
    paper_exponents: Callable
    #: (run state, outputs) → None: the kind's own results
    results: Callable
    #: whether the seeds of a scene can share the lanes of one kernel
    lanes: bool


ROTORS = SceneKind("rotors", ("theta", "u"), rotor_run.rotor_system, rotor_run.rotor_start,
                   rotor_run.rotor_invariants, rotor_run.rotor_curvature,
                   rotor_run.rotor_angles_pass, rotor_run.rotor_paper_exponents,
                   lambda st, out: None, True)
_invariants = lambda st: mechanism_run.mechanism_invariants(st.system, st.y, st.speed)  # noqa: E731
LINKAGE = SceneKind("linkage", ("q", "v"), mechanism_run.linkage_system,
                    mechanism_run.linkage_start, _invariants, mechanism_run.linkage_curvature,
                    mechanism_run.mechanism_angles_pass, mechanism_run.linkage_paper_exponents,
                    mechanism_run.linkage_result, False)

MECHANISM = SceneKind("mechanism", ("q", "v"), mechanism_run.mechanism_system,
                      mechanism_run.mechanism_start, _invariants,
                      mechanism_run.mechanism_curvature_sample,
                      mechanism_run.mechanism_angles_pass, lambda st, k: None,
                      mechanism_run.mechanism_result, False)
#: The kinds by their name.
KINDS = {kind.name: kind for kind in (ROTORS, LINKAGE, MECHANISM)}


def scene_kind(scene) -> SceneKind:
    """The `SceneKind` of a scene (``[system] kind``, "rotors" where it has none)."""
    return KINDS[scene.system.get("kind", "rotors")]
