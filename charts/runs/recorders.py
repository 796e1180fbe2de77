"""What a scene run records along the way: the recorders called by the engines at every
recording position (waveforms, spectrum rotor, invariant drift, curvature samples); the
invariants and curvatures themselves are the scene kind's (``charts.runs.scene_kind``)."""
from __future__ import annotations

import numpy as np

from .run_state import RunState
from .scene_kind import scene_kind

__all__ = ["make_recorders"]


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
        invariants = scene_kind(sc).invariants

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
        curvature = scene_kind(sc).curvature

        def rec_curv(pos, every=every, kdir=kdir, routes=routes):
            r = rel(pos)
            if r > 0 and r % every == 0:
                Kn, Ke = curvature(st, kdir, routes)
                st.rec_t["curvature"].append(r * unit)
                st.rec["curvature_y"].append(st.y.copy())
                if Kn is not None:
                    st.rec["curvature_num"].append(Kn)
                if Ke is not None:
                    st.rec["curvature_exact"].append(Ke)
        recs.append(rec_curv)
    return recs
