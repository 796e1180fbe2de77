"""Ensembles and the angle tally on a Dask cluster (docs/cluster.md).

``client=`` of `lyapunov_ensemble`, `hyperbolicity_ensemble`, `covariant_ensemble`,
`linkage_ensemble` and `hyperbolicity_tally` follows ``charts sweep``'s convention:

* a ``dask.distributed.Client``: the caller's, left open;
* a scheduler's address (``tcp://host:8786``, as ``--scheduler``): a client of that cluster for
  the call; its workers are its own (``workers`` must then be None);
* ``"local"``: a new LocalCluster of ``workers`` single-threaded processes (default: every
  core) for the call, as ``charts sweep`` without ``--scheduler``;
* a Dask cluster object (``LocalCluster(...)``, a batch system's): a client of it for the call.

`cluster_pool` turns it into a ``concurrent.futures`` executor (``Client.get_executor``) that
``charts.analyses.ensemble.map_jobs`` fans the jobs out to, as it does a process pool: the
results in order, the workers' compile seconds announced here, the progress here.  The
connection itself (`dask_client`, `check_scheduler_address`, `sigint_held`) is the sweeps'
(``charts.runs.sweep`` calls it), kept in the lowest layer that needs it.  Dask is imported
only when a cluster is asked for.
"""
from __future__ import annotations

import contextlib
import logging
import os
import signal
import threading

from .arguments import positive_int

__all__ = ["cluster_pool", "cluster_device", "dask_client", "check_scheduler_address",
           "sigint_held", "ClusterError", "LOCAL", "SCHEDULER_TIMEOUT_S"]

#: How long a client waits for an existing scheduler before the call fails.
SCHEDULER_TIMEOUT_S = 10
#: ``client=LOCAL``: a new LocalCluster of ``workers`` processes for the call.
LOCAL = "local"


class ClusterError(ValueError):
    """A cluster that cannot be used: a malformed address, an unreachable scheduler, options
    that do not go together.  The message names the value."""


def check_scheduler_address(scheduler, error=ClusterError, name="--scheduler ") -> str:
    """``scheduler`` if it is a well-formed Dask address (``tcp://host:port``, ``host:port``);
    ``error`` (a ValueError class) naming it, as ``name`` + its value, otherwise.  Called before
    any work."""
    from distributed.comm import parse_address, parse_host_port

    try:
        if not isinstance(scheduler, str) or not scheduler.strip():
            raise ValueError("empty")
        proto, loc = parse_address(scheduler)
        if proto in ("tcp", "tls", "ws", "wss"):
            parse_host_port(loc)
    except (ValueError, TypeError) as exc:
        raise error(f"{name}{scheduler!r} is not a Dask scheduler address ({exc}); "
                    "expected e.g. tcp://host:8786") from None
    return scheduler


def dask_client(scheduler, workers, error=ClusterError):
    """``(client, cluster)``: a client of the cluster at ``scheduler`` (cluster None), or of
    a new LocalCluster of ``workers`` single-threaded processes (default: every core); what
    goes wrong raises ``error`` (a ValueError class) with the remedy."""

    from dask.distributed import Client, LocalCluster

    if scheduler:
        if workers:
            raise error("--workers applies to the local cluster only; an existing cluster "
                        "(--scheduler) has its own workers")
        check_scheduler_address(scheduler, error)
        try:
            return Client(scheduler, timeout=f"{SCHEDULER_TIMEOUT_S}s"), None
        except (OSError, TimeoutError, ValueError) as exc:
            raise error(f"cannot reach the Dask scheduler at {scheduler!r} within "
                        f"{SCHEDULER_TIMEOUT_S} s: {exc} (start "
                        "one with `dask scheduler`, workers with `dask worker ADDRESS`)") \
                from None
    n = (os.cpu_count() or 1) if workers is None else positive_int("workers", workers)
    client = cluster = None
    try:
        with sigint_held():
            # the workers' own logs only when critical: an interrupted sweep's teardown made
            # them print a semaphore release's traceback ("Is the connection unstable?") at
            # ERROR; a point that fails reaches the table through its future, with the
            # error's text.  No dashboard; the scheduler's HTTP server (health, metrics) on
            # a free port of this host: without an address it tries 8787 and warns "Port
            # 8787 is already in use" whenever another Dask cluster runs here
            cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                   dashboard_address="127.0.0.1:0",
                                   scheduler_kwargs={"dashboard": False},
                                   silence_logs=logging.CRITICAL)
            client = Client(cluster)
    except BaseException:           # a Ctrl-C while the cluster started: nothing left open
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
        raise
    return client, cluster


