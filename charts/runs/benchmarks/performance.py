"""Every performance target of charts, measured in one run: the Lyapunov task side by side
with its peers, ensembles in vector lanes, every analysis against the Lyapunov kernel, cost
against N, the cold start and `charts reproduce`, then the table of targets met or not.

    charts bench performance            # t = 2000, reproduce --full: ~15 minutes on 2 cores
    charts bench performance --quick    # t = 500, reproduce --quick: ~6 minutes

Task: N = 5, equal masses, unit speed, leading 3 Lyapunov exponents from one fixed state
(``RotorSystem(5).random_state(seed=1)``), averaged over t after a transient of 50.
  * charts: ``lyapunov_spectrum`` (RK4 of eqs 8 + 17 in the tangent kernel, dt = 0.01, eq 18
    every 0.1 time units by default, and every step for comparison);
  * JiTCODE (if installed) and SciPy ``solve_ivp`` + NumPy QR: see
    ``charts.runs.benchmarks.peers`` (SciPy runs over a shorter time and is scaled: it is slow).
Reports warm medians, throughput, the accuracy of each route (trajectory
error at t = 20 against DOP853 at rtol 1e-13, and the exponents beside a long reference), the
speed-up of independent trajectories on all cores and the code-generation time.  Installs
nothing; peers that are missing are skipped.  The implementations take turns, every number
is a median of ``--repeat`` runs with its range, CPU times (``time.process_time``) beside wall
times, and the load average is printed with them: other jobs on the machine show as wall
time above CPU time.
"""
from __future__ import annotations

import argparse
import datetime
import os
import statistics
import sys
import time

import numpy as np

from ...analyses.lyapunov import lyapunov_spectrum
from ...analyses.worker_pool import worker_pool
from ...geometry.system import RotorSystem
from ..cli_parser import OneLineParser
from .environment import load, machine, spread
from .targets import (coldstart_section, ensemble_section, format_targets, pace_section,
                      reproduce_section, scaling_section, target_rows)
from .peers import (K, N, SEED, TRANSIENT, fixed_state, jitcode_run, jitcode_setup, scipy_run,
                    trajectory_errors)

__all__ = ["REFERENCE", "REFERENCE_SE", "ours", "ensemble_speedup", "codegen_time", "main"]

#: 8 independent trajectories × t = 2.5·10⁴ (``charts reproduce --full``, docs/reproduce.md),
#: the long reference the t = 2000 estimates are compared with.
REFERENCE = np.array([0.2977, 0.2255, 0.1227])
REFERENCE_SE = np.array([0.0007, 0.0006, 0.0007])
DT = 0.01
#: the sections after the Lyapunov task (``--skip`` leaves them out).
SECTIONS = ("ensemble", "pace", "scaling", "coldstart", "reproduce", "cores")


def ours(t_final, reorth_every=0.1):
    """The task with charts: (wall s, exponents, stderr, CPU s)."""
    S = RotorSystem(N)
    th, u = fixed_state()
    t0, c0 = time.perf_counter(), time.process_time()
    r = lyapunov_spectrum(S, th, u, t_final, dt=DT, n_exponents=K, t_transient=TRANSIENT,
                                 reorth_every=reorth_every)
    return (time.perf_counter() - t0, np.asarray(r.exponents), time.process_time() - c0,
            np.asarray(r.stderr))


# ----------------------------------------------------------------------------- both cores
def _member(job):
    """One trajectory of an ensemble in a worker: its CPU seconds."""
    seed, t_final, kwargs = job
    S = RotorSystem(N)
    th, u = S.random_state(seed=seed)
    c0 = time.process_time()
    lyapunov_spectrum(S, th, u, t_final, seed=seed, n_exponents=K, **kwargs)
    return time.process_time() - c0


def _warm(job):
    """Load the kernels in a worker and stay busy a moment, so that every worker gets one."""
    _member(job)
    time.sleep(1.0)


