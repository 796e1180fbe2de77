"""``charts reproduce``: every result of the paper from one command.

    charts reproduce [--quick|--full] [-o DIR] [--quiet] [--workers K]
    python -m charts.runs.reproduce --quick

Writes into DIR (default ``reproduce-out``): ``table.md`` (Lyapunov exponents with
error bars beside the paper's), ``fig2.png`` … ``fig5.png`` (the paper's panel layouts),
``results.json`` (all numbers), ``report.md`` (each claim of the paper with our number, its
error and a verdict, the run lengths, what the preset cannot show:
``charts.runs.reproduce_report``), and the hyperbolicity test by a second route (covariant
Lyapunov vectors on the trajectories of the angle test, ``charts.runs.reproduce_clv``:
``clv.png``, ``ftle.png``).
Independent trajectories run in parallel processes (all cores by default).  Each finished
trajectory is kept in ``DIR/pieces/`` as it finishes (``.npz`` with JSON metadata, never
pickle: ``charts.runs.pieces``): a reproduction interrupted (Ctrl-C, exit 130; SIGTERM, exit
143) and run again with the same command computes only the missing pieces.

Presets (unit speed, equal masses, RK4 dt = 0.01 everywhere):

=============  ====================================  ==========================
preset          Lyapunov                              angles / curvature
=============  ====================================  ==========================
quick           4 trajectories × t = 5·10³ per N      2 × 2·10³ / t = 10³
full            8 trajectories × t = 2.5·10⁴ per N    4 × 2.5·10⁴ / t = 10⁴
=============  ====================================  ==========================

The angles of both routes (adjoint and CLV) use transients of ``angle_transient`` = 200
forward and backward.
"""
from __future__ import annotations

import json
import os
import sys
import time
from concurrent.futures import as_completed

import numpy as np

from ..analyses.statistics import standard_error
from ..analyses.worker_pool import worker_pool, workers_of
from .io import atomic_text
from .outdir import OutputLock, prepare_output
from .pieces import kept_pieces, load_piece, save_piece
from . import reproduce_clv, reproduce_report
from .paper import PAPER_EXPONENTS
from .cli_parser import OneLineParser, positive_count
from .interrupts import handled, exit_status, interrupt_for, quiet_worker

__all__ = ["main", "PRESETS", "PAPER_EXPONENTS"]

NS = (3, 4, 5)
EXIT_INTERRUPTED = 130

PRESETS = {
    "quick": dict(lyap_members=4, lyap_t=5.0e3, lyap_batches=10, angle_members=2, angle_t=2.0e3,
                  curv_t=1.0e3, wave_t=4.0e3, angle_transient=200.0),
    "full": dict(lyap_members=8, lyap_t=2.5e4, lyap_batches=25, angle_members=4, angle_t=2.5e4,
                 curv_t=1.0e4, wave_t=2.0e4, angle_transient=200.0),
}


# ------------------------------------------------------------------------ worker tasks
def _task_lyapunov(n, seeds, t, batches):
    """The members ``seeds`` of N by `lyapunov_lanes` (in the lanes of one kernel where they
    pay, else one by one; each equal to ``lyapunov_spectrum`` from ``random_state(seed)``),
    stacked along a first member axis."""
    from ..analyses.lyapunov import lyapunov_settings
    from ..analyses.lyapunov_members import lyapunov_lanes
    from ..geometry.system import RotorSystem
    s = RotorSystem(n)
    cfg = lyapunov_settings(s, t, n_batches=batches, seed=seeds[0], t_transient=50.0)
    rs = lyapunov_lanes((s, cfg, list(seeds), 1.0))
    return dict(exponents=np.array([r.exponents for r in rs]),
                stderr=np.array([r.stderr for r in rs]),
                batches=np.array([r.batches for r in rs]), history_t=rs[0].history_t,
                history=np.array([r.history for r in rs]))


def _task_angles(n, seed, t, t_transient):
    from ..analyses.hyperbolicity import hyperbolicity_angles
    from ..geometry.system import RotorSystem
    s = RotorSystem(n)
    th, u = s.random_state(seed=seed)
    r = hyperbolicity_angles(s, th, u, t, t_transient=t_transient, seed=seed)
    return dict(phi_full=r.phi_full, phi_restricted=r.phi_restricted,
                forward=r.forward_exponents, adjoint=r.adjoint_exponents)


#: The curvature tasks' transient, written (the API's default is a rule of N since): the
#: presets' numbers stay those they were measured with.
CURVATURE_TRANSIENT = 50.0


