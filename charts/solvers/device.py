"""Tangent flows on a GPU: one CUDA thread per trajectory, each running the one time loop.

Every thread advances one `TangentFlow`'s state and k tangent vectors by ``stacked_loop`` of
``charts.solvers.tangent`` — the loop of every CPU analysis, with its RK4 step, its
equations (``charts.flows.ambient``), its step policy, its projection and its
re-orthonormalisation — compiled by Numba for the CUDA target instead of the CPU: no
formula is written a second time here.  The loop allocates nothing; its work arrays are the
thread's local memory (sizes fixed per (N, k), so each (N, k) compiles its own kernel, in
seconds).  `member_advance` is what one thread does (load its member, run the loop, store it
back, flag a stop); the CUDA kernel calls it for the thread's member and `cpu_members` for
every member in turn, so the device driver's logic runs and is tested without a GPU.

Differences from the CPU lanes, stated: the GPU's compiler contracts a·b + c into fused
multiply-adds and its libm (libdevice) rounds sin, cos and log its own way, so a member's
bits differ from the CPU's; the exponents agree to rounding that chaos amplifies over the run
(tests/test_device.py on the CPU twin: bit for bit; ``charts bench gpu`` on a GPU).

`DeviceFlows` keeps the members' arrays on the device between calls, with the interface of
``charts.solvers.lanes.LaneFlows`` (``advance``, ``logsum``, ``steps``, ``stopped_lanes``,
``error``), so the Lyapunov drivers run on either unchanged.
"""
from __future__ import annotations

import functools

import numpy as np
from ..jit import njit

from .status import RUNNING, status_error
from .driver import Phases
from .tangent import (Records, Rotors, Stack, Stepping, memory_budget, stacked_loop,
                      tangent_vectors_rate)

__all__ = ["DeviceFlows", "DeviceUnavailable", "cuda_module", "cuda_available",
           "member_advance", "member_stops", "device_bytes", "DeviceArrays", "flow_states", "load_member", "store_member", "cpu_members", "resolve_device", "cuda_kernel", "kernel_function",
           "THREADS_PER_BLOCK"]

#: Threads per CUDA block (one trajectory each); their local memory, not registers, bounds
#: how many run at once.
THREADS_PER_BLOCK = 64


#: Numba's CUDA module once `cuda_module` found it usable (a global, not a closure variable,
#: so that Numba's CUDA simulator can stand in for it inside the kernel).
cuda = None


class DeviceUnavailable(RuntimeError):
    """device="cuda" was asked for where no usable CUDA GPU or toolkit is."""


def cuda_module():
    """Numba's CUDA target (``numba.cuda``), usable: a GPU with its driver is present.
    Raises `DeviceUnavailable` naming what is missing (the ``charts[gpu]`` extra, the
    driver, the GPU)."""
    global cuda
    if not hasattr(np, "row_stack"):     # numba-cuda 0.30 imports it; NumPy 2.5 removed it
        np.row_stack = np.vstack
    try:
        from numba import cuda as module
    except ImportError as e:             # pragma: no cover - depends on the installation
        raise DeviceUnavailable(f"device='cuda' needs Numba's CUDA target "
                                f"(pip install 'charts[gpu]'): {e}") from e
    try:
        ok = module.is_available()
    except Exception as e:               # pragma: no cover - driver errors vary
        raise DeviceUnavailable(f"device='cuda': the CUDA driver failed: {e}") from e
    if not ok:
        raise DeviceUnavailable("device='cuda' needs an NVIDIA GPU with its driver and the "
                                "CUDA toolkit (pip install 'charts[gpu]'); none was found "
                                "here. Use device='cpu' (or 'auto')")
    cuda = module
    return module


def cuda_available() -> bool:
    """Whether `cuda_module` would succeed (a GPU is present and usable)."""
    try:
        cuda_module()
    except DeviceUnavailable:
        return False
    return True


