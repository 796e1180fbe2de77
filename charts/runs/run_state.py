"""The state of a scene run, saved whole in the checkpoint after every chunk: the state y,
the tangent vectors, the log-norm sums, the counters and everything recorded so far.

``checkpoint.npz`` holds :meth:`RunState.to_arrays` plus the :func:`scene_hash` of the scene
it belongs to (a resume from a checkpoint of another scene is refused).
"""
from __future__ import annotations

import hashlib
import json

import numpy as np

from .plan import Plan
from .scene import Scene, scene_to_dict
from .scene_kind import scene_kind

__all__ = ["RunState", "RunError", "CheckpointError", "CHECKPOINT", "scene_hash", "units_done",
           "read_checkpoint"]

#: File name of the checkpoint in the output folder.
CHECKPOINT = "checkpoint.npz"


class RunError(RuntimeError):
    """A scene that validated but cannot run in this installation or output folder."""


class CheckpointError(RunError):
    """A checkpoint that a resume cannot trust: it cannot be read (empty, torn, not a
    checkpoint), or what it holds disagrees with itself or with the run's settings.  The
    message names the file and what is wrong.  ``charts run --resume`` refuses it; a
    sweep's point takes it as torn and computes the point again, with a notice."""


def read_checkpoint(path) -> dict:
    """Every array of the checkpoint at ``path``, read whole (``allow_pickle=False``);
    `CheckpointError` naming the file where it cannot be read: empty or torn (an
    ``EOFError``, a ``BadZipFile``, a member cut short), not a checkpoint at all."""
    try:
        with np.load(path, allow_pickle=False) as a:
            if not hasattr(a, "files"):                     # a bare .npy array
                raise ValueError("an array, not a folder of named arrays")
            return {k: a[k] for k in a.files}
    except Exception as exc:        # noqa: BLE001 - whatever a damaged file makes NumPy raise
        text = " ".join(str(exc).split()) or "no detail"
        raise CheckpointError(f"{path} is not a usable checkpoint ({type(exc).__name__}: "
                              f"{text[:200]})") from None


def scene_hash(scene: Scene) -> str:
    """Short digest of the scene as run (every default filled in)."""
    blob = json.dumps(scene_to_dict(scene), sort_keys=True).encode()
    return hashlib.sha256(blob).hexdigest()[:16]


class RunState:
    """Everything a run accumulates; saved whole in the checkpoint."""

    def __init__(self, scene: Scene, plan: Plan, system):
        self.scene, self.plan, self.system = scene, plan, system
        #: positions in y before the velocities: N, or 7 for the linkage's q = (θ, x, y, α);
        #: the initial state, its speed, and the tangent flow of the kernel engine (state,
        #: vectors, log-norm sums; None for the integrate engine)
        self.nq, self.y0, self.speed, self.flow = scene_kind(scene).start(scene, system, plan)
        #: the angle test's `AngleResult` where it was computed with other seeds' (on a GPU,
        #: ``charts.runs.seed_lanes``); None: the angle pass computes it
        self.angles_result = None
        self._y = self.y0.copy()
        self.lyap_marks = []           # (tick, logsum) at Lyapunov batch boundaries
        self.shares_partial = False    # resumed from a checkpoint without the energy shares
        self.rhs = 0                   # evaluations of the (augmented) vector field
        self.rhs_frame = 0             # extra evaluations for the curvature frame steps
        self.steps = 0                 # accepted integrator steps
        self.chart = -1                # chart in use (chart formulation), -1: not yet chosen
        self.rec = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature_num",
                                          "curvature_exact", "curvature_y", "switches", "angles",
                                          "angles_exponents", "clv", "clv_exponents",
                                          "clv_domination", "clv_ftle")}
        self.rec_t = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature")}
        self.elapsed = 0.0
        self.compile_s = 0.0   # of this process's chunks (compiling or loading kernels; not checkpointed)
        self.done = False
        self.chunk_index = 0
        self.n_main = None             # chunks of the main pass (set by the runner)
        #: {"t_done", "chunks_done"} of the checkpoint this run continued; None: from the start
        self.resumed_from = None

    def add_compile_time(self, seconds):
        """Count ``seconds`` of compiling (``charts.jit.compilation.compile_timer``)."""
        self.compile_s += seconds

    @property
    def y(self):
        """The current state (θ, u), shape (2N,)."""
        return self.flow.y if self.flow is not None else self._y

    @y.setter
    def y(self, value):
        if self.flow is not None:
            raise AttributeError("the kernel engine's state is advanced by its tangent flow")
        self._y = value

    @property
    def X(self):
        """The tangent vectors, shape (k, 2N) (none without the kernel engine)."""
        return self.flow.X if self.flow is not None else np.empty((0, self._y.size))

    @property
    def logsum(self):
        """Log-norm sums of eq (18) since the end of the transient, shape (k,)."""
        return self.flow.logsum if self.flow is not None else np.empty(0)

    # -- checkpoint ------------------------------------------------------------------------
    def to_arrays(self) -> dict:
        a = {"y": self.y,
             "scalars": np.array([self.rhs, self.rhs_frame, self.chunk_index,
                                  self.elapsed, float(self.done), self.steps, self.chart]),
             "lyap_ticks": np.array([m[0] for m in self.lyap_marks], dtype=np.int64),
             "lyap_logsums": np.array([m[1] for m in self.lyap_marks]).reshape(
                 len(self.lyap_marks), self.plan.tangent_vectors)}
        if self.flow is not None:
            a.update({"flow_" + k: v for k, v in self.flow.state().items()})
            a["shares_partial"] = np.array(self.shares_partial)
        for name, rows in self.rec.items():
            a["rec_" + name] = np.array(rows, dtype=float)
        for name, rows in self.rec_t.items():
            a["rect_" + name] = np.array(rows, dtype=float)
        return a

    def load_arrays(self, a):
        if self.flow is not None:
            # a checkpoint written before the energy shares were recorded has none: the
            # histogram then covers only what follows, and the result says so
            keys = self.flow.state()              # (the linkage's flow records none)
            old = "shares" in keys and "flow_shares" not in a
            self.shares_partial = old or bool(a.get("shares_partial", False))
            self.flow.load_state({k: a["flow_" + k] for k in keys if not (old and k == "shares")})
        else:
            self._y = a["y"].copy()
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
