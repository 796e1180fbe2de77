"""Ensembles in vector lanes against the one-trajectory kernel, measured in one run.

    charts bench ensemble               # t = 500 per member, 3 repetitions
    charts bench ensemble --quick       # t = 100, 1 repetition, no scans

Task: ``members`` trajectories of N rotors (``RotorSystem(N).random_state(seed=i)``, unit
speed), k = min(3, N − 1) exponents, dt = 0.01, eq (18) every 0.1, a transient of 50, then
t time units:
  * lanes: ``lyapunov_ensemble(..., workers=1)`` (every member in the lanes of one kernel,
    ``charts.solvers.lanes``, on one core);
  * single: ``lyapunov_spectrum`` on each member in turn (the one-trajectory tangent kernel);
  * JiTCODE (if installed; ``charts.runs.benchmarks.peers``): one trajectory of the N = 5
    task.
Reported: CPU seconds (``time.process_time``), aggregate time units (transient + t, summed
over the members) per CPU second, and their ratio, the routes taking turns in one run
(medians of ``--repeat``); the members' exponents are checked identical between the routes.
The headline row is the target (16 members, N = 5, 3 exponents); the scans vary the lane
count at N = 5 and N at 16 lanes.
"""
from __future__ import annotations

import argparse
import datetime
import statistics
import sys
import time

import numpy as np

from ...analyses.lyapunov import lyapunov_spectrum
from ...analyses.lyapunov_members import lyapunov_ensemble
from ...geometry.system import RotorSystem
from ..cli_parser import OneLineParser
from .environment import load, machine
from .peers import TRANSIENT, jitcode_run, jitcode_setup

__all__ = ["ensemble_rows", "main", "DT", "REORTH"]

DT = 0.01
REORTH = 0.1


def _settings(n, t_final):
    return dict(dt=DT, n_exponents=min(3, n - 1), t_transient=TRANSIENT, reorth_every=REORTH,
                n_batches=2)


def _lanes(n, members, t_final):
    """(CPU s, exponents (members, k)) of the ensemble in lanes, one process."""
    S = RotorSystem(n)
    c0 = time.process_time()
    ens = lyapunov_ensemble(S, members, t_final, workers=1, lanes=True, **_settings(n, t_final))
    return time.process_time() - c0, np.array([m.exponents for m in ens.members])


def _single(n, members, t_final):
    """(CPU s, exponents (members, k)) of the members one after the other."""
    S = RotorSystem(n)
    states = [S.random_state(seed=i) for i in range(members)]
    c0 = time.process_time()
    exps = [lyapunov_spectrum(S, th, u, t_final, seed=i, **_settings(n, t_final)).exponents
            for i, (th, u) in enumerate(states)]
    return time.process_time() - c0, np.array(exps)


def ensemble_rows(t_final=500.0, repeat=3, cases=((5, 16),), jitcode=True):
    """One row per (N, members) in ``cases`` (and JiTCODE's N = 5 row if installed and
    ``jitcode``): dicts with route, n, members, k, CPU seconds (median of ``repeat``, the
    routes taking turns), time units per CPU second (aggregate) and the ratio of the lanes
    to the single kernel; ``identical`` says whether every member's exponents agree bit for
    bit between the two routes."""
    rows = []
    for n, members in cases:
        _lanes(n, members, 2 * REORTH * 2)   # compile / load both kernels first (with
        _single(n, 1, 2 * REORTH * 2)        # `members`: fewer than MIN_LANES run single)
        cl, cs, same = [], [], True
        for _ in range(repeat):
            c, el = _lanes(n, members, t_final)
            cl.append(c)
            c, es = _single(n, members, t_final)
            cs.append(c)
            same &= bool(np.array_equal(el, es))
        units = members * (TRANSIENT + t_final)
        ml, ms = statistics.median(cl), statistics.median(cs)
        k = min(3, n - 1)
        rows.append(dict(route="single", n=n, members=members, k=k, cpu=ms, rate=units / ms,
                         ratio=1.0, identical=same))
        rows.append(dict(route="lanes", n=n, members=members, k=k, cpu=ml, rate=units / ml,
                         ratio=ms / ml, identical=same))
    jit = jitcode_setup() if jitcode else None
    if jit is not None:
        single5 = next((r for r in rows if r["route"] == "single" and r["n"] == 5), None)
        cpu = statistics.median(jitcode_run(jit[1], t_final)[2] for _ in range(repeat))
        rate = (TRANSIENT + t_final) / cpu
        rows.append(dict(route="JiTCODE", n=5, members=1, k=3, cpu=cpu, rate=rate,
                         ratio=rate / single5["rate"] if single5 else float("nan"),
                         identical=None))
    return rows


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench ensemble", description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--t", type=float, default=None, help="averaging time per member "
                    "(default 500; 100 with --quick)")
    ap.add_argument("--repeat", type=int, default=None, help="repetitions (default 3; 1 with "
                    "--quick)")
    ap.add_argument("--quick", action="store_true", help="the target row only, short runs")
    args = ap.parse_args(argv)
    T = args.t or (100.0 if args.quick else 500.0)
    rep = args.repeat or (1 if args.quick else 3)
    cases = [(5, 16)]
    if not args.quick:
        cases += [(5, 8), (5, 32), (5, 64), (3, 16), (4, 16), (8, 16)]
    print(f"date: {datetime.date.today().isoformat()}\nmachine: {machine()}")
    print("command: charts bench ensemble " + " ".join(sys.argv[1:] if argv is None else argv))
    print(f"task: members × (transient {TRANSIENT:g} + t={T:g}), dt={DT:g}, eq 18 every "
          f"{REORTH:g}, unit speed, seeds 0…; medians of {rep}\n{load()}\n", flush=True)
    rows = ensemble_rows(T, rep, cases)
    print("| route | N | members | exponents | CPU s | time units per CPU s (aggregate) | "
          "ratio to single | members identical |")
    print("|---|---:|---:|---:|---:|---:|---:|---|")
    for r in rows:
        same = "" if r["identical"] is None else ("yes" if r["identical"] else "NO")
        what = {"lanes": "lanes (lyapunov_ensemble, 1 core)",
                "single": "single (lyapunov_spectrum per member)",
                "JiTCODE": "JiTCODE (one trajectory, dopri5)"}[r["route"]]
        print(f"| {what} | {r['n']} | {r['members']} | {r['k']} | {r['cpu']:.3f} | "
              f"{r['rate']:,.0f} | {r['ratio']:.2f} | {same} |")
    print(f"\n{load()}")
    return 0 if all(r["identical"] is not False for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
