"""First use of each public analysis, in CPU seconds: what a fresh install waits for.

    charts bench first_use                      # every row below, ~10 min on 2 loaded cores
    charts bench first_use --only analyses      # or: shared, warmup, reproduce
    charts bench first_use --path DIR           # another checkout's package (DIR holds charts/)
    charts bench first_use --compiles           # also list every compilation (function, signature)

Rows: for each public analysis, a new process with an empty numba cache (``NUMBA_CACHE_DIR``
and ``CHARTS_CACHE_DIR`` new empty folders) makes the shortest call at N = 3, then at N = 4,
5, 6 in the same process: the CPU seconds of the first call and the extra of each next N
(*fresh*).  Then all analyses one after another in one process and one cache, as a user would
call them (*shared*).  Then ``charts warmup`` (CPU of the command and its workers, and wall)
and ``charts reproduce --quick`` (wall and CPU), each on an empty cache.  CPU is the
process's own plus its children's (``RUSAGE_CHILDREN``), so it is blind to the other jobs on a
shared machine; wall is not.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager

from ..cli_parser import OneLineParser
from .coldstart import process_env
from .environment import load, machine

__all__ = ["ANALYSES", "PROBE", "probe", "main"]

#: name -> the shortest call of the public analysis (S, th, u in scope).
ANALYSES = {
    "lyapunov_spectrum": "charts.lyapunov_spectrum(S, th, u, 0.2, t_transient=0.0, n_batches=2)",
    "hyperbolicity_angles": "charts.hyperbolicity_angles(S, th, u, 0.2, t_transient=0.0)",
    "covariant_lyapunov_vectors": "charts.covariant_lyapunov_vectors(S, th, u, 0.4, "
                                  "t_transient=0.1)",
    "curvature_along_trajectory": "charts.curvature_along_trajectory(S, th, u, 0.2, "
                                  "t_transient=0.0)",
    "integrate_ambient": "charts.integrate(S, th, u, 0.1, formulation='ambient')",
    "integrate_chart": "charts.integrate(S, th, u, 0.1, formulation='chart')",
}

#: One process: runs the calls named in argv[1] (JSON list of [name, code]) for each N in
#: argv[2] (JSON list) and prints one JSON line: per call its CPU and the compilations
#: (function, signature, own CPU s) numba reported on the way.
PROBE = r"""
import json, sys, time
from numba.core import event
calls, ns = json.loads(sys.argv[1]), json.loads(sys.argv[2])
stack, compiles = [], []
class Listener(event.Listener):
    def on_start(self, e):
        stack.append([time.process_time(), 0.0])
    def on_end(self, e):
        c0, inner = stack.pop()
        c = time.process_time() - c0
        if stack:
            stack[-1][1] += c
        d = e.data.get("dispatcher")
        f = getattr(d, "py_func", None)
        name = f"{f.__module__}.{f.__qualname__}".removeprefix("charts.") if f else "?"
        compiles.append([name, str(e.data.get("args")), c - inner, len(stack)])
event.register("numba:compile", Listener())
import charts
rows = []
for n in ns:
    S = charts.RotorSystem(n)
    th, u = S.random_state(seed=1)
    for name, code in calls:
        del compiles[:]
        c0 = time.process_time()
        eval(code)
        rows.append(dict(name=name, n=n, cpu=time.process_time() - c0, compiles=list(compiles),
                         package=charts.__file__))
