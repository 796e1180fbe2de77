"""What accuracy costs in time: work–precision study behind ``charts bench accuracy``.

Three questions, each answered by error against CPU time (log–log), one point per setting:

(a) **trajectory** — the state (θ, u) at a fixed time T from one initial state, against a
    reference from ambient DOP853 at rtol = 1e-14 (its own error is estimated by the
    distance to the chart DOP853 run at the same tolerance, and shown as a floor).  Methods:
    ambient RK4 over a range of dt, ambient DOP853 over a range of rtol, the intrinsic chart
    RK4 and DOP853 — each with and without projection — and, as a baseline,
    ``scipy.integrate.solve_ivp`` (DOP853) on eq (8);
(b) **leading Lyapunov exponent** (N = 3) — |λ̄₁(dt) − λ̄₁(dt_ref)|, λ̄₁ the mean over a few
    trajectories of a fixed averaging time, next to its standard error: below the standard
    error, a smaller step buys nothing (the cost of accuracy is then the averaging time);
(c) **N = 3 curvature** — the numerical route of eqs (19)–(21) against the closed form of
    eq (22) at the same points (median relative error), against its cost; the exact route
    (generated Riemann tensor) as one point.

The cost is CPU time (``time.process_time``, as the project's other benchmarks: blind to
the time-slicing of other jobs on a shared machine, where wall time zigzags), the best of
``repeat`` runs after a warm-up run (compilation excluded).  In (a) the runs to T last
milliseconds, so the cost is timed on a run ``COST_FACTOR`` times longer from the same state
and scaled back to T (the error is that of the run to T).  Warnings raised during the study
(numba's, numpy's, ``ErrorBarWarning``…) and the lines the library prints on stderr (its
compilation notices) are collected while the progress bar runs and reported once after it
closes, and in ``accuracy.md``.  Outputs in the output folder: ``accuracy.png`` (four
panels: the trajectory study split by formulation, ambient | chart, each with SciPy's
solve_ivp as the shared baseline and the reference floor; the Lyapunov and curvature
studies), ``accuracy.md`` (the headline, the table, the warnings), ``accuracy.json`` (every
number).
"""
from __future__ import annotations

import contextlib
import io
import json
import sys
import time
import warnings
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ..geometry.system import RotorSystem
from .cli_parser import OneLineParser

__all__ = ["Point", "trajectory_study", "lyapunov_study", "curvature_study", "run_study",
           "headline", "table", "report", "draw_figure", "figure", "main"]

#: Reference tolerance of the trajectory study (the smallest rtol the DOP853 estimate
#: still tracks, one decade above rounding).
REFERENCE_RTOL = 1e-14
#: (a): the cost is timed over COST_FACTOR·T and divided by COST_FACTOR (less timer noise).
COST_FACTOR = 10
#: The clock of every cost: CPU time of this process (the words the outputs use).
CLOCK = "CPU time (time.process_time), best of `repeat` runs after a warm-up"
#: The headline compares DOP853 with RK4 at the paper's step.
HEADLINE_DT = 0.01

PRESETS = {
    "quick": dict(T=10.0, dts=(0.04, 0.02, 0.01, 0.005), rtols=(1e-5, 1e-7, 1e-9, 1e-11, 1e-13),
                  lyap_T=300.0, lyap_dts=(0.16, 0.08, 0.04, 0.02, 0.01), lyap_ref=0.005,
                  lyap_members=4,
                  curv_T=10.0, curv_dts=(0.04, 0.02, 0.01, 0.005), repeat=2),
    "full": dict(T=20.0, dts=(0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125),
                 rtols=(1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13),
                 lyap_T=1000.0, lyap_dts=(0.16, 0.08, 0.04, 0.02, 0.01, 0.005), lyap_ref=0.0025,
                 lyap_members=8,
                 curv_T=20.0, curv_dts=(0.04, 0.02, 0.01, 0.005, 0.0025), repeat=5),
}


@dataclass
class Point:
    """One setting of one method: its error, CPU time (s, ``time.process_time``) and work."""
    study: str
    method: str
    setting: str
    value: float
    error: float
    cpu: float
    rhs: int = 0
    note: str = ""
    stderr: float = float("nan")       # statistical error of ``error`` (Lyapunov study)


#: The SciPy baseline's method name in the points.
SCIPY = "scipy solve_ivp DOP853 (ambient)"


