#!/usr/bin/env python
"""Issue 6: our Lyapunov kernel side by side with the peers, measured in one run.

    python scripts/bench_performance.py            # t = 2000 (the issue's task), ~5 minutes
    python scripts/bench_performance.py --quick    # t = 500, fewer repeats, ~2 minutes
    charts bench performance [--quick]             # the same

Task: N = 5, equal masses, unit speed, leading 3 Lyapunov exponents from one fixed state,
averaged over t after a transient of 50.
  * charts: `lyapunov_spectrum` (fused RK4 of eq 8 + eq 17, dt = 0.01, eq 18 every 10 steps
    by default, and every step for comparison);
  * JiTCODE (if installed): `jitcode_lyap` of eq (8) in SymEngine, simplify=False, dopri5,
    rtol 1e-8, atol 1e-10, re-orthonormalised every time unit (its own QR);
  * SciPy: `solve_ivp` DOP853 (same tolerances) of eq (8) + eq (17) in NumPy, QR every time
    unit; run over a shorter time and scaled (it is slow).
Reports cold start (a new process with an empty numba cache, i.e. the first-ever compile,
and with the cache filled), warm medians, throughput, the accuracy of each route (trajectory
error at t = 20 against DOP853 at rtol 1e-13, and the exponents beside a long reference), the
speed-up of independent trajectories on all cores and the code-generation time.  Installs
nothing; peers that are missing are skipped.  Wall times on a shared machine are noisy: every
number is a median of ``--repeat`` runs, and the load average is printed with them.
"""
from __future__ import annotations

import argparse
import datetime
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
N = 5
K = 3
SEED = 1
TRANSIENT = 50.0
#: `charts reproduce --full`: 8 independent trajectories × t = 2.5·10⁴ (docs/reproduce.md),
#: the long reference the t = 2000 estimates are compared with.
REFERENCE = np.array([0.2981, 0.2257, 0.1237])
REFERENCE_SE = np.array([0.0006, 0.0009, 0.0009])


def fixed_state():
    import charts

    return charts.RotorSystem(N).random_state(seed=SEED)


def load():
    return "load average {:.1f} {:.1f} {:.1f}".format(*os.getloadavg())


def machine():
    cpu = "?"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import numba

    vers = [f"python {platform.python_version()}", f"numpy {np.__version__}",
            f"numba {numba.__version__}"]
    for mod in ("scipy", "jitcode", "symengine"):
        try:
            vers.append(f"{mod} {__import__(mod).__version__}")
        except ImportError:
            pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; " + ", ".join(vers)


# ----------------------------------------------------------------------------- charts
def ours(t_final, dt=0.01, reorth_every=10):
    import charts

    S = charts.RotorSystem(N)
    th, u = fixed_state()
    t0, c0 = time.perf_counter(), time.process_time()
    r = charts.lyapunov_spectrum(S, th, u, t_final, dt=dt, n_exponents=K, t_transient=TRANSIENT,
                                 reorth_every=reorth_every)
    return (time.perf_counter() - t0, np.asarray(r.exponents), np.asarray(r.stderr),
            time.process_time() - c0)


_COLD = """
import sys, time; t0 = time.perf_counter()
import charts
S = charts.RotorSystem(5); th, u = S.random_state(seed=1)
t1 = time.perf_counter()
charts.lyapunov_spectrum(S, th, u, 2.0, dt=0.01, n_exponents=3, t_transient=0.0, n_batches=2)
t2 = time.perf_counter()
charts.lyapunov_spectrum(S, th, u, float(sys.argv[1]), dt=0.01, n_exponents=3, t_transient=50.0)
t3 = time.perf_counter()
print(t1 - t0, t2 - t1, t3 - t2)
"""


