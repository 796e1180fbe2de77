"""The lane kernel (``charts.solvers.lanes``) against the one-trajectory tangent kernel: every
lane does the same operations in the same order, so the comparison is exact (bit for bit,
tolerance 0), with masses, with the constraint family (weights, level), through chunking,
and with a lane that stops at a singular point or on a non-finite state beside lanes that
go on."""
import numpy as np
import pytest

import charts
from charts.analyses.lyapunov import lyapunov_spectrum
from charts.analyses.lyapunov_members import MIN_LANES, lyapunov_ensemble
from charts.geometry.system import RotorSystem
from charts.solvers.lanes import LaneFlows
from charts.solvers.status import NONFINITE, RUNNING, SINGULAR
from charts.solvers.tangent import TangentFlow

SYSTEMS = {
    "N=3": RotorSystem(3),
    "N=4 masses": RotorSystem(4, [1.0, 2.0, 0.5, 1.5]),
    "N=5": RotorSystem(5),
    "N=4 weights, level": RotorSystem(4, [1.0, 1.5, 1.0, 0.7], weights=[1.0, 2.0, 1.5, 1.0],
                                      level=0.4),
}


def _flows(system, states, k, seeds=None):
    seeds = range(len(states)) if seeds is None else seeds
    return [TangentFlow(system, th, u, k, dt=0.01, reorth_every=10, project_every=100, seed=s)
            for (th, u), s in zip(states, seeds)]


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_every_lane_equals_the_tangent_kernel_bit_for_bit(name):
    """Lanes (an odd count: no lane-count assumption) against one `TangentFlow` each, after
    steps that include projections (every 100) and re-orthonormalisations (every 10), in
    uneven chunks for the lanes: identical states, sin/cos and log-norm sums."""
    system = SYSTEMS[name]
    k = system.n - 1
    states = [system.random_state(seed=s) for s in range(5)]
    singles = _flows(system, states, k)
    lanes = LaneFlows(_flows(system, states, k))
    for f in singles:
        f.advance(450)
    for chunk in (1, 99, 350):
        assert lanes.advance(chunk) == 5
    for i, f in enumerate(singles):
        assert np.array_equal(lanes.lane(i), f.Z)
        assert np.array_equal(lanes.sc[:, :, i], f.sc)
        assert np.array_equal(lanes.logsum[i], f.logsum)
    assert lanes.steps == 450


@pytest.mark.parametrize("members", [MIN_LANES - 1, MIN_LANES + 1])
@pytest.mark.parametrize("name", ["N=3", "N=4 weights, level"])
def test_ensemble_members_equal_lyapunov_spectrum(name, members):
    """Each member of `lyapunov_ensemble` is `lyapunov_spectrum` on its own random state and
    seed: exponents, batches, history and settings identical, in lanes (at least
    `MIN_LANES` members) and one after the other (fewer)."""
    system = SYSTEMS[name]
    kw = dict(t_transient=2.0, n_batches=4, record_every=2.0)
    ens = lyapunov_ensemble(system, members, 8.0, seed=7, workers=1, speed=1.3, lanes=True,
                            **kw)
    assert len(ens.members) == members
    for i, m in enumerate(ens.members):
        th, u = system.random_state(seed=7 + i, speed=1.3)
        r = lyapunov_spectrum(system, th, u, 8.0, seed=7 + i, **kw)
        for a in ("exponents", "stderr", "batches", "history", "history_t", "energy_shares"):
            assert np.array_equal(getattr(m, a), getattr(r, a)), a
        assert m.energy_shares.sum() == 80       # every 0.1 of the 8 time units
        assert m.params == {**r.params, "state_seed": 7 + i}   # the ensemble drew its state
    E = np.array([m.exponents for m in ens.members])
    assert np.array_equal(ens.exponents, E.mean(axis=0))


# the N = 4 geodesic aimed exactly through the singular point (0, 0, π, π)
# (tests/test_singular_policy.py)
_A, _B = 0.42426406871192845, 0.565685424949238
THROUGH = (np.array([0.0, 0.0, np.pi, np.pi]) - np.array([_A, _B, _A, _B]),
           np.array([_A, _B, _A, _B]))