def _task_curvature(n, seed, t):
    from ..analyses.curvature import curvature_along_trajectory, gaussian_curvature_eq22
    from ..geometry.system import RotorSystem
    s = RotorSystem(n)
    th, u = s.random_state(seed=seed)
    r = curvature_along_trajectory(s, th, u, t, t_transient=CURVATURE_TRANSIENT)
    out = dict(Ka=r.diagonal("numerical"), Kb=r.diagonal("exact"),
               max_ab=float(np.abs(r.K_numeric - r.K_exact).max()),
               median_rel_ab=float(np.median(np.abs(r.K_numeric - r.K_exact).max(axis=(1, 2))
                                             / np.abs(r.K_exact).max(axis=(1, 2)))))
    if n == 3:
        K22 = gaussian_curvature_eq22(r.theta)
        rel = np.abs(r.K_numeric[:, 0, 0] - K22) / np.abs(K22)
        out.update(eq22_median_rel=float(np.median(rel)), eq22_max_abs=float(
            np.abs(r.K_numeric[:, 0, 0] - K22).max()))
    return out


def _task_waveform(n, seed, t):
    from ..analyses.spectra import power_spectrum, waveform
    from ..geometry.system import RotorSystem
    s = RotorSystem(n)
    th, u = s.random_state(seed=seed)
    w = waveform(s, th, u, t, t_transient=10.0)
    om, p = power_spectrum(w.u[:, 0], w.dt_sample)
    sel = w.t - w.t[0] <= 100.0
    return dict(t=w.t[sel], u=w.u[sel], dt_sample=w.dt_sample, omega=om, psd=p)


# ------------------------------------------------------------------------ orchestration
def _tasks(cfg):
    tasks = {}
    for n in NS:
        tasks.update(_lyapunov_tasks(n, cfg))
        for i in range(cfg["angle_members"]):
            a = (n, 200 + i, cfg["angle_t"], cfg["angle_transient"])
            tasks[("angle", n, i)] = (_task_angles, a)
            tasks[("clv", n, i)] = (reproduce_clv.task_clv, a)
        tasks[("curv", n, 0)] = (_task_curvature, (n, 300, cfg["curv_t"]))
        tasks[("wave", n, 0)] = (_task_waveform, (n, 400, cfg["wave_t"]))
    return tasks


def _lyapunov_tasks(n, cfg):
    """The Lyapunov members of N: one task in the lanes of one kernel where they pay
    (``charts.solvers.lanes.lanes_pay``: compiled for N, or long enough), else one task per
    member, so that the pool balances them (the same numbers either way)."""
    from ..analyses.lyapunov import lyapunov_settings
    from ..analyses.lyapunov_members import members_pay
    from ..geometry.system import RotorSystem

    seeds = list(range(100, 100 + cfg["lyap_members"]))
    t, batches = cfg["lyap_t"], cfg["lyap_batches"]
    system = RotorSystem(n)
    if members_pay(system, lyapunov_settings(system, t, n_batches=batches), len(seeds)):
        return {("lyap", n, 0): (_task_lyapunov, (n, seeds, t, batches))}
    return {("lyap", n, i): (_task_lyapunov, (n, [s], t, batches)) for i, s in enumerate(seeds)}


def _lyapunov_members(results, n):
    """The Lyapunov task results of N (one task, or one per member) as one, stacked along
    the member axis."""
    parts = [results[k] for k in sorted(k for k in results if k[:2] == ("lyap", n))]
    out = {k: np.concatenate([p[k] for p in parts]) for k in ("exponents", "stderr", "batches",
                                                             "history")}
    return dict(out, history_t=parts[0]["history_t"])


