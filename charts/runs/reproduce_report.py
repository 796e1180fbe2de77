"""``report.md`` of ``charts reproduce``: a report that stands alone.

For each claim of the paper the preset checks, the report states the claim (its number and
where in the paper), our number with its sample size and standard error, and a verdict by
one rule (``charts.runs.claim_rule.verdict``: "confirmed", "not confirmed", "inconclusive",
with a one-line reason from the numbers; the claims: ``charts.runs.reproduce_claims``); then
the run lengths and seeds, what the preset cannot show (each point from the numbers), and
the tables of the paper's sections.

Everything in the report is read back from ``results.json`` (`write_report`); what the
report needs beyond the sections' tables (the errors of the curvature statistics, where the
two curvature routes differ most, the run's settings and seeds) is added to it first by
`add_measurements`.  No number is written in the report's modules but the paper's
(``charts.runs.paper``), the rule's thresholds (``charts.runs.claim_rule``) and the batch
count of the curvature errors (`CURVE_BATCHES`).
"""
from __future__ import annotations

import inspect
import json
import os
import platform

import numpy as np

from ..analyses.statistics import standard_error
from .io import atomic_text
from .claim_rule import RULE, VERDICTS
from .reproduce_claims import ANGLE_BATCHES, cannot_show, claims, curvature_gap_lines

__all__ = ["add_measurements", "report_text", "write_report", "CURVE_BATCHES"]

#: Contiguous blocks of the one curvature trajectory per N for the batch-means errors (as the
#: angle statistics' small-value law: ``charts.analyses.hyperbolicity.angle_statistics``).
CURVE_BATCHES = 10


# ------------------------------------------------------------------------ what results.json gains
def _default(func, name):
    return float(inspect.signature(func).parameters[name].default)


def _settings(cfg, tasks, curvature_transient):
    """The run's settings and seeds, from the preset ``cfg``, the task arguments ``tasks``
    (``{(kind, N, i): (function, args)}`` of ``charts.runs.reproduce``), the curvature
    tasks' transient and the defaults of the analyses the tasks leave (dt, sample steps)."""
    from ..analyses.curvature import curvature_along_trajectory
    from ..analyses.hyperbolicity import hyperbolicity_angles
    from ..analyses.lyapunov import lyapunov_settings
    from ..analyses.spectra import waveform
    from ..geometry.system import RotorSystem
    seeds = {}
    for (kind, n, _), (_, args) in sorted(tasks.items(), key=lambda kv: str(kv[0])):
        got = args[1] if isinstance(args[1], (list, tuple)) else [args[1]]
        seeds.setdefault(kind, {}).setdefault(str(n), []).extend(int(s) for s in got)
    ns = sorted({k[1] for k in tasks})
    ly = lyapunov_settings(RotorSystem(ns[0]), cfg["lyap_t"], n_batches=cfg["lyap_batches"])
    seeds = {k: {n: sorted(v) for n, v in d.items()} for k, d in seeds.items()}
    return dict(
        lyapunov=dict(members=cfg["lyap_members"], t_final=cfg["lyap_t"], dt=ly.dt,
                      t_transient=ly.transient * ly.dt, batches=cfg["lyap_batches"],
                      seeds=seeds["lyap"]),
        angles=dict(members=cfg["angle_members"], t_final=cfg["angle_t"],
                    dt=_default(hyperbolicity_angles, "dt"), t_transient=cfg["angle_transient"],
                    sample_every=_default(hyperbolicity_angles, "sample_every"),
                    seeds=seeds["angle"]),
        curvature=dict(members=1, t_final=cfg["curv_t"],
                       dt=_default(curvature_along_trajectory, "dt"),
                       t_transient=curvature_transient,
                       sample_every=_default(curvature_along_trajectory, "sample_every"),
                       batches=CURVE_BATCHES, seeds=seeds["curv"]),
        waveform=dict(members=1, t_final=cfg["wave_t"], dt=_default(waveform, "dt"),
                      sample_every=_default(waveform, "sample_every"), seeds=seeds["wave"]))