def test_a_stopping_lane_is_frozen_and_leaves_the_others_alone():
    """Lane 1 runs into the singular point, lane 3 starts with a NaN velocity: they stop with
    the status, time and state the one-trajectory kernel stops with, and lanes 0 and 2 equal
    their own `TangentFlow` s to the bit."""
    system = RotorSystem(4)
    states = [system.random_state(seed=1), THROUGH, system.random_state(seed=2),
              system.random_state(seed=3)]
    singles = _flows(system, states, 2)
    lanes = LaneFlows(_flows(system, states, 2))
    n = system.n
    lanes.Z[n, 3] = np.nan                    # lane 3: u₀ = NaN
    singles[3].Z[0, 0 + n] = np.nan
    assert lanes.advance(300) == 2
    assert lanes.stopped_lanes() == [1, 3]
    assert list(lanes.status) == [RUNNING, SINGULAR, RUNNING, NONFINITE]
    for i in (0, 2):
        singles[i].advance(300)
        assert np.array_equal(lanes.lane(i), singles[i].Z)
        assert np.array_equal(lanes.logsum[i], singles[i].logsum)
    for i, exc in ((1, charts.SingularPointError), (3, charts.IntegrationError)):
        with pytest.raises(exc) as single:
            singles[i].advance(300)
        err = lanes.error(i, "RK4")
        assert type(err) is type(single.value) and str(err) == str(single.value)
        assert np.array_equal(lanes.lane(i), singles[i].Z, equal_nan=True)
        assert np.array_equal(lanes.sc[:, :, i], singles[i].sc)
    # the stopped lanes stay frozen through further calls
    frozen = lanes.Z[:, [1, 3]].copy()
    lanes.advance(20)
    assert np.array_equal(lanes.Z[:, [1, 3]], frozen, equal_nan=True)


@pytest.mark.parametrize("members", [MIN_LANES - 1, MIN_LANES + 1])
def test_ensemble_reports_the_member_that_stops(members):
    """`lyapunov_ensemble` raises the error `lyapunov_spectrum` raises for the member, naming
    its seed (here a system whose random states are replaced by the singular geodesic), in
    lanes and one after the other."""

    class Aimed(RotorSystem):
        def random_state(self, seed=0, speed=1.0):
            return THROUGH if seed == 11 else super().random_state(seed=seed, speed=speed)

    system = Aimed(4)
    with pytest.raises(charts.SingularPointError, match=r"seed=11\).*t = 0\.9899999"):
        lyapunov_ensemble(system, members, 4.0, seed=10, workers=1, t_transient=0.0,
                          n_batches=2, lanes=True)
    with pytest.raises(charts.SingularPointError, match=r"t = 0\.9899999"):
        lyapunov_spectrum(system, *THROUGH, 4.0, t_transient=0.0, n_batches=2)


def test_ensemble_names_an_unknown_setting_itself():
    with pytest.raises(TypeError, match="lyapunov_ensemble\\(\\) got an unexpected keyword "
                                        "argument 'foo'.*n_batches"):
        lyapunov_ensemble(RotorSystem(3), 2, 1.0, workers=1, foo=1)


def test_lanes_refuse_mixed_settings():
    system = RotorSystem(3)
    th, u = system.random_state(seed=0)
    a = TangentFlow(system, th, u, 1, dt=0.01, reorth_every=10)
    b = TangentFlow(system, th, u, 1, dt=0.02, reorth_every=10)
    with pytest.raises(ValueError, match="share their system and settings"):
        LaneFlows([a, b])
    with pytest.raises(ValueError, match="at least one"):
        LaneFlows([])


