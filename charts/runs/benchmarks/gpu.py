"""Lyapunov ensembles on the GPU against the CPU lanes on every core, measured in one run;
then the angle test's and the covariant Lyapunov vectors' GPU routes.

    charts bench gpu                # the table of docs/gpu.md (about 4 minutes on an H100)
    charts bench gpu --quick        # fewer members and shorter runs
    charts bench gpu --flops        # then the FP64 operations per step, read by Nsight Compute

Task: members of N rotors (``RotorSystem(N).random_state(seed=i)``, unit speed), k
exponents, dt = 0.01, eq (18) every 0.1 with the projection onto T_r, the state projected
every 1.0: ``lyapunov_ensemble``'s defaults, the same settings on both devices.

  * Throughput: the GPU kernel (``charts.solvers.device``, one thread per member) advancing
    M members by T, timed after a launch that compiles it (the members' initial states and
    the compilation are reported apart); time units (summed over the members) per second.
  * CPU: ``lyapunov_ensemble(device="cpu", lanes=True)`` on every core (the lanes of
    ``charts.solvers.lanes``, one block per process), warm, wall time of the whole call.
  * Agreement: the members' exponents of both routes for the same seeds (relative
    differences, at several T: the GPU's fused multiply-adds and libm round differently and
    the chaos amplifies it), and the ensemble means at long T in units of their standard
    error.
  * Angle test and CLVs (``--only angles``, ``--only clv``): their GPU routes' rates, and
    their agreement with the CPU route for the same seeds.
  * FP64 share (``--flops``): double-precision adds, multiplies and fused multiply-adds per
    thread and step, counted by Nsight Compute (``ncu``) in a child process, against the
    chip's FP64 peak (multiprocessors × 64 FP64 units × 2 × clock, for compute capability
    8.0 and 9.x).
"""
from __future__ import annotations

import argparse
import datetime
import os
import shutil
import statistics
import subprocess
import sys
import time
import warnings

import numpy as np

from ...analyses.clv_ensemble import covariant_ensemble
from ...analyses.ensemble import member_states_of
from ...analyses.hyperbolicity import hyperbolicity_ensemble
from ...analyses.lyapunov import lyapunov_settings
from ...analyses.lyapunov_members import lyapunov_ensemble, member_states
from ...geometry.system import RotorSystem
from ...solvers.device import DeviceFlows, cuda_module
from ...solvers.tangent import inner_weights
from ..cli_parser import OneLineParser
from .environment import load, machine

__all__ = ["main", "ROWS", "device_flows", "kernel_rate"]

#: (N, k, members, T) of the throughput rows.
ROWS = ((3, 1, 65536, 200.0), (4, 2, 65536, 200.0), (5, 3, 65536, 200.0), (8, 6, 65536, 50.0),
        (16, 14, 32768, 20.0), (64, 8, 8192, 5.0))
QUICK_ROWS = ((5, 3, 16384, 50.0), (16, 14, 4096, 5.0))
#: FP64 units per multiprocessor by compute capability (major, minor).
FP64_UNITS = {(8, 0): 32, (9, 0): 64}


def device_flows(n, k, members, t_final, workers, backend="cuda"):
    """(DeviceFlows of ``members`` seeds for N = n, k exponents, settings, seconds building
    the initial states); ``backend="cpu"``: the kernel's logic on the CPU (tests)."""
    S = RotorSystem(n)
    cfg = lyapunov_settings(S, t_final, n_exponents=k, t_transient=0.0, n_batches=2)
    t0 = time.perf_counter()
    states = member_states_of(member_states, S, cfg, list(range(members)), 1.0, workers)
    flows = DeviceFlows(S, states, dt=cfg.dt, w=inner_weights(S, cfg.inner), restricted=True,
                        reorth_every=cfg.reorth, project_every=cfg.project, backend=backend)
    return flows, cfg, time.perf_counter() - t0


