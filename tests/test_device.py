"""The GPU route's logic without a GPU (``charts.solvers.device``).

What a GPU thread does (`member_advance`: load a member, run the one time loop, store it,
flag a stop) runs here member by member (`cpu_members`), and the CUDA kernel's own Python
body runs with a stand-in for ``numba.cuda`` (grid index and local arrays); both must give
the lanes' (``charts.solvers.lanes``) bits exactly — the same loop and equations in the same
order.  On a GPU the bits differ by fused multiply-adds and libm (``charts bench gpu``)."""
import types

import numpy as np
import pytest

import charts
import charts.solvers.device as device
from charts.analyses.lyapunov import lyapunov_settings
from charts.analyses.lyapunov_members import lyapunov_device, lyapunov_ensemble
from charts.geometry.energy_shares import SHARE_BINS
from charts.geometry.system import RotorSystem
from charts.runs.benchmarks.gpu import kernel_rate
from charts.solvers.device import DeviceFlows, DeviceUnavailable, cuda_available
from charts.solvers.lanes import LaneFlows
from charts.solvers.status import NONFINITE, RUNNING, SINGULAR
from charts.solvers.tangent import TangentFlow

SYSTEM = RotorSystem(4, [1.0, 1.5, 1.0, 0.7], weights=[1.0, 2.0, 1.5, 1.0], level=0.4)
# the N = 4 geodesic aimed exactly through the singular point (0, 0, π, π) (tests/test_lanes.py)
_A, _B = 0.42426406871192845, 0.565685424949238
THROUGH = (np.array([0.0, 0.0, np.pi, np.pi]) - np.array([_A, _B, _A, _B]),
           np.array([_A, _B, _A, _B]))


def _flows(system, states, k, share_bins=SHARE_BINS):
    return [TangentFlow(system, th, u, k, dt=0.01, reorth_every=10, project_every=100, seed=s,
                        share_bins=share_bins) for s, (th, u) in enumerate(states)]


def _run(flows, chunks, events):
    logs = np.zeros((len(events), len(flows.logsum), flows.logsum.shape[1]))
    for c in chunks:
        flows.advance(c, events=events, event_logs=logs)
    return logs


def test_the_cpu_twin_equals_the_lanes_bit_for_bit():
    """Five members of a weighted family with a level, k = 3, in uneven chunks with events
    inside and at the chunk ends: states, log-norm sums, event logs and energy-share
    histograms identical."""
    states = [SYSTEM.random_state(seed=s) for s in range(5)]
    events = np.array([1, 10, 100, 250, 449])
    lanes = LaneFlows(_flows(SYSTEM, states, 3))
    twin = DeviceFlows.of_flows(_flows(SYSTEM, states, 3), backend="cpu")
    a, b = _run(lanes, (1, 99, 350), events), _run(twin, (100, 149, 201), events)
    assert np.array_equal(a, b) and a[-1].any()
    assert np.array_equal(lanes.logsum, twin.logsum)
    assert np.array_equal(lanes.shares, twin.shares) and twin.shares.sum() == 5 * 45
    for i in range(5):
        assert np.array_equal(lanes.lane(i), twin.lane(i))
    assert twin.steps == 450