def resolve_device(device) -> str:
    """``"cpu"`` or ``"cuda"`` for the argument ``device`` ("cpu", "cuda" or "auto": the GPU
    when there is one); "cuda" without a GPU raises `DeviceUnavailable`."""
    if not isinstance(device, str) or device not in ("cpu", "cuda", "auto"):
        raise ValueError(f"device must be 'cpu', 'cuda' or 'auto', got {device!r}")
    if device == "auto":
        return "cuda" if cuda_available() else "cpu"
    if device == "cuda":
        cuda_module()
    return device


@njit(cache=True, inline="always")
def member_advance(l, Zs, scs, counters, status, stopped, minv, m, wts, level, speeds, dt,
                   nsteps, reorth_every, w, restricted, project_every, logsums, events,
                   event_logs, shares, Z, sc, counter, logsum, rec, work):
    """What one GPU thread does: member l (Zs: (L, 1 + k, 2N), scs: (L, 2, N), counters,
    status, stopped: (L,), logsums: (L, k)) copied into the work arrays Z, sc, counter,
    logsum (``work``: the loop's work arrays, see `stacked_loop`), advanced ``nsteps`` steps by `stacked_loop` with eq (17)'s hook, copied back; a
    member that stops is flagged in ``status`` with its global step in ``stopped`` and keeps
    the state at the start of the failing step (as `LaneFlows` freezes it); a stopped member
    is left alone.  At the global steps ``events`` (all after the counter) the log-norm sums
    go to event_logs[l, e]; the largest kinetic-energy shares to the member's histogram
    shares[l] (shares: (L, bins), bins 0: none).  ``rec``: a (1, 1) array, never written
    (no records)."""
    if status[l] != RUNNING:
        return
    load_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum)
    code, done = stacked_loop(Stack(Z, sc, counter, logsum, shares[l]),
                              Rotors(minv, m, wts, level), Stepping(speeds[l], dt, w, restricted),
                              Phases(project_every, reorth_every, 0, 0),
                              Records(rec, events, event_logs[l]), nsteps, tangent_vectors_rate,
                              work)
    store_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum, code, status, stopped)


@njit(cache=True, inline="always")
def load_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum):
    """Member l's flow — stacked state Zs[l], sin/cos scs[l], step counter counters[l],
    log-norm sums logsums[l] — into a thread's work arrays Z, sc, counter, logsum."""
    R, d = Z.shape
    for i in range(R):
        for j in range(d):
            Z[i, j] = Zs[l, i, j]
    for j in range(d // 2):
        sc[0, j] = scs[l, 0, j]
        sc[1, j] = scs[l, 1, j]
    for r in range(R - 1):
        logsum[r] = logsums[l, r]
    counter[0] = counters[l]


@njit(cache=True, inline="always")
def store_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum, code, status, stopped):
    """The reverse of `load_member`; a loop status ``code`` other than RUNNING flags member l
    (its global step in ``stopped``)."""
    R, d = Z.shape
    for i in range(R):
        for j in range(d):
            Zs[l, i, j] = Z[i, j]
    for j in range(d // 2):
        scs[l, 0, j] = sc[0, j]
        scs[l, 1, j] = sc[1, j]
    for r in range(R - 1):
        logsums[l, r] = logsum[r]
    counters[l] = counter[0]
    if code != RUNNING:
        status[l] = code
        stopped[l] = counter[0]


@njit(cache=True)
def cpu_members(Zs, scs, counters, status, stopped, minv, m, wts, level, speeds, dt, nsteps,
                reorth_every, w, restricted, project_every, logsums, events, event_logs, shares):
    """The CUDA kernel's work done on the CPU, member after member, each with its own work
    arrays: the device driver's logic without a GPU (tests; the CPU routes themselves are
    `TangentFlow` and `LaneFlows`)."""
    L, R, d = Zs.shape
    n = d // 2
    D = R * d
    for l in range(L):
        member_advance(l, Zs, scs, counters, status, stopped, minv, m, wts, level, speeds, dt,
                       nsteps, reorth_every, w, restricted, project_every, logsums, events,
                       event_logs, shares, np.empty((R, d)), np.empty((2, n)),
                       np.empty(1, dtype=np.int64), np.empty(R - 1), np.empty((1, 1)),
                       (np.empty(D), np.empty(4 * D), np.empty(n), np.empty(n), np.empty(n),
                        np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)))


