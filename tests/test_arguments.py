"""Every analysis refuses zero, negative and non-finite step, sampling and time arguments,
and durations that are not whole numbers of steps, with a ValueError naming the argument
(never a ZeroDivisionError, an OverflowError or a silently rounded step count)."""
import math

import numpy as np
import pytest

import charts
from charts.analyses.arguments import steps_of

SYSTEM = charts.RotorSystem(4, [1.0, 2.0, 1.0, 2.0])
THETA, U = SYSTEM.random_state(seed=0)

#: (analysis, its time-like arguments, a valid t_final) — every analysis of the public API
ANALYSES = [
    (charts.lyapunov_spectrum, ("dt", "t_transient", "reorth_every", "project_every", "record_every"), 2.0),
    (charts.curvature_along_trajectory, ("dt", "t_transient", "sample_every", "project_every"), 1.0),
    (charts.hyperbolicity_angles, ("dt", "t_transient", "sample_every", "checkpoint_every", "project_every"), 1.0),
    (charts.waveform, ("dt", "t_transient", "sample_every", "project_every"), 1.0),
]
BAD = [0.0, -0.01, math.nan, math.inf, -math.inf]
CASES = [(fn, arg, t, bad) for fn, args, t in ANALYSES for arg in args for bad in BAD
         if not (arg == "t_transient" and bad == 0.0)]


@pytest.mark.parametrize("fn, arg, t_final, bad", CASES,
                         ids=[f"{c[0].__name__}-{c[1]}-{c[3]}" for c in CASES])
def test_bad_time_argument_is_a_value_error_naming_it(fn, arg, t_final, bad):
    with pytest.raises(ValueError, match=arg):
        fn(SYSTEM, THETA, U, t_final, **{arg: bad})


@pytest.mark.parametrize("fn, t_final", [(a[0], a[2]) for a in ANALYSES],
                         ids=[a[0].__name__ for a in ANALYSES])
@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_bad_t_final_is_a_value_error_naming_it(fn, t_final, bad):
    with pytest.raises(ValueError, match="t_final"):
        fn(SYSTEM, THETA, U, bad)


@pytest.mark.parametrize("fn, arg", [(charts.lyapunov_spectrum, "reorth_every"),
                                     (charts.curvature_along_trajectory, "sample_every"),
                                     (charts.hyperbolicity_angles, "sample_every"),
                                     (charts.waveform, "sample_every")])
def test_a_duration_off_the_step_grid_is_refused_not_rounded(fn, arg):
    with pytest.raises(ValueError, match=f"{arg}=0.015 is not a whole number of steps"):
        fn(SYSTEM, THETA, U, 2.0, **{arg: 0.015})


def test_counts_and_modes_are_checked():
    for kw, name in [({"n_batches": 1}, "n_batches"), ({"n_batches": 2.5}, "n_batches"),
                     ({"n_exponents": 0}, "n_exponents"), ({"n_exponents": 2.7}, "n_exponents"),
                     ({"seed": -1}, "seed"), ({"space": "other"}, "space"),
                     ({"progress": "yes"}, "progress")]:
        with pytest.raises(ValueError, match=name):
            charts.lyapunov_spectrum(SYSTEM, THETA, U, 2.0, **kw)
    with pytest.raises(ValueError, match="n_unstable"):
        charts.hyperbolicity_angles(SYSTEM, THETA, U, 1.0, n_unstable=0)
    with pytest.raises(ValueError, match="n_trajectories"):
        charts.lyapunov_ensemble(SYSTEM, 1, 2.0)


def test_state_is_checked_by_every_analysis():
    off = THETA + 0.1
    for fn, _, t in ANALYSES:
        with pytest.raises(ValueError, match="off the manifold"):
            fn(SYSTEM, off, U, t)
        with pytest.raises(ValueError, match="zero"):
            fn(SYSTEM, THETA, np.zeros(4), t)