def test_the_kernel_body_with_a_stand_in_for_cuda(monkeypatch):
    """The CUDA kernel's Python function, each thread index in turn and numpy arrays for its
    local memory: the same bits as the CPU twin (its grid guard, local array shapes and
    argument order are what the GPU runs)."""
    state = {"l": 0}
    fake = types.SimpleNamespace(grid=lambda dim: state["l"],
                                 local=types.SimpleNamespace(
                                     array=lambda shape, dtype: np.empty(shape, dtype=np.dtype(str(dtype)))))
    monkeypatch.setattr(device, "cuda", fake)
    system = RotorSystem(3)
    states = [system.random_state(seed=s) for s in range(3)]
    twin = DeviceFlows.of_flows(_flows(system, states, 2), backend="cpu")
    ref = DeviceFlows.of_flows(_flows(system, states, 2), backend="cpu")
    kernel = device.kernel_function(3, 2)
    d = twin._dev
    events, logs = np.array([30]), np.zeros((3, 1, 2))
    for l in range(4):                      # one index past the members: the guard
        state["l"] = l
        kernel(d["Zs"], d["scs"], d["counters"], d["status"], d["stopped"], d["minv"], d["m"],
               d["wts"], 0.0, d["speeds"], 0.01, 60, 10, d["w"], True, 100, twin.logsum,
               events, logs, twin.shares)
    ref_logs = np.zeros((1, 3, 2))
    ref.advance(60, events=events, event_logs=ref_logs)
    assert np.array_equal(twin.logsum, ref.logsum)
    assert np.array_equal(twin.shares, ref.shares) and twin.shares.sum() == 3 * 6
    assert np.array_equal(np.moveaxis(logs, 1, 0), ref_logs)
    assert all(np.array_equal(twin.lane(i), ref.lane(i)) for i in range(3))


def test_a_stopping_member_is_flagged_and_frozen_like_a_lane():
    """Member 1 runs into the singular point, member 3 starts with a NaN velocity: status,
    error and frozen state as the lanes give them; the others go on, bit for bit."""
    system = RotorSystem(4)
    states = [system.random_state(seed=1), THROUGH, system.random_state(seed=2),
              system.random_state(seed=3)]
    fl = _flows(system, states, 2), _flows(system, states, 2)
    for f in fl:
        f[3].Z[0, system.n] = np.nan
    lanes, twin = LaneFlows(fl[0]), DeviceFlows.of_flows(fl[1], backend="cpu")
    assert lanes.advance(300) == twin.advance(300) == 2
    assert twin.stopped_lanes() == [1, 3]
    assert list(twin.status) == [RUNNING, SINGULAR, RUNNING, NONFINITE]
    for i in range(4):
        assert np.array_equal(lanes.lane(i), twin.lane(i), equal_nan=True)
    for i in (1, 3):
        a, b = lanes.error(i, "RK4"), twin.error(i, "RK4")
        assert type(a) is type(b) and str(a) == str(b)
    frozen = [twin.lane(i) for i in (1, 3)]
    twin.advance(20)
    assert all(np.array_equal(twin.lane(i), f, equal_nan=True) for i, f in zip((1, 3), frozen))


def test_device_members_equal_the_ensemble_members():
    """`lyapunov_device` (the GPU driver, its states built in two processes) on the CPU twin
    gives `lyapunov_ensemble`'s members: exponents, errors, history and settings."""
    kw = dict(t_transient=2.0, n_batches=4, record_every=2.0)
    ens = lyapunov_ensemble(SYSTEM, 4, 8.0, seed=7, workers=1, speed=1.3, lanes=True, **kw)
    cfg = lyapunov_settings(SYSTEM, 8.0, seed=7, **kw)
    got = lyapunov_device((SYSTEM, cfg, [7, 8, 9, 10], 1.3), backend="cpu", workers=2)
    for i, (m, r) in enumerate(zip(ens.members, got)):
        for a in ("exponents", "stderr", "batches", "history", "history_t"):
            assert np.array_equal(getattr(m, a), getattr(r, a)), a
        assert m.params == {**r.params, "state_seed": 7 + i}     # the ensemble drew the state


@pytest.mark.skipif(cuda_available(), reason="this machine has a GPU")
def test_the_device_argument_without_a_gpu():
    with pytest.raises(DeviceUnavailable, match="needs an NVIDIA GPU.*charts\\[gpu\\]"):
        lyapunov_ensemble(RotorSystem(3), 2, 1.0, device="cuda")
    with pytest.raises(ValueError, match="device must be 'cpu', 'cuda' or 'auto'"):
        lyapunov_ensemble(RotorSystem(3), 2, 1.0, device="gpu")
    auto = lyapunov_ensemble(RotorSystem(3), 3, 2.0, device="auto", workers=1, n_batches=2)
    cpu = lyapunov_ensemble(RotorSystem(3), 3, 2.0, workers=1, n_batches=2)
    assert np.array_equal(auto.exponents, cpu.exponents)


