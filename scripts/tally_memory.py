"""The caller's memory of `hyperbolicity_tally` as the run grows tenfold (docs/cluster.md).

Each configuration runs in a fresh Python process (so that its peak resident memory is its
own): N rotors, ``--members`` members, the window T and 10·T, on a LocalCluster of
``--workers`` processes (``client="local"``, the default route ``dask``) or in a local
process pool (``pool``); and for contrast `hyperbolicity_ensemble`, which brings every
member's angles back (``ensemble``).  Printed per run: the angles, the peak of the memory
Python allocated in the caller during the call (tracemalloc: NumPy's arrays included),
the caller's peak resident memory (ru_maxrss, the whole process: interpreter, libraries,
compiled kernels) and the wall time.

    python scripts/tally_memory.py                    # N = 4, 8 members, T = 10^4 and 10^5
    python scripts/tally_memory.py --routes dask pool ensemble --t 2000
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys

CHILD = r"""
import json, resource, sys, time, tracemalloc
from charts import RotorSystem
from charts.analyses.hyperbolicity import hyperbolicity_ensemble
from charts.analyses.tally_run import hyperbolicity_tally
route, n, members, T, workers = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
S = RotorSystem(n)
kw = dict(t_transient=10.0)
from dask.distributed import Client, LocalCluster
cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                       dashboard_address=None) if route != "pool" else None
client = Client(cluster) if cluster is not None else None
# the kernels compiled and the libraries imported before the measurement
hyperbolicity_tally(S, 2, 1.0, workers=1, **kw)
hyperbolicity_ensemble(S, 2, 1.0, workers=1, **kw)
tracemalloc.start()
t0 = time.perf_counter()
if route == "ensemble":
    ens = hyperbolicity_ensemble(S, members, T, client=client, **kw)
    angles = sum(m.phi_restricted.size for m in ens.members)
elif route == "dask":
    angles = int(hyperbolicity_tally(S, members, T, client=client, **kw).n.sum())
else:
    angles = int(hyperbolicity_tally(S, members, T, workers=workers, **kw).n.sum())
wall = time.perf_counter() - t0
peak = tracemalloc.get_traced_memory()[1]
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
print(json.dumps(dict(route=route, T=T, angles=angles, traced_peak=peak, max_rss=rss,
                      wall=wall)))
if client is not None:
    client.close(); cluster.close()
"""


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=4)
    p.add_argument("--members", type=int, default=8)
    p.add_argument("--t", type=float, default=1e4, help="the shorter window T (default 1e4)")
    p.add_argument("--factor", type=float, default=10.0, help="the longer window: T x this")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--routes", nargs="+", default=["dask"], choices=("dask", "pool", "ensemble"))
    a = p.parse_args(argv)
    print(f"N = {a.n}, {a.members} members, {a.workers} workers; caller's memory during the call")
    print(f"{'route':9} {'T':>9} {'angles':>11} {'traced peak':>12} {'max RSS':>9} {'wall':>7}")
    for route in a.routes:
        for T in (a.t, a.t * a.factor):
            out = subprocess.run([sys.executable, "-c", CHILD, route, str(a.n), str(a.members),
                                  str(T), str(a.workers)], capture_output=True, text=True)
            if out.returncode:
                sys.exit(out.stderr[-3000:])
            r = json.loads(out.stdout.strip().splitlines()[-1])
            print(f"{r['route']:9} {r['T']:9g} {r['angles']:11.3g} "
                  f"{r['traced_peak'] / 2**20:9.2f} MiB {r['max_rss'] / 2**20:5.0f} MiB "
                  f"{r['wall']:6.1f}s", flush=True)


if __name__ == "__main__":
    main()
