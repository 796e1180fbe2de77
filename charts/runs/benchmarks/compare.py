"""Lyapunov throughput of several installations of charts, interleaved in one run.

Each engine is a Python interpreter (optionally with a source folder put first on its
``PYTHONPATH``) in which ``import charts`` finds the installation to measure, e.g. the
virtual environments of two checkouts.  One worker process per engine stays alive for the
whole run; after a warm-up call per N (compilation or loading of the cached kernels) the
engines take turns on the same task, repetition after repetition, so that load from other
jobs falls on all of them alike.  Task, per N: unit masses, ``random_state(seed)``,

    lyapunov_spectrum(system, theta, u, T, n_exponents=N - 2, t_transient=0)

with every other argument at its default (RK4, dt = 0.01; both before and after the
one-engine rewrite eq (18) every 10 steps and the projection every 100 steps).  Measured:
time units per second of CPU time of the worker (``time.process_time``, blind to
time-slicing with other processes), median and range over the repetitions; the ratio of
each engine to the first one is the ratio of the medians, and the median and range of the
ratios within a repetition (adjacent runs, so the paired ratio sees the same machine state).

    charts bench compare --engine old=/path/to/venv-old/bin/python \\
                         --engine new=/path/to/venv-new/bin/python [--t 3000] [--repeat 7]
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from .environment import load, machine, spread
from ..cli_parser import OneLineParser

__all__ = ["Engine", "parse_engine", "main"]

#: The worker: reads one JSON job per line, answers one JSON line.  Uses only API that is
#: the same before and after the rewrite (times in time units; t_transient = 0 allowed).
WORKER = r"""
import json, sys, time
import charts
print(json.dumps({"charts": charts.__file__}), flush=True)
for line in sys.stdin:
    job = json.loads(line)
    try:
        S = charts.RotorSystem(job["n"])
        th, u = S.random_state(seed=job["seed"])
        c0, w0 = time.process_time(), time.perf_counter()
        r = charts.lyapunov_spectrum(S, th, u, job["t"], n_exponents=job["k"], t_transient=0,
                                     **job["kw"])
        c1, w1 = time.process_time(), time.perf_counter()
        out = {"cpu": c1 - c0, "wall": w1 - w0, "exponents": [float(x) for x in r.exponents]}
    except Exception as exc:
        out = {"error": f"{type(exc).__name__}: {exc}"}
    print(json.dumps(out), flush=True)
