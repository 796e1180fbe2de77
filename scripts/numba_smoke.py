"""Smoke test of charts under the OLDEST allowed numba (pyproject's lower bound).

    python scripts/numba_smoke.py [--numba 0.61.2] [--venv /tmp/charts-numba-smoke] [--keep]

1. Snapshots the repository's committed HEAD (``git worktree add --detach``), so that edits
   made to the working tree during the run do not affect it.
2. Creates a venv with ``numba==<version>`` (and the numpy pip picks for it), then installs the
   snapshot with ``pip install -e '<snapshot>[test]'`` under a constraint ``numba==<version>``.
3. Runs ``charts reproduce --quick`` in that venv and in the current interpreter
   (``sys.executable``, its own numba), the latter importing the same snapshot (installed
   non-editable into a folder put first on PYTHONPATH), each with fresh NUMBA_CACHE_DIR and
   CHARTS_CACHE_DIR; compares every number of the two ``results.json`` (timings excepted).
4. Runs the numerical tests of each formulation with pytest in the venv.
5. Prints a summary; exits non-zero if the tests (or the old-numba reproduce) fail.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
TESTS = ["tests/test_integrate_accuracy.py", "tests/test_integrate_api.py",
         "tests/test_ambient_tangent_identity.py", "tests/test_chart_transport_variant.py",
         "tests/test_lyapunov.py", "tests/test_hyperbolicity.py", "tests/test_covariant.py",
         "tests/test_curvature.py", "tests/test_lanes.py", "tests/test_numba_guest.py"]
TIMING_KEYS = {"elapsed_s", "workers"}        # run facts, not results: left out of the comparison
REL_TOL = 1e-9


def log(msg: str) -> None:
    print(f"[numba-smoke {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def run(cmd, *, env=None, cwd=None, check=True, capture=False):
    log("$ " + " ".join(str(c) for c in cmd))
    r = subprocess.run([str(c) for c in cmd], env=env, cwd=cwd, text=True,
                       stdout=subprocess.PIPE if capture else None,
                       stderr=subprocess.STDOUT if capture else None)
    if capture and r.stdout:
        print(r.stdout, end="" if r.stdout.endswith("\n") else "\n", flush=True)
    if check and r.returncode != 0:
        raise SystemExit(f"command failed (exit {r.returncode}): {' '.join(map(str, cmd))}")
    return r


def lower_bound() -> str:
    text = (REPO / "pyproject.toml").read_text()
    m = re.search(r'"numba\s*>=\s*([0-9][0-9.]*)', text)
    if not m:
        raise SystemExit("no numba>=X requirement in pyproject.toml")
    return m.group(1)


def newest_patch(base: str) -> str:
    """The newest release pip offers with the same major.minor as ``base``; ``base.*`` if pip
    cannot say."""
    mm = ".".join(base.split(".")[:2])
    r = subprocess.run([sys.executable, "-m", "pip", "index", "versions", "numba"],
                       capture_output=True, text=True)
    m = re.search(r"Available versions:\s*(.*)", r.stdout)
    if m:
        vs = [v.strip() for v in m.group(1).split(",")]
        vs = [v for v in vs if re.fullmatch(rf"{re.escape(mm)}\.\d+", v)]
        if vs:
            return max(vs, key=lambda v: tuple(int(x) for x in v.split(".")))
    return mm + ".*"


def versions(python, env, cwd) -> str:
    r = subprocess.run([str(python), "-P", "-c",
                        "import numba, numpy, llvmlite, charts, sys; "
                        "print(f'python {sys.version.split()[0]}, numba {numba.__version__}, "
                        "llvmlite {llvmlite.__version__}, numpy {numpy.__version__}; "
                        "charts from {charts.__file__}')"],
                       env=env, cwd=cwd, capture_output=True, text=True)
    return (r.stdout.strip() or r.stderr.strip().splitlines()[-1]) if (r.stdout or r.stderr) else "?"


def fresh(path: Path) -> Path:
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    return path


def compare(a, b, path="", out=None):
    """Walk two JSON trees; collect (path, x, y) for every pair of numbers, and structural
    mismatches as (path, x, y) with a None relative difference."""
    out = [] if out is None else out
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in TIMING_KEYS and not path:
                continue
            if k not in a or k not in b:
                out.append((f"{path}/{k}", a.get(k, "<absent>"), b.get(k, "<absent>"), None))
            else:
                compare(a[k], b[k], f"{path}/{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append((path, f"len {len(a)}", f"len {len(b)}", None))
        for i, (x, y) in enumerate(zip(a, b)):
            compare(x, y, f"{path}[{i}]", out)
    elif (isinstance(a, (int, float)) and not isinstance(a, bool)
          and isinstance(b, (int, float)) and not isinstance(b, bool)):
        if a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)):
            rel = 0.0
        elif math.isinf(a) or math.isinf(b) or math.isnan(a) or math.isnan(b):
            rel = math.inf
        else:
            rel = abs(a - b) / max(abs(a), abs(b))
        out.append((path, a, b, rel))
    elif a != b:
        out.append((path, a, b, None))
    return out


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--numba", default=None,
                   help="numba version to test (default: pyproject's lower bound, newest patch)")
    p.add_argument("--venv", default="/tmp/charts-numba-smoke", type=Path)
    p.add_argument("--keep", action="store_true", help="reuse an existing venv")
    args = p.parse_args()
    t0 = time.time()
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))     # run the clean-up on kill
    version = args.numba or newest_patch(lower_bound())
    spec = f"numba=={version}"
    venv = args.venv.resolve()
    log(f"testing {spec} in {venv} against {sys.executable}")

    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True,
                          text=True, check=True).stdout.strip()
    snap = Path(tempfile.mkdtemp(prefix="charts-snapshot-")) / "src"
    run(["git", "-C", REPO, "worktree", "add", "--detach", snap, head])
    summary = {}
    rc = 0
    try:
        # -- the old-numba venv
        py = venv / "bin" / "python"
        if not (args.keep and py.exists()):
            shutil.rmtree(venv, ignore_errors=True)
            run([sys.executable, "-m", "venv", venv])
            run([py, "-m", "pip", "install", "-q", "--upgrade", "pip"])
        cons = venv / "constraints.txt"
        run([py, "-m", "pip", "install", "-q", spec])
        cons.write_text(f"{spec}\n")
        run([py, "-m", "pip", "install", "-q", "-c", cons, "-e", f"{snap}[test]"])
        # -- the default interpreter imports the same snapshot, installed into a folder
        site = fresh(venv / "default-site")
        run([sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", site, snap])

        base = {k: v for k, v in os.environ.items()
                if k not in ("PYTHONPATH", "NUMBA_CACHE_DIR", "CHARTS_CACHE_DIR")}
        env_old = dict(base, NUMBA_CACHE_DIR=str(fresh(venv / "numba-cache-old")),
                       CHARTS_CACHE_DIR=str(fresh(venv / "charts-cache-old")),
                       PATH=f"{venv / 'bin'}{os.pathsep}{base.get('PATH', '')}", VIRTUAL_ENV=str(venv))
        env_new = dict(base, NUMBA_CACHE_DIR=str(fresh(venv / "numba-cache-default")),
                       CHARTS_CACHE_DIR=str(fresh(venv / "charts-cache-default")),
                       PYTHONPATH=str(site))
        # cwd: a neutral folder and python -P, so that neither the working tree nor the
        # snapshot's top folder shadows the installed package (charts.generated lives in
        # generated/ at the top, mapped into the package only by the install)
        neutral = fresh(venv / "cwd")
        summary["old"] = versions(py, env_old, neutral)
        summary["new"] = versions(sys.executable, env_new, neutral)
        log("old-numba env: " + summary["old"])
        log("default env:   " + summary["new"])

        # -- charts reproduce --quick in both
        outs = {"old": venv / "reproduce-old", "new": venv / "reproduce-default"}
        times = {}
        for key, cmd, env in (
                ("old", [venv / "bin" / "charts", "reproduce", "--quick", "--quiet", "-o", outs["old"]], env_old),
                ("new", [sys.executable, "-P", "-c", "import sys; from charts.cli import main; "
                         "sys.exit(main(sys.argv[1:]))", "reproduce", "--quick", "--quiet",
                         "-o", outs["new"]], env_new)):
            shutil.rmtree(outs[key], ignore_errors=True)
            t = time.time()
            r = run(cmd, env=env, cwd=neutral, check=False)
            times[key] = (time.time() - t, r.returncode)
        files = {k: v / "results.json" for k, v in outs.items()}
        if all(f.exists() for f in files.values()) and all(c == 0 for _, c in times.values()):
            a, b = (json.loads(files[k].read_text()) for k in ("old", "new"))
            diffs = compare(a, b)
            nums = [d for d in diffs if d[3] is not None]
            struct = [d for d in diffs if d[3] is None]
            differing = sorted((d for d in nums if d[3] > 0), key=lambda d: -d[3])
            worst = differing[0] if differing else None
            lines = [f"{len(nums)} numbers compared (timings {sorted(TIMING_KEYS)} left out); "
                     f"{len(differing)} differ; structural mismatches: {len(struct)}"]
            lines.append("bit-for-bit identical" if not differing and not struct
                         else "NOT bit-for-bit identical")
            if worst:
                lines.append(f"largest relative difference {worst[3]:.3g} at {worst[0]} "
                             f"({worst[1]!r} vs {worst[2]!r})")
                for d in differing[1:5]:
                    lines.append(f"  next: {d[3]:.3g} at {d[0]} ({d[1]!r} vs {d[2]!r})")
            else:
                lines.append("largest relative difference 0")
            for d in struct[:5]:
                lines.append(f"  structural: {d[0]}: {d[1]!r} vs {d[2]!r}")
            ok = not struct and (worst is None or worst[3] <= REL_TOL)
            lines.append(f"agrees to {REL_TOL:g} relative: {'yes' if ok else 'NO'}")
            # the raw per-task results (before numpy's post-processing) byte for byte: tells
            # numba/LLVM differences apart from numpy ones in results.json
            pa, pb = outs["old"] / "pieces", outs["new"] / "pieces"
            names = sorted(f.name for f in pa.glob("*")) if pa.is_dir() else []
            same = [n for n in names if (pb / n).is_file()
                    and (pa / n).read_bytes() == (pb / n).read_bytes()]
            lines.append(f"raw pieces (pieces/*.npz, the compiled kernels' output): "
                         f"{len(same)} of {len(names)} byte-identical"
                         + ("" if len(same) == len(names) else
                            "; differ: " + ", ".join(n for n in names if n not in same)[:300]))
            summary["reproduce"] = lines
        else:
            summary["reproduce"] = [f"reproduce failed: old exit {times['old'][1]}, "
                                    f"default exit {times['new'][1]} (see log above)"]
            if times["old"][1] != 0:
                rc = 1
        summary["reproduce_times"] = (f"old {times['old'][0]:.0f} s (exit {times['old'][1]}), "
                                      f"default {times['new'][0]:.0f} s (exit {times['new'][1]})")

        # -- pytest in the old-numba venv
        present = [t for t in TESTS if (snap / t).exists()]
        missing = [t for t in TESTS if t not in present]
        for t in missing:
            log(f"note: {t} is not in the snapshot; skipped")
        env_test = dict(env_old, NUMBA_CACHE_DIR=str(fresh(venv / "numba-cache-tests")),
                        CHARTS_CACHE_DIR=str(fresh(venv / "charts-cache-tests")))
        t = time.time()
        # from the snapshot's folder: its top folder comes first on sys.path, but the venv's
        # editable install maps charts.generated to the same snapshot
        cmd = [str(py), "-m", "pytest", "-n", "2", "-q", "-p", "no:cacheprovider", *present]
        log("$ (cd snapshot) " + " ".join(cmd))
        proc = subprocess.Popen(cmd, cwd=snap, env=env_test, text=True,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        lines_out = []
        for ln in proc.stdout:                          # streamed, and kept for the result line
            print(ln, end="", flush=True)
            lines_out.append(ln)
        r = subprocess.CompletedProcess(cmd, proc.wait())
        tail = [ln.rstrip() for ln in lines_out if ln.strip()]
        result_line = next((ln for ln in reversed(tail) if re.search(r"\b(passed|failed|error)", ln)),
                           tail[-1] if tail else "(no output)")
        summary["pytest"] = f"{result_line}  [exit {r.returncode}, {time.time() - t:.0f} s]"
        summary["missing"] = missing
        if r.returncode != 0:
            rc = 1
    finally:
        subprocess.run(["git", "-C", str(REPO), "worktree", "remove", "--force", str(snap)])
        shutil.rmtree(snap.parent, ignore_errors=True)

    print("\n===== numba smoke summary =====")
    print(f"snapshot: HEAD {head[:12]}")
    print(f"old-numba venv ({spec}): {summary.get('old')}")
    print(f"default env ({sys.executable}): {summary.get('new')}")
    print("reproduce --quick: " + summary.get("reproduce_times", "not run"))
    for ln in summary.get("reproduce", []):
        print("  " + ln)
    if summary.get("missing"):
        print(f"tests skipped (absent from snapshot): {', '.join(summary['missing'])}")
    print(f"pytest ({spec}): {summary.get('pytest', 'not run')}")
    print(f"total wall time: {time.time() - t0:.0f} s")
    print(f"exit: {rc}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