def _run_all(cfg, workers, quiet, pieces=None, timings=None):
    """Every task's result; with ``pieces`` (a folder), each finished task is kept there
    (:func:`save_piece`) and a task already kept with the same arguments is not run again;
    ``timings`` (a dict), if given, receives ``compile_wall_s``: the wall time of the
    workers' compiling (or loading) before the tasks, and ``compile_summed_s``: each worker's
    compiling wall time, summed (numba's compile events: 0 when every kernel was loaded
    from the cache; both 0 when every task was kept)."""
    tasks = _tasks(cfg)
    results = {}
    if pieces is not None:
        for key, (f, a) in tasks.items():
            got = load_piece(pieces, key, a)
            if got is not None:
                results[key] = got
        if results and not quiet:
            print(f"reusing {len(results)} of {len(tasks)} finished pieces from {pieces}",
                  file=sys.stderr)
    from tqdm.auto import tqdm
    pool = worker_pool(workers, initializer=quiet_worker)
    try:
        compiled = _compile_first(pool, workers, quiet) if len(results) < len(tasks) \
            else (0.0, 0.0)
        if timings is not None:
            timings.update(compile_wall_s=compiled[0], compile_summed_s=compiled[1])
        futs = {pool.submit(f, *a): key for key, (f, a) in tasks.items() if key not in results}
        with tqdm(total=len(tasks), initial=len(results), desc="reproduce", disable=quiet) as bar:
            for fut in as_completed(futs):
                key = futs[fut]
                results[key] = fut.result()
                if pieces is not None:
                    save_piece(pieces, key, tasks[key][1], results[key])
                bar.update(1)
    except BaseException as exc:
        _stop(pool)                     # the pieces in flight are lost, the finished ones kept
        interrupt = interrupt_for(exc)
        if interrupt is not None:       # the pool broke under a Ctrl-C or SIGTERM: that
            raise interrupt from None   # interrupt, not a failure
        raise
    pool.shutdown()
    return results


def _stop(pool):
    """Stop ``pool`` now: what is queued cancelled, its workers killed and reaped (a worker
    in the middle of a piece would otherwise run it to its end, and the command with it)."""
    workers = workers_of(pool)
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in workers:
        proc.kill()
    for proc in workers:
        proc.join()


def _compile_first(pool, workers, quiet):
    """The kernels of every task, each compiled once by one worker (`charts warmup`'s
    stages) before the tasks start, instead of by every worker at once on an empty cache;
    with the cache filled, the workers load them here (what the tasks would do anyway).
    Returns (the wall time it took, each worker's compiling wall time summed), in s; the
    notice gives both (the sum is longer than the wall time when the workers compile at
    once; it is not CPU time)."""
    from contextlib import nullcontext

    from ..jit.compilation import NOTE_SECONDS, compiling_line
    from .warmup import warmup
    where = f" in its {workers} worker processes"
    start = time.perf_counter()
    with nullcontext() if quiet else compiling_line("reproduce", where + ", before the tasks"):
        spent = sum(r["compile"] for r in warmup(NS, ["lyapunov", "angles", "clv", "curvature"],
                                                 pool=pool))
    wall = time.perf_counter() - start
    if not quiet and spent > NOTE_SECONDS:
        print(f"charts: reproduce compiled its kernels{where} in {wall:.1f} s of wall time "
              f"({spent:.1f} s: each worker's compiling wall time, summed; once: they are "
              "cached on disk for the next runs)", file=sys.stderr, flush=True)
    return wall, spent


PIECES = "pieces"


def _lyapunov_table(results, cfg):
    rows = {}
    for n in NS:
        lyap = _lyapunov_members(results, n)
        E = np.asarray(lyap["exponents"])
        B = np.concatenate(lyap["batches"])
        mean = E.mean(0)
        se_batch = standard_error(B)   # pooled batch means
        se_ens = standard_error(E)     # spread of the trajectories
        rows[n] = dict(exponents=mean.tolist(), stderr=np.maximum(se_batch, se_ens).tolist(),
                       stderr_batch=se_batch.tolist(), stderr_ensemble=se_ens.tolist(),
                       paper=PAPER_EXPONENTS[n], t_total=cfg["lyap_members"] * cfg["lyap_t"])
    return rows


def _fmt_table(rows):
    lines = ["| N | k | ours | ± s.e. | paper | (ours − paper)/s.e. |",
             "|---|---|------|--------|-------|---------------------|"]
    for n, r in rows.items():
        for k, (e, s, p) in enumerate(zip(r["exponents"], r["stderr"], r["paper"])):
            lines.append(f"| {n} | λ{k + 1} | {e:.4f} | {s:.4f} | {p:.3f} | {(e - p) / s:+.1f} |")
    return "\n".join(lines)