def test_the_benchmark_rows_run_on_the_twin():
    setup, compile_s, run, rate = kernel_rate(3, 1, 4, 1.0, 1, repeat=1, backend="cpu")
    assert min(setup, compile_s, run) >= 0 and rate > 0


def test_members_of_another_size_are_refused():
    th, u = RotorSystem(3).random_state(seed=0)
    flows = _flows(RotorSystem(3), [(th, u)], 1)
    Z = flows[0].Z[None]
    with pytest.raises(ValueError, match="do not fit N = 4"):
        DeviceFlows(RotorSystem(4), (Z, flows[0].sc[None], np.ones(1)), dt=0.01,
                    w=np.ones(6), restricted=True, reorth_every=10, project_every=100,
                    backend="cpu")
    assert issubclass(DeviceUnavailable, RuntimeError) and charts is not None


def test_the_angle_rows_run_on_the_cpu_route():
    from charts.runs.benchmarks.gpu import angle_rate
    wall, window, integrated = angle_rate(3, 2, 2.0, 1.0, 1, backend="cpu")
    assert wall > 0 and integrated > window > 0


def test_the_clv_rows_run_on_the_twin():
    from charts.runs.benchmarks.gpu import clv_rate
    wall, window = clv_rate(3, 2, 2.0, 1.0, 1, backend="cpu")
    assert wall > 0 and window > 0


def test_ensembles_too_large_for_memory_are_refused_before_they_start():
    """10⁹ members (the most an ensemble takes): refused at once with the bytes and the
    remedy, on every route that keeps per-member results; more members are refused by count."""
    from charts.analyses.hyperbolicity import hyperbolicity_ensemble
    from charts.analyses.tally_run import hyperbolicity_tally
    S = RotorSystem(4)
    with pytest.raises(ValueError, match=r"results of 1000000000 members .* GiB.*fewer members"):
        lyapunov_ensemble(S, 10**9, 100.0)
    with pytest.raises(ValueError, match=r"angles of 1000000000 members .* GiB"):
        hyperbolicity_ensemble(S, 10**9, 100.0)
    with pytest.raises(ValueError, match=r"sums of a tally of 1000000000 members need \d+\.\d GiB"
                                         r".*fewer members"):
        hyperbolicity_tally(S, 10**9, 100.0)
    with pytest.raises(ValueError, match=r"results of 1000000000 members \(1000 samples each\) "
                                         r"need \d+\.\d GiB.*fewer members"):
        charts.covariant_ensemble(S, 10**9, 100.0)
    with pytest.raises(ValueError, match=r"results of 1000000000 members over t_final=100 need "
                                         r"\d+\.\d GiB.*run fewer members"):
        charts.linkage_ensemble(charts.LinkageSystem(0.1), 10**9, 100.0)
    with pytest.raises(ValueError, match=r"n_trajectories must be an integer in 2\.\.1000000000"):
        lyapunov_ensemble(S, 10**12, 100.0)


def test_the_states_compile_once_before_the_workers(monkeypatch):
    """The members' initial states are built in processes; the first seed's is built here
    first (``prime``), so that the workers load its kernels instead of each compiling them."""
    import charts.analyses.ensemble as ensemble
    seen = {}

    def fake(fn, jobs, sizes, workers, t_final, progress, desc, prime=None, name=None, n=None):
        seen.update(prime=prime, name=name, n=n)
        return [fn(job) for job in jobs]

    def states_of(job):
        system, cfg, seeds, speed = job
        return [np.array(seeds, float), np.array(seeds, float), np.array(seeds, float)]
    monkeypatch.setattr(ensemble, "map_jobs", fake)
    out = ensemble.member_states_of(states_of, RotorSystem(4), None, [5, 6, 7], 1.0, 2)
    assert out[0].tolist() == [5.0, 6.0, 7.0]
    assert seen["prime"][0] is states_of and seen["prime"][1][2] == [5]
    assert (seen["name"], seen["n"]) == ("states_of", 4)