def kernel_rate(n, k, members, t_final, workers, repeat=3, backend="cuda"):
    """Row of the throughput table: (setup s, compile s, median run s, time units/s)."""
    flows, cfg, setup = device_flows(n, k, members, t_final, workers, backend)
    t0 = time.perf_counter()
    flows.advance(1)                              # compiles the kernel for (N, k)
    compile_s = time.perf_counter() - t0
    steps = cfg.total
    runs = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        flows.advance(steps)
        runs.append(time.perf_counter() - t0)
    if flows.stopped_lanes():
        raise RuntimeError(f"N = {n}: {len(flows.stopped_lanes())} members stopped")
    run = statistics.median(runs)
    return setup, compile_s, run, members * steps * cfg.dt / run


def cpu_rate(n, k, members, t_final, workers):
    """(wall s, time units/s) of ``lyapunov_ensemble(device="cpu", lanes=True)`` on
    ``workers`` cores, warm (a first call compiles)."""
    S = RotorSystem(n)
    kw = dict(n_exponents=k, t_transient=0.0, n_batches=2, lanes=True)
    lyapunov_ensemble(S, members, 1.0, workers=workers, **kw)   # compiles the lanes
    t0 = time.perf_counter()
    lyapunov_ensemble(S, members, t_final, workers=workers, **kw)
    wall = time.perf_counter() - t0
    return wall, members * t_final / wall


def agreement(n, k, members, times, workers):
    """Rows (T, largest relative difference of a member's exponents GPU vs CPU, mean GPU,
    mean CPU, |difference| / combined standard error)."""
    S = RotorSystem(n)
    out = []
    for T in times:
        kw = dict(n_exponents=k, n_batches=2)
        gpu = lyapunov_ensemble(S, members, T, device="cuda", workers=workers, **kw)
        cpu = lyapunov_ensemble(S, members, T, workers=workers, **kw)
        out.append((T, *compare_ensembles(gpu, cpu)))
    return out


def compare_ensembles(gpu, cpu):
    """(largest relative difference of a member's exponents GPU vs CPU, mean GPU, mean CPU,
    largest |difference of the means| / their combined standard error) of two
    `EnsembleResult` s of the same seeds."""
    G = np.array([m.exponents for m in gpu.members])
    C = np.array([m.exponents for m in cpu.members])
    rel = float(np.max(np.abs(G - C) / np.maximum(np.abs(C), 1e-300)))
    z = np.abs(gpu.exponents - cpu.exponents) / np.hypot(gpu.stderr, cpu.stderr)
    return rel, gpu.exponents, cpu.exponents, float(z.max())


def fp64_peak(cuda):
    """(name, FP64 peak flop/s or None) of the current GPU."""
    dev = cuda.get_current_device()
    cc = tuple(dev.compute_capability)
    units = FP64_UNITS.get(cc)
    name = dev.name.decode() if isinstance(dev.name, bytes) else str(dev.name)
    try:
        sms, khz = dev.MULTIPROCESSOR_COUNT, dev.CLOCK_RATE
    except Exception:                             # attribute names vary between versions
        return name, None
    name = f"{name} (compute capability {cc[0]}.{cc[1]}, {sms} multiprocessors, {khz / 1e6:.2f} GHz)"
    return name, (sms * units * 2 * khz * 1e3 if units else None)