def _timed(fn, repeat):
    """(best CPU seconds of ``repeat`` calls of fn after a warm-up call, fn's last result)."""
    fn()                                   # warm-up: compilation, caches
    best, out = np.inf, None
    for _ in range(max(1, int(repeat))):
        c0 = time.process_time()
        out = fn()
        best = min(best, time.process_time() - c0)
    return best, out


# ------------------------------------------------------------------------------- (a)
def trajectory_study(n=4, seed=0, T=20.0, dts=(0.02, 0.01), rtols=(1e-8, 1e-11), repeat=1,
                     progress=None):
    """Error of the state at time T against the DOP853 reference, for every method.

    Returns (points, info) with info = {"reference_error": ..., "T": T, ...}."""
    from scipy.integrate import solve_ivp

    from ..flows.ambient import flow_rhs
    from ..solvers.integrate import integrate

    system = RotorSystem(n)
    theta0, u0 = system.random_state(seed=seed, speed=1.0)

    def state(res):
        return np.concatenate([res.theta[-1], res.u[-1]])

    ref_amb = state(integrate(system, theta0, u0, T, formulation="ambient", method="dop853",
                              rtol=REFERENCE_RTOL, atol=REFERENCE_RTOL * 1e-2))
    ref_chart = state(integrate(system, theta0, u0, T, formulation="chart", method="dop853",
                                rtol=REFERENCE_RTOL, atol=REFERENCE_RTOL * 1e-2))
    ref_err = float(np.max(np.abs(ref_amb - ref_chart)))
    jobs = []
    for form in ("ambient", "chart"):
        for proj in (False, True):
            tag = f"{form} RK4" + (" + projection" if proj else "")
            for dt in dts:
                jobs.append((tag, f"dt={dt:g}", dt, dict(formulation=form, method="rk4", dt=dt,
                                                          project=proj)))
            tag = f"{form} DOP853" + (" + projection" if proj else "")
            for rtol in rtols:
                jobs.append((tag, f"rtol={rtol:g}", rtol,
                             dict(formulation=form, method="dop853", rtol=rtol,
                                  atol=rtol * 1e-2, project=proj)))
    points = []
    for tag, setting, value, kw in jobs:
        res = integrate(system, theta0, u0, T, **kw)
        cpu, _ = _timed(lambda kw=kw: integrate(system, theta0, u0, COST_FACTOR * T, **kw),
                        repeat)
        cpu /= COST_FACTOR
        err = float(np.max(np.abs(state(res) - ref_amb)))
        points.append(Point("trajectory", tag, setting, value, err, cpu, res.n_rhs))
        if progress:
            progress()
    minv = system.minv
    wts = system.weights

    def f(t, y):
        dy = np.empty_like(y)
        flow_rhs(y, minv, wts, dy)
        return dy

    y0 = np.concatenate([theta0, u0])
    for rtol in rtols:
        res = solve_ivp(f, (0.0, T), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-2)
        cpu, _ = _timed(lambda r=rtol: solve_ivp(f, (0.0, COST_FACTOR * T), y0, method="DOP853",
                                                 rtol=r, atol=r * 1e-2), repeat)
        cpu /= COST_FACTOR
        err = float(np.max(np.abs(res.y[:, -1] - ref_amb)))
        points.append(Point("trajectory", SCIPY, f"rtol={rtol:g}", rtol, err, cpu,
                            int(res.nfev)))
        if progress:
            progress()
    return points, {"n": n, "seed": seed, "T": T, "reference": f"ambient DOP853 rtol="
                    f"{REFERENCE_RTOL:g}", "reference_error": ref_err}


