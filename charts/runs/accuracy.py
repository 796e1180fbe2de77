"""What accuracy costs in time: work–precision study behind ``charts bench accuracy``.

Three questions, each answered by error against wall time (log–log), one point per setting:

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

Wall time is the best of ``repeat`` runs after a warm-up run (compilation excluded).  In
(a) the runs to T last milliseconds, so the cost is timed on a run ``COST_FACTOR`` times
longer from the same state and scaled back to T (the error is that of the run to T).
Outputs in the output folder: ``accuracy.png`` (three panels), ``accuracy.md`` (the
table), ``accuracy.json`` (every number).
"""
from __future__ import annotations

import json
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ..geometry.system import RotorSystem
from .cli_parser import OneLineParser

__all__ = ["Point", "trajectory_study", "lyapunov_study", "curvature_study", "run_study", "main"]

#: Reference tolerance of the trajectory study (the smallest rtol the DOP853 estimate
#: still tracks, one decade above rounding).
REFERENCE_RTOL = 1e-14
#: (a): the cost is timed over COST_FACTOR·T and divided by COST_FACTOR (less timer noise).
COST_FACTOR = 10

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
    """One setting of one method: its error, wall time (s) and work."""
    study: str
    method: str
    setting: str
    value: float
    error: float
    wall: float
    rhs: int = 0
    note: str = ""
    stderr: float = float("nan")       # statistical error of ``error`` (Lyapunov study)


def _timed(fn, repeat):
    fn()                                   # warm-up: compilation, caches
    best, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
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
        wall, _ = _timed(lambda kw=kw: integrate(system, theta0, u0, COST_FACTOR * T, **kw),
                         repeat)
        wall /= COST_FACTOR
        err = float(np.max(np.abs(state(res) - ref_amb)))
        points.append(Point("trajectory", tag, setting, value, err, wall, res.n_rhs))
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
        wall, _ = _timed(lambda r=rtol: solve_ivp(f, (0.0, COST_FACTOR * T), y0, method="DOP853",
                                                  rtol=r, atol=r * 1e-2), repeat)
        wall /= COST_FACTOR
        err = float(np.max(np.abs(res.y[:, -1] - ref_amb)))
        points.append(Point("trajectory", "scipy solve_ivp DOP853 (ambient)", f"rtol={rtol:g}",
                            rtol, err, wall, int(res.nfev)))
        if progress:
            progress()
    return points, {"n": n, "seed": seed, "T": T, "reference": f"ambient DOP853 rtol="
                    f"{REFERENCE_RTOL:g}", "reference_error": ref_err}


