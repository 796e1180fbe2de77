"""The rotors' pieces of a scene run (``[system] kind = "rotors"``, the default): its
`RotorSystem`, its tangent flow with the API's settings, its invariants, its curvature
samples, its angle pass and its reference exponents; the linkage's counterparts are in
``charts.runs.mechanism_run``, and ``charts.runs.scene_kind`` hands the runner, the recorders
and the result writers the ones of a scene's kind."""
from __future__ import annotations

import numpy as np

from ..geometry.projection import invariants as invariants_of
from ..geometry.system import RotorSystem
from .paper import PAPER_EXPONENTS
from .scene_schema import api_default

__all__ = ["rotor_system", "rotor_start", "lyapunov_settings_of", "tangent_flow",
           "rotor_invariants", "rotor_curvature", "angle_settings_of", "rotor_angles_pass",
           "rotor_paper_exponents"]


def rotor_system(scene):
    """The scene's `RotorSystem`."""
    s = scene.system
    return RotorSystem(s["n"], s["masses"], s.get("weights"), s.get("level", 0.0))


def rotor_start(scene, system, plan):
    """(positions per state nq = N, initial state y0 = (θ, u), its speed, the tangent flow of
    the kernel engine or None): the initial state given in the scene, or drawn from its
    seed."""
    if scene.initial["theta"] is not None:
        theta, u = np.array(scene.initial["theta"]), np.array(scene.initial["u"])
    else:
        theta, u = system.random_state(seed=scene.initial["seed"], speed=scene.system["speed"])
    flow = tangent_flow(scene, system, theta, u, plan.tangent_vectors) \
        if plan.engine == "kernel" else None
    return system.n, np.concatenate([theta, u]), float(system.speed(u)), flow


def lyapunov_settings_of(scene, system, k: int):
    """The settings of `charts.lyapunov_spectrum` that the scene's tangent flow mirrors
    (validated by the scene schema): a scene and that API call give identical numbers."""
    from ..analyses.lyapunov import lyapunov_settings

    integ, run, eff = scene.integrator, scene.run, scene.effects
    ly = eff.get("lyapunov", {})
    dt = integ["dt"]
    # without a Lyapunov effect the vectors (curvature frames) are re-orthonormalised every
    # step, as in charts.curvature_along_trajectory
    reorth = ly.get("reorth_every", dt)
    project = dt if integ["project"] else (integ["project_every"] or None)
    return lyapunov_settings(system, run["t_final"], dt=dt, n_exponents=max(k, 1),
                             inner=ly.get("inner_product", "theta"), space="restricted",
                             t_transient=run["t_transient"], n_batches=ly.get("n_batches", 2),
                             reorth_every=reorth, project_every=project, record_every=reorth,
                             seed=scene.initial["seed"] or 0)


def tangent_flow(scene, system, theta, u, k: int):
    """The tangent flow of the kernel engine: ``k`` vectors, settings as the API's."""
    from ..analyses.lyapunov import lyapunov_flow
    from ..solvers.tangent import TangentFlow

    cfg = lyapunov_settings_of(scene, system, k)
    if k:
        return lyapunov_flow(system, theta, u, cfg)
    return TangentFlow(system, theta, u, 0, dt=cfg.dt, reorth_every=cfg.reorth,
                       project_every=cfg.project)


def rotor_invariants(st) -> list:
    """[Σ a cos θ − c, Σ u a sin θ, E/E₀ − 1] of the run's current state
    (``geometry.projection``)."""
    n = st.system.n
    F, G, E = invariants_of(st.y[:n], st.y[n:], st.system.masses, st.system.weights,
                            st.system.level)
    return [float(F), float(G), float(E / (0.5 * st.speed ** 2) - 1.0)]


def rotor_curvature(st, kdir: int, routes: str):
    """(K(v̂, eᵢ) by the numerical route, by the exact route), i = 1…kdir, each None where
    ``routes`` leaves it out: the diagonals of the K matrices at the current point in the
    frame of the velocity and the θ-parts of the first ``kdir`` Lyapunov vectors
    (eqs 19–21)."""
    from ..analyses.curvature import curvature_frame, exact_curvature_matrix, numerical_curvature

    sys_, y = st.system, st.y
    n = sys_.n
    Xj = np.empty((kdir, 2 * n))
    P = np.empty((kdir + 1, n))
    uu = curvature_frame(y, np.ascontiguousarray(st.X[:kdir]), sys_.minv, sys_.weights,
                         sys_.masses, Xj, P)
    Kn = Ke = None
    if routes in ("numerical", "both"):
        K = np.empty((kdir, kdir))
        numerical_curvature(y, Xj, P, sys_.minv, sys_.weights, sys_.masses,
                            st.scene.integrator["dt"], uu, K)
        Kn = np.diagonal(K).copy()
        st.rhs_frame += 8
    if routes in ("exact", "both"):
        Ke = np.diagonal(exact_curvature_matrix(sys_, y[:n], P)).copy()
    return Kn, Ke


def angle_settings_of(st) -> dict:
    """The settings of `hyperbolicity_angles` that the scene's angle effect asks for (the
    API's own checkpoints; the projection of its tangent flow; the scene's seed)."""
    sc = st.scene
    a = sc.effects["angles"]
    dt = sc.integrator["dt"]
    return dict(dt=dt, n_unstable=a["n_vectors"], t_transient=a["t_transient"],
                sample_every=a["sample_every"],
                checkpoint_every=api_default("angles", "checkpoint_every"),
                project_every=st.flow.project_every * dt or None, seed=sc.initial["seed"] or 0)


def rotor_angles_pass(st) -> None:
    """The hyperbolicity test (section 4) from the initial state: forward tangent vectors,
    backward adjoint vectors along the re-integrated trajectory (`hyperbolicity_angles`),
    recorded as rows [t, φ full, φ restricted]; ``st.angles_result`` instead where it was
    computed already (a point's seeds together on a GPU, ``charts.runs.seed_lanes``)."""
    from ..analyses.hyperbolicity import hyperbolicity_angles

    res = st.angles_result
    if res is None:
        n = st.system.n
        res = hyperbolicity_angles(st.system, st.y0[:n], st.y0[n:], st.scene.run["t_final"],
                                   **angle_settings_of(st))
    st.rec["angles"] = [list(r) for r in np.column_stack([res.t, res.phi_full,
                                                          res.phi_restricted])]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.adjoint_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += 2 * st.plan.angles["steps"]


def rotor_paper_exponents(st, k: int):
    """(the paper's first ``k`` exponents scaled by the run's speed, where they come from),
    or None where the paper has none for this system (section 2: N = 3, 4, 5 at unit
    speed, equal masses, Σ cos θᵢ = 0)."""
    n = st.system.n
    if n not in PAPER_EXPONENTS or not np.allclose(st.system.masses, 1.0) \
            or not st.system.is_paper_family:
        return None
    paper = np.array(PAPER_EXPONENTS[n]) * st.speed
    return ([round(float(p), 12) for p in paper[:k]],
            "section 2, unit speed, equal masses; scaled by the speed")
