"""The first-ever call, measured: where the seconds go between a new process's start and its
first Lyapunov exponents, on a fresh install (empty numba cache) and after a warm-up.

    charts bench coldstart               # 2 repetitions per case, ~1 minute on 2 cores
    charts bench coldstart --path DIR    # another checkout's package (DIR holds charts/)

Each repetition is a new process with ``NUMBA_CACHE_DIR`` set to a folder of its own: a new,
empty one for the *empty cache* case (the first-ever run after an install), the folder the
last of them filled for the *filled cache* case (every later run, and the first one after
``charts warmup``).  The process times, in CPU and wall seconds, its phases: importing
numpy, numba, ``charts`` and the analysis, ``RotorSystem(5)`` with a random state, and the
first ``lyapunov_spectrum`` (t = 2, 3 exponents); and, from numba's ``numba:compile`` events,
every function compiled (or loaded from the cache) on the way, with its own CPU time (without
the functions compiled inside it) and its depth in the chain of compilations.

`coldstart_rows` returns the rows (medians over the repetitions); `main` prints them with
the machine and the load average.  Python's byte-code is compiled by an untimed import first
(an installer does that), so only numba's compilation is cold.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from ..cli_parser import OneLineParser
from .environment import load, machine

__all__ = ["TARGET_SECONDS", "PROBE", "probe", "coldstart_rows", "main"]

#: The target: exponents within this many seconds of ``import charts`` on a fresh install.
TARGET_SECONDS = 2.0

#: The process measured: prints one JSON line (phases: (name, wall, cpu) at their ends;
#: compilations: (depth, function, own cpu, cpu, wall); the functions loaded from the cache,
#: which numba's events do not show).
PROBE = r"""
import json, time
def now():
    return time.perf_counter(), time.process_time()
marks = [("start",) + now()]
import numpy
marks.append(("import numpy",) + now())
import numba
from numba.core import event
marks.append(("import numba",) + now())
compiles, stack = [], []
class Compilations(event.Listener):
    def on_start(self, e):
        stack.append([*now(), 0.0])
    def on_end(self, e):
        w0, c0, inner = stack.pop()
        w1, c1 = now()
        f = getattr(e.data.get("dispatcher"), "py_func", None)
        name = f"{f.__module__}.{f.__qualname__}" if f else "?"
        compiles.append((len(stack), name, c1 - c0 - inner, c1 - c0, w1 - w0))
        if stack:
            stack[-1][2] += c1 - c0
event.register("numba:compile", Compilations())
import charts
marks.append(("import charts",) + now())
lyapunov_spectrum, RotorSystem = charts.lyapunov_spectrum, charts.RotorSystem
marks.append(("import the analysis (charts.lyapunov_spectrum)",) + now())
S = RotorSystem(5)
th, u = S.random_state(seed=1)
marks.append(("RotorSystem(5).random_state (numba's start-up)",) + now())
lyapunov_spectrum(S, th, u, 2.0, dt=0.01, n_exponents=3, t_transient=0.0, n_batches=2)
marks.append(("first lyapunov_spectrum (t = 2, 3 exponents)",) + now())
import sys
from numba.core.registry import CPUDispatcher
loaded = sorted({f"{v.py_func.__module__}.{v.py_func.__qualname__}"
                 for m in list(sys.modules.values()) if m and m.__name__.startswith("charts")
                 for v in vars(m).values() if isinstance(v, CPUDispatcher) and v._cache_hits})
