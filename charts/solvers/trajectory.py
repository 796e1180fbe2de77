"""``IntegrationResult``: the samples of a geodesic that ``integrate`` returns, in ambient
coordinates for both formulations; saved and loaded as NetCDF (``charts.io.archive``), plotted
by ``charts.plotting``."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..io.archive import Archivable, attributes, dataset
from ..io.result_words import ANGULAR_VELOCITY, counted
from .dense import DenseSolution

__all__ = ["IntegrationResult"]


@dataclass(eq=False, repr=False)
class IntegrationResult(Archivable):
    """Samples of a geodesic, in ambient coordinates for both formulations.

    Attributes
    ----------
    t : ndarray, shape (m,)
    theta, u : ndarray, shape (m, n)
        Ambient angles (continuous, not wrapped) and velocities dθ/dt.
    transported : ndarray, shape (m, k, n), or None
        The transported vectors (eq 16 / eq 19), ambient components.
    switches : list of (t, from_chart, to_chart)
        Chart switches, in order (chart formulation; empty for the ambient one).
    drift : dict
        Max over every accepted step and every sample of ``constraint`` = |Σ cos θ|,
        ``tangency`` = |Σ uᵢ sin θᵢ|, ``energy`` = |E − E₀|/E₀; with ``transport``, also
        ``transport`` = max change of the Gram matrix of (u, p¹…pᵏ) relative to |u|·|p|.
    n_steps, n_rejected, n_rhs : int
        Accepted steps, rejected DOP853 attempts, right-hand-side evaluations (work done: after
        a terminal event, steps of the last chunk beyond it count too).
    status : str
        ``"finished"``, ``"stopped"`` (by ``progress``) or ``"event"`` (a terminal event), or
        the error status on ``IntegrationError.result``.
    sol : DenseSolution or None
        With ``dense_output=True``: ``sol(t)`` → ``[θ, u, p…]`` anywhere in ``t_span``.
    t_events, y_events : list of ndarray, or None
        With ``events``: per event, the times (m,) and ambient states (m, (2 + k)·n) of its
        zeros, as in SciPy.
    options, params : dict
        The call's settings (step, tolerances, projection, span) and its system and initial
        state (n, masses, weights, level, speed, theta0, u0): saved with the result, so a
        file says what produced it.
    """

    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    transported: np.ndarray | None
    switches: list
    drift: dict
    n_steps: int
    n_rejected: int
    n_rhs: int
    status: str
    formulation: str
    method: str
    options: dict = field(default_factory=dict)
    params: dict = field(default_factory=dict)
    sol: DenseSolution | None = None
    t_events: list | None = None
    y_events: list | None = None

    KIND = "trajectory"

    def to_xarray(self):
        """Dataset with dims (t, rotor[, vector]; switch; event): theta, u[, transported],
        the chart switches, the events; settings, drift and counters as attributes (the dense
        output ``sol`` is not saved)."""
        n = self.theta.shape[1]
        sw = np.array(self.switches, dtype=float).reshape(-1, 3)
        data = {"theta": (("t", "rotor"), self.theta, "rad", "ambient angles θᵢ (not wrapped)"),
                "u": (("t", "rotor"), self.u, ANGULAR_VELOCITY, "angular velocities dθᵢ/dt"),
                "switch_t": (("switch",), sw[:, 0], "time", "time of the chart switch"),
                "switch_from": (("switch",), sw[:, 1].astype(np.int64), "1", "chart left"),
                "switch_to": (("switch",), sw[:, 2].astype(np.int64), "1", "chart entered")}
        if self.transported is not None:
            data["transported"] = (("t", "vector", "rotor"), self.transported, "rad",
                                   "parallel-transported vectors, ambient components")
        attrs = dict(drift=self.drift, n_steps=self.n_steps, n_rejected=self.n_rejected,
                     n_rhs=self.n_rhs, status=self.status, formulation=self.formulation,
                     method=self.method, options=self.options, params=self.params)
        if self.t_events is not None:
            ids = np.concatenate([np.full(len(te), i) for i, te in enumerate(self.t_events)])
            data["event_t"] = (("event",), np.concatenate(self.t_events), "time", "event time")
            data["event_index"] = (("event",), ids.astype(np.int64), "1", "index in events")
            Y = np.concatenate(self.y_events)
            data["event_y"] = (("event", "state"), Y, "1",
                               "ambient state [θ, u, p…] at the event: the units of each "
                               "component are in state_units")
            attrs["n_events"] = len(self.t_events)
        coords = {"t": (("t",), self.t, "time"),
                  "rotor": (("rotor",), np.arange(n), "1", "rotor index, from 0 as in scenes")}
        if self.t_events is not None:
            k = Y.shape[1] // n - 2
            coords["state"] = (("state",), [f"theta_{i}" for i in range(n)]
                               + [f"u_{i}" for i in range(n)]
                               + [f"p{r}_{i}" for r in range(k) for i in range(n)], "1",
                               "component of the ambient state")
            coords["state_units"] = (("state",), ["rad"] * n + [ANGULAR_VELOCITY] * n
                                     + ["rad"] * (k * n), "1", "units of each component")
        return dataset(self.KIND, data, coords=coords, attrs=attrs)

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        sw = [(float(t), int(i), int(j)) for t, i, j in
              zip(ds["switch_t"].values, ds["switch_from"].values, ds["switch_to"].values)]
        res = cls(t=ds["t"].values, theta=ds["theta"].values, u=ds["u"].values,
                  transported=ds["transported"].values if "transported" in ds else None,
                  switches=sw, drift=a["drift"], n_steps=a["n_steps"], n_rejected=a["n_rejected"],
                  n_rhs=a["n_rhs"], status=a["status"], formulation=a["formulation"],
                  method=a["method"], options=a["options"], params=a.get("params", {}))
        if "n_events" in a:
            ids = ds["event_index"].values
            res.t_events = [ds["event_t"].values[ids == i] for i in range(a["n_events"])]
            res.y_events = [ds["event_y"].values[ids == i] for i in range(a["n_events"])]
        return res

    def plot(self, kind="angles", **kw):
        """Figure of the trajectory: ``"angles"`` (θᵢ(t) wrapped to (−π, π] with the chart
        switches marked; ``window=(t0, t1)`` for a span of a long run, ``max_points`` per
        line), ``"surface"`` (N = 3: the path on Σ cos θ = 0 in 3D),
        ``"poincare"`` (the states at an event of ``events=``, in the plane of two state
        components: ``coords=``, ``event=``, ``select=`` one sheet), or ``"animation"`` (the
        rotors; a ``matplotlib.animation.FuncAnimation``).  Returns ``(fig, ax)`` (the
        animation for ``"animation"``); see ``charts.plotting``."""
        from .. import plotting
        return plotting.plot_trajectory(self, kind, **kw)

    def summary_parts(self):
        """Formulation and method, steps, chart switches, events, energy drift, status."""
        events = sum(len(te) for te in self.t_events) if self.t_events is not None else None
        energy = self.drift.get("energy")
        return [f"{self.formulation}/{self.method}", counted(self.n_steps, "step"),
                counted(len(self.switches), "chart switch", "chart switches")
                if self.formulation == "chart" else "",
                counted(events, "event") if events is not None else "",
                f"energy drift {energy:.1e}" if energy is not None else "",
                f"status={self.status!r}"]