# ------------------------------------------------------------------------------- (b)
def lyapunov_study(seed=0, T=2000.0, dts=(0.04, 0.01), ref_dt=0.0025, repeat=1, progress=None,
                   members=4):
    """|λ̄₁(dt) − λ̄₁(ref_dt)| for N = 3: λ̄₁ is the mean over ``members`` trajectories
    (seeds seed, seed+1, …) each averaged over time T; its standard error is the spread of
    the members / √members.  The cost is the wall time of all members (run one after the
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
        wall, lam = _timed(lambda dt=dt: ensemble(dt), repeat) if repeat > 1 else \
            _untimed_warm(lambda dt=dt: ensemble(dt))
        se = float(standard_error(lam))
        steps = members * int(round((T + 50.0) / dt))
        points.append(Point("lyapunov", "RK4 + QR (eq 17, 18)", f"dt={dt:g}", dt,
                            abs(float(lam.mean()) - lam_ref), wall, 4 * steps,
                            note=f"lambda1={lam.mean():.5f}+-{se:.5f}",
                            stderr=float(np.hypot(se, se_ref))))
        if progress:
            progress()
    return points, {"T": T, "members": members, "reference_dt": ref_dt,
                    "lambda1_reference": lam_ref, "stderr_at_T": se_ref, "paper": 0.500}


def _untimed_warm(fn):
    """One timed run (the kernels are compiled by the reference run already)."""
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


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
        wall, res = _timed(lambda dt=dt, every=every: curvature_along_trajectory(
            system, theta0, u0, T, dt=dt, sample_every=every, t_transient=10.0, exact=False,
            seed=seed), repeat)
        K = res.K_numeric[:, 0, 0]
        K22 = gaussian_curvature_eq22(res.theta)
        err = float(np.median(np.abs(K - K22) / np.abs(K22)))
        steps = int(round((T + 10.0) / dt))
        points.append(Point("curvature", "numerical route (eqs 19-21)", f"dt={dt:g}", dt, err,
                            wall, 4 * steps + 8 * K.size, note=f"{K.size} samples"))
        last = res
        if progress:
            progress()
    # exact route at the last run's points and frames: cost on top of the trajectory
    th, fr = last.theta, last.frames

    def exact():
        return exact_curvatures(system, th, fr)[:, 0, 0]

    wall, Ke = _timed(exact, repeat)
    err = float(np.median(np.abs(Ke - gaussian_curvature_eq22(th)) /
                          np.abs(gaussian_curvature_eq22(th))))
    points.append(Point("curvature", "exact route (Riemann tensor), added cost",
                        f"{len(th)} points", float("nan"), err, wall, 0,
                        note="evaluated at the points of the smallest dt"))
    return points, {"T": T, "seed": seed}


# ------------------------------------------------------------------------------- driver
def run_study(preset="quick", n=4, seed=0, progress=True):
    p = PRESETS[preset]
    total = (4 * (len(p["dts"]) + len(p["rtols"])) + len(p["rtols"]) + len(p["lyap_dts"]) + 1
             + len(p["curv_dts"]))
    from tqdm.auto import tqdm
    bar = tqdm(total=total, desc=f"accuracy ({preset})", disable=not progress, leave=False)
    tick = bar.update
    a, ia = trajectory_study(n, seed, p["T"], p["dts"], p["rtols"], p["repeat"], tick)
    b, ib = lyapunov_study(seed, p["lyap_T"], p["lyap_dts"], p["lyap_ref"], 1, tick,
                           p["lyap_members"])
    c, ic = curvature_study(seed, p["curv_T"], p["curv_dts"], p["repeat"], tick)
    bar.close()
    return {"preset": preset, "trajectory": ia, "lyapunov": ib, "curvature": ic,
            "points": [asdict(x) for x in a + b + c]}


def table(study: dict) -> str:
    """The markdown table of every point."""
    rows = ["| study | method | setting | error | wall time (ms) | rhs evaluations |",
            "|---|---|---|---|---|---|"]
    for q in study["points"]:
        err = f"{q['error']:.2e}"
        if q["stderr"] == q["stderr"]:          # not NaN: a statistical error is known
            err += f" ± {q['stderr']:.1e}"
        rows.append(f"| {q['study']} | {q['method']} | {q['setting']} | {err} | "
                    f"{1e3 * q['wall']:.1f} | {q['rhs'] or '—'} |")
    return "\n".join(rows)


def figure(study: dict, path: Path) -> None:
    """Write :func:`draw_figure` to ``path`` (PNG, atomically)."""
    from ..plotting.style import save_png

    save_png(draw_figure(study), path)


def draw_figure(study: dict):
    """The three work–precision panels of the study, a matplotlib Figure."""
    from matplotlib.ticker import FormatStrFormatter, LogLocator, MaxNLocator, NullFormatter

    from ..plotting.style import new_figure

    pts = study["points"]
    fig, axes = new_figure(1, 3, figsize=(15, 6.2))
    below = dict(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)   # off the data
    floor = 1e-16
    ax = axes[0]
    methods = sorted({q["method"] for q in pts if q["study"] == "trajectory"})
    for m in methods:
        qs = [q for q in pts if q["method"] == m and q["study"] == "trajectory"]
        style = "--" if "projection" in m else "-"
        marker = "s" if "RK4" in m else ("x" if "scipy" in m else "o")
        ax.loglog([q["wall"] for q in qs], [max(q["error"], floor) for q in qs], style,
                  marker=marker, ms=4, label=m)
    ref = study["trajectory"]["reference_error"]
    ax.axhline(max(ref, floor), color="k", lw=0.6, ls=":", label="reference uncertainty")
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel(f"max |state − reference| at t = {study['trajectory']['T']:g}")
    ax.set_title(f"(a) trajectory, N = {study['trajectory']['n']}")
    ax.legend(fontsize=6.5, **below)
    ax = axes[1]
    qs = [q for q in pts if q["study"] == "lyapunov"]
    L = study["lyapunov"]
    lam = [float(q["note"].split("=")[1].split("+-")[0]) for q in qs]
    ax.errorbar([q["wall"] for q in qs], [x - L["lambda1_reference"] for x in lam],
                yerr=[q["stderr"] for q in qs], fmt="-o", ms=4, capsize=3,
                label="λ̄₁(dt) − λ̄₁(dt_ref), ± standard error")
    for q, x in zip(qs, lam):
        ax.annotate(q["setting"], (q["wall"], x - L["lambda1_reference"]), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.axhline(L["paper"] - L["lambda1_reference"], color="g", ls=":", lw=0.8,
               label="paper (0.500)")
    ax.set_xscale("log")
    ax.set_xlabel(f"wall time (s), {L['members']} trajectories × T = {L['T']:g}")
    ax.set_ylabel(f"λ̄₁ − λ̄₁(dt = {L['reference_dt']:g}) = {L['lambda1_reference']:.4f}")
    ax.set_title("(b) leading Lyapunov exponent, N = 3")
    ax.legend(fontsize=7, **below)
    ax = axes[2]
    qs = [q for q in pts if q["study"] == "curvature" and "numerical" in q["method"]]
    ax.loglog([q["wall"] for q in qs], [q["error"] for q in qs], "-o", ms=4,
              label="numerical route (19)–(21)")
    for q in qs:
        ax.annotate(q["setting"], (q["wall"], q["error"]), fontsize=7)
    ex = [q for q in pts if q["study"] == "curvature" and "exact" in q["method"]]
    if ex:
        ax.loglog([ex[0]["wall"]], [max(ex[0]["error"], floor)], "k*", ms=9,
                  label="exact route (added cost)")
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("median |K − K_eq22| / |K_eq22|")
    ax.set_title("(c) N = 3 curvature vs eq (22)")
    ax.legend(fontsize=7, **below)
    for ax in axes:   # x labels readable at any span: two or more powers of 10 inside the
        lo, hi = ax.get_xlim()      # axis: those only; else 1-2-5 labels; narrower than 4x: plain
        decades = np.floor(np.log10(hi)) - np.ceil(np.log10(lo)) + 1
        if hi < 4 * lo:
            ax.xaxis.set_major_locator(MaxNLocator(4))
        elif decades < 2:
            ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        if decades < 2:
            ax.xaxis.set_major_formatter(FormatStrFormatter("%.2g"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    return fig


def main(argv=None, quiet=False) -> int:
    ap = OneLineParser(
        prog="charts bench accuracy",
        description="Work–precision diagrams: error against wall time for the trajectory "
        "(every formulation and method, with and without projection), the leading Lyapunov "
        "exponent and the N = 3 curvature. Writes accuracy.png, accuracy.md, accuracy.json.")
    ap.add_argument("--quick", action="store_true",
                    help="fewer settings, shorter times, one timing repeat (about a minute)")
    ap.add_argument("-o", "--output", type=Path, default=Path("bench-accuracy"), metavar="DIR",
                    help="output folder (default: ./bench-accuracy)")
    ap.add_argument("--n", type=int, default=4, help="N of the trajectory study (default 4)")
    ap.add_argument("--seed", type=int, default=0, help="seed of the initial states")
    ap.add_argument("--quiet", "-q", action="store_true", help="no progress bar")
    args = ap.parse_args(argv)
    if not 3 <= args.n <= 6:
        ap.error(f"--n {args.n}: expected 3..6")
    quiet = quiet or args.quiet
    from .io import atomic_write
    study = run_study("quick" if args.quick else "full", args.n, args.seed, progress=not quiet)
    out = args.output
    out.mkdir(parents=True, exist_ok=True)
    figure(study, out / "accuracy.png")      # written atomically by plotting.save_png
    md = table(study)
    atomic_write(out / "accuracy.md", (md + "\n").encode())
    atomic_write(out / "accuracy.json", json.dumps(study, indent=1).encode())
    if not quiet:
        print(md)
        print(f"\nreference uncertainty (a): {study['trajectory']['reference_error']:.1e}; "
              f"λ₁ reference {study['lyapunov']['lambda1_reference']:.5f} ± "
              f"{study['lyapunov']['stderr_at_T']:.5f} (paper 0.500)")
        print(f"wrote {out}/accuracy.png, accuracy.md, accuracy.json")
    return 0
