"""The work-precision study behind ``charts bench accuracy`` (charts.runs.accuracy), on a
shrunken preset: its files, and its three claims checked against independent routes — the
trajectory errors against a reference computed here (SciPy's DOP853 on eq (8) written in
tests/scenarios.py), RK4 of order 4, DOP853 within its tolerance; the Lyapunov study's reference
against the full-preset value; the numerical curvature of order 2 against eq (22).  The run's
form: the figure's panels (the trajectory study split by formulation), the warnings raised
during the study reported once after the progress bar and in accuracy.md, the cost in CPU
time."""
import contextlib
import importlib
import io
import json
import time
import warnings
from dataclasses import asdict

import numpy as np
import pytest

from charts import RotorSystem, integrate
from charts.runs import accuracy

from figure_checks import check_axes, legend_off_data
from scenarios import REFERENCE_EXPONENTS, REFERENCE_STDERR, TOL, eq8_rhs

#: a preset small enough for the test suite, same structure as "quick"
TINY = dict(T=2.0, dts=(0.02, 0.01), rtols=(1e-7, 1e-9), lyap_T=500.0, lyap_dts=(0.04,),
            lyap_ref=0.02, lyap_members=4, curv_T=5.0, curv_dts=(0.02, 0.01), repeat=1)
#: SciPy DOP853 at rtol 1e-13 on eq (8) against the study's reference (ambient DOP853 at
#: 1e-14) at T = 2: both within ~1e-12 of the exact solution (λ ≈ 0.4: no amplification).
INDEPENDENT_REFERENCE = 1e-11
#: RK4 halving dt divides the error by 2⁴ = 16: the ratio of two global errors lies in
#: [8, 32] (a factor 2 for pre-asymptotic terms; measured 15.96-16.10 at dt = 0.02, 0.01).
RK4_RATIO = (8.0, 32.0)
#: the second-difference curvature route: error ∝ Δt², ratio 4 when Δt halves, in [2.5, 6].
CURV_RATIO = (2.5, 6.0)
#: DOP853 global error at T = 2 in units of rtol (the study's atol is rtol·1e-2; SciPy's
#: test_ivp allows 5 for its RMS norm, the max norm here gets a factor 10 more)
DOP853_UNITS = 50.0


#: the warning the fixture's study raises (twice) from inside the progress bar
PLANTED = "planted warning from inside the study"