def flops_per_step(rows):
    """{(N, k): FP64 operations per thread and step} read by ``ncu`` from a child process
    that launches each row's kernel once for 10 steps; {} without ncu."""
    ncu = shutil.which("ncu")
    if ncu is None:
        return {}
    metrics = ",".join(f"smsp__sass_thread_inst_executed_op_d{op}_pred_on.sum"
                       for op in ("add", "mul", "fma"))
    spec = ";".join(f"{n},{k}" for n, k, *_ in rows)
    cmd = [ncu, "--metrics", metrics, "--csv", "--kernel-name", "regex:kernel",
           sys.executable, "-m", "charts.runs.benchmarks.gpu", "--probe", spec]
    res = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
    counts = []
    for line in res.stdout.splitlines():
        cells = [c.strip('"') for c in line.split('","')]
        if len(cells) > 3 and cells[-3].startswith("smsp__sass_thread_inst_executed_op_d"):
            counts.append((cells[-3], float(cells[-1].replace(",", ""))))
    out = {}
    per = 3
    for i, (n, k, *_) in enumerate(rows):
        got = dict(counts[per * i: per * (i + 1)])
        if len(got) == per:
            total = sum(v * (2 if "dfma" in m else 1) for m, v in got.items())
            out[(n, k)] = total / (PROBE_THREADS * PROBE_STEPS)
    if not out:
        print(res.stdout[-2000:], res.stderr[-2000:], file=sys.stderr)
    return out


PROBE_THREADS = 1024
PROBE_STEPS = 10


def _probe(spec):
    """One launch of PROBE_STEPS steps per (N, k) of ``spec`` (under ncu)."""
    for part in spec.split(";"):
        n, k = (int(x) for x in part.split(","))
        flows, _, _ = device_flows(n, k, PROBE_THREADS, 1.0, 1)
        flows.advance(PROBE_STEPS)


def main(argv=None) -> int:
    p = OneLineParser(prog="charts bench gpu", description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="fewer members, shorter runs")
    p.add_argument("--flops", action="store_true",
                   help="count the FP64 operations per step with Nsight Compute (ncu)")
    p.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                   help="CPU processes (default: all cores)")
    p.add_argument("--only", choices=("lyapunov", "angles", "clv"),
                   help="one part of the table (default: both)")
    p.add_argument("--probe", help=argparse.SUPPRESS)
    a = p.parse_args(argv)
    warnings.simplefilter("ignore")               # occupancy notes of numba-cuda
    if a.probe:
        _probe(a.probe)
        return 0
    cuda = cuda_module()
    name, peak = fp64_peak(cuda)
    rows = QUICK_ROWS if a.quick else ROWS
    w = a.workers
    print(f"# charts bench gpu{' --quick' if a.quick else ''}  ({datetime.date.today()})")
    print(f"GPU: {name}, FP64 peak {peak / 1e12:.1f} TFLOP/s" if peak else f"GPU: {name}")
    print(f"CPU: {machine()}; {load()}; {w} workers", flush=True)

    if a.only != "angles":
        _lyapunov_part(a, rows, w, peak)
    if a.only in (None, "angles"):
        _angle_part(a, w)
    if a.only in (None, "clv"):
        _clv_part(a, w)
    return 0


def clv_rate(n, members, t_final, t_transient, workers, backend="cuda"):
    """(wall s of `covariant_ensemble`, window time units per second), its first call
    compiled before; restricted CLVs."""
    from ...analyses.clv_ensemble import clv_ensemble_settings, clvs_on_device
    S = RotorSystem(n)
    kw = dict(t_transient=t_transient)
    if backend == "cuda":
        covariant_ensemble(S, 2, 1.0, device="cuda", workers=workers, **kw)    # compiles
    t0 = time.perf_counter()
    if backend == "cuda":
        covariant_ensemble(S, members, t_final, device="cuda", workers=workers, **kw)
    else:                                         # the twin: the same driver on the CPU
        cfg = clv_ensemble_settings(S, t_final, "restricted", 0, kw)
        clvs_on_device(S, cfg, "restricted", list(range(members)), 1.0, backend="cpu",
                       workers=workers)
    wall = time.perf_counter() - t0
    return wall, members * t_final / wall


def clv_agreement(n, members, t_final, t_transient, workers):
    """(max relative difference of a member's CLV exponents, GPU mean, CPU mean, max
    |Δ mean| / s.e.) for the same seeds on both devices, restricted CLVs."""
    S = RotorSystem(n)
    kw = dict(t_transient=t_transient, workers=workers)
    return compare_ensembles(covariant_ensemble(S, members, t_final, device="cuda", **kw),
                             covariant_ensemble(S, members, t_final, **kw))


