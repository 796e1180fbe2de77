"""Ensembles and the angle tally on a Dask cluster (``client=``, docs/cluster.md).

One LocalCluster of two single-threaded worker processes for the module:

* `lyapunov_ensemble`, `hyperbolicity_ensemble` and `hyperbolicity_tally` give, bit for bit,
  the numbers of the local route for the same seeds (a Client, a scheduler's address);
* a tally interrupted (Ctrl-C in the caller after its first chunk merged) goes on from its
  checkpoint on the cluster to the uninterrupted numbers;
* a worker killed (SIGKILL) while a tally's chunks run: the run finishes with the
  uninterrupted numbers (Dask runs the lost chunk again);
* what does not go together is refused before any work.
"""
from __future__ import annotations

import os
import signal

import numpy as np
import pytest

from charts import RotorSystem
from charts.analyses.angle_tally import SUMS
from charts.analyses.cluster import ClusterError, cluster_pool
from charts.analyses.hyperbolicity import hyperbolicity_ensemble
from charts.analyses.tally_run import hyperbolicity_tally
from charts.analyses.lyapunov_members import lyapunov_ensemble

distributed = pytest.importorskip("distributed")

S3 = RotorSystem(3)
#: short angle tests: a transient of 1, a window of 3 (30 samples per member)
ANGLES = dict(t_transient=1.0)


@pytest.fixture(scope="module")
def cluster():
    from dask.distributed import LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as c:
        yield c


@pytest.fixture(scope="module")
def client(cluster):
    from dask.distributed import Client
    with Client(cluster) as c:
        c.wait_for_workers(2)
        yield c


def _same_tally(a, b):
    for k in SUMS:
        assert np.array_equal(getattr(a, k), getattr(b, k)), k
    assert np.array_equal(a.seeds, b.seeds) and a.params == b.params


def test_lyapunov_ensemble_on_the_cluster_is_the_local_one(client):
    kw = dict(seed=3, t_transient=1.0, n_batches=2)
    here = lyapunov_ensemble(S3, 3, 4.0, workers=1, **kw)
    there = lyapunov_ensemble(S3, 3, 4.0, client=client, **kw)
    assert np.array_equal(there.exponents, here.exponents)
    assert np.array_equal(there.stderr, here.stderr)
    for a, b in zip(there.members, here.members):
        for f in ("exponents", "stderr", "history", "batches"):
            assert np.array_equal(getattr(a, f), getattr(b, f)), f
        assert a.params["state_seed"] == b.params["state_seed"]
        assert a.params["vectors_seed"] == b.params["vectors_seed"]
    assert there.params == here.params


def test_hyperbolicity_ensemble_on_the_cluster_by_its_address(cluster, client):
    here = hyperbolicity_ensemble(S3, 3, 3.0, seed=1, workers=1, **ANGLES)
    there = hyperbolicity_ensemble(S3, 3, 3.0, seed=1, client=cluster.scheduler_address,
                                   **ANGLES)
    for a, b in zip(there.members, here.members):
        for f in ("phi_full", "phi_restricted", "forward_exponents", "adjoint_exponents"):
            assert np.array_equal(getattr(a, f), getattr(b, f)), f
        assert a.params == b.params


def test_hyperbolicity_tally_on_the_cluster_is_the_local_one(client):
    here = hyperbolicity_tally(S3, 5, 3.0, seed=2, workers=1, **ANGLES)
    for chunk in (1, 2):                      # every route and chunk size: the same tally
        _same_tally(hyperbolicity_tally(S3, 5, 3.0, seed=2, client=client, chunk=chunk,
                                        **ANGLES), here)


def test_an_interrupted_tally_goes_on_from_its_checkpoint_on_the_cluster(client, tmp_path):
    pytest.importorskip("xarray")
    from charts import load
    whole = hyperbolicity_tally(S3, 6, 3.0, workers=1, **ANGLES)
    path = tmp_path / "partial.nc"

    def interrupt(done, total):             # after the first chunk merged and saved
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        hyperbolicity_tally(S3, 6, 3.0, client=client, chunk=2, checkpoint=path,
                            progress=interrupt, **ANGLES)
    assert load(path).params["members_done"] == 2
    _same_tally(hyperbolicity_tally(S3, 6, 3.0, client=client, chunk=2, checkpoint=path,
                                    **ANGLES), whole)
    assert not path.exists()


def test_a_worker_killed_during_a_tally_costs_its_chunk_not_the_numbers(client, tmp_path):
    """A worker process is killed (SIGKILL) as soon as the first chunk is merged and saved:
    the caller takes the chunks in seed order, so every later chunk is then running or
    done on a worker, its tally not yet fetched; the killed worker's are lost.  Its nanny
    starts a new one, Dask runs the lost chunks again, and the tally is the uninterrupted
    one."""
    kw = dict(seed=7, chunk=1, t_transient=1.0)
    T = 300.0
    whole = hyperbolicity_tally(S3, 8, T, workers=1, **kw)
    killed, lost = [], []

    def kill_a_busy_worker(done, total):
        if killed:
            return
        pids = client.run(os.getpid)
        held = {w: [*client.processing().get(w, ()), *client.has_what().get(w, ())]
                for w in pids}
        worker = max(held, key=lambda w: len(held[w]))
        assert held[worker], "no chunk on a worker after the first chunk was merged"
        lost.extend(held[worker])
        killed.append(pids[worker])
        os.kill(pids[worker], signal.SIGKILL)
    got = hyperbolicity_tally(S3, 8, T, client=client, checkpoint=tmp_path / "partial.nc",
                              progress=kill_a_busy_worker, **kw)
    assert killed
    # the scheduler took the chunks from the killed worker and ran them again elsewhere
    taken = [row[1] for row in client.story(*lost) if row[0] == "scheduler"
             and row[2] in ("processing", "memory") and row[3] == "released"]
    assert taken
    _same_tally(got, whole)
    client.wait_for_workers(2)              # the nanny's new worker, for the next tests


def test_what_does_not_go_together_is_refused(client):
    with pytest.raises(ValueError, match="device must be 'cpu' or 'auto'"):
        hyperbolicity_tally(S3, 2, 3.0, client=client, device="cuda")
    with pytest.raises(ClusterError, match="applies to a local cluster"):
        lyapunov_ensemble(S3, 2, 4.0, client=client, workers=2)
    with pytest.raises(ClusterError, match="is not a Dask scheduler address"):
        hyperbolicity_ensemble(S3, 2, 3.0, client="tcp://host:port", **ANGLES)
    with pytest.raises(ClusterError, match="client must be"):
        with cluster_pool(42):
            pass


def test_charts_verdict_statistics_on_a_scheduler_gives_the_local_numbers(cluster, tmp_path):
    from charts.cli.main import main
    args = ["verdict", "--statistics", "--n", "3", "--samples", "400", "--members", "3",
            "--t-transient", "1"]
    assert main(args + ["--device", "cpu", "--json", str(tmp_path / "here.json")]) == 0
    assert main(args + ["--scheduler", cluster.scheduler_address,
                        "--json", str(tmp_path / "there.json")]) == 0
    import json
    here, there = (json.loads((tmp_path / f).read_text()) for f in ("here.json", "there.json"))
    assert [r["statistics"] for r in there] == [r["statistics"] for r in here]
    assert main(args + ["--scheduler", "tcp://host:port"]) == 2