def test_lanes_pay_where_compiled_or_where_the_run_pays_for_compiling(monkeypatch):
    """`lanes_pay`: never below MIN_LANES to a kernel; with the lane kernel compiled for
    (N, k), always; else only where the time the lanes save (the one-trajectory kernel's
    time per entry and step, less the lanes' pace at that count) exceeds a compilation, with
    every run that shares the compilation counted."""
    from charts.solvers import lanes as L

    entries = (1 + 3) * 2 * 5                                    # N = 5, k = 3
    alone = 16 * entries * L.ALONE_SECONDS                       # per step, 16 alone
    assert L.lanes_saving(5, 3, 16, 1) == pytest.approx(alone * (1 - 1 / 3.3), rel=1e-12)
    assert L.lanes_saving(5, 3, 3, 1, runs=16) == pytest.approx(alone * (1 - 1 / 1.44))
    assert L.lanes_saving(5, 3, 6, 1, runs=16) == pytest.approx(alone * (1 - 1 / 1.83))
    assert L.lanes_saving(5, 3, MIN_LANES - 1, 10**9) == 0.0
    even = L.COMPILE_SECONDS / L.lanes_saving(5, 3, 16, 1)       # steps: saving = compiling
    compiled = {"yes": False}
    monkeypatch.setattr(L, "lanes_compiled", lambda n, k: compiled["yes"])
    assert not L.lanes_pay(5, 3, 16, int(even * 0.99))
    assert L.lanes_pay(5, 3, 16, int(even * 1.01) + 1)
    assert L.lanes_pay(5, 3, 16, int(even * 0.26) + 1, runs=64)  # four blocks, one compilation
    assert not L.lanes_pay(5, 3, MIN_LANES - 1, 10**12)
    compiled["yes"] = True
    assert L.lanes_pay(5, 3, MIN_LANES, 1)
    assert not L.lanes_pay(5, 3, MIN_LANES - 1, 1)


def test_lanes_compiled_reads_this_process_and_the_disk_cache():
    """After a lane kernel for (N = 3, k = 1) ran here, `lanes_compiled` says so, here and in
    a new process that shares numba's disk cache (nothing in its memory); not for a (N, k)
    never compiled."""
    import os
    import subprocess
    import sys

    from charts.solvers.lanes import lanes_compiled

    system = RotorSystem(3)
    LaneFlows(_flows(system, [system.random_state(seed=s) for s in range(3)], 1)).advance(2)
    assert lanes_compiled(3, 1) and not lanes_compiled(3, 29)
    from charts.solvers.lanes import _lanes_run
    if not os.path.exists(_lanes_run._cache._cache_file._index_path):
        pytest.skip("numba's disk cache is not writable here")
    out = subprocess.run([sys.executable, "-c", "from charts.solvers.lanes import lanes_compiled;"
                          "print(lanes_compiled(3, 1), lanes_compiled(3, 29))"],
                         capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["True", "False"]


def test_ensemble_takes_the_lanes_where_they_pay(monkeypatch):
    """`lyapunov_ensemble` with lanes=None asks `lanes_pay` (the blocks' size and the steps of
    transient and averaging) and takes the lanes or the one-trajectory kernel accordingly;
    lanes=True / False decide for it; both routes give the same bits; another value is
    refused."""
    from charts.analyses import lyapunov_members as M

    system = RotorSystem(3)
    asked, built = [], []
    monkeypatch.setattr(M, "lanes_pay", lambda n, k, lanes, steps, runs=None: asked.append(
        (n, k, lanes, steps, runs)) or pay)
    monkeypatch.setattr(M, "LaneFlows", lambda flows: built.append(1) or LaneFlows(flows))
    kw = dict(seed=3, workers=1, t_transient=1.0, n_batches=2)
    pay = False
    one = lyapunov_ensemble(system, 4, 2.0, **kw)
    assert asked == [(3, 1, 4, 300, 4)] and built == []
    pay = True
    both = lyapunov_ensemble(system, 4, 2.0, **kw)
    assert built == [1]
    for a, b in zip(one.members, both.members):
        assert np.array_equal(a.exponents, b.exponents) and np.array_equal(a.batches, b.batches)
    lyapunov_ensemble(system, 4, 2.0, lanes=False, **kw)
    assert built == [1] and len(asked) == 2
    for bad in ("yes", 1):
        with pytest.raises(ValueError, match="lanes must be None"):
            lyapunov_ensemble(system, 4, 2.0, lanes=bad, **kw)