print(json.dumps(rows))
"""


@contextmanager
def _fresh_env(path):
    """The environment of a new process on an empty cache: new ``NUMBA_CACHE_DIR`` and
    ``CHARTS_CACHE_DIR`` folders (removed afterwards) and, with ``path``, charts imported
    from there (``coldstart``'s environment)."""
    with tempfile.TemporaryDirectory(prefix="charts-first-use-") as tmp:
        env = process_env(os.path.join(tmp, "numba"), path)
        env["CHARTS_CACHE_DIR"] = os.path.join(tmp, "charts")
        yield env, tmp


def probe(names, ns, path=None) -> list[dict]:
    """`PROBE` in a new process on an empty cache: one dict per (N, analysis) call:
    {name, n, cpu, compiles: [[function, signature, own cpu s, depth]]}."""
    calls = [[k, ANALYSES[k]] for k in names]
    with _fresh_env(path) as (env, tmp):
        # run in the empty folder: `python -c` puts its working directory first on sys.path,
        # so a run from a checkout's root would import that checkout instead of ``path``
        out = subprocess.run([sys.executable, "-c", PROBE, json.dumps(calls),
                              json.dumps(list(ns))], env=env, capture_output=True, text=True,
                             check=True, cwd=tmp)
    rows = json.loads(out.stdout.strip().splitlines()[-1])
    if path and not all(os.path.realpath(r["package"]).startswith(os.path.realpath(path))
                        for r in rows):
        raise RuntimeError(f"the probe imported charts from {rows[0]['package']}, not {path}")
    return rows


def command(argv, path=None, cwd=None) -> tuple[float, float, int]:
    """(CPU s of the command and its children, wall s, exit status) of ``charts ARGV`` in a new
    process on an empty cache."""
    with _fresh_env(path) as (env, tmp):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        w0 = time.perf_counter()
        # `python -m` puts its working directory first on sys.path: the empty folder by default
        rc = subprocess.run([sys.executable, "-m", "charts.cli.main", *argv], env=env,
                            cwd=cwd or tmp,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        wall = time.perf_counter() - w0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, rc


def _compile_lines(rows):
    lines = []
    for r in rows:
        for name, sig, own, depth in r["compiles"]:
            if own >= 0.1 or depth == 0:
                lines.append(f"    N={r['n']} {r['name']:<27} {'  ' * depth}{name} "
                             f"{own:6.2f} s  {sig[:90]}")
    return lines


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench first_use", description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="+", default=["analyses", "shared", "warmup", "reproduce"],
                    choices=["analyses", "shared", "warmup", "reproduce"])
    ap.add_argument("--analysis", nargs="+", default=list(ANALYSES), choices=list(ANALYSES))
    ap.add_argument("--n", nargs="+", type=int, default=[3, 4, 5, 6])
    ap.add_argument("--path", default=None, help="import charts from this folder instead")
    ap.add_argument("--compiles", action="store_true", help="list every compilation")
    ap.add_argument("--json", default=None, help="also write the rows to this file")
    args = ap.parse_args(argv)
    print(machine())
    print(load(), "(before)")
    out = {}
    if "analyses" in args.only:
        print(f"fresh process and empty cache per analysis; CPU s of the first call at N = "
              f"{args.n[0]}, then of each next N:")
        out["fresh"] = {}
        for name in args.analysis:
            rows = probe([name], args.n, args.path)
            out["fresh"][name] = rows
            print(f"  {name:<28}" + "".join(f" N={r['n']}: {r['cpu']:6.2f}" for r in rows),
                  flush=True)
            if args.compiles:
                print("\n".join(_compile_lines(rows)))
    if "shared" in args.only:
        print(f"one process, one empty cache, every analysis in turn for N = {args.n}:")
        rows = probe(args.analysis, args.n, args.path)
        out["shared"] = rows
        for n in args.n:
            line = "".join(f" {r['cpu']:6.2f}" for r in rows if r["n"] == n)
            print(f"  N={n}:{line}   (order: {', '.join(args.analysis)})")
        total = sum(r["cpu"] for r in rows)
        print(f"  total {total:.2f} s CPU", flush=True)
        if args.compiles:
            print("\n".join(_compile_lines(rows)))
    if "warmup" in args.only:
        cpu, wall, rc = command(["warmup"], args.path)
        out["warmup"] = dict(cpu=cpu, wall=wall, rc=rc)
        print(f"charts warmup (empty cache): CPU {cpu:.1f} s, wall {wall:.1f} s, exit {rc}",
              flush=True)
    if "reproduce" in args.only:
        with tempfile.TemporaryDirectory(prefix="charts-first-use-out-") as tmp:
            cpu, wall, rc = command(["reproduce", "--quick", "-o", os.path.join(tmp, "q")],
                                    args.path, cwd=tmp)
        out["reproduce"] = dict(cpu=cpu, wall=wall, rc=rc)
        print(f"charts reproduce --quick (empty cache): wall {wall:.1f} s, CPU {cpu:.1f} s, "
              f"exit {rc}", flush=True)
    print(load(), "(after)")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