def _curvature_numbers(c, dt, batches):
    """Batch-means errors of the positive fractions (route b), the N = 3 median's error, and
    where the two routes differ most on the diagonal, from one curvature task's ``Ka``,
    ``Kb`` (S, N−2)."""
    Ka, Kb = np.asarray(c["Ka"]), np.asarray(c["Kb"])
    blocks = np.array_split(np.arange(Kb.shape[0]), batches)
    pos = Kb > 0
    fb = np.array([pos[b].mean(0) for b in blocks])
    holding = np.array([pos[b].any(0) for b in blocks]).sum(0)
    se = standard_error(fb)
    out = dict(fraction_positive_se=[float(s) if h >= 2 else None for s, h in zip(se, holding)],
               positive_count=pos.sum(0).tolist(), batches=len(blocks))
    D = np.abs(Ka - Kb)
    s, i = np.unravel_index(int(D.argmax()), D.shape)
    absK = np.abs(Kb)
    K = float(Kb[s, i])
    out["route_gap"] = dict(
        max_abs=float(D[s, i]), direction=int(i) + 1, sample=int(s), K_exact=K,
        K_numerical=float(Ka[s, i]), abs_K_p999=float(np.percentile(absK, 99.9)),
        abs_K_max=float(absK.max()), per_dt2_K2=float(D[s, i] / (dt * K) ** 2) if K else None,
        dt=dt)
    if Kb.shape[1] == 1:      # N = 3: route (b) is eq (22) to rounding (tests/test_curvature.py)
        rel = D[:, 0] / absK[:, 0]
        out["eq22_median_rel_se"] = float(standard_error([np.median(rel[b]) for b in blocks]))
    return out


def add_measurements(summary, cfg, curv, tasks, curvature_transient):
    """Add to ``summary`` (what ``results.json`` holds) what the report needs besides the
    sections' numbers: ``run`` (`_settings`) and, per N of ``curv`` (the curvature tasks'
    outputs), the batch-means errors of the curvature statistics and the largest difference
    of the two curvature routes (`_curvature_numbers`); ``curvature_transient``: the
    curvature tasks' transient."""
    run = _settings(cfg, tasks, curvature_transient)
    summary["run"] = run
    cv = run["curvature"]
    for n, c in curv.items():
        summary["curvature"][n].update(_curvature_numbers(c, cv["dt"], cv["batches"]))
    return summary


# ------------------------------------------------------------------------ the report
def _run_section(results):
    r = results["run"]
    ly, an, cv, wv = r["lyapunov"], r["angles"], r["curvature"], r["waveform"]
    ns = sorted(results["lyapunov"], key=int)

    def seeds(d):
        per = {tuple(d["seeds"][n]) for n in ns}
        s = ", ".join(str(x) for x in sorted(per)[0])
        return s + " (each N)" if len(per) == 1 else "; ".join(
            f"N = {n}: {', '.join(map(str, d['seeds'][n]))}" for n in ns)

    n_ang = results["angles"][ns[0]]["full"]["n"]
    n_curv = results["curvature"][ns[0]]["samples"]
    L = ["## Run lengths, samples and seeds", "",
         "Every trajectory starts from `RotorSystem.random_state(seed)` (unit speed, equal "
         "masses) and is integrated by RK4 with step dt.", "",
         "| analysis | trajectories × t_final | transient | dt | sampled every | samples per N "
         "| batches of the error bars | seeds |",
         "|---|---|---|---|---|---|---|---|",
         f"| Lyapunov exponents (§2) | {ly['members']} × {ly['t_final']:g} | {ly['t_transient']:g}"
         f" | {ly['dt']:g} | — | — | {ly['batches']} per trajectory, "
         f"{ly['members'] * ly['batches']} in all (and the spread of the {ly['members']} "
         f"trajectories) | {seeds(ly)} |",
         f"| angles, adjoint and CLV routes (§4) | {an['members']} × {an['t_final']:g} | "
         f"{an['t_transient']:g} forward and {an['t_transient']:g} backward | {an['dt']:g} | "
         f"{an['sample_every']:g} | {n_ang} per variant | {ANGLE_BATCHES} contiguous blocks | "
         f"{seeds(an)} |",
         f"| curvature, routes (a) and (b) (§3) | {cv['members']} × {cv['t_final']:g} | "
         f"{cv['t_transient']:g} | {cv['dt']:g} | {cv['sample_every']:g} | {n_curv} | "
         f"{cv['batches']} contiguous blocks | {seeds(cv)} |",
         f"| waveforms and spectra (figures 2, 3 only) | {wv['members']} × {wv['t_final']:g} | "
         f"— | {wv['dt']:g} | {wv['sample_every']:g} | — | — | {seeds(wv)} |", ""]
    return L


def _claims_section(rows):
    L = ["## The paper's claims and our verdicts", "", RULE, "",
         "| claim | where in the paper | paper | ours (± s.e.) | n | verdict | why |",
         "|---|---|---|---|---|---|---|"]
    for c in rows:
        cells = [c["claim"], c["where"], c["paper"], c["ours"], c["n"], f"**{c['verdict']}**",
                 c["reason"]]
        L.append("| " + " | ".join(x.replace("|", "\\|") for x in cells) + " |")
    counts = {w: sum(c["verdict"] == w for c in rows) for w in VERDICTS}
    L += ["", "In all: " + ", ".join(f"{k} {w}" for w, k in counts.items()) + ".", ""]
    return L