@functools.lru_cache(maxsize=None)
def cuda_kernel(n, k):
    """The CUDA kernel of `member_advance` for N = n rotors and k vectors, one thread per
    member (`kernel_function`); compiled at its first launch."""
    return cuda_module().jit(kernel_function(n, k))


def kernel_function(n, k):
    """The Python function of the CUDA kernel for N = n and k vectors: its local arrays have
    these sizes (``numba.cuda.compile_ptx`` compiles it without a GPU, once the module
    global ``cuda`` is set)."""
    from numba import float64, int64

    R, d = k + 1, 2 * n
    D = R * d
    D4 = 4 * D                           # sizes: constants of the closure, not expressions

    def kernel(Zs, scs, counters, status, stopped, minv, m, wts, level, speeds, dt, nsteps,
               reorth_every, w, restricted, project_every, logsums, events, event_logs, shares):
        l = cuda.grid(1)
        if l >= Zs.shape[0]:
            return
        member_advance(l, Zs, scs, counters, status, stopped, minv, m, wts, level, speeds, dt,
                       nsteps, reorth_every, w, restricted, project_every, logsums, events,
                       event_logs, shares, cuda.local.array((R, d), float64),
                       cuda.local.array((2, n), float64), cuda.local.array(1, int64),
                       cuda.local.array(k, float64), cuda.local.array((1, 1), float64),
                       (cuda.local.array(D, float64), cuda.local.array(D4, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64),
                        cuda.local.array(n, float64), cuda.local.array(n, float64)))

    return kernel


def member_stops(arr, dev, seeds, dt, where):
    """[(member index, seed, time, error)] of the members of a device route that stopped, in
    member order, from its ``status`` and ``stopped`` arrays (``dev``, where ``arr`` keeps
    them): each error the one the CPU route raises, ``where(l)`` naming the route and member
    l."""
    status = arr.get(dev["status"])
    bad = np.flatnonzero(status != RUNNING)
    if not bad.size:
        return []
    stopped = arr.get(dev["stopped"])
    return [(int(l), int(seeds[l]), float(stopped[l] * dt),
             status_error(int(status[l]), int(stopped[l]) * dt, where(l))) for l in bad]


class DeviceArrays:
    """The members' arrays on the GPU (``backend="cuda"``) or in host memory (``"cpu"``, the
    twin): one place for what the two drivers (`DeviceFlows`, the angle test's
    ``charts.analyses.angle_blocks``) move between host and device."""

    def __init__(self, backend):
        if backend not in ("cuda", "cpu"):
            raise ValueError(f"backend must be 'cuda' or 'cpu', got {backend!r}")
        self.backend = backend
        self.cuda = cuda_module() if backend == "cuda" else None

    def budget(self) -> int:
        """The bytes the members' stores may take by default: half the GPU's free memory,
        or on the CPU twin ``charts.solvers.tangent.memory_budget``."""
        if self.cuda is None:
            return memory_budget()
        return self.cuda.current_context().get_memory_info()[0] // 2

    def put(self, a):
        """A contiguous copy of the host array ``a`` where the members live."""
        a = np.ascontiguousarray(a)
        return self.cuda.to_device(a) if self.cuda else a.copy()

    def get(self, a):
        """``a`` as a host array."""
        return a.copy_to_host() if self.cuda else a

    def copy(self, a):
        """A copy of ``a`` where it lives."""
        if self.cuda is None:
            return a.copy()
        b = self.cuda.device_array_like(a)
        b.copy_to_device(a)
        return b