class PlantedWarning(UserWarning):
    pass


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The tiny study through main, with its progress bar on, a study function that warns
    twice (the same warning), and stdout and stderr captured."""
    out = tmp_path_factory.mktemp("accuracy")
    curvature_study = accuracy.curvature_study

    def warning_curvature_study(*args, **kwargs):
        for _ in range(2):
            warnings.warn(PLANTED, PlantedWarning)
        return curvature_study(*args, **kwargs)

    stdout, stderr = io.StringIO(), io.StringIO()
    with pytest.MonkeyPatch.context() as mp, contextlib.redirect_stdout(stdout), \
            contextlib.redirect_stderr(stderr):
        mp.setitem(accuracy.PRESETS, "quick", TINY)
        mp.setattr(accuracy, "curvature_study", warning_curvature_study)
        assert accuracy.main(["--quick", "-o", str(out), "--n", "3"]) == 0
    return out, json.loads((out / "accuracy.json").read_text()), stdout.getvalue(), \
        stderr.getvalue()


@pytest.fixture(scope="module")
def study(run):
    return run[:2]


def test_figure_panels_readable(study):
    """Four panels: the trajectory study split by formulation (ambient | chart: each its
    own four series, SciPy's solve_ivp as the shared baseline, the reference floor, the same
    axes), then the Lyapunov and curvature studies; every panel with labels (the cost
    axis: CPU time in ms), visible tick labels, finite limits, a title, the legend off the
    data."""
    _, st = study
    fig = accuracy.draw_figure(st)
    assert len(fig.axes) == 4
    for ax in fig.axes:
        check_axes(ax)
        assert ax.get_title() and "CPU time" in ax.get_xlabel() and "(ms)" in ax.get_xlabel()
        assert ax.get_legend() is not None and legend_off_data(ax, ax.get_legend())
    amb, chart = fig.axes[:2]
    for ax, form in ((amb, "ambient"), (chart, "chart")):
        assert form in ax.get_title()
        labels = ax.get_legend_handles_labels()[1]
        series = {"RK4", "RK4 + projection", "DOP853", "DOP853 + projection"}
        assert series <= set(labels)
        assert any("SciPy" in x for x in labels) and "reference floor" in labels
        drawn = [line for line in ax.get_lines() if line.get_label() in series]
        assert len(drawn) == 4 and all(len(line.get_xdata()) == len(
            TINY["dts"] if "RK4" in line.get_label() else TINY["rtols"]) for line in drawn)
    assert amb.get_xlim() == chart.get_xlim() and amb.get_ylim() == chart.get_ylim()
    assert "Lyapunov" in fig.axes[2].get_title() and "curvature" in fig.axes[3].get_title()


def test_warnings_reported_once_after_the_bar(run):
    """The study's warnings are collected while the bar runs and reported once after it
    closes (the bar's last frame comes before them; a repeated warning is one line), and in
    accuracy.md and accuracy.json; none reaches the bar."""
    out, st, stdout, stderr = run
    assert "accuracy (quick)" in stderr                 # the progress bar ran
    assert stderr.count(PLANTED) == 1
    assert stderr.rindex("accuracy (quick)") < stderr.index(PLANTED)
    assert stderr.rindex("\r") < stderr.index(PLANTED)   # no bar frame after the report
    assert PLANTED not in stdout
    md = (out / "accuracy.md").read_text()
    section = md[md.index("## Warnings during the study"):]
    assert section.count(PLANTED) == 1 and "PlantedWarning" in section
    (w,) = [w for w in st["warnings"] if w["message"] == PLANTED]
    assert w["category"] == "PlantedWarning" and w["where"].startswith("test_accuracy_study.py")


def test_headline_quoted_from_the_points(run):
    """The headline is printed and written in accuracy.md, and quotes the points' numbers:
    ambient RK4 at dt = 0.01 and the loosest ambient DOP853 rtol at least as accurate."""
    out, st, stdout, _ = run
    h = st["headline"]
    assert h and f"headline: {h}" in stdout
    assert f"Headline: {h}" in (out / "accuracy.md").read_text()
    pts = {(p["method"], p["value"]): p for p in st["points"]}
    rk = pts["ambient RK4", 0.01]
    good = [p for p in st["points"]
            if p["method"] == "ambient DOP853" and p["error"] <= rk["error"]]
    dp = max(good, key=lambda p: p["value"])
    assert f"rtol = {dp['value']:g} reaches {dp['error']:.1e}" in h
    assert f"in {accuracy._ms(dp['cpu'])} ms of CPU time" in h
    assert f"against {accuracy._ms(rk['cpu'])} ms for ambient RK4 at dt = 0.01" in h


def test_cost_is_cpu_time(monkeypatch):
    """The cost follows time.process_time, not the wall clock: with a fake CPU clock that
    advances by a known amount per run (and a wall clock running wild), the best of
    ``repeat`` after a warm-up is the fake clock's, and the trajectory study records it
    scaled by COST_FACTOR."""
    cpu = [0.0]
    monkeypatch.setattr(time, "process_time", lambda: cpu[0])
    wild = iter(range(0, 10 ** 9, 1000))
    monkeypatch.setattr(time, "perf_counter", lambda: float(next(wild)))
    spent = iter([7.0, 3.0, 2.0, 5.0])                  # warm-up, then three timed runs

    def work():
        cpu[0] += next(spent)
        return "done"

    assert accuracy._timed(work, 3) == (2.0, "done")
    monkeypatch.setattr(time, "perf_counter", time.monotonic)   # back to a sane clock
    integrate_module = importlib.import_module("charts.solvers.integrate")

    real = integrate_module.integrate

    def ticking(system, theta0, u0, t_final, **kw):     # each run costs 0.5 CPU s per unit t
        cpu[0] += 0.5 * t_final
        return real(system, theta0, u0, t_final, **kw)

    monkeypatch.setattr(integrate_module, "integrate", ticking)
    pts, info = accuracy.trajectory_study(n=3, T=1.0, dts=(0.02,), rtols=(1e-8,), repeat=2)
    ours = [p for p in pts if p.method != accuracy.SCIPY]
    assert len(ours) == 8
    # timed over COST_FACTOR·T, scaled back to T: the fake clock's 0.5 per time unit
    assert all(p.cpu == pytest.approx(0.5 * info["T"]) for p in ours), [p.cpu for p in ours]
    row = accuracy.table({"points": [asdict(p) for p in ours[:1]]}).splitlines()
    assert "CPU time (ms)" in row[0] and f"| {1e3 * 0.5:.2f} |" in row[2]


def _points(study, name):
    return [p for p in study["points"] if p["study"] == name]


def test_files_and_table(study):
    out, st = study
    assert (out / "accuracy.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    rows = [r for r in (out / "accuracy.md").read_text().splitlines() if r.startswith("| ")]
    assert len(rows) == 1 + len(st["points"])                  # header + one row per point
    assert accuracy.table(st) in (out / "accuracy.md").read_text()
    assert accuracy.report(st) == (out / "accuracy.md").read_text().strip()
    # 4 formulations x (2 dt + 2 rtol) + SciPy x 2 rtol; 1 Lyapunov; 2 + 1 curvature
    assert [len(_points(st, s)) for s in ("trajectory", "lyapunov", "curvature")] == [18, 1, 3]
    assert all(p["cpu"] > 0 for p in st["points"]) and "wall" not in st["points"][0]
    assert st["clock"].startswith("CPU time (time.process_time)")


def test_trajectory_errors_against_an_independent_reference(study):
    from scipy.integrate import solve_ivp

    _, st = study
    info = st["trajectory"]
    assert info["T"] == TINY["T"] and info["reference_error"] < INDEPENDENT_REFERENCE
    s = RotorSystem(info["n"])
    theta0, u0 = s.random_state(seed=info["seed"], speed=1.0)
    y0 = np.concatenate([theta0, u0])
    ref = solve_ivp(lambda t, y: eq8_rhs(y, s.masses), (0.0, TINY["T"]), y0, method="DOP853",
                    rtol=1e-13, atol=1e-15).y[:, -1]
    pts = _points(st, "trajectory")
    by = {(p["method"], p["value"]): p for p in pts}
    # the errors the study reports are the distances to the true state
    for dt in TINY["dts"]:
        r = integrate(s, theta0, u0, TINY["T"], formulation="ambient", method="rk4", dt=dt)
        err = np.abs(np.concatenate([r.theta[-1], r.u[-1]]) - ref).max()
        assert by["ambient RK4", dt]["error"] == pytest.approx(err, abs=INDEPENDENT_REFERENCE)
    # RK4: fourth order in every formulation, with and without projection
    for method in {p["method"] for p in pts if "RK4" in p["method"]}:
        e = [by[method, dt]["error"] for dt in TINY["dts"]]
        assert RK4_RATIO[0] < e[0] / e[1] < RK4_RATIO[1], (method, e)
    # DOP853 (ours and SciPy's) within its tolerance, and tighter with a tighter rtol
    for method in {p["method"] for p in pts if "DOP853" in p["method"]}:
        e = [by[method, rtol]["error"] for rtol in TINY["rtols"]]
        assert all(x < DOP853_UNITS * r for x, r in zip(e, TINY["rtols"])), (method, e)
        assert e[1] < e[0], (method, e)


def test_lyapunov_study(study):
    """The reference exponent (dt = 0.02, 4 members × T = 500) agrees with the full-preset
    value within N_SIGMA combined standard errors; at dt = 0.04 no step-size bias shows above
    the statistical error (the trajectories of the two steps decorrelate within ~100 time
    units, so their difference is statistical: within N_SIGMA of the combined error); the
    reported error is |λ̄₁(0.04) − λ̄₁(0.02)|."""
    _, st = study
    info = st["lyapunov"]
    lam, se = info["lambda1_reference"], info["stderr_at_T"]
    assert 0 < se < 0.02 and info["paper"] == 0.500
    ref, ref_se = REFERENCE_EXPONENTS[3][0], REFERENCE_STDERR[3][0]
    assert abs(lam - ref) < TOL["n_sigma"] * np.hypot(se, ref_se), info
    (p,) = _points(st, "lyapunov")
    assert p["value"] == 0.04 and p["error"] < TOL["n_sigma"] * p["stderr"], p
    lam_dt = float(p["note"].split("=")[1].split("+-")[0])          # printed to 5 digits
    assert p["error"] == pytest.approx(abs(lam_dt - lam), abs=1e-5)


def test_curvature_study_is_second_order(study):
    _, st = study
    num = [p for p in _points(st, "curvature") if "numerical" in p["method"]]
    e = [p["error"] for p in sorted(num, key=lambda p: -p["value"])]
    assert CURV_RATIO[0] < e[0] / e[1] < CURV_RATIO[1], e
    (exact,) = [p for p in _points(st, "curvature") if "exact" in p["method"]]
    # the Riemann route is eq (22) up to rounding and the ≲ 1e-13 distance of the unprojected
    # state from the manifold between projections (measured 5e-12, median relative)
    assert exact["error"] < 1e-10


def test_direct_calls_return_points():
    """The study functions are usable on their own (a point per setting, as dataclasses)."""
    pts, info = accuracy.curvature_study(seed=1, T=2.0, dts=(0.02,))
    assert len(pts) == 2 and info == {"T": 2.0, "seed": 1}
    d = asdict(pts[0])
    assert d["study"] == "curvature" and d["error"] > 0 and d["rhs"] > 0