def ensemble_speedup(t_member, n_members):
    """{workers: (wall s, median CPU s per trajectory)} for ``n_members`` trajectories on warm
    pools of 1 and of all cores (workers started and their kernels loaded before timing)."""
    jobs = [(3 + i, t_member, {}) for i in range(n_members)]
    warm = [(0, 2.0, dict(n_batches=2, t_transient=0.0))]
    times = {}
    for workers in sorted({1, os.cpu_count() or 1}):
        with worker_pool(workers) as pool:
            list(pool.map(_warm, warm * workers))
            t0 = time.perf_counter()
            cpu = list(pool.map(_member, jobs))
            times[workers] = (time.perf_counter() - t0, statistics.median(cpu))
    return times


def codegen_time():
    """(seconds, N range) to derive and print every shipped generated module."""
    from ...codegen.emit import SHIPPED_N, module_source

    t0 = time.perf_counter()
    for n in SHIPPED_N:
        module_source(n)
    return time.perf_counter() - t0, f"N={min(SHIPPED_N)}..{max(SHIPPED_N)}"


# ----------------------------------------------------------------------------- main
def fmt_lam(lam):
    return " ".join(f"{x:.4f}" for x in lam)


def _fmt(values):
    med, lo, hi = spread(values)
    return f"{med:.3f} ({lo:.3f}–{hi:.3f})"


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench performance", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--t", type=float, default=None,
                    help="averaging time (default 2000; 500 with --quick)")
    ap.add_argument("--repeat", type=int, default=None,
                    help="repetitions for medians (default 5; 3 with --quick)")
    ap.add_argument("--scipy-t", type=float, default=None, help="averaging time of the (slow) "
                    "SciPy run, scaled to --t (default 150; 30 with --quick)")
    ap.add_argument("--quick", action="store_true", help="shorter runs, fewer repeats")
    ap.add_argument("--skip-codegen", action="store_true", help="do not time the code generator")
    ap.add_argument("--skip", nargs="+", default=[], choices=SECTIONS, metavar="SECTION",
                    help="sections to leave out: " + ", ".join(SECTIONS))
    args = ap.parse_args(argv)
    skip = set(args.skip)
    T = args.t or (500.0 if args.quick else 2000.0)
    rep = args.repeat or (3 if args.quick else 5)
    t_sp = args.scipy_t or (30.0 if args.quick else 150.0)
    print(f"date: {datetime.date.today().isoformat()}\nmachine: {machine()}")
    print("command: charts bench performance " + " ".join(sys.argv[1:] if argv is None else argv))
    print(f"task: N={N}, {K} exponents, unit speed, seed {SEED}, t={T:g} after a transient of "
          f"{TRANSIENT:g}; medians (min–max) of {rep}\n{load()}\n", flush=True)

    kernel_section(T, rep, t_sp)
    ens, pace, rep_time, preset, totals = target_sections(args, T, skip)
    print("\n## targets\n" + format_targets(target_rows(ens, pace, rep_time, preset, totals)))
    return 0


