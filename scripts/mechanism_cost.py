#!/usr/bin/env python
"""What a mechanism costs to build and to run (docs/mechanisms.md, "Code generation and cost").

    python scripts/mechanism_cost.py                 # both parts
    python scripts/mechanism_cost.py --part build    # (a) only
    python scripts/mechanism_cost.py --part speed --repeat 7 --steps 100000   # (b) only

(a) A user's new three-rotor mechanism (φ1..φ3, Σ cos φᵢ = 0, unit masses: the rotors' model
    under other names, so its key is new and nothing shipped serves it), from nothing, in a
    fresh process with an empty generated-code cache (``CHARTS_CACHE_DIR`` a new temporary
    folder): imports, SymPy derivation (``derive``: derivatives and lambdification), the jets
    module's source (``charts.codegen.mechanism.jets_module``: written into the cache), numba's
    compilation of the jets, a random state, and a first Lyapunov run (t = 100, dt = 0.01); then
    the same in a second process on the now warm cache.  With ``--cold-numba`` numba's own
    cache is a new folder too (``NUMBA_CACHE_DIR``): the library's compiled drivers are then
    compiled as well, as on a machine that never ran charts.  CPU seconds of the process
    (``time.process_time``) and wall seconds, per stage.
(b) The generic generated route on the rotor instance against the rotors' hand-written
    kernels, one process, interleaved repetitions: steps per CPU second of
    ``MechanismTangentFlow(rotors(3), k=2, dt=0.01, reorth=10, project=100)`` against
    ``charts.lyapunov_spectrum(RotorSystem(3), n_exponents=2, t_transient=0)`` with its
    defaults (RK4, dt = 0.01, eq (18) every 10 steps, projection every 100: the task of
    ``charts bench compare``, timed as it times it); the ratio of the medians and the range of
    the paired ratios.  Where the generic route's time goes: its compiled steps without the
    projection (``project=0``), NumPy's ``project_now`` (the fallback), and each piece of one
    RK4 stage timed alone in a compiled loop (the jets, the KKT matrix and its LU, the
    motion's right-hand side and solve, the linearisation's matrix, and per tangent vector
    its right-hand side and solve); and µs per step on the triple linkage and with all 2d
    vectors.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: The child of part (a): prints one JSON line {stage: [cpu s, wall s]}.
BUILD = r"""
import time
c0, w0 = time.process_time(), time.perf_counter()
out = {}
def mark(stage):
    global c0, w0
    c, w = time.process_time(), time.perf_counter()
    out[stage] = [c - c0, w - w0]
    c0, w0 = c, w
import json
import numpy as np
import sympy as sp
from charts.mechanism import Mechanism
from charts.analyses.mechanism_lyapunov import lyapunov_spectrum
from charts.codegen.mechanism import JET_ORDER, jets_module
mark("import")
phi = sp.symbols("phi1:4")
mech = Mechanism(phi, [sum(sp.cos(p) for p in phi)], masses=[1, 1, 1], periodic=phi,
                 name="three rotors of my own")
mech.derive()
mark("derive (SymPy)")
jets_module(mech.q, mech.params, mech.F, mech.M, say=mech.name,
            arrays=lambda: [mech._jet_array(k) for k in JET_ORDER])