# ------------------------------------------------------------------------------- (b)
def lyapunov_study(seed=0, T=2000.0, dts=(0.04, 0.01), ref_dt=0.0025, repeat=1, progress=None,
                   members=4):
    """|λ̄₁(dt) − λ̄₁(ref_dt)| for N = 3: λ̄₁ is the mean over ``members`` trajectories
    (seeds seed, seed+1, …) each averaged over time T; its standard error is the spread of
    the members / √members.  The cost is the CPU time of all members (run one after the
    other).  A single finite-T estimate differs from another by its statistical error
    whatever the step, so the step's bias only shows where it exceeds that error."""
    from ..analyses.lyapunov import lyapunov_spectrum
    from ..analyses.statistics import standard_error

    system = RotorSystem(3)
    states = [system.random_state(seed=seed + i, speed=1.0) for i in range(members)]
    kw = dict(n_exponents=1, n_batches=10)

    def ensemble(dt):  # re-orthonormalise every step, project every 100, at every dt
        lam = [lyapunov_spectrum(system, th, u, T, dt=dt, seed=seed + i, reorth_every=dt,
                                 record_every=max(1, round(1.0 / dt)) * dt,
                                 project_every=100 * dt, t_transient=round(50.0 / dt) * dt,
                                 **kw).exponents[0]
               for i, (th, u) in enumerate(states)]
        return np.array(lam)

    ref = ensemble(ref_dt)
    lam_ref, se_ref = float(ref.mean()), float(standard_error(ref))
    if progress:
        progress()
    points = []
    for dt in dts:
        cpu, lam = _timed(lambda dt=dt: ensemble(dt), repeat) if repeat > 1 else \
            _timed_once(lambda dt=dt: ensemble(dt))
        se = float(standard_error(lam))
        steps = members * int(round((T + 50.0) / dt))
        points.append(Point("lyapunov", "RK4 + QR (eq 17, 18)", f"dt={dt:g}", dt,
                            abs(float(lam.mean()) - lam_ref), cpu, 4 * steps,
                            note=f"lambda1={lam.mean():.5f}+-{se:.5f}",
                            stderr=float(np.hypot(se, se_ref))))
        if progress:
            progress()
    return points, {"T": T, "members": members, "reference_dt": ref_dt,
                    "lambda1_reference": lam_ref, "stderr_at_T": se_ref, "paper": 0.500}


def _timed_once(fn):
    """CPU seconds of one run (the kernels are compiled by the reference run already)."""
    c0 = time.process_time()
    out = fn()
    return time.process_time() - c0, out


# ------------------------------------------------------------------------------- (c)
def curvature_study(seed=0, T=20.0, dts=(0.02, 0.01), repeat=1, progress=None):
    """N = 3 numerical curvature (route a) against eq (22) at the same points; exact route
    (b) timed at the same points."""
    from ..analyses.curvature import (curvature_along_trajectory, exact_curvatures,
                                      gaussian_curvature_eq22)

    system = RotorSystem(3)
    theta0, u0 = system.random_state(seed=seed, speed=1.0)
    points = []
    last = None
    for dt in dts:
        every = max(1, int(round(0.1 / dt))) * dt
        cpu, res = _timed(lambda dt=dt, every=every: curvature_along_trajectory(
            system, theta0, u0, T, dt=dt, sample_every=every, t_transient=10.0, exact=False,
            seed=seed), repeat)
        K = res.K_numeric[:, 0, 0]
        K22 = gaussian_curvature_eq22(res.theta)
        err = float(np.median(np.abs(K - K22) / np.abs(K22)))
        steps = int(round((T + 10.0) / dt))
        points.append(Point("curvature", "numerical route (eqs 19-21)", f"dt={dt:g}", dt, err,
                            cpu, 4 * steps + 8 * K.size, note=f"{K.size} samples"))
        last = res
        if progress:
            progress()
    # exact route at the last run's points and frames: cost on top of the trajectory
    th, fr = last.theta, last.frames

    def exact():
        return exact_curvatures(system, th, fr)[:, 0, 0]

    cpu, Ke = _timed(exact, repeat)
    err = float(np.median(np.abs(Ke - gaussian_curvature_eq22(th)) /
                          np.abs(gaussian_curvature_eq22(th))))
    points.append(Point("curvature", "exact route (Riemann tensor), added cost",
                        f"{len(th)} points", float("nan"), err, cpu, 0,
                        note="evaluated at the points of the smallest dt"))
    return points, {"T": T, "seed": seed}


# ------------------------------------------------------------------------------- driver
def _warning_lines(caught) -> list:
    """The recorded warnings, each distinct one once: {category, message, where, count}."""
    seen = {}
    for w in caught:
        key = (w.category.__name__, str(w.message), f"{Path(w.filename).name}:{w.lineno}")
        seen[key] = seen.get(key, 0) + 1
    return [dict(category=c, message=m, where=where, count=k)
            for (c, m, where), k in seen.items()]


def _notice_lines(text) -> list:
    """The distinct non-empty lines printed on stderr during the study, in order."""
    out = []
    for line in text.splitlines():
        line = line.strip()
        if line and line not in out:
            out.append(line)
    return out