def flow_states(flows):
    """(Zs (L, 1 + k, 2N), scs (L, 2, N), speeds (L,)): the `TangentFlow` s' states in the
    form `DeviceFlows` and the angle test's device driver take them."""
    return (np.stack([f.Z for f in flows]), np.stack([f.sc for f in flows]),
            np.array([f.speed for f in flows]))


def device_bytes(n, k, share_bins=0) -> int:
    """Bytes one member of `DeviceFlows` holds on the GPU: its stacked state (1 + k)·2N,
    sin/cos 2N, log-norm sums k, speed, counter, status and stop step, and its histogram of
    energy shares (``share_bins``)."""
    return 8 * ((1 + k) * 2 * n + 2 * n + k + 4 + share_bins)


_NO_EVENTS = np.empty(0, dtype=np.int64)


class DeviceFlows:
    """L tangent flows of one system and one set of settings, each advanced by its own GPU
    thread (``backend="cuda"``) or by `cpu_members` (``backend="cpu"``: the same logic, for
    tests).  The interface of ``charts.solvers.lanes.LaneFlows``: ``logsum`` (L, k) is a host
    array that the caller may reset between calls (it is sent to the device at each
    `advance` and read back after it); the stacked states stay on the device (`lane`).

    Parameters
    ----------
    system : RotorSystem
    states : (Zs, scs, speeds)
        The members' stacked states (L, 1 + k, 2N), weighted sin/cos (L, 2, N) and speeds
        (L,), as `TangentFlow` holds them (`of_flows`), none advanced.
    dt, w, restricted, reorth_every, project_every, share_bins
        The settings of `TangentFlow`, shared by all members (``shares`` (L, share_bins):
        the members' histograms of the largest energy share, a host array like ``logsum``).
    threads : int, optional
        Threads per CUDA block (default `THREADS_PER_BLOCK`).
    """

    def __init__(self, system, states, *, dt, w, restricted, reorth_every, project_every,
                 share_bins=0, backend="cuda", threads=None):
        Zs, scs, speeds = (np.ascontiguousarray(a, dtype=float) for a in states)
        L, R, d = Zs.shape
        if d != 2 * system.n or scs.shape != (L, 2, system.n) or speeds.shape != (L,):
            raise ValueError(f"states of shapes {Zs.shape}, {scs.shape}, {speeds.shape} do not "
                             f"fit N = {system.n}")
        self.system, self.dt, self.w = system, float(dt), np.ascontiguousarray(w, dtype=float)
        self.restricted, self.reorth_every = bool(restricted), int(reorth_every)
        self.project_every = int(project_every)
        self.backend = backend
        self.threads = THREADS_PER_BLOCK if threads is None else int(threads)
        self.shape = (L, R, d)
        self.speed = speeds
        host = {"Zs": Zs, "scs": scs, "counters": np.zeros(L, dtype=np.int64),
                "status": np.full(L, RUNNING, dtype=np.int64),
                "stopped": np.zeros(L, dtype=np.int64), "speeds": speeds}
        consts = {"minv": system.minv, "m": system.masses, "wts": system.weights, "w": self.w}
        consts = {k: np.asarray(v, dtype=float) for k, v in consts.items()}
        self.logsum = np.zeros((L, R - 1))
        self.shares = np.zeros((L, int(share_bins)), dtype=np.int64)
        self._steps = 0
        self._arr = DeviceArrays(backend)
        if backend == "cuda":
            self._kernel = cuda_kernel(int(system.n), R - 1)
        self._dev = {k: self._arr.put(v) for k, v in {**host, **consts}.items()}

    @classmethod
    def of_flows(cls, flows, backend="cuda"):
        """The `DeviceFlows` of `TangentFlow` s (checked as `LaneFlows` checks them)."""
        from .lanes import LaneFlows
        p = LaneFlows(flows)
        L = len(p.speed)
        Zs = p.Z.T.reshape(L, *flows[0].Z.shape)
        return cls(p.system, (Zs, np.moveaxis(p.sc, 2, 0), p.speed), dt=p.dt, w=p.w,
                   restricted=p.restricted, reorth_every=p.reorth_every,
                   project_every=p.project_every, share_bins=p.shares.shape[1],
                   backend=backend)

    @property
    def steps(self) -> int:
        return self._steps

    def _host(self, name):
        return self._arr.get(self._dev[name])

    @property
    def status(self):
        return self._host("status")

    def lane(self, l):
        """Member l's stacked state Z, shape (1 + k, 2N) (a copy)."""
        return np.array(self._host("Zs")[l])

    def store(self, l, flow) -> None:
        """Member l's whole state (stacked state, sin/cos, step counter, log-norm sums, energy
        shares) into the `TangentFlow` ``flow``, as ``LaneFlows.store`` does."""
        flow.load_state({"Z": self.lane(l), "sc": np.array(self._host("scs")[l]),
                         "counter": np.array(self._host("counters")[l:l + 1]),
                         "logsum": self.logsum[l].copy(), "shares": self.shares[l].copy()})

    def advance(self, nsteps, *, events=None, event_logs=None) -> int:
        """Advance every running member ``nsteps`` steps; at the global steps ``events``
        (sorted), store its log-norm sums in ``event_logs`` (E, L, k).  Returns the number
        of running members (see `error` for the others)."""
        nsteps = int(nsteps)
        L, R, _ = self.shape
        start, end = self._steps, self._steps + nsteps
        if events is None:
            events, lo, hi = _NO_EVENTS, 0, 0
        else:
            events = np.asarray(events, dtype=np.int64)
            lo, hi = np.searchsorted(events, [start + 1, end + 1])
        chunk = np.ascontiguousarray(events[lo:hi])
        logs = np.zeros((L, hi - lo, R - 1))
        sys_ = self.system
        dev = self._dev
        if self.backend == "cuda":
            arr = self._arr
            dev["logsums"] = arr.put(self.logsum)
            d_shares = arr.put(self.shares)
            d_events, d_logs = arr.put(chunk), arr.put(logs)
            blocks = -(-L // self.threads)
            self._kernel[blocks, self.threads](
                dev["Zs"], dev["scs"], dev["counters"], dev["status"], dev["stopped"],
                dev["minv"], dev["m"], dev["wts"], float(sys_.level), dev["speeds"],
                self.dt, nsteps, self.reorth_every, dev["w"], self.restricted, self.project_every,
                dev["logsums"], d_events, d_logs, d_shares)
            arr.cuda.synchronize()
            self.logsum[...] = arr.get(dev["logsums"])
            self.shares[...] = arr.get(d_shares)
            logs = arr.get(d_logs)
        else:
            dev["logsums"] = self.logsum
            cpu_members(dev["Zs"], dev["scs"], dev["counters"], dev["status"], dev["stopped"],
                        dev["minv"], dev["m"], dev["wts"], float(sys_.level), dev["speeds"],
                        self.dt, nsteps, self.reorth_every, dev["w"], self.restricted,
                        self.project_every, self.logsum, chunk, logs, self.shares)
        if event_logs is not None and hi > lo:
            event_logs[lo:hi] = np.moveaxis(logs, 1, 0)
        self._steps = end
        return int(np.count_nonzero(self.status == RUNNING))

    def stopped_lanes(self):
        """The members that stopped (see `error`), in order."""
        return [int(l) for l in np.flatnonzero(self.status != RUNNING)]

    def error(self, l, where):
        """The exception `TangentFlow.advance` raises for the stopped member l."""
        return status_error(int(self.status[l]), int(self._host("stopped")[l]) * self.dt, where)

