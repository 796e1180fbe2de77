"""What a scene run records along the way: the recorders called by the engines at every
recording position (waveforms, spectrum rotor, invariant drift, curvature samples), the
invariants of the run and the curvature matrices at one point."""
from __future__ import annotations

import numpy as np

from ..geometry.projection import invariants as invariants_of

from .run_state import RunState
from .linkage_run import linkage_curvature, linkage_invariants
from .scene_linkage import is_linkage

__all__ = ["make_recorders", "invariants", "curvature_sample"]


def make_recorders(st: RunState, transient_units: int):
    """Functions called with the absolute unit position after each advance."""
    sc, plan = st.scene, st.plan
    n = st.nq                          # the velocities of y = (positions, velocities) start here
    eff = sc.effects
    unit = sc.integrator["dt"] if plan.engine == "kernel" else sc.run["sample_dt"]
    recs = []

    def rel(pos):
        return pos - transient_units

    if "waveforms" in eff:
        rotors = np.array(eff["waveforms"]["rotors"])
        every, limit = plan.every["waveforms"], plan.stored["waveforms"]

        def rec_wave(pos, every=every, limit=limit, rotors=rotors):
            r = rel(pos)
            if r > 0 and r % every == 0 and r // every <= limit:
                st.rec_t["waveforms"].append(r * unit)
                st.rec["waveforms"].append(st.y[n + rotors])
        recs.append(rec_wave)
    if "spectrum" in eff:
        rot, every = eff["spectrum"]["rotor"], plan.every["spectrum"]

        def rec_spec(pos, every=every, rot=rot):
            r = rel(pos)
            if r > 0 and r % every == 0:
                st.rec["spectrum"].append(st.y[n + rot])
        recs.append(rec_spec)
    if "drift" in eff:
        every = plan.every["drift"]

        def rec_drift(pos, every=every):
            r = rel(pos)
            if r > 0 and r % every == 0:
                st.rec_t["drift"].append(r * unit)
                st.rec["drift"].append(invariants(st))
        recs.append(rec_drift)
    if "curvature" in eff:
        c = eff["curvature"]
        every, kdir = plan.every["curvature"], c["n_directions"]
        routes = c["route"]

        def rec_curv(pos, every=every, kdir=kdir, routes=routes):
            r = rel(pos)
            if r > 0 and r % every == 0 and is_linkage(sc):   # the Gauss equation
                st.rec_t["curvature"].append(r * unit)
                st.rec["curvature_y"].append(st.y.copy())
                st.rec["curvature_exact"].append(linkage_curvature(st, kdir))
            elif r > 0 and r % every == 0:
                Kn, Ke = curvature_sample(st, kdir, routes)
                st.rec_t["curvature"].append(r * unit)
                st.rec["curvature_y"].append(st.y.copy())
                if Kn is not None:
                    st.rec["curvature_num"].append(np.diagonal(Kn).copy())
                if Ke is not None:
                    st.rec["curvature_exact"].append(np.diagonal(Ke).copy())
        recs.append(rec_curv)
    return recs


def invariants(st: RunState):
    """[Σ a cos θ − c, Σ u a sin θ, E/E₀ − 1] of the current state (``geometry.projection``);
    for the linkage its constraint, tangency and energy (``scene_linkage.linkage_invariants``)."""
    if is_linkage(st.scene):
        return linkage_invariants(st.system, st.y, st.speed)
    n = st.system.n
    F, G, E = invariants_of(st.y[:n], st.y[n:], st.system.masses, st.system.weights,
                            st.system.level)
    return [float(F), float(G), float(E / (0.5 * st.speed ** 2) - 1.0)]


def curvature_sample(st: RunState, kdir: int, routes: str):
    """K matrices (route a numerical, route b exact) at the current point, in the frame of
    the velocity and the θ-parts of the first ``kdir`` Lyapunov vectors (eqs 19–21)."""
    from ..analyses.curvature import curvature_frame, exact_curvature_matrix, numerical_curvature

    sys_, y = st.system, st.y
    n = sys_.n
    Xj = np.empty((kdir, 2 * n))
    P = np.empty((kdir + 1, n))
    uu = curvature_frame(y, np.ascontiguousarray(st.X[:kdir]), sys_.minv, sys_.weights,
                         sys_.masses, Xj, P)
    Kn = Ke = None
    if routes in ("numerical", "both"):
        Kn = np.empty((kdir, kdir))
        numerical_curvature(y, Xj, P, sys_.minv, sys_.weights, sys_.masses, st.scene.integrator["dt"], uu, Kn)
        st.rhs_frame += 8
    if routes in ("exact", "both"):
        Ke = exact_curvature_matrix(sys_, y[:n], P)
    return Kn, Ke
