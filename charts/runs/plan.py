"""What a scene's effects need: :func:`plan_scene` decides, from the requested effects alone,
what is integrated (no integration happens here).

* the state — 2N ambient variables (eq 8) or 2(N−1) chart variables (eq 14);
* tangent vectors (eq 17) — none unless ``lyapunov`` or ``curvature`` is requested, then
  max(n_exponents, n_directions) forward vectors, shared by both;
* the angles pass (``charts.analyses.hyperbolicity``) — only for ``angles``: m forward vectors, then
  the backward adjoint pass (m vectors) along the trajectory re-integrated from sparse
  checkpoints; it runs as one unit after the main pass (which is skipped when nothing
  else needs it);
* the CLV pass (``charts.analyses.covariant``) — only for ``clv``: D = 2N−2 (restricted)
  and/or 2N (full) forward vectors with their Q and R factors stored at every sample (in
  memory or streamed to disk), then the backward iteration; one unit after the angles pass;
* the parallel-transport frame (eq 19) — only for the numerical curvature route, N−1
  vectors moved one step back and forth at each curvature sample;
* stored samples — only the window of the requested waveforms, the one rotor of the
  spectrum, the drift records, the curvature samples; nothing for Lyapunov alone.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..geometry.checks import instance
from .scene import Scene

__all__ = ["Plan", "plan_scene", "ticks", "linkage_angles_plan",
           "angles_checkpoint_steps"]


def angles_checkpoint_steps(dt) -> int:
    """Steps between the stored trajectory checkpoints of the angles pass (its memory bound:
    one state per checkpoint; the backward pass re-integrates each segment from it): the
    default checkpoint_every of `hyperbolicity_angles`, which the scene does not set, on the
    grid of ``dt`` as the API places it (100 steps at dt = 0.01)."""
    from ..analyses.arguments import steps_of
    from .scene_schema import api_default

    return steps_of("checkpoint_every", api_default("angles", "checkpoint_every"), dt)


@dataclass
class Plan:
    """What a scene's effects require.  All counts are per run.

    engine : "kernel" (fused ambient RK4 of eqs 8 + 17, ``charts.analyses.lyapunov``) or
        "integrate" (``charts.integrate``: chart formulation or adaptive method).
    state_dim : int   number of integrated state variables.
    tangent_vectors : int   forward tangent vectors (eq 17), 0 if none needed.
    transport_vectors : int   frame vectors transported (eq 19) at curvature samples.
    adjoint_vectors : int   vectors of the backward adjoint pass (angles pass only).
    angles : dict   the angles pass (forward/adjoint vectors, steps, stored checkpoints and
        samples), empty when not requested.
    clv : dict   the CLV pass (vectors per variant, steps, stored samples and bytes), empty
        when not requested.
    main_pass : bool   whether the chunked main pass runs (False when only the angles and
        CLV passes are requested).
    stored : dict   name -> number of stored samples (rows).
    every : dict   name -> recording interval in integrator steps (kernel engine) or
        samples (integrate engine).
    """
    engine: str
    formulation: str
    method: str
    state_dim: int
    tangent_vectors: int = 0
    transport_vectors: int = 0
    adjoint_vectors: int = 0
    stored: dict = field(default_factory=dict)
    every: dict = field(default_factory=dict)
    needs_trajectory_store: bool = False
    angles: dict = field(default_factory=dict)
    clv: dict = field(default_factory=dict)
    main_pass: bool = True

    @property
    def passes(self) -> list[str]:
        """The separate passes after the main pass, in order."""
        return [p for p in ("angles", "clv") if getattr(self, p)]

    def pass_steps(self) -> int:
        """RK4 steps of the separate passes (their share of the progress bar)."""
        return sum(getattr(self, p)["steps"] for p in self.passes)

    def as_dict(self):
        return {"engine": self.engine, "formulation": self.formulation, "method": self.method,
                "state_dimension": self.state_dim, "tangent_vectors": self.tangent_vectors,
                "transport_vectors": self.transport_vectors,
                "adjoint_vectors": self.adjoint_vectors,
                "stored_samples": dict(self.stored),
                "stored_trajectory": self.needs_trajectory_store,
                "main_pass": self.main_pass, "angles_pass": dict(self.angles),
                "clv_pass": dict(self.clv)}


def ticks(t, unit):
    """The whole number of ``unit`` in time ``t`` (both in time units of the flow)."""
    return int(round(t / unit))


def linkage_angles_plan(scene) -> dict:
    """The angles pass of `linkage_angles` or a mechanism's `mechanism_angles`: forward
    t_transient + t_final + t_transient, backward t_final + t_transient, ``n_vectors`` vectors
    each (the linkage's 2)."""
    dt = scene.integrator["dt"]
    n_tr = ticks(scene.effects["angles"]["t_transient"], dt)
    total = ticks(scene.run["t_final"], dt)
    steps = (2 * n_tr + total) + (n_tr + total)
    m = scene.effects["angles"]["n_vectors"]
    return {"forward_vectors": m, "adjoint_vectors": m, "steps": steps,
            "rhs_evaluations": 4 * steps, "stored_trajectory_checkpoints": 0,
            "stored_samples": ticks(scene.run["t_final"],
                                    scene.effects["angles"]["sample_every"]) + 1}


def plan_scene(scene: Scene) -> Plan:
    """The smallest computation serving ``scene.effects`` (no integration happens here)."""
    instance("scene", scene, Scene, "charts.Scene (load_scene, parse_scene)")
    n = scene.system.get("n")          # (none for a mechanism: its coordinates)
    integ, run, eff = scene.integrator, scene.run, scene.effects
    ambient_rk4 = integ["formulation"] == "ambient" and integ["method"] == "rk4"
    engine = "kernel" if ambient_rk4 else "integrate"
    linkage = scene.system.get("kind") == "linkage"   # q = (θ₀…θ₃, x, y, α): 14 variables
    state_dim = (2 * len(scene.system["coordinates"]) if "coordinates" in scene.system
                 else 14 if linkage else 2 * n if integ["formulation"] == "ambient"
                 else 2 * (n - 1))
    plan = Plan(engine, integ["formulation"], integ["method"], state_dim)
    # the recording grid: integrator steps for the kernel engine, samples otherwise
    unit = integ["dt"] if engine == "kernel" else run["sample_dt"]
    sdt = ticks(run["sample_dt"], unit)
    n_samples = ticks(run["t_final"], run["sample_dt"])
    if "waveforms" in eff:
        w = eff["waveforms"]
        plan.every["waveforms"] = sdt
        plan.stored["waveforms"] = ticks(w["t_window"], run["sample_dt"])
    if "spectrum" in eff:
        plan.every["spectrum"] = sdt
        plan.stored["spectrum"] = n_samples
    if "drift" in eff:
        plan.every["drift"] = ticks(eff["drift"]["sample_every"], unit)
        plan.stored["drift"] = ticks(run["t_final"], eff["drift"]["sample_every"])
    k = 0
    if "lyapunov" in eff:
        k = max(k, eff["lyapunov"]["n_exponents"])
    if "curvature" in eff:
        c = eff["curvature"]
        k = max(k, c["n_directions"])
        plan.every["curvature"] = ticks(c["sample_every"], unit)
        plan.stored["curvature"] = ticks(run["t_final"], c["sample_every"])
        if c["route"] in ("numerical", "both"):   # (the linkage's route is "exact")
            plan.transport_vectors = c["n_directions"] + 1
    if "angles" in eff and (linkage or "coordinates" in scene.system):   # (a mechanism's)
        plan.adjoint_vectors = eff["angles"]["n_vectors"]
        plan.angles = linkage_angles_plan(scene)
    elif "angles" in eff:
        a = eff["angles"]
        dt = integ["dt"]
        m = a["n_vectors"]
        n_tr = ticks(a["t_transient"], dt)
        ce = angles_checkpoint_steps(dt)
        nseg = -(-(2 * n_tr + ticks(run["t_final"], dt)) // ce)
        plan.adjoint_vectors = m
        plan.needs_trajectory_store = True
        plan.angles = {"forward_vectors": m, "adjoint_vectors": m, "steps": nseg * ce,
                       "rhs_evaluations": 2 * 4 * nseg * ce,
                       "stored_trajectory_checkpoints": nseg + 1,
                       "stored_samples": ticks(run["t_final"], a["sample_every"])}
    if "clv" in eff:
        from ..analyses.covariant import clv_dimension, sample_bytes
        c = eff["clv"]
        dt = integ["dt"]
        variants = ["full", "restricted"] if c["variant"] == "both" else [c["variant"]]
        sample = ticks(c["sample_every"], dt)
        n_tr = ticks(c["t_transient"], dt)
        stored = ticks(run["t_final"], c["sample_every"]) + max(1, -(-n_tr // sample))
        plan.clv = {"variants": variants,
                    "vectors": {v: clv_dimension(n, v) for v in variants},
                    "steps": len(variants) * (n_tr + (stored - 1) * sample),
                    "rhs_evaluations": 4 * len(variants) * (n_tr + (stored - 1) * sample),
                    "stored_samples": ticks(run["t_final"], c["sample_every"]),
                    "stored_factor_bytes": {v: stored * sample_bytes(n, v) for v in variants}}
    plan.tangent_vectors = k
    plan.main_pass = any(e not in ("angles", "clv") for e in eff)
    return plan