def kernel_section(T, rep, t_sp):
    """The Lyapunov kernel warm in this process against JiTCODE and SciPy, the
    implementations taking turns: the table of CPU times and exponents, trajectory errors."""
    total = T + TRANSIENT
    nsteps = total / DT
    # -- warm, this process; the implementations take turns
    jit = jitcode_setup()
    ode = None if jit is None else jit[1]
    if jit is None:
        print("JiTCODE not installed (pip install 'charts[bench]'): skipped")
    impls = {"default": lambda: ours(T), "every": lambda: ours(T, reorth_every=DT)}
    if ode is not None:
        impls["jitcode"] = lambda: jitcode_run(ode, T)
    ours(20.0)
    ours(20.0, reorth_every=DT)
    runs = {name: [] for name in impls}
    for _ in range(rep):
        for name, f in impls.items():
            runs[name].append(f())
    wall = {name: [r[0] for r in rr] for name, rr in runs.items()}
    cpu = {name: [r[2] for r in rr] for name, rr in runs.items()}
    c_ours = statistics.median(cpu["default"])
    lam_ours, err_ours = runs["default"][0][1], runs["default"][0][3]
    for name, what in (("default", "eq 18 every 0.1 (10 steps, the default)"),
                       ("every", "eq 18 every step")):
        c = statistics.median(cpu[name])
        print(f"charts warm, {what}: CPU {_fmt(cpu[name])} s, wall {_fmt(wall[name])} s -> "
              f"{total / c:,.0f} time units per CPU-second (1 core), {c / nsteps * 1e6:.3f} µs "
              f"per RK4 step", flush=True)
    rows = [("charts RK4 dt=0.01, eq 18 every 0.1 (default), warm", cpu["default"], lam_ours),
            ("charts RK4 dt=0.01, eq 18 every step, warm", cpu["every"], runs["every"][0][1]),
]
    if ode is not None:
        t_gen = jit[0]
        rows.append(("JiTCODE jitcode_lyap dopri5 1e-8/1e-10, warm", cpu["jitcode"],
                     runs["jitcode"][0][1]))
        rows.append(("JiTCODE code generation + compilation (wall)", [t_gen], None))
        print(f"JiTCODE: code generation + compilation {t_gen:.2f} s; warm CPU "
              f"{_fmt(cpu['jitcode'])} s, wall {_fmt(wall['jitcode'])} s", flush=True)
    try:
        sp_wall, lam_sp, sp_cpu = scipy_run(t_sp)
        scale = total / (t_sp + TRANSIENT)
        rows.append((f"SciPy solve_ivp DOP853 + numpy QR (t={t_sp:g}, scaled)", [sp_cpu * scale],
                     lam_sp))
    except ImportError:
        print("SciPy not installed: skipped")

    print("\n| implementation | CPU s: median (min–max) | ratio to charts warm | exponents |")
    print("|---|---:|---:|---|")
    for name, c, lam in rows:
        med_c, lo, hi = spread(c)
        rng = f" ({lo:.3f}–{hi:.3f})" if len(c) > 1 else ""
        print(f"| {name} | {med_c:.3f}{rng} | {med_c / c_ours:.2f} | "
              f"{fmt_lam(lam) if lam is not None else ''} |")
    jit_total = "-" if ode is None else f"{jit[0] + statistics.median(wall['jitcode']):.3f} s"
    print(f"\nJiTCODE generation + compilation + task: {jit_total}")
    print(f"charts batch-means standard errors at t={T:g}: {fmt_lam(err_ours)}; long reference "
          f"(8 × 2.5e4): {fmt_lam(REFERENCE)} ± {fmt_lam(REFERENCE_SE)}")
    for name, _, lam in rows:
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


def target_sections(args, T, skip):
    """The sections the targets are judged by (ensembles, analysis pace, scaling, cold start,
    reproduce, all cores, code generation): (ensemble rows, pace rows, reproduce time,
    preset, cold-start totals)."""
    rep = args.repeat or (3 if args.quick else 5)
    ens = pace = totals = rep_time = None
    preset = "quick" if args.quick else "full"
    if "ensemble" not in skip:
        print("\n## ensembles in vector lanes (lyapunov_ensemble, 1 core)")
        ens = ensemble_section(T / 4, rep)
    if "pace" not in skip:
        print("\n## every analysis against the Lyapunov kernel")
        pace = pace_section(T / 4, rep)
    if "scaling" not in skip:
        print("\n## cost per time unit against N")
        scaling_section((3, 5, 8, 16) if args.quick else (3, 5, 8, 16, 32, 64), 3)
    if "coldstart" not in skip:
        print("\n## cold start (new processes, import charts to the first exponents)")
        totals = coldstart_section(1 if args.quick else 2)
    if "reproduce" not in skip:
        print(f"\n## charts reproduce --{preset}")
        rep_time = reproduce_section(preset)
    if "cores" not in skip:
        print("\n## independent trajectories on all cores (process pool)")
        all_cores(T, rep)
    if not args.skip_codegen:
        secs, which = codegen_time()
        print(f"code generation {which} (charts.codegen.emit.module_source): {secs:.1f} s; "
              + load())
    return ens, pace, rep_time, preset, totals


def all_cores(T, rep):
    """Print the speed-up of independent trajectories in a warm process pool."""
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
    m, lo, hi = spread(sp)
    print(f"speed-up on all cores: median {m:.2f}x (range {lo:.2f}-{hi:.2f}); parallel "
          f"efficiency (CPU time of the trajectories / (workers x wall)): median "
          f"{statistics.median(eff):.2f}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