print(json.dumps({"marks": marks, "compiles": compiles, "loaded": loaded}))
"""


def process_env(cache_dir, path):
    """This process's environment with ``NUMBA_CACHE_DIR=cache_dir`` (None: numba's own) and,
    with ``path``, charts imported from there (its generated modules stay the installed
    ones: the editable install maps ``charts.generated``)."""
    env = dict(os.environ)
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = str(cache_dir)
    if path:
        env["PYTHONPATH"] = os.pathsep.join([str(path), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return env


def probe(cache_dir, path=None) -> dict:
    """Run `PROBE` in a new process with ``NUMBA_CACHE_DIR=cache_dir`` (None: numba's cache
    of this installation): {"phases": [(name, wall s, cpu s)], "compiles": [(depth, function,
    own cpu s, cpu s, wall s)], "loaded": [function loaded from the cache]}."""
    out = subprocess.run([sys.executable, "-c", PROBE], env=process_env(cache_dir, path),
                         capture_output=True, text=True, check=True, cwd=cache_dir)
    data = json.loads(out.stdout.strip().splitlines()[-1])
    marks = data["marks"]
    phases = [(m[0], m[1] - p[1], m[2] - p[2]) for p, m in zip(marks, marks[1:])]
    return {"phases": phases, "compiles": [tuple(c) for c in data["compiles"]],
            "loaded": data["loaded"]}


def _median_rows(case, runs):
    """Rows of one case: the phases, the total, then every compilation (medians over runs)."""
    rows = []
    for i, (name, _, _) in enumerate(runs[0]["phases"]):
        rows.append(dict(case=case, kind="phase", name=name, depth=0,
                         wall=statistics.median(r["phases"][i][1] for r in runs),
                         cpu=statistics.median(r["phases"][i][2] for r in runs)))
    totals = [(sum(p[1] for p in r["phases"]), sum(p[2] for p in r["phases"])) for r in runs]
    rows.append(dict(case=case, kind="total", name="import charts (numpy, numba) to exponents",
                     depth=0, wall=statistics.median(t[0] for t in totals),
                     cpu=statistics.median(t[1] for t in totals),
                     range=(min(t[1] for t in totals), max(t[1] for t in totals))))
    rows.append(dict(case=case, kind="loaded", name="functions loaded from the cache", depth=0,
                     count=statistics.median(len(r["loaded"]) for r in runs)))
    seen = {}
    for r in runs:
        for depth, name, own, cpu, wall in r["compiles"]:
            seen.setdefault((depth, name), []).append((own, cpu, wall))
    for (depth, name), v in sorted(seen.items(), key=lambda kv: -statistics.median(
            x[0] for x in kv[1])):
        rows.append(dict(case=case, kind="compile", name=name, depth=depth,
                         own=statistics.median(x[0] for x in v),
                         cpu=statistics.median(x[1] for x in v),
                         wall=statistics.median(x[2] for x in v), count=len(v) / len(runs)))
    return rows


def coldstart_rows(repeat=2, path=None, progress=None) -> list[dict]:
    """Rows (dicts: case, kind ∈ {phase, total, loaded, compile}, name, depth, cpu, wall
    and, for compilations, own cpu; for ``loaded`` only count) for the empty-cache and the filled-cache case, medians over
    ``repeat`` new processes each.  ``path``: a folder to import ``charts`` from instead."""
    say = progress or (lambda msg: None)
    with tempfile.TemporaryDirectory(prefix="charts-coldstart-") as tmp:
        subprocess.run([sys.executable, "-c", "import charts; charts.lyapunov_spectrum"],
                       env=process_env(tmp, path), check=True, cwd=tmp)    # byte-code, not timed
        empty = []
        for i in range(repeat):
            cache = tempfile.mkdtemp(dir=tmp)
            say(f"empty cache, run {i + 1} of {repeat}")
            empty.append(probe(cache, path))
        filled = []
        for i in range(repeat):
            say(f"filled cache, run {i + 1} of {repeat}")
            filled.append(probe(cache, path))
    return _median_rows("empty cache", empty) + _median_rows("filled cache", filled)


def format_rows(rows) -> list[str]:
    """The rows as the lines `main` prints."""
    lines = []
    for case in dict.fromkeys(r["case"] for r in rows):
        lines.append(f"{case}:                                             CPU s   wall s")
        for r in (r for r in rows if r["case"] == case):
            if r["kind"] == "loaded":
                lines.append(f"  {r['name']:<55} {r['count']:6g}")
                continue
            if r["kind"] == "compile":
                if r["own"] >= 0.05 or r["depth"] == 0:
                    name = "  " * r["depth"] + r["name"].removeprefix("charts.")
                    lines.append(f"    compile {name:<44} {r['own']:6.2f} own, {r['cpu']:6.2f} "
                                 f"with nested, {r['wall']:6.2f} wall")
                continue
            extra = ""
            if "range" in r:
                verdict = "met" if r["cpu"] <= TARGET_SECONDS else "not met"
                extra = (f"   ({r['range'][0]:.2f}–{r['range'][1]:.2f}; target "
                         f"{TARGET_SECONDS:g} s: {verdict})")
            lines.append(f"  {r['name']:<55} {r['cpu']:6.2f}  {r['wall']:6.2f}{extra}")
    return lines


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench coldstart", description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=2, help="new processes per case (default 2)")
    ap.add_argument("--path", default=None,
                    help="import charts from this folder (another checkout) instead")
    args = ap.parse_args(argv)
    if args.repeat < 1:
        ap.error(f"--repeat must be at least 1, got {args.repeat}")
    print(machine())
    print(load(), "(before)")
    rows = coldstart_rows(args.repeat, args.path,
                          progress=lambda msg: print(f"  … {msg}", file=sys.stderr, flush=True))
    print("\n".join(format_rows(rows)))
    print(load(), "(after)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