def cold_start(cache_dir, t_final):
    """New process: (import, first tiny integration = load or compile, then the task)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache_dir))
    out = subprocess.run([sys.executable, "-c", _COLD, str(t_final)], env=env, capture_output=True,
                         text=True, check=True)
    return tuple(map(float, out.stdout.split()))


# ----------------------------------------------------------------------------- JiTCODE
def jitcode_setup():
    """(code generation + compilation time, ode) or None if JiTCODE is missing."""
    try:
        import symengine
        from jitcode import jitcode_lyap, y
    except ImportError:
        return None
    t0 = time.perf_counter()
    theta = [y(i) for i in range(N)]
    vel = [y(N + i) for i in range(N)]
    A = sum(vel[j] ** 2 * symengine.cos(theta[j]) for j in range(N))
    B = sum(symengine.sin(theta[j]) ** 2 for j in range(N))
    f = vel + [-A / B * symengine.sin(theta[i]) for i in range(N)]
    ode = jitcode_lyap(f, n_lyap=K, simplify=False, verbose=False)
    ode.compile_C(verbose=False)
    t_gen = time.perf_counter() - t0
    ode.set_integrator("dopri5", rtol=1e-8, atol=1e-10)
    return t_gen, ode


def jitcode_run(ode, t_final):
    th, u = fixed_state()
    ode.set_initial_value(np.concatenate([th, u]), 0.0)
    t1, c1 = time.perf_counter(), time.process_time()
    sums = np.zeros(K)
    for t in np.arange(1.0, TRANSIENT + t_final + 0.5):
        _, lyaps, _ = ode.integrate(t)
        if t > TRANSIENT:
            sums += lyaps
    return time.perf_counter() - t1, sums / t_final, None, time.process_time() - c1


def jitcode_state(ode, t):
    th, u = fixed_state()
    ode.set_initial_value(np.concatenate([th, u]), 0.0)
    for s in np.arange(1.0, t + 0.5):
        state, _, _ = ode.integrate(s)
    return np.asarray(state)[: 2 * N]


# ----------------------------------------------------------------------------- SciPy
def _rhs8(t, y):
    s, c, v = np.sin(y[:N]), np.cos(y[:N]), y[N:]
    return np.concatenate([v, -np.sum(v * v * c) / np.sum(s * s) * s])


def scipy_run(t_final):
    from scipy.integrate import solve_ivp

    th, u = fixed_state()
    rng = np.random.default_rng(0)

    def rhs(t, z):
        y, X = z[:2 * N], z[2 * N:].reshape(K, 2 * N)
        s, c = np.sin(y[:N]), np.cos(y[:N])
        v = y[N:]
        A, B = np.sum(v * v * c), np.sum(s * s)
        lam = A / B
        dA = 2 * (X[:, N:] * v * c).sum(1) - (X[:, :N] * v * v * s).sum(1)
        dB = 2 * (X[:, :N] * s * c).sum(1)
        dlam = (dA - lam * dB) / B
        dX = np.concatenate([X[:, N:], -(dlam[:, None] * s + lam * c * X[:, :N])], axis=1)
        return np.concatenate([v, -lam * s, dX.ravel()])

    X, _ = np.linalg.qr(rng.normal(size=(2 * N, K)))
    z = np.concatenate([th, u, X.T.ravel()])
    sums = np.zeros(K)
    t0 = time.perf_counter()
    for t in np.arange(0.0, TRANSIENT + t_final - 0.5):
        z = solve_ivp(rhs, (t, t + 1.0), z, method="DOP853", rtol=1e-8, atol=1e-10).y[:, -1]
        Q, R = np.linalg.qr(z[2 * N:].reshape(K, 2 * N).T)
        if t + 1.0 > TRANSIENT:
            sums += np.log(np.abs(np.diag(R)))
        z[2 * N:] = Q.T.ravel()
    return time.perf_counter() - t0, sums / t_final


# ----------------------------------------------------------------------------- accuracy
def trajectory_errors(ode, t=20.0):
    """Largest error of (θ, u) at time t from the fixed state: our RK4 dt = 0.01 (as in the
    Lyapunov run, projection every 100 steps) and JiTCODE's dopri5, against SciPy DOP853 at
    rtol = atol = 1e-13."""
    from scipy.integrate import solve_ivp

    import charts
    from charts.analyses.lyapunov import advance_tangent

    th, u = fixed_state()
    y0 = np.concatenate([th, u])
    ref = solve_ivp(_rhs8, (0.0, t), y0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
    y = y0.copy()
    advance_tangent(charts.RotorSystem(N), y, np.empty((0, 2 * N)), t, dt=0.01)
    errs = {"charts RK4 dt=0.01": np.abs(y - ref).max()}
    if ode is not None:
        errs["JiTCODE dopri5 1e-8/1e-10"] = np.abs(jitcode_state(ode, t) - ref).max()
    return errs


# ----------------------------------------------------------------------------- ensemble
def _warm(job):
    """Load the kernels in a worker and stay busy a moment, so every worker gets one."""
    _member(job)
    time.sleep(1.0)


def _member(job):
    from charts.analyses.lyapunov import _ensemble_member

    t0 = time.process_time()
    _ensemble_member(job)
    return time.process_time() - t0


def ensemble_speedup(t_member, n_members):
    """Warm pools (workers started and their kernels loaded before timing), so the factor
    is that of the integrations; returns {workers: (wall seconds, median CPU seconds per
    trajectory)}.  The CPU time per trajectory is blind to time-slicing with other jobs and
    shows how much the cores slow each other down."""
    jobs = [(N, np.ones(N), 3 + i, 1.0, t_member, dict(n_exponents=K)) for i in range(n_members)]
    warm = [(N, np.ones(N), 0, 1.0, 2.0, dict(n_exponents=K, n_batches=2, t_transient=0.0))]
    times = {}
    for workers in sorted({1, os.cpu_count() or 1}):
        with ProcessPoolExecutor(max_workers=workers) as pool:
            list(pool.map(_warm, warm * workers))
            t0 = time.perf_counter()
            cpu = list(pool.map(_member, jobs))
            times[workers] = (time.perf_counter() - t0, statistics.median(cpu))
    return times


# ----------------------------------------------------------------------------- main
def fmt_lam(lam):
    return " ".join(f"{x:.4f}" for x in lam)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--t", type=float, default=None, help="averaging time (default 2000; 500 with --quick)")
    ap.add_argument("--repeat", type=int, default=None, help="repetitions for medians (default 5; 3 with --quick)")
    ap.add_argument("--scipy-t", type=float, default=None,
                    help="averaging time of the (slow) SciPy run, scaled to --t (default 150; 30 with --quick)")
    ap.add_argument("--quick", action="store_true", help="shorter runs, fewer repeats")
    ap.add_argument("--skip-codegen", action="store_true", help="do not time scripts/generate.py")
    args = ap.parse_args(argv)
    T = args.t or (500.0 if args.quick else 2000.0)
    rep = args.repeat or (3 if args.quick else 5)
    t_sp = args.scipy_t or (30.0 if args.quick else 150.0)
    total = T + TRANSIENT
    nsteps = total / 0.01
    print(f"date: {datetime.date.today().isoformat()}")
    print(f"machine: {machine()}")
    cmd = (["charts bench performance"] + list(argv) if argv is not None
           else ["python scripts/bench_performance.py"] + sys.argv[1:])
    print(f"command: {' '.join(cmd)}")
    print(f"task: N={N}, {K} exponents, unit speed, t={T:g} after a transient of {TRANSIENT:g}; "
          f"medians of {rep}\n{load()}\n", flush=True)

    # -- cold start: new processes, empty then filled numba cache
    with tempfile.TemporaryDirectory() as cache:
        first = cold_start(cache, T)
        filled = [cold_start(cache, T) for _ in range(rep)]
    med = [statistics.median(f[i] for f in filled) for i in range(3)]
    print(f"cold start, empty numba cache (first-ever compile): import {first[0]:.2f} s, "
          f"first integration (compile) {first[1]:.2f} s, then the task {first[2]:.2f} s")
    print(f"cold start, cache filled (median of {rep}): import {med[0]:.2f} s, first integration "
          f"(load) {med[1]:.2f} s -> integrating after {med[0] + med[1]:.2f} s; the task {med[2]:.2f} s")
    cold_empty = first[1] + first[2]
    cold_filled = med[1] + med[2]
    print(load(), flush=True)

    # -- warm, this process; the implementations take turns, so that the load of other jobs
    #    falls on all of them alike
    jit = jitcode_setup()
    ode = None if jit is None else jit[1]
    if jit is None:
        print("JiTCODE not installed (pip install -e '.[bench]'): skipped")
    impls = {"default": lambda: ours(T), "every": lambda: ours(T, reorth_every=1)}
    if ode is not None:
        impls["jitcode"] = lambda: jitcode_run(ode, T)
    ours(20.0)
    ours(20.0, reorth_every=1)
    runs = {name: [] for name in impls}
    for _ in range(rep):
        for name, f in impls.items():
            runs[name].append(f())
    wall = {name: statistics.median(r[0] for r in rr) for name, rr in runs.items()}
    cpu = {name: statistics.median(r[3] for r in rr) for name, rr in runs.items()}
    t_ours, t_ours1 = wall["default"], wall["every"]
    lam_ours, err_ours = runs["default"][0][1], runs["default"][0][2]
    print(f"charts warm: {t_ours:.3f} s -> {total / t_ours:,.0f} time units per wall-second (1 core), "
          f"{t_ours / nsteps * 1e6:.3f} µs per RK4 step (eq 18 every 10 steps; CPU time "
          f"{cpu['default'] / nsteps * 1e6:.3f} µs); every step: {t_ours1:.3f} s, "
          f"{t_ours1 / nsteps * 1e6:.3f} µs per step (CPU {cpu['every'] / nsteps * 1e6:.3f} µs)",
          flush=True)
    rows = [("charts RK4 dt=0.01, eq 18 every 10 steps (default), warm", t_ours, lam_ours),
            ("charts RK4 dt=0.01, eq 18 every step, warm", t_ours1, runs["every"][0][1]),
            ("charts, new process, cache filled (load + task)", cold_filled, None),
            ("charts, new process, empty cache (compile + task)", cold_empty, None)]
    if ode is not None:
        t_gen, t_jit = jit[0], wall["jitcode"]
        rows.append(("JiTCODE jitcode_lyap dopri5 1e-8/1e-10, warm", t_jit, runs["jitcode"][0][1]))
        rows.append(("JiTCODE code generation + compilation", t_gen, None))
        rows.append(("JiTCODE code generation + compilation + task", t_gen + t_jit, None))
        print(f"JiTCODE: code generation + compilation {t_gen:.2f} s; warm {t_jit:.3f} s (CPU "
              f"{cpu['jitcode']:.3f} s; CPU-time ratio to charts {cpu['jitcode'] / cpu['default']:.2f})",
              flush=True)

    try:
        sp_time, lam_sp = scipy_run(t_sp)
        rows.append((f"SciPy solve_ivp DOP853 + numpy QR (t={t_sp:g}, scaled)",
                     sp_time * total / (t_sp + TRANSIENT), lam_sp))
    except ImportError:
        print("SciPy not installed: skipped")

    print(f"\n| implementation | median s | ratio to charts warm | exponents |")
    print("|---|---:|---:|---|")
    for name, t, lam in rows:
        print(f"| {name} | {t:.3f} | {t / t_ours:.2f} | {fmt_lam(lam) if lam is not None else ''} |")
    print(f"\ncharts batch-means standard errors at t={T:g}: {fmt_lam(err_ours)}; long reference "
          f"(8 × 2.5e4): {fmt_lam(REFERENCE)} ± {fmt_lam(REFERENCE_SE)}")
    for name, t, lam in rows:
        if lam is not None:
            z = (lam - REFERENCE) / np.hypot(err_ours, REFERENCE_SE)
            print(f"  {name[:40]:40s} deviation from reference in charts s.e.: "
                  + " ".join(f"{x:+.1f}" for x in z))
    try:
        errs = trajectory_errors(ode)
        print("trajectory error at t=20 against DOP853 rtol 1e-13: "
              + ", ".join(f"{k} {v:.1e}" for k, v in errs.items()))
    except ImportError:
        print("SciPy not installed: no trajectory errors")
    print(load(), flush=True)

    # -- both cores
    n_members = 4 * (os.cpu_count() or 1)
    sp, eff = [], []
    for _ in range(rep):
        times = ensemble_speedup(T / 2, n_members)
        w = max(times)
        sp.append(times[1][0] / times[w][0])
        eff.append(n_members * times[w][1] / (w * times[w][0]))
        print(f"{n_members} independent trajectories of t={T / 2:g} (warm worker pools): 1 worker "
              f"{times[1][0]:.2f} s, {w} workers {times[w][0]:.2f} s -> speed-up {sp[-1]:.2f}x; "
              f"CPU time per trajectory {times[1][1]:.3f} s alone, {times[w][1]:.3f} s with {w} "
              f"workers; parallel efficiency {eff[-1]:.2f}; " + load(), flush=True)
    print(f"two-core speed-up: median {statistics.median(sp):.2f}x (range {min(sp):.2f}-{max(sp):.2f}); "
          f"parallel efficiency (CPU time of the trajectories / (workers x wall)): median "
          f"{statistics.median(eff):.2f}\n", flush=True)

    if not args.skip_codegen:
        sys.path.insert(0, str(ROOT / "scripts"))
        import generate

        from charts.codegen.emit import SHIPPED_N

        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            generate.write_all(Path(tmp), SHIPPED_N, verbose=False)
            print(f"code generation N={min(SHIPPED_N)}..{max(SHIPPED_N)} (scripts/generate.py): "
                  f"{time.perf_counter() - t0:.1f} s; " + load())


if __name__ == "__main__":
    main()