def _sections(results, table):
    """The sections' tables: exponents, curvature (with the two routes' difference), angles."""
    ns = sorted(results["lyapunov"], key=int)
    curv, ang = results["curvature"], results["angles"]
    small = ang[ns[0]]["full"]["small"]
    L = ["## Lyapunov exponents (section 2)", "",
         "Leading N−2 exponents, θ-only inner product (the paper's), tangent vectors kept in "
         "the constraint-preserving subspace.  Standard error: the larger of pooled batch "
         "means and the spread of the independent trajectories (two-sided).  The full "
         "spectrum is (λ…, 0, 0, −λ…).", "", table, "",
         "## Curvature (section 3, figure 4)", "",
         "| N | K_ii | fraction > 0 (route b) | ± s.e. | route (a) vs (b): median rel. diff "
         "| max abs diff |",
         "|---|------|------------------------|--------|-----------------------------------"
         "|--------------|"]
    for n in ns:
        c = curv[n]
        for i, f in enumerate(c["fraction_positive"]):
            se = c["fraction_positive_se"][i]
            L.append(f"| {n} | K_{i + 1}{i + 1} | {f:.4f} | "
                     f"{'—' if se is None else format(se, '.4f')} | "
                     f"{c['median_rel_ab']:.1e} | {c['max_ab']:.1e} |")
    L += [""] + curvature_gap_lines(results) + [
        "Eq (21) needs a minus sign (Jacobi equation c̈ + Kc = 0); with it, N = 3 curvature is "
        "negative everywhere, as eq (22) says.", "",
        "## Hyperbolicity angles (section 4, figure 5)", "",
        f"| N | variant | min φ (rad) | fraction φ < {small:g} | samples below | 1st percentile "
        "| samples |",
        "|---|---------|-------------|------------------|-----|----------------|---------|"]
    for n in ns:
        for var in ("full", "restricted"):
            s = ang[n][var]
            L.append(f"| {n} | {var} | {s['min']:.2e} | {s['frac_small']:.4g} | "
                     f"{s['law_count']} | {s['p01']:.3f} | {s['n']} |")
    L += ["", "*full*: the paper's variant, E_cs in all of R^{2N}, containing the two "
          "non-physical directions that break the constraint; *restricted*: everything in the "
          "invariant constraint-preserving subspace T_r (the physical phase space's tangent "
          "space).  Only the restricted angles are intrinsic: the full variant depends on how "
          "eq (8) is continued off the constraint manifold.", ""]
    return L


def _compile_share(results) -> str:
    """What part of the wall time was the workers' compiling (results.json's
    ``compile_wall_s``, the wall time of the compiling before the tasks, where
    ``compile_summed_s``, the workers' compile events, says that something was compiled;
    files written before they were recorded have none: nothing is said)."""
    spent = results.get("compile_wall_s")
    if spent is None:
        return ""
    if results.get("compile_summed_s", spent) < 0.5:
        return " (the kernels loaded from numba's cache, none compiled)"
    return (f" ({spent:.0f} s of it compiling the kernels, once: a run on the filled cache "
            "does without)")


def report_text(results, table, clv_lines, command="", host=""):
    """report.md from ``results`` (``results.json`` as read back), ``table`` (table.md's
    text) and ``clv_lines`` (``charts.runs.reproduce_clv.report_lines``)."""
    rows = claims(results)
    dt = results["run"]["lyapunov"]["dt"]
    L = [f"# Reproduction of Kuznetsov, rotators with Σcos θ = 0 — preset `{results['preset']}`",
         "", f"Command: `{command}`; wall time {results['elapsed_s']:.0f} s"
         f"{_compile_share(results)} on "
         f"{results['workers']} worker processes{host}.  Unit speed, equal masses, RK4 "
         f"dt = {dt:g}.  Every number below is read from results.json.", ""]
    L += _claims_section(rows) + _run_section(results)
    L += ["## What this preset cannot show", ""] + cannot_show(results) + [""]
    L += _sections(results, table) + list(clv_lines)
    return "\n".join(L) + "\n"


def write_report(out, clv_lines):
    """Write ``out/report.md`` from ``out/results.json`` and ``out/table.md`` (written
    before, with `add_measurements`' numbers)."""
    results = json.loads((out / "results.json").read_text())
    table = (out / "table.md").read_text().strip()
    host = f" ({platform.processor() or platform.machine()}, {os.cpu_count()} cores)"
    text = report_text(results, table, clv_lines,
                       f"charts reproduce --{results['preset']} -o {out}", host)
    atomic_text(out / "report.md", text)
    return out / "report.md"