mark("jets source (write or read)")
q0, v0 = mech.random_state(seed=1)
mark("random state")
jets = mech.compiled_jets()
jets(q0, mech.param_values, *[np.zeros(mech._eval(k, q0).shape) for k in JET_ORDER])
mark("numba jets (compile or load)")
res = lyapunov_spectrum(mech, q0, v0, 100.0, t_transient=0.0)
mark("first Lyapunov run (t = 100)")
out["lambda1"] = float(res.exponents[0])
out["module"] = jets.py_func.__module__
print(json.dumps(out))
"""


def build(cold_numba: bool) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, CHARTS_CACHE_DIR=str(Path(tmp) / "charts"))
        if cold_numba:
            env["NUMBA_CACHE_DIR"] = str(Path(tmp) / "numba")
        runs = []
        for label in ("empty cache", "warm cache (second process)"):
            done = subprocess.run([sys.executable, "-c", BUILD], env=env, capture_output=True,
                                  text=True, cwd=ROOT)
            if done.returncode:
                sys.exit(done.stderr)
            runs.append((label, json.loads(done.stdout.strip().splitlines()[-1])))
    stages = [k for k in runs[0][1] if isinstance(runs[0][1][k], list)]
    print(f"(a) a user's three-rotor mechanism, numba cache {'empty' if cold_numba else 'as installed'}"
          "; CPU s / wall s")
    print(f"  {'stage':32s}" + "".join(f"{label:>30s}" for label, _ in runs))
    for stage in stages + ["total"]:
        cells = []
        for _, r in runs:
            c, w = ((sum(r[s][0] for s in stages), sum(r[s][1] for s in stages))
                    if stage == "total" else r[stage])
            cells.append(f"{c:8.2f} / {w:6.2f}")
        print(f"  {stage:32s}" + "".join(f"{x:>30s}" for x in cells))
    for label, r in runs:
        print(f"  {label}: jets from {r['module']}, lambda1 = {r['lambda1']:.3f} (t = 100)")


def speed(steps: int, repeat: int) -> None:
    import time

    import charts
    from charts.mechanism import rotors
    from charts.mechanism.tangent_flow import MechanismTangentFlow

    S = charts.RotorSystem(3)
    th, u = S.random_state(seed=1)
    mech = rotors(3)
    q0, v0 = mech.random_state(seed=1)
    t_final = steps * 0.01

    def rotor_run():
        c = time.process_time()
        charts.lyapunov_spectrum(S, th, u, t_final, n_exponents=2, t_transient=0)
        return steps / (time.process_time() - c)

    def generic_run(project=100):
        flow = MechanismTangentFlow(mech, q0, v0, 2, dt=0.01, reorth=10, project=project)
        c = time.process_time()
        flow.advance(steps)
        return steps / (time.process_time() - c)

    rotor_run(), generic_run(), generic_run(0)                  # warm-up: compile or load
    rows = {"rotors": [], "generic": [], "generic, no projection": []}
    for _ in range(repeat):
        rows["rotors"].append(rotor_run())
        rows["generic"].append(generic_run())
        rows["generic, no projection"].append(generic_run(0))
    flow = MechanismTangentFlow(mech, q0, v0, 2, dt=0.01, reorth=10, project=100)
    flow.advance(100)
    c = time.process_time()
    for _ in range(200):
        flow.project_now()
    projection = (time.process_time() - c) / 200
    med = {k: statistics.median(v) for k, v in rows.items()}
    print(f"(b) rotors(3), 2 tangent vectors, RK4 dt = 0.01, eq (18) every 10 steps, projection "
          f"every 100; {steps} steps x {repeat} repetitions, steps per CPU second")
    for k, v in rows.items():
        print(f"  {k:24s} median {med[k]:12.0f}   range {min(v):.0f}-{max(v):.0f}"
              f"   ({1e6 / med[k]:.3f} us/step)")
    paired = [r / g for r, g in zip(rows["rotors"], rows["generic"])]
    print(f"  rotors / generic: {med['rotors'] / med['generic']:.1f} x (ratio of medians; paired "
          f"{min(paired):.1f}-{max(paired):.1f})")
    compiled = 1e6 / med["generic, no projection"]
    per_step = 1e6 / med["generic"]
    print(f"  generic, per step: {per_step:.2f} us, of which the compiled projection every 100 "
          f"steps {per_step - compiled:+.2f} us (NumPy's project_now, the fallback: "
          f"{projection * 1e3:.3f} ms a call, {projection * 1e6 / 100:.2f} us a step)")
    parts(mech, q0, v0)
    others(steps // 5)


def others(steps: int) -> None:
    """µs per step of the generic route on the triple linkage (r = 0.1: n = 5, k = 3) and on
    rotors(3): the state alone, one vector and all 2d, as docs/mechanisms.md's table (median
    of 3)."""
    import time

    from charts.mechanism import rotors, triple_linkage
    from charts.mechanism.tangent_flow import MechanismTangentFlow

    print(f"  other settings (eq (18) every 10 steps, projection every 100; {steps} steps, median of 3):")
    for label, mech in (("rotors(3)", rotors(3)), ("triple_linkage(0.1)", triple_linkage(0.1))):
        q0, v0 = mech.random_state(seed=1)
        row = []
        for k, inner in ((0, "theta"), (1, "theta"), (2 * mech.dim, "full")):
            times = []
            for _ in range(4):
                flow = MechanismTangentFlow(mech, q0, v0, k, dt=0.01, reorth=10, project=100,
                                            inner=inner)
                c = time.process_time()
                flow.advance(steps)
                times.append((time.process_time() - c) / steps * 1e6)
            row.append(f"k = {k} ({inner}): {statistics.median(times[1:]):.2f} us/step")
        print(f"    {label:22s}" + ";  ".join(row))


#: The pieces of one stage of the generic route, each timed alone in a compiled loop.
PARTS = r"""
from numba import njit
from charts.mechanism.kernels import (apply_tangent_matrix, kkt_matrix, lu_in_place,
                                      lu_solve_columns, motion_rhs, schur_factor,
                                      schur_solve_columns, tangent_motion_matrix)