def _clv_part(a, w):
    print("\n## Covariant Lyapunov vectors (restricted; forward on the GPU, Ginelli's backward "
          "iteration on the host), t_transient = 20")
    print("| N | D | members | T | wall s | window tu/s |")
    print("|---|---|---|---|---|---|")
    rows = ((4, 1024, 50.0),) if a.quick else ((4, 4096, 200.0), (5, 4096, 200.0))
    for n, members, T in rows:
        try:
            wall, win = clv_rate(n, members, T, 20.0, w)
            print(f"| {n} | {2 * n - 2} | {members} | {T:g} | {wall:.2f} | {win:.3g} |",
                  flush=True)
        except Exception as e:
            print(f"| {n} | {2 * n - 2} | {members} | {T:g} | failed: {type(e).__name__}: {e} ||",
                  flush=True)
    print("\n## CLV agreement, N = 4, 64 members (exponents along the CLVs, same seeds)")
    print("| T | max relative difference of a member | GPU mean | CPU mean | max |Δ mean| / s.e. |")
    print("|---|---|---|---|---|")
    for T in (1.0, 100.0):
        try:
            rel, g, c, z = clv_agreement(4, 64, T, 20.0, w)
            print(f"| {T:g} | {rel:.2e} | {np.round(g, 4).tolist()} | {np.round(c, 4).tolist()} "
                  f"| {z:.2f} |", flush=True)
        except Exception as e:
            print(f"| {T:g} | failed: {type(e).__name__}: {e} ||||", flush=True)


def angle_rate(n, members, t_final, t_transient, workers, backend="cuda"):
    """(wall s of `hyperbolicity_ensemble`, window time units per second, integrated time
    units per second: both passes with their transients), its first call compiled before."""
    S = RotorSystem(n)
    kw = dict(t_transient=t_transient, device=backend, workers=workers)
    hyperbolicity_ensemble(S, 2, 1.0, **kw)                     # compiles
    t0 = time.perf_counter()
    hyperbolicity_ensemble(S, members, t_final, **kw)
    wall = time.perf_counter() - t0
    integrated = members * (3 * t_transient + 2 * t_final)
    return wall, members * t_final / wall, integrated / wall


def angle_agreement(n, members, t_final, t_transient, workers):
    """Per quantile q of φ (restricted): (q, GPU mean of the members' quantiles, CPU mean,
    |difference| / combined standard error) for the same seeds on both devices."""
    S = RotorSystem(n)
    kw = dict(t_transient=t_transient, workers=workers)
    gpu = hyperbolicity_ensemble(S, members, t_final, device="cuda", **kw)
    cpu = hyperbolicity_ensemble(S, members, t_final, **kw)
    out = []
    for q in (0.01, 0.1, 0.5, 0.9):
        G = np.array([np.quantile(m.phi_restricted, q) for m in gpu.members])
        C = np.array([np.quantile(m.phi_restricted, q) for m in cpu.members])
        se = np.hypot(G.std(ddof=1), C.std(ddof=1)) / np.sqrt(members)
        out.append((q, G.mean(), C.mean(), abs(G.mean() - C.mean()) / se))
    return out


