"""The sections of `charts bench performance` beyond the one-trajectory Lyapunov task, each
measured in the same run, and the table of targets they are judged by.

* ensembles in vector lanes (`charts.runs.benchmarks.ensemble`): 16 members of N = 5 with
  3 exponents in one lane kernel against the single-trajectory kernel and JiTCODE;
* every analysis against the Lyapunov kernel (`charts.runs.benchmarks.pace`);
* cost per time unit against N (`charts.runs.benchmarks.scaling`);
* the cold start of a new process (`charts.runs.benchmarks.coldstart`);
* `charts reproduce` end to end in a new process (wall and CPU time of all its processes).

Each ``*_section`` prints its rows and returns the numbers `target_rows` judges.
"""
from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time

from .coldstart import TARGET_SECONDS, coldstart_rows
from .environment import load
from .ensemble import ensemble_rows
from .pace import analysis_pace, format_rows
from .scaling import fit_slope, measure

__all__ = ["ensemble_section", "pace_section", "scaling_section", "coldstart_section",
           "reproduce_time", "reproduce_section", "target_rows", "format_targets",
           "ENSEMBLE_TARGET", "PACE_TARGET", "REPRODUCE_TARGET"]

#: ensemble of 16 N = 5 trajectories: aggregate time units per CPU second over the single kernel.
ENSEMBLE_TARGET = 3.0
#: analyses: CPU per time unit over the Lyapunov kernel's.
PACE_TARGET = 2.0
#: `charts reproduce --full` on two cores, wall seconds.
REPRODUCE_TARGET = 120.0
#: the analyses the pace target names (row names of `charts.runs.benchmarks.pace`).
PACE_JUDGED = ("hyperbolicity_angles (forward + backward)",
               "curvature_along_trajectory, both routes", "integrate, chart RK4")


def ensemble_section(t_final, repeat, cases=((5, 16),)):
    """Print the lane kernel's rows; return the N = 5, 16-member ratio (None if not run)."""
    rows = ensemble_rows(t_final, repeat, cases)
    print("| route | N | members | exponents | CPU s | time units per CPU s | ratio to single "
          "| members identical |\n|---|---:|---:|---:|---:|---:|---:|---|")
    for r in rows:
        same = "" if r["identical"] is None else ("yes" if r["identical"] else "NO")
        print(f"| {r['route']} | {r['n']} | {r['members']} | {r['k']} | {r['cpu']:.3f} | "
              f"{r['rate']:,.0f} | {r['ratio']:.2f} | {same} |")
    print(load(), flush=True)
    hit = [r for r in rows if r["route"] == "lanes" and r["n"] == 5 and r["members"] == 16]
    return hit[0]["ratio"] if hit else None


def pace_section(t_final, repeat, n=5):
    """Print every analysis's cost against the Lyapunov kernel; return {name: ratio}."""
    rows = analysis_pace(t_final, n=n, repeats=repeat)
    print(format_rows(rows, t_final, n))
    print(load(), flush=True)
    return {name: ratio for name, _, ratio in rows}


def scaling_section(ns, repeat, min_cpu=0.2):
    """Print CPU µs per time unit against N (k = N − 2, k = 3, chart RK4) and the slopes."""
    kinds = ("k=N-2", "k=3", "chart")
    costs = {k: [measure(n, k, min_cpu=min_cpu, repeat=repeat) for n in ns] for k in kinds}
    print("| N | " + " | ".join(f"{k} µs per time unit" for k in kinds) + " |")
    print("|---:|" + "---:|" * len(kinds))
    for i, n in enumerate(ns):
        cells = ["" if costs[k][i] is None else f"{costs[k][i] * 1e6:.1f}" for k in kinds]
        print(f"| {n} | " + " | ".join(cells) + " |")
    big = [n for n in ns if n >= 8]
    if len(big) >= 2:
        for k in kinds:
            slope, _ = fit_slope(ns, costs[k], big[0])
            print(f"slope of log(cost) against log(N), N >= {big[0]}, {k}: {slope:.2f}")
    print(load(), flush=True)


def coldstart_section(repeat):
    """Print the cold start's phases (new processes, empty and filled numba cache); return
    {case: CPU seconds from process start to the first exponents}."""
    rows = coldstart_rows(repeat)
    totals = {}
    for r in rows:
        if r["kind"] in ("phase", "total"):
            print(f"  {r['case']:<13} {r['name']:<50} CPU {r['cpu']:6.2f} s, wall "
                  f"{r['wall']:6.2f} s")
        if r["kind"] == "total":
            totals[r["case"]] = r["cpu"]
    print(load(), flush=True)
    return totals


_CLI = "import sys; from charts.cli import main; sys.exit(main())"


def reproduce_time(preset, workers):
    """(wall s, CPU s of all its processes) of ``charts reproduce --<preset>`` in a new process
    writing to a temporary folder."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory(prefix="charts-reproduce-") as out:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", _CLI, "reproduce", f"--{preset}", "-o", out,
                        "--quiet", "--workers", str(workers)], check=True,
                       stdout=subprocess.DEVNULL)
        wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def reproduce_section(preset, workers=None):
    """Print and return (wall s, CPU s) of `charts reproduce --<preset>`."""
    workers = workers or os.cpu_count() or 1
    wall, cpu = reproduce_time(preset, workers)
    print(f"charts reproduce --{preset} --workers {workers}: wall {wall:.1f} s, CPU of all its "
          f"processes {cpu:.1f} s; {load()}", flush=True)
    return wall, cpu


def target_rows(ensemble_ratio=None, pace=None, reproduce=None, reproduce_preset="full",
                coldstart=None):
    """(target, measured, met) rows for the numbers that were measured (None: not run)."""
    rows = []
    if ensemble_ratio is not None:
        rows.append((f"ensemble of 16 (N = 5, 3 exponents) >= {ENSEMBLE_TARGET:g}x the single "
                     "kernel per core", f"{ensemble_ratio:.2f}x", ensemble_ratio >= ENSEMBLE_TARGET))
    for name in PACE_JUDGED if pace else ():
        if name in pace:
            rows.append((f"{name} <= {PACE_TARGET:g}x the Lyapunov kernel", f"{pace[name]:.2f}x",
                         pace[name] <= PACE_TARGET))
    if reproduce is not None:
        wall, cpu = reproduce
        judged = reproduce_preset == "full"
        rows.append((f"charts reproduce --{reproduce_preset} <= {REPRODUCE_TARGET:g} s (wall)"
                     + ("" if judged else ", judged on --full only"),
                     f"{wall:.0f} s (CPU {cpu:.0f} s)", (wall <= REPRODUCE_TARGET) if judged
                     else None))
    for case, cpu in (coldstart or {}).items():
        rows.append((f"cold start, {case}: first exponents <= {TARGET_SECONDS:g} s of CPU",
                     f"{cpu:.2f} s", cpu <= TARGET_SECONDS))
    return rows


def format_targets(rows) -> str:
    """The targets as a Markdown table."""
    verdict = {True: "met", False: "**not met**", None: "not judged"}
    lines = ["| target | measured | verdict |", "|---|---:|---|"]
    lines += [f"| {t} | {m} | {verdict[ok]} |" for t, m, ok in rows]
    return "\n".join(lines)