def run_study(preset="quick", n=4, seed=0, progress=True):
    """Every point of the preset, the studies' information, the headline, and the warnings
    and stderr notices raised meanwhile (collected, never printed into the progress bar: the
    caller reports them once, :func:`report_warnings`)."""
    p = PRESETS[preset]
    total = (4 * (len(p["dts"]) + len(p["rtols"])) + len(p["rtols"]) + len(p["lyap_dts"]) + 1
             + len(p["curv_dts"]))
    from tqdm.auto import tqdm
    w0, c0 = time.perf_counter(), time.process_time()
    bar = tqdm(total=total, desc=f"accuracy ({preset})", disable=not progress, leave=False,
               file=sys.stderr)          # the bar keeps the real stderr; notices go aside
    tick = bar.update
    notices = io.StringIO()
    try:
        with warnings.catch_warnings(record=True) as caught, \
                contextlib.redirect_stderr(notices):
            a, ia = trajectory_study(n, seed, p["T"], p["dts"], p["rtols"], p["repeat"], tick)
            b, ib = lyapunov_study(seed, p["lyap_T"], p["lyap_dts"], p["lyap_ref"], 1, tick,
                                   p["lyap_members"])
            c, ic = curvature_study(seed, p["curv_T"], p["curv_dts"], p["repeat"], tick)
    except BaseException:            # a failed or interrupted study: what it printed, as is
        bar.close()
        sys.stderr.write(notices.getvalue())
        raise
    bar.close()
    study = {"preset": preset, "clock": CLOCK, "repeat": p["repeat"],
             "cost_factor": COST_FACTOR, "trajectory": ia, "lyapunov": ib, "curvature": ic,
             "points": [asdict(x) for x in a + b + c],
             "warnings": _warning_lines(caught), "notices": _notice_lines(notices.getvalue()),
             "duration": {"wall_s": time.perf_counter() - w0,
                          "cpu_s": time.process_time() - c0}}
    study["headline"] = headline(study)
    return study


def _headline_pair(study):
    """(RK4 point, DOP853 point): ambient RK4 at the dt nearest `HEADLINE_DT`, and the
    loosest ambient DOP853 rtol whose error is no larger (the most accurate one if none is);
    the errors are deterministic, so the pair is too — only its costs vary between runs."""
    traj = [q for q in study["points"] if q["study"] == "trajectory"]
    rk4 = [q for q in traj if q["method"] == "ambient RK4"]
    dop = [q for q in traj if q["method"] == "ambient DOP853"]
    if not rk4 or not dop:
        return None
    rk = min(rk4, key=lambda q: abs(np.log(q["value"] / HEADLINE_DT)))
    good = [q for q in dop if q["error"] <= rk["error"]]
    dp = max(good, key=lambda q: q["value"]) if good else min(dop, key=lambda q: q["error"])
    return rk, dp


def _ms(seconds) -> str:
    """Milliseconds to two significant digits, trailing zeros kept (0.40, 1.0), whole
    milliseconds from 10 on (12, 123)."""
    ms = 1e3 * seconds
    return f"{ms:.0f}" if ms >= 9.95 else f"{ms:#.2g}"


def headline(study) -> str:
    """The one sentence quoted in the README and docs/accuracy.md, from the study."""
    pair = _headline_pair(study)
    if pair is None:
        return ""
    rk, dp = pair
    info = study["trajectory"]
    return (f"N = {info['n']}, t = {info['T']:g}: ambient DOP853 at rtol = {dp['value']:g} "
            f"reaches {dp['error']:.1e} in {_ms(dp['cpu'])} ms of CPU time, against "
            f"{_ms(rk['cpu'])} ms for ambient RK4 at dt = {rk['value']:g} "
            f"({rk['error']:.1e}): {rk['cpu'] / dp['cpu']:.1f}× cheaper")


def table(study: dict) -> str:
    """The markdown table of every point."""
    rows = ["| study | method | setting | error | CPU time (ms) | rhs evaluations |",
            "|---|---|---|---|---|---|"]
    for q in study["points"]:
        err = f"{q['error']:.2e}"
        if q["stderr"] == q["stderr"]:          # not NaN: a statistical error is known
            err += f" ± {q['stderr']:.1e}"
        rows.append(f"| {q['study']} | {q['method']} | {q['setting']} | {err} | "
                    f"{1e3 * q['cpu']:.2f} | {q['rhs'] or '—'} |")
    return "\n".join(rows)