def _angle_part(a, w):
    print("\n## Angle test (forward + backward + both angles), t_transient = 20")
    print("| N | m | members | T | wall s | window tu/s | integrated tu/s |")
    print("|---|---|---|---|---|---|---|")
    rows = ((5, 4096, 100.0),) if a.quick else ((4, 16384, 200.0), (5, 16384, 200.0))
    for n, members, T in rows:
        try:
            wall, win, integ = angle_rate(n, members, T, 20.0, w)
            print(f"| {n} | {n - 2} | {members} | {T:g} | {wall:.2f} | {win:.3g} | {integ:.3g} |",
                  flush=True)
        except Exception as e:
            print(f"| {n} | {n - 2} | {members} | {T:g} | failed: {type(e).__name__}: {e} |||",
                  flush=True)
    print("\n## Angle agreement, N = 5, 64 members, T = 200 (quantiles of φ restricted, "
          "mean over the members)")
    print("| quantile | GPU | CPU | |Δ| / s.e. |")
    print("|---|---|---|---|")
    try:
        for q, g, c, z in angle_agreement(5, 64, 200.0, 20.0, w):
            print(f"| {q:g} | {g:.5f} | {c:.5f} | {z:.2f} |", flush=True)
    except Exception as e:
        print(f"| failed: {type(e).__name__}: {e} ||||", flush=True)


def _lyapunov_part(a, rows, w, peak):
    print("\n## Throughput (time units per second, all members together)")
    print("| N | k | members | T | states s | compile s | run s | GPU tu/s |")
    print("|---|---|---|---|---|---|---|---|")
    rates = {}
    for n, k, m, T in rows:
        try:
            setup, comp, run, rate = kernel_rate(n, k, m, T, w)
        except Exception as e:                   # one row failing leaves the others
            print(f"| {n} | {k} | {m} | {T:g} | failed: {type(e).__name__}: {e} |||||", flush=True)
            continue
        rates[(n, k)] = rate
        print(f"| {n} | {k} | {m} | {T:g} | {setup:.1f} | {comp:.1f} | {run:.3f} | {rate:.3g} |",
              flush=True)

    n, k = 5, 3
    cm, cT = (w * 64, 200.0) if a.quick else (w * 64, 2000.0)
    try:
        wall, crate = cpu_rate(n, k, cm, cT, w)
        print(f"\nCPU lanes, N = {n}, k = {k}: {cm} members × T = {cT:g} on {w} cores in "
              f"{wall:.1f} s: {crate:.3g} tu/s ({crate / w:.3g} per core)")
        if (n, k) in rates:
            print(f"GPU / all {w} cores: {rates[(n, k)] / crate:.0f}×; GPU / one core: "
                  f"{rates[(n, k)] / (crate / w):.0f}×", flush=True)
    except Exception as e:
        print(f"\nCPU lanes failed: {type(e).__name__}: {e}", flush=True)

    print("\n## Agreement, N = 5, k = 3 (same seeds on both devices)")
    print("| T | members | max relative difference of a member | GPU mean | CPU mean | "
          "max |Δ mean| / s.e. |")
    print("|---|---|---|---|---|---|")
    for members, times in ((64, (1.0, 10.0, 100.0)), (512, (2000.0,) if a.quick else (10000.0,))):
        try:
            for T, rel, g, c, z in agreement(n, k, members, times, w):
                print(f"| {T:g} | {members} | {rel:.2e} | {np.round(g, 5).tolist()} | "
                      f"{np.round(c, 5).tolist()} | {z:.2f} |", flush=True)
        except Exception as e:
            print(f"| {times} | {members} | failed: {type(e).__name__}: {e} ||||", flush=True)

    if a.flops:
        print("\n## FP64 work (Nsight Compute, one launch of 10 steps)")
        fl = flops_per_step(rows)
        print("| N | k | FP64 flop per thread·step | GFLOP/s | share of FP64 peak |")
        print("|---|---|---|---|---|")
        for n, k, *_ in rows:
            if (n, k) in fl and (n, k) in rates:
                gf = fl[(n, k)] * rates[(n, k)] / 0.01
                share = f"{gf / peak:.1%}" if peak else "n/a"
                print(f"| {n} | {k} | {fl[(n, k)]:.0f} | {gf / 1e9:.0f} | {share} |", flush=True)
            else:
                print(f"| {n} | {k} | n/a | n/a | n/a |")


if __name__ == "__main__":
    sys.exit(main())