@contextlib.contextmanager
def sigint_held():
    """Ctrl-C held back while the local cluster starts, and delivered when it has.

    The worker processes must not take Ctrl-C (every one would print a KeyboardInterrupt
    traceback): the main process reports the interrupt and closes the cluster.  So SIGINT
    is blocked in this thread while the cluster starts, and with it in the threads started
    meanwhile and in the processes those spawn (a signal mask survives both), the workers
    among them.  A Ctrl-C pressed meanwhile reaches the process anyway, as pending or by a
    thread that was already running (e.g. the one NumPy's OpenBLAS starts at import): the
    handler installed here notes it, and once the previous handler is back the signal is
    raised again, so a Ctrl-C during the start interrupts the run instead of being lost.
    Without ``pthread_sigmask`` (Windows) SIGINT is ignored meanwhile instead, a disposition
    the workers inherit.  Outside the main thread nothing changes (no handler can be set)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    if not hasattr(signal, "pthread_sigmask"):
        old = signal.signal(signal.SIGINT, signal.SIG_IGN)
        try:
            yield
        finally:
            signal.signal(signal.SIGINT, old)
        return
    # multiprocessing's resource tracker, started by the first semaphore of a worker's
    # queue, unblocks SIGINT in the thread that starts it (the cluster's event loop, whose
    # threads spawn the workers): started here, before, it leaves the mask alone
    from multiprocessing import resource_tracker

    resource_tracker.ensure_running()
    caught = []
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    old = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        yield
    finally:
        try:
            signal.signal(signal.SIGINT, old)
        finally:
            # a Ctrl-C pending for this thread is delivered (to ``old``) by this call
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
        if caught:
            signal.raise_signal(signal.SIGINT)


def cluster_device(device, client) -> str:
    """``device`` of an analysis called with ``client``: without one,
    ``charts.solvers.device.resolve_device``'s; with one the cluster's CPU workers run it
    ("auto" is "cpu" there), and "cuda" is refused (ValueError)."""
    from ..solvers.device import resolve_device

    if client is None:
        return resolve_device(device)
    if not isinstance(device, str) or device not in ("cpu", "auto"):
        raise ValueError(f"client= runs the members on the cluster's CPU workers; device must be "
                         f"'cpu' or 'auto' with it, got {device!r} (a GPU run: client=None, "
                         "device='cuda')")
    return "cpu"


def cluster_pool(client, workers=None):
    """A context manager giving ``(executor, slots)``: for ``client`` None, ``(None,
    workers)`` (the caller's own processes); otherwise a ``concurrent.futures`` executor of
    the cluster ``client`` names (module docstring) and its task slots (the workers' threads
    together, at least 1).  Jobs still queued or running when the block ends by an error or
    a Ctrl-C are cancelled; a client or cluster opened here is closed."""
    if client is None:
        return contextlib.nullcontext((None, workers))
    return _cluster_pool(client, workers)


@contextlib.contextmanager
def _cluster_pool(client, workers):
    from dask.distributed import Client
    from distributed.deploy import Cluster

    own = cluster = None
    if isinstance(client, Client) or isinstance(client, Cluster) or (
            isinstance(client, str) and client != LOCAL):
        if workers is not None:
            raise ClusterError(f"workers={workers!r} applies to a local cluster (client="
                               f"{LOCAL!r}) only; the cluster of client= has its own workers")
    if isinstance(client, Client):
        c = client
    elif isinstance(client, Cluster):
        c = own = Client(client)
    elif isinstance(client, str) and client == LOCAL:
        own, cluster = dask_client(None, workers)
        c = own
    elif isinstance(client, str):
        check_scheduler_address(client, name="client=")
        c = own = dask_client(client, None)[0]
    else:
        raise ClusterError(f"client must be a dask.distributed Client, a scheduler address "
                           f"(tcp://host:8786), {LOCAL!r} or a Dask cluster, got {client!r}")
    try:
        executor = c.get_executor(pure=False)      # every call its own tasks: never cached
        try:
            yield executor, max(1, sum(c.nthreads().values()))
        except BaseException:
            executor.shutdown(wait=False)          # cancels what is queued or running
            raise
    finally:
        if own is not None:
            own.close()
        if cluster is not None:
            cluster.close()