def main(argv=None):
    p = OneLineParser(prog="charts reproduce", description=__doc__.splitlines()[0])
    g = p.add_mutually_exclusive_group()
    g.add_argument("--quick", dest="preset", action="store_const", const="quick",
                   help="a few minutes on 2 cores (default)")
    g.add_argument("--full", dest="preset", action="store_const", const="full",
                   help="publication accuracy (exponents to ±0.001)")
    p.add_argument("-o", "--output", default="reproduce-out", help="output folder")
    p.add_argument("--quiet", action="store_true", help="no progress bars")
    p.add_argument("--workers", type=positive_count, default=None, help="processes (default: all cores)")
    args = p.parse_args(argv)
    preset = args.preset or "quick"
    cfg = PRESETS[preset]
    out = prepare_output(args.output)
    workers = args.workers or os.cpu_count() or 1
    with OutputLock(out, f"charts reproduce --{preset}"):
        pieces = prepare_output(out / PIECES)
        try:
            return _reproduce(out, pieces, preset, cfg, workers, args.quiet)
        except KeyboardInterrupt:
            kept = len(kept_pieces(pieces))
            print(f"\ninterrupted: {kept} of {len(_tasks(cfg))} pieces kept in {pieces}; run "
                  f"the same command again to continue:\n  charts reproduce --{preset} "
                  f"-o {out}", file=sys.stderr)
            return EXIT_INTERRUPTED


def _reproduce(out, pieces, preset, cfg, workers, quiet) -> int:
    t0 = time.time()
    timings = {}
    results = _run_all(cfg, workers, quiet, pieces, timings)
    from . import paper_figures
    from ..analyses.hyperbolicity import angle_statistics
    from ..analyses.spectra import Waveform
    rows = _lyapunov_table(results, cfg)
    curv = {n: results[("curv", n, 0)] for n in NS}
    ang, ang_raw = {}, {}
    for n in NS:
        mem = [results[("angle", n, i)] for i in range(cfg["angle_members"])]
        pf = np.concatenate([m["phi_full"] for m in mem])
        pr = np.concatenate([m["phi_restricted"] for m in mem])
        ang_raw[n] = (pf, pr)
        ang[n] = dict(full=angle_statistics(pf), restricted=angle_statistics(pr),
                      forward=[m["forward"].tolist() for m in mem],
                      adjoint=[m["adjoint"].tolist() for m in mem])
    clv, pairs, ftle = {}, {}, {}
    for n in NS:
        mem = [results[("clv", n, i)] for i in range(cfg["angle_members"])]
        amem = [results[("angle", n, i)] for i in range(cfg["angle_members"])]
        clv[n] = reproduce_clv.summarise(mem, amem)
        pairs[n] = {v: (ang_raw[n][v == "restricted"],
                        np.concatenate([m[v]["phi"] for m in mem])) for v in ("full", "restricted")}
        ftle[n] = {w: np.concatenate([m["ftle"][w] for m in mem]) for w in reproduce_clv.FTLE_WINDOWS}
    reproduce_clv.figure_clv(pairs, out / "clv.png")
    reproduce_clv.figure_ftle(ftle, out / "ftle.png")
    waves = {n: results[("wave", n, 0)] for n in NS}
    paper_figures.figure2({n: Waveform(w["t"], None, w["u"], w["dt_sample"]) for n, w in waves.items()},
                    out / "fig2.png")
    paper_figures.figure3({n: (w["omega"], w["psd"]) for n, w in waves.items()}, out / "fig3.png")
    paper_figures.figure4({n: curv[n]["Ka"] for n in NS}, out / "fig4.png")
    paper_figures.figure5(ang_raw, out / "fig5.png")
    elapsed = time.time() - t0
    atomic_text(out / "table.md", _fmt_table(rows) + "\n")
    summary = dict(preset=preset, config=cfg, elapsed_s=elapsed, workers=workers,
                   **timings,
                   lyapunov=rows,
                   curvature={n: {k: v for k, v in c.items() if not isinstance(v, np.ndarray)}
                              | dict(fraction_positive=(c["Kb"] > 0).mean(0).tolist(),
                                     samples=int(c["Kb"].shape[0])) for n, c in curv.items()},
                   angles=ang, clv=clv)
    reproduce_report.add_measurements(summary, cfg, curv, _tasks(cfg), CURVATURE_TRANSIENT)
    atomic_text(out / "results.json", json.dumps(summary, indent=1, default=float))
    reproduce_report.write_report(out, reproduce_clv.report_lines(clv, NS, cfg["angle_transient"]))
    if not quiet:
        print(_fmt_table(rows))
        print(f"wrote {out}/report.md, table.md, results.json, fig2-5.png, clv.png, ftle.png "
              f"in {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    with handled():                     # SIGTERM as Ctrl-C (exit 143): charts.runs.interrupts
        sys.exit(exit_status(main()))