def test_power_spectrum_checks_its_signal_and_times():
    x = np.sin(np.arange(4000) * 0.05)
    with pytest.raises(ValueError, match="dt_sample"):
        charts.power_spectrum(x, 0.0)
    with pytest.raises(ValueError, match="segment_time"):
        charts.power_spectrum(x, 0.05, segment_time=-1.0)
    with pytest.raises(ValueError, match="finite"):
        charts.power_spectrum(np.where(x > 0.99, np.nan, x), 0.05)
    with pytest.raises(ValueError, match="too short"):
        charts.power_spectrum(x[:100], 0.05)


def test_steps_of_accepts_decimal_multiples_and_names_the_argument():
    assert steps_of("x", 0.1, 0.01) == 10 and steps_of("x", 2.5e4, 0.01) == 2_500_000
    assert steps_of("x", 0.0, 0.01, allow_zero=True) == 0
    with pytest.raises(ValueError, match="x=0.105"):
        steps_of("x", 0.105, 0.01)


def test_progress_callable_sees_the_simulated_time():
    seen = []
    charts.lyapunov_spectrum(SYSTEM, THETA, U, 2.0, t_transient=1.0,
                             progress=lambda t, total: seen.append((t, total)))
    assert seen[-1] == pytest.approx((3.0, 3.0)) and len(seen) > 2
    assert all(b[0] >= a[0] for a, b in zip(seen, seen[1:]))


def test_durations_off_the_sampling_grid_are_refused():
    """t_final must hold a whole number of samples (it was floored silently)."""
    with pytest.raises(ValueError, match="multiple of sample_every"):
        charts.waveform(SYSTEM, THETA, U, 1.03, sample_every=0.05)
    with pytest.raises(ValueError, match="multiple of sample_every"):
        charts.hyperbolicity_angles(SYSTEM, THETA, U, 1.05, sample_every=0.1, t_transient=0.0)
    x = np.sin(np.arange(4000) * 0.05)
    with pytest.raises(ValueError, match="segment_time=200.03"):
        charts.power_spectrum(x, 0.05, segment_time=200.03)


def test_ensembles_check_their_arguments_and_report_simulated_time():
    with pytest.raises(ValueError, match="progress"):
        charts.lyapunov_ensemble(SYSTEM, 2, 2.0, progress="x")
    with pytest.raises(ValueError, match="t_final"):
        charts.hyperbolicity_ensemble(SYSTEM, 2, -1.0)
    seen = []
    charts.lyapunov_ensemble(SYSTEM, 2, 2.0, workers=1, t_transient=0.0, n_batches=2,
                             progress=lambda t, total: seen.append((t, total)))
    # the members advance together (lanes of one kernel): 2 × the averaging time in total
    assert all(total == 4.0 for _, total in seen) and len(seen) > 1
    assert np.all(np.diff([t for t, _ in seen]) > 0) and seen[-1][0] == pytest.approx(4.0)


def test_curvature_checks_seed_and_exact():
    with pytest.raises(ValueError, match="seed"):
        charts.curvature_along_trajectory(SYSTEM, THETA, U, 1.0, seed="a")
    with pytest.raises(ValueError, match="exact"):
        charts.curvature_along_trajectory(SYSTEM, THETA, U, 1.0, exact="yes")


def test_an_ensemble_never_starts_more_processes_than_jobs(monkeypatch):
    """workers=10**6 for two members starts two processes (the pool is asked for two)."""
    import charts.analyses.ensemble as ensemble
    asked = []
    real = ensemble.worker_pool

    def pool(max_workers=None):
        asked.append(max_workers)
        return real(max_workers)

    monkeypatch.setattr(ensemble, "worker_pool", pool)
    res = charts.lyapunov_ensemble(SYSTEM, 2, 2.0, workers=10**6, t_transient=0.0, n_batches=2)
    assert asked == [2] and len(res.members) == 2