"""

#: First-ever call in a new process with an empty numba cache (``--cold``): prints the wall
#: and CPU seconds of ``import charts`` and of the first (compiling) Lyapunov call.
COLD = r"""
import sys, time
w0, c0 = time.perf_counter(), time.process_time()
import charts
w1, c1 = time.perf_counter(), time.process_time()
S = charts.RotorSystem(int(sys.argv[1])); th, u = S.random_state(seed=1)
charts.lyapunov_spectrum(S, th, u, 2.0, n_exponents=S.n - 2, t_transient=0, n_batches=2)
w2, c2 = time.perf_counter(), time.process_time()
print(w1 - w0, c1 - c0, w2 - w1, c2 - c1)
"""


class Engine:
    """A worker process running `WORKER` under ``python`` (``src`` first on PYTHONPATH)."""

    def __init__(self, label, python, src=None, cwd=None):
        self.label, self.python, self.src = label, python, src
        env = dict(os.environ)
        if src:
            env["PYTHONPATH"] = os.pathsep.join(filter(None, [src, env.get("PYTHONPATH")]))
        # cwd: a folder without a `charts` package, so that `python -c` cannot import the
        # checkout the benchmark was started from instead of the engine's installation
        self.env = env
        self.proc = subprocess.Popen([python, "-c", WORKER], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, text=True, env=env, cwd=cwd)
        self.charts_file = self._read()["charts"]
        self.source = describe_source(Path(self.charts_file).resolve().parent.parent)

    def _read(self):
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"engine {self.label!r} ({self.python}) exited")
        return json.loads(line)

    def run(self, n, t, seed, kw=None):
        job = {"n": n, "k": n - 2, "t": t, "seed": seed, "kw": kw or {}}
        self.proc.stdin.write(json.dumps(job) + "\n")
        self.proc.stdin.flush()
        out = self._read()
        if "error" in out:
            raise RuntimeError(f"engine {self.label!r}, N={n}: {out['error']}")
        return out

    def cold(self, n):
        """(import wall, import CPU, compile wall, compile CPU) in a new process whose numba
        cache starts empty."""
        with tempfile.TemporaryDirectory() as cache:
            env = dict(self.env, NUMBA_CACHE_DIR=cache)
            out = subprocess.run([self.python, "-c", COLD, str(n)], env=env, cwd=cache,
                                 capture_output=True, text=True, check=True)
        return tuple(map(float, out.stdout.split()))

    def close(self):
        self.proc.stdin.close()
        self.proc.wait(timeout=60)


def describe_source(folder: Path) -> str:
    """``folder`` with its git commit and whether the working tree differs from it."""
    try:
        rev = subprocess.run(["git", "-C", str(folder), "rev-parse", "--short", "HEAD"],
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(folder), "status", "--porcelain", "charts"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return str(folder)
    return f"{folder} @ {rev}" + (" + uncommitted changes in charts/" if dirty else "")


def parse_engine(text: str) -> tuple[str, str, str | None]:
    """``LABEL=PYTHON`` or ``LABEL=PYTHON:SRC`` -> (label, python, src or None)."""
    label, sep, rest = text.partition("=")
    if not sep or not label or not rest:
        raise argparse.ArgumentTypeError(f"expected LABEL=PYTHON[:SRC], got {text!r}")
    python, _, src = rest.partition(":")
    return label, python, src or None


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench compare", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--engine", action="append", type=parse_engine, metavar="LABEL=PYTHON[:SRC]",
                    help="an installation to measure (repeatable; the first is the baseline of "
                    "the ratios; default: this interpreter)")
    ap.add_argument("--n", type=int, nargs="+", default=[3, 4, 5], help="numbers of rotors")
    ap.add_argument("--t", type=float, default=3000.0, help="time units per run (default 3000)")
    ap.add_argument("--repeat", type=int, default=7, help="repetitions per engine (default 7)")
    ap.add_argument("--seed", type=int, default=1, help="seed of the initial state (default 1)")
    ap.add_argument("--record-every", type=float, default=None, metavar="T",
                    help="pass record_every=T to lyapunov_spectrum (default: its default, 1.0; "
                    "a larger T means fewer, longer calls of the compiled kernel)")
    ap.add_argument("--cold", type=int, default=0, metavar="K",
                    help="also time the first-ever call (empty numba cache, new process) K "
                    "times per engine, for the largest N (default 0: no)")
    args = ap.parse_args(argv)
    specs = args.engine or [("this", sys.executable, None)]
    print(f"date: {datetime.date.today().isoformat()}\nmachine: {machine()}")
    print("command: charts bench compare " + " ".join(sys.argv[1:] if argv is None else argv))
    print(f"task: lyapunov_spectrum(RotorSystem(N), *random_state(seed={args.seed}), "
          f"{args.t:g}, n_exponents=N-2, t_transient=0"
          + ("" if args.record_every is None else f", record_every={args.record_every:g}")
          + f"); CPU time per run, "
          f"{args.repeat} repetitions, engines taking turns\n{load()}", flush=True)
    with tempfile.TemporaryDirectory() as cwd:
        engines = [Engine(label, py, src, cwd) for label, py, src in specs]
        try:
            for e in engines:
                print(f"  {e.label}: {e.python}" + (f" (PYTHONPATH {e.src})" if e.src else "")
                      + f" -> {e.source}")
            kw = {} if args.record_every is None else {"record_every": args.record_every}
            results = measure(engines, args.n, args.t, args.repeat, args.seed, kw)
            colds = {e.label: [] for e in engines}
            for _ in range(args.cold):
                for e in engines:
                    colds[e.label].append(e.cold(max(args.n)))
        finally:
            for e in engines:
                e.close()
    print(load())
    report(engines, results, args.t)
    if args.cold:
        print(f"\nfirst-ever call, N={max(args.n)} (new process, empty numba cache), median "
              f"(min–max) of {args.cold}:")
        for e in engines:
            c = colds[e.label]
            parts = [f"{what} {_range([x[i] for x in c], 'wall')}, "
                     f"CPU {_range([x[i + 1] for x in c])}"
                     for what, i in (("import charts", 0), ("first Lyapunov call (compile)", 2))]
            print(f"  {e.label}: " + "; ".join(parts))
    return 0


def _range(values, unit=""):
    med, lo, hi = spread(values)
    return f"{med:.2f} s ({lo:.2f}–{hi:.2f})" + (f" {unit}" if unit else "")


def measure(engines, ns, t, repeat, seed, kw):
    """{(label, n): [worker answers]}: a warm-up per engine and N, then the engines take turns
    (their order reversed every other repetition)."""
    for n in ns:
        for e in engines:
            e.run(n, 20.0, seed)
    results = {(e.label, n): [] for e in engines for n in ns}
    for rep in range(repeat):
        order = engines if rep % 2 == 0 else engines[::-1]
        for n in ns:
            for e in order:
                results[e.label, n].append(e.run(n, t, seed, kw))
        print(f"  repetition {rep + 1}/{repeat} done; {load()}", flush=True)
    return results


def report(engines, results, t):
    base = engines[0].label
    ns = sorted({n for _, n in results})
    print(f"\n| N | exponents | engine | time units per CPU-second: median (min–max) | "
          f"spread | ratio to {base} (of medians) | paired ratio: median (min–max) |")
    print("|---:|---:|---|---:|---:|---:|---:|")
    for n in ns:
        rate0 = [t / r["cpu"] for r in results[base, n]]
        for e in engines:
            rate = [t / r["cpu"] for r in results[e.label, n]]
            med, lo, hi = spread(rate)
            ratio = med / statistics.median(rate0)
            paired = spread(a / b for a, b in zip(rate, rate0))
            print(f"| {n} | {n - 2} | {e.label} | {med:,.0f} ({lo:,.0f}–{hi:,.0f}) | "
                  f"±{50 * (hi - lo) / med:.0f} % | {ratio:.3f} | "
                  f"{paired[0]:.3f} ({paired[1]:.3f}–{paired[2]:.3f}) |")
    print("\nspread: half the range over the median. Exponents of the first repetition, and the "
          "median ratio of wall to CPU time (above 1: other jobs took turns on the core):")
    for n in ns:
        for e in engines:
            rr = results[e.label, n]
            busy = statistics.median(x["wall"] / x["cpu"] for x in rr)
            print(f"  N={n} {e.label}: " + " ".join(f"{x:.4f}" for x in rr[0]["exponents"])
                  + f"  (wall/CPU {busy:.2f})")


if __name__ == "__main__":
    sys.exit(main())