from charts.solvers.rk import NO_REFCOUNT

fast = dict(error_model="numpy", **NO_REFCOUNT)          # as the flow's driver

@njit(**fast)
def solve(sc, B, first, last):
    K, piv, Minv, J, W, S, spiv, u, schur = sc
    if schur:
        schur_solve_columns(Minv, J, W, S, spiv, B, first, last, u)
    else:
        lu_solve_columns(K, piv, B, first, last)

@njit(**fast)
def jets_part(jets, q, p, jt, N):
    F, J, F2, F3, M, dM, d2M = jt
    for i in range(N):
        q[0] += 1e-15
        jets(q, p, F, J, F2, F3, M, dM, d2M)

@njit(**fast)
def kkt_part(jt, sc, B, T, v, N):
    F, J, F2, F3, M, dM, d2M = jt
    K, piv, Minv, J, W, S, spiv, u, schur = sc
    for i in range(N):
        if schur:
            schur_factor(Minv, J, W, S, spiv)
        else:
            kkt_matrix(M, J, -1.0, K)
            lu_in_place(K, piv)

@njit(**fast)
def motion_part(jt, sc, B, T, v, N):
    F, J, F2, F3, M, dM, d2M = jt
    for i in range(N):
        motion_rhs(dM, F2, v, B[:, 0], True)
        solve(sc, B, 0, 1)

@njit(**fast)
def matrix_part(jt, sc, B, T, v, N):
    F, J, F2, F3, M, dM, d2M = jt
    for i in range(N):
        tangent_motion_matrix(dM, d2M, F2, F3, v, B[:, 0], T, True)

@njit(**fast)
def vector_part(jt, sc, B, T, v, N):
    for i in range(N):
        apply_tangent_matrix(T, v, v, B[:, 1])
        solve(sc, B, 1, 2)
"""


def parts(mech, q0, v0, count=1_000_000) -> None:
    """ns per call of each piece of a stage (``PARTS``), on rotors(3) at its random state, by
    the route the flow takes (its constant definite M: the Schur complement; the linearisation
    at the state's solution, its structural zeros as in the flow; compiled as the flow's
    driver, without reference counting)."""
    import time

    import numpy as np

    ns = {"np": np}
    exec(PARTS, ns)
    from charts.mechanism.tangent_flow import MechanismTangentFlow

    flow = MechanismTangentFlow(mech, q0, v0, 2, dt=0.01, reorth=10, project=100)
    K, piv, B, T, flat, schur, Minv, W, S, spiv, u = flow._work[:11]
    jets = mech.compiled_jets()
    jt = flow._jt
    jets(q0.copy(), mech.param_values, *jt)
    sc = (K, piv, Minv, jt[1], W, S, spiv, u, schur)
    calls = {"the jets (generated)": ("jets_part", (jets, q0.copy(), mech.param_values, jt)),
             ("Schur complement + LU" if schur else "KKT matrix + LU"):
                 ("kkt_part", (jt, sc, B, T, v0)),
             "motion rhs + solve": ("motion_part", (jt, sc, B, T, v0)),
             "linearisation matrix": ("matrix_part", (jt, sc, B, T, v0)),
             "per vector: apply + solve": ("vector_part", (jt, sc, B, T, v0))}
    print("  one RK4 stage of the generic route, by piece (4 stages a step; ns per call, CPU):")
    for label, (name, args) in calls.items():
        fn = ns[name]
        fn(*args, 10)                                   # compile
        c = time.process_time()
        fn(*args, count)
        print(f"    {label:28s} {(time.process_time() - c) / count * 1e9:7.0f}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--part", choices=("build", "speed", "both"), default="both")
    ap.add_argument("--cold-numba", action="store_true",
                    help="(a) with numba's cache in a new folder too (the drivers compiled)")
    ap.add_argument("--steps", type=int, default=100_000, help="(b) steps per timed run")
    ap.add_argument("--repeat", type=int, default=5, help="(b) interleaved repetitions")
    args = ap.parse_args(argv)
    if args.part in ("build", "both"):
        build(args.cold_numba)
    if args.part in ("speed", "both"):
        speed(args.steps, args.repeat)
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    sys.exit(main())
