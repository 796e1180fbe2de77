"""The state of a scene run, saved whole in the checkpoint after every chunk: the state y,
the tangent vectors, the log-norm sums, the counters and everything recorded so far.

``checkpoint.npz`` holds :meth:`RunState.to_arrays` plus the :func:`scene_hash` of the scene
it belongs to (a resume from a checkpoint of another scene is refused).
"""
from __future__ import annotations

import hashlib
import json

import numpy as np

from ..geometry.system import RotorSystem
from .plan import Plan
from .scene import Scene, scene_to_dict

__all__ = ["RunState", "RunError", "CHECKPOINT", "scene_hash", "units_done"]

#: File name of the checkpoint in the output folder.
CHECKPOINT = "checkpoint.npz"


class RunError(RuntimeError):
    """A scene that validated but cannot run in this installation or output folder."""


def scene_hash(scene: Scene) -> str:
    """Short digest of the scene as run (every default filled in)."""
    blob = json.dumps(scene_to_dict(scene), sort_keys=True).encode()
    return hashlib.sha256(blob).hexdigest()[:16]


class RunState:
    """Everything a run accumulates; saved whole in the checkpoint."""

    def __init__(self, scene: Scene, plan: Plan, system: RotorSystem):
        self.scene, self.plan, self.system = scene, plan, system
        if scene.initial["theta"] is not None:
            theta, u = np.array(scene.initial["theta"]), np.array(scene.initial["u"])
        else:
            theta, u = system.random_state(seed=scene.initial["seed"],
                                           speed=scene.system["speed"])
        self.y0 = np.concatenate([theta, u])
        self.y = self.y0.copy()
        self.speed = float(system.speed(u))
        self.X = self._initial_vectors(plan.tangent_vectors)
        self.logsum = np.zeros(plan.tangent_vectors)
        self.lyap_marks = []           # (tick, logsum) at Lyapunov batch boundaries
        self.rhs = 0                   # evaluations of the (augmented) vector field
        self.rhs_frame = 0             # extra evaluations for the curvature frame steps
        self.steps = 0                 # accepted integrator steps
        self.chart = -1                # chart in use (chart formulation), -1: not yet chosen
        self.rec = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature_num",
                                          "curvature_exact", "curvature_y", "switches", "angles",
                                          "angles_exponents")}
        self.rec_t = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature")}
        self.elapsed = 0.0
        self.done = False
        self.chunk_index = 0
        self.n_main = None             # chunks of the main pass (set by the runner)

    def _initial_vectors(self, k):
        n = self.system.n
        if k == 0:
            return np.empty((0, 2 * n))
        # TODO(lead): a public initial-vectors function in charts.analyses.lyapunov
        from ..analyses.lyapunov import _initial_vectors, inner_weights
        inner = self.scene.effects.get("lyapunov", {}).get("inner_product", "theta")
        return _initial_vectors(self.system, self.y, k, self.scene.initial["seed"] or 0, True,
                                inner_weights(self.system, inner))

    # -- checkpoint ------------------------------------------------------------------------
    def to_arrays(self) -> dict:
        a = {"y": self.y, "X": self.X, "logsum": self.logsum,
             "scalars": np.array([self.rhs, self.rhs_frame, self.chunk_index,
                                  self.elapsed, float(self.done), self.steps, self.chart]),
             "lyap_ticks": np.array([m[0] for m in self.lyap_marks], dtype=np.int64),
             "lyap_logsums": np.array([m[1] for m in self.lyap_marks]).reshape(
                 len(self.lyap_marks), self.plan.tangent_vectors)}
        for name, rows in self.rec.items():
            a["rec_" + name] = np.array(rows, dtype=float)
        for name, rows in self.rec_t.items():
            a["rect_" + name] = np.array(rows, dtype=float)
        return a

    def load_arrays(self, a):
        self.y, self.X, self.logsum = a["y"].copy(), a["X"].copy(), a["logsum"].copy()
        rhs, rhs_frame, chunk, elapsed, done, steps, chart = a["scalars"]
        self.steps, self.chart = int(steps), int(chart)
        self.rhs, self.rhs_frame = int(rhs), int(rhs_frame)
        self.chunk_index, self.elapsed, self.done = int(chunk), float(elapsed), bool(done)
        self.lyap_marks = [(int(t), l.copy()) for t, l in zip(a["lyap_ticks"], a["lyap_logsums"])]
        for name in self.rec:
            self.rec[name] = list(a["rec_" + name])
        for name in self.rec_t:
            self.rec_t[name] = list(a["rect_" + name])


def units_done(st: RunState, ends) -> int:
    """Units (steps or samples, transient included) of the main pass done, from the chunk
    ends ``ends``."""
    k = min(st.chunk_index, len(ends) if st.n_main is None else st.n_main)
    return ends[k - 1] if k else 0