def warnings_text(study: dict) -> str:
    """The warnings and stderr notices of the study, one line each ("none" if none)."""
    lines = [f"- {w['category']}: {w['message']} ({w['where']}"
             + (f", {w['count']} times)" if w["count"] > 1 else ")")
             for w in study.get("warnings", [])]
    lines += [f"- stderr: {x}" for x in study.get("notices", [])]
    return "\n".join(lines) if lines else "none"


def report(study: dict) -> str:
    """``accuracy.md``: the headline, the clock, the table, the warnings."""
    return "\n".join([
        f"Headline: {study.get('headline', '')}", "",
        f"Cost: {study.get('clock', CLOCK)} (repeat = {study.get('repeat', '?')}); trajectory "
        f"runs timed over {study.get('cost_factor', COST_FACTOR)}·T and scaled back to T.", "",
        table(study), "",
        "## Warnings during the study", "",
        warnings_text(study)])


def report_warnings(study: dict, file=None) -> None:
    """Print the study's warnings and notices once (after the progress bar has closed)."""
    file = sys.stderr if file is None else file
    k = len(study.get("warnings", [])) + len(study.get("notices", []))
    if k:
        print(f"charts bench accuracy: {k} warning(s) or notice(s) during the study "
              f"(also in accuracy.md):\n{warnings_text(study)}", file=file, flush=True)


def figure(study: dict, path: Path) -> None:
    """Write :func:`draw_figure` to ``path`` (PNG, atomically)."""
    from ..plotting.style import save_png

    save_png(draw_figure(study), path)


def draw_figure(study: dict):
    """The four work–precision panels of the study (a matplotlib Figure;
    ``charts.plotting.accuracy``), the headline pair ringed."""
    from ..plotting.accuracy import work_precision_figure

    return work_precision_figure(study, _headline_pair(study), SCIPY)


def main(argv=None, quiet=False) -> int:
    ap = OneLineParser(
        prog="charts bench accuracy",
        description="Work–precision diagrams: error against CPU time for the trajectory "
        "(every formulation and method, with and without projection), the leading Lyapunov "
        "exponent and the N = 3 curvature. Writes accuracy.png, accuracy.md, accuracy.json.")
    ap.add_argument("--quick", action="store_true",
                    help="fewer settings, shorter times, two timing repeats "
                    "(about 10 s once compiled)")
    ap.add_argument("-o", "--output", type=Path, default=Path("bench-accuracy"), metavar="DIR",
                    help="output folder (default: ./bench-accuracy)")
    ap.add_argument("--n", type=int, default=4, help="N of the trajectory study (default 4)")
    ap.add_argument("--seed", type=int, default=0, help="seed of the initial states")
    ap.add_argument("--quiet", "-q", action="store_true",
                    help="no progress bar and no table (warnings are still reported)")
    args = ap.parse_args(argv)
    if not 3 <= args.n <= 6:
        ap.error(f"--n {args.n}: expected 3..6")
    quiet = quiet or args.quiet
    from .io import atomic_write
    study = run_study("quick" if args.quick else "full", args.n, args.seed, progress=not quiet)
    out = args.output
    out.mkdir(parents=True, exist_ok=True)
    with warnings.catch_warnings(record=True) as caught:      # the figure's, reported too
        figure(study, out / "accuracy.png")      # written atomically by plotting.save_png
    study["warnings"] += _warning_lines(caught)
    atomic_write(out / "accuracy.md", (report(study) + "\n").encode())
    atomic_write(out / "accuracy.json", json.dumps(study, indent=1).encode())
    if not quiet:
        print(table(study))
        print(f"\nreference uncertainty (a): {study['trajectory']['reference_error']:.1e}; "
              f"λ₁ reference {study['lyapunov']['lambda1_reference']:.5f} ± "
              f"{study['lyapunov']['stderr_at_T']:.5f} (paper 0.500)")
        print(f"headline: {study['headline']}")
        print(f"study: {study['duration']['wall_s']:.0f} s wall, "
              f"{study['duration']['cpu_s']:.0f} s CPU")
        print(f"wrote {out}/accuracy.png, accuracy.md, accuracy.json")
    report_warnings(study)
    return 0
