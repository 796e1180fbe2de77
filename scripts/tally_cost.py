"""What the angle tally costs per core (docs/cluster.md): CPU seconds of `hyperbolicity_tally`
in this process (``workers=1``: one core), per angle and per time unit integrated, and the
core-hours of the 10⁹-angle run of ``charts verdict --statistics --samples 1e9`` (16384
members, each T = 6104 after a transient of 100) that they predict.

A few members of that run's shape (the same window and transient), after a short call
that compiles the kernels:

    python scripts/tally_cost.py                 # N = 4, 8 members
    python scripts/tally_cost.py --n 3 4 5 --members 4
"""
from __future__ import annotations

import argparse
import time

from charts import RotorSystem
from charts.analyses.tally_run import hyperbolicity_tally
from charts.runs.verdict_statistics import members_window


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, nargs="+", default=[4])
    p.add_argument("--members", type=int, default=8, help="members measured (default 8)")
    p.add_argument("--samples", type=float, default=1e9, help="angles of the run priced")
    p.add_argument("--run-members", type=int, default=16384,
                   help="members of the run priced (default 16384, the command's)")
    p.add_argument("--t-transient", type=float, default=100.0)
    a = p.parse_args(argv)
    T = members_window(a.samples, a.run_members)
    print(f"{a.members} members x T = {T:g}, transient {a.t_transient:g}, one core "
          f"(the window of {a.samples:.0e} angles over {a.run_members} members)")
    print(f"{'N':>2} {'CPU s':>7} {'wall s':>7} {'µs/angle':>9} {'µs/time unit':>13} "
          f"{'core-h for the run':>19}")
    for n in a.n:
        S = RotorSystem(n)
        kw = dict(t_transient=a.t_transient, workers=1)
        hyperbolicity_tally(S, 2, 1.0, **dict(kw, t_transient=1.0))     # compiled here
        c0, w0 = time.process_time(), time.perf_counter()
        tally = hyperbolicity_tally(S, a.members, T, **kw)
        cpu, wall = time.process_time() - c0, time.perf_counter() - w0
        angles = int(tally.n.sum())
        units = a.members * (2 * T + 3 * a.t_transient)        # both passes, integrated
        run = cpu / a.members * a.run_members / 3600
        print(f"{n:2d} {cpu:7.2f} {wall:7.2f} {1e6 * cpu / angles:9.3f} "
              f"{1e6 * cpu / units:13.3f} {run:19.2f}", flush=True)


if __name__ == "__main__":
    main()
