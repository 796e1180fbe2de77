"""Sweep tables -> summaries over seeds, markdown, and figures over the swept parameters.

:func:`summarize` groups the rows of ``sweep.csv`` by their parameters without the seed;
:func:`write_summary` writes ``summary.csv`` and ``summary.md``; :func:`plot_sweep` draws
one PNG per headline statistic (curves over one numeric parameter, heat maps over two,
bars otherwise) and ``overview.png``.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...analyses.angle_tally import SMALL_ANGLE
from ...io.result_words import RATE
from ...analyses.spectrum_quantities import leading_entropy_with_error
from ...analyses.statistics import standard_error
from ..io import atomic_text
from ..scene import positive_exponents
from ...plotting.style import new_figure, save_png
from .limits import limit_of, limit_row, plot_limit_sweep
from .points import SweepPoint
from .statistics import KS_ENTROPY
from .table import HEAD, TAIL, WEIGHT_VECTOR, csv_text, format_cell

__all__ = ["summarize", "write_summary", "summary_markdown", "plot_sweep", "PLOTTED", "SUMMARY"]

SUMMARY = "summary.csv"
#: Statistics that get a figure (the others are in the tables only).
PLOTTED = ("lambda_", KS_ENTROPY[0], "Kpos_", "phi_full_min", "phi_restricted_min",
           "phi_full_frac", "phi_restricted_frac")


# --------------------------------------------------------------------------- summary
def _num(s):
    """A table cell as a number: an integer stays an integer (N, seeds, counts), others
    float; non-numbers as they are."""
    for kind in (int, float):
        try:
            return kind(s)
        except (TypeError, ValueError):
            continue
    return s


def summarize(header: list[str], rows: list[dict], points: list[SweepPoint]) -> dict:
    """Average over seeds: one entry per parameter combination.  Each statistic ``c`` gets
    ``c`` (mean over seeds; the minimum for ``*_min``) and ``c_se``: the larger of the
    standard error from the spread over seeds and the one propagated from the points' own
    errors (``lambda_i_se``, batch means), as either alone can be too small.  ``h_ks``
    (Pesin's sum of the positive exponents) is summed per seed over the exponents positive
    in the mean over the seeds, then averaged (`_entropy_over_seeds`), with the same rule
    for its ``h_ks_se``."""
    params = [c for c in header[len(HEAD):] if c in points[0].params and c != "seed"]
    stats = [c for c in header if c not in HEAD + TAIL + params + ["seed", WEIGHT_VECTOR]
             and not c.endswith("_se")]
    by_id = {p.point_id: p for p in points}
    groups: dict = {}
    for r in rows:
        if r["status"] != "complete":
            continue
        groups.setdefault(tuple(r[c] for c in params), []).append(r)
    out = []
    for key, rs in groups.items():
        entry = {c: _num(v) for c, v in zip(params, key)}
        entry["n_seeds"] = len(rs)
        for c in stats:
            vals = np.array([float(r[c]) for r in rs if r.get(c, "") != ""])
            if not vals.size:
                continue
            entry[c] = float(vals.min() if c.endswith("_min") else vals.mean())
            ses = []
            if vals.size >= 2 and not c.endswith("_min"):
                ses.append(standard_error(vals))
            own = [float(r[c + "_se"]) for r in rs if r.get(c + "_se", "") != ""]
            if own and len(own) == vals.size:       # the points' own (batch-means) errors
                ses.append(np.sqrt(np.sum(np.square(own))) / len(own))
            if ses:                                 # two seeds alone underestimate often
                entry[c + "_se"] = float(max(ses))
        if KS_ENTROPY[0] in stats:
            _entropy_over_seeds(entry, rs, positive_exponents(by_id[rs[0]["point_id"]].scene))
        out.append(entry)
    return {"params": params, "stats": stats, "rows": out, "limit": limit_of(params, points)}


def _entropy_over_seeds(entry: dict, rs: list, k: int) -> None:
    """``h_ks`` and ``h_ks_se`` of one parameter combination from its seeds' rows ``rs``:
    each seed's h_KS summed over the leading k (N − 2; d − 1 of a d-dimensional mechanism)
    exponents positive in the mean over the
    seeds (``leading_entropy_with_error``: an exponent consistent with zero counts for every
    seed or for none), their mean, and as the error the larger of the standard error of the
    seeds' sums and the one propagated from their own (batch-means) ``h_ks_se``."""
    h, se = KS_ENTROPY
    lam = [f"lambda_{i}" for i in range(1, k + 1)]
    rs = [r for r in rs if r.get(h, "") != "" and all(r.get(c, "") != "" for c in lam)]
    entry.pop(h, None)
    entry.pop(se, None)
    if not rs:
        return
    E = np.array([[float(r[c]) for c in lam] for r in rs])
    value, spread = leading_entropy_with_error(E.mean(axis=0), E, k)
    entry[h] = value
    ses = [spread] if len(rs) >= 2 else []
    own = [float(r[se]) for r in rs if r.get(se, "") != ""]
    if own and len(own) == len(rs):
        ses.append(np.sqrt(np.sum(np.square(own))) / len(own))
    if ses:
        entry[se] = float(max(ses))


def write_summary(path: Path, summary: dict) -> None:
    """``summary.csv`` at ``path`` (every statistic and its ``_se``) and ``summary.md``."""
    cols = summary["params"] + ["n_seeds"]
    for c in summary["stats"]:
        cols += [c, c + "_se"]
    atomic_text(path, csv_text(cols, ([format_cell(e.get(c)) for c in cols]
                                      for e in summary["rows"])))
    atomic_text(path.with_suffix(".md"), summary_markdown(summary))


def summary_markdown(summary: dict) -> str:
    """The headline statistics as a markdown table (exponents and fractions of positive
    curvature ± s.e., angle minima and 0.1 % quantiles); every column is in summary.csv."""
    stats = [c for c in summary["stats"] if c.startswith("lambda_") or c == KS_ENTROPY[0]
             or (c.startswith("Kpos_exact") or (c.startswith("Kpos_numerical")
                                                and not any(x.startswith("Kpos_exact")
                                                            for x in summary["stats"])))
             or c.endswith("_min") or c == "phi_restricted_p001"]
    head = summary["params"] + ["seeds"] + stats
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for e in summary["rows"]:
        cells = [f"{e[p]:g}" if isinstance(e[p], float) else str(e[p]) for p in summary["params"]]
        cells.append(str(e["n_seeds"]))
        for c in stats:
            v, se = e.get(c), e.get(c + "_se")
            if v is None:
                cells.append("")
            elif c.startswith("lambda_") or c == KS_ENTROPY[0]:
                cells.append(f"{v:.4f} ± {se:.4f}" if se is not None else f"{v:.4f}")
            elif c.startswith("phi_"):
                cells.append(f"{v:.1e}")
            elif c.startswith("Kpos_") and se is not None:
                cells.append(f"{v:.3f} ± {se:.3f}")
            else:
                cells.append(f"{v:.3f}")
        lines.append("| " + " | ".join(cells) + " |")
    lines += limit_row(summary, stats)     # a sweep toward a limit (ε → 0, r → 0): the paper's
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- plots
def _label(stat: str) -> str:
    parts = stat.split("_")
    if parts[0] == "lambda":
        return f"λ{parts[1]}"
    if stat == KS_ENTROPY[0]:
        return "h_KS = Σ λᵢ > 0 (Pesin)"
    if parts[0] in ("Kpos", "Kmean"):
        d = "some K_ii" if parts[2] == "any" else f"K_{parts[2]}{parts[2]}"
        if parts[0] == "Kpos":
            return f"fraction of samples with {d} > 0 ({parts[1]})"
        return f"mean {d} ({parts[1]})"
    if parts[0] == "phi":
        what = "_".join(parts[2:])
        if what == "frac_small":
            return f"fraction of angles φ < {SMALL_ANGLE:g} rad ({parts[1]} space)"
        return f"φ {what} ({parts[1]} space) [rad]"
    return stat


def _axis_label(stat: str) -> str:
    """The value axis of ``stat``, with its unit."""
    if stat.startswith("lambda_") or stat == KS_ENTROPY[0]:
        return f"{_label(stat)} ({RATE})"
    if stat.startswith(("Kpos_", "phi_full_frac", "phi_restricted_frac")):
        return "fraction of samples"
    if stat.startswith("phi_"):
        return "φ (rad)"
    return stat


def _fixed(rows, params) -> str:
    """The parameters that keep one value over the rows ("n=4, pattern=(1,m,1,m)")."""
    out = []
    for p in params:
        vals = {str(r[p]) for r in rows}
        if len(vals) == 1:
            v = rows[0][p]
            out.append(f"{p}={v:g}" if isinstance(v, float) else f"{p}={v}")
    return ", ".join(out)


def plot_sweep(summary: dict, folder, title="") -> list[str]:
    """One PNG per statistic: curves over the one numeric swept parameter (one line per
    value of the others, error bars = ``_se``), a heat map over the first two numeric
    parameters (one panel per value of the others), or bars when nothing numeric varies."""
    from matplotlib.colors import LogNorm, Normalize

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    rows, params = summary["rows"], summary["params"]
    if not rows:
        return []
    varying = [p for p in params if len({str(r[p]) for r in rows}) > 1]
    numeric = [p for p in varying if all(isinstance(r[p], float) for r in rows)]
    groups_by = [p for p in varying if p not in numeric[:2]]
    gkey = lambda r: tuple(r[p] for p in groups_by)
    glabel = lambda k: ", ".join(f"{p}={v:g}" if isinstance(v, float) else f"{p}={v}"
                                 for p, v in zip(groups_by, k)) or "all"
    groups = sorted({gkey(r) for r in rows}, key=str)
    files = []
    for stat in summary["stats"]:
        if not stat.startswith(PLOTTED):
            continue
        have = [r for r in rows if stat in r]
        if not have:
            continue
        logy = stat.startswith("phi_") and not stat.endswith("frac_small") and \
            all(r[stat] > 0 for r in have)
        if len(numeric) == 1:
            x = numeric[0]
            fig, ax = new_figure(figsize=(5.2, 3.6))
            _curves(ax, have, stat, x, groups, gkey, glabel, ms=3.5, capsize=2.5)
            ax.set_xlabel(x)
            ax.set_ylabel(_axis_label(stat), fontsize=8)
            if len(groups) > 1:
                ax.legend(fontsize=7)
        elif len(numeric) >= 2:
            x, y = numeric[:2]
            fig, axs = new_figure(1, len(groups), figsize=(4.2 * len(groups), 3.6),
                                  squeeze=False)
            vals = [r[stat] for r in have]
            norm = LogNorm() if logy else Normalize(min(vals), max(vals))
            for ax, g in zip(axs[0], groups):
                rs = [r for r in have if gkey(r) == g]
                xs, ys = sorted({r[x] for r in rs}), sorted({r[y] for r in rs})
                if len(xs) * len(ys) == len(rs):          # a full grid: a heat map
                    Z = np.full((len(ys), len(xs)), np.nan)
                    for r in rs:
                        Z[ys.index(r[y]), xs.index(r[x])] = r[stat]
                    im = ax.imshow(Z, origin="lower", aspect="auto", norm=norm, cmap="viridis")
                    ax.set_xticks(range(len(xs)), [f"{v:g}" for v in xs], fontsize=7)
                    ax.set_yticks(range(len(ys)), [f"{v:g}" for v in ys], fontsize=7)
                else:                                      # a random sample: a scatter
                    im = ax.scatter([r[x] for r in rs], [r[y] for r in rs],
                                    c=[r[stat] for r in rs], norm=norm, cmap="viridis", s=25)
                ax.set_xlabel(x)
                ax.set_ylabel(y)
                ax.set_title(glabel(g), fontsize=8)
            fig.colorbar(im, ax=axs[0].tolist(), shrink=0.9, label=_axis_label(stat))
            ax = axs[0][0]
        else:
            fig, ax = new_figure(figsize=(5.2, 3.6))
            ax.bar(range(len(have)), [r[stat] for r in have],
                   yerr=[r.get(stat + "_se", 0.0) or 0.0 for r in have])
            ax.set_xticks(range(len(have)), [glabel(gkey(r)) for r in have], rotation=30,
                          fontsize=7)
            ax.set_ylabel(_axis_label(stat), fontsize=8)
        if logy and len(numeric) < 2:
            ax.set_yscale("log")
        fixed = _fixed(rows, params)
        fig.suptitle(f"{title}: {_label(stat)}" + (f"\n({fixed})" if fixed else ""), fontsize=9)
        path = folder / f"{stat}.png"
        save_png(fig, path)
        files.append(str(path))
    if len(numeric) == 1:
        files.append(_overview(summary, folder, title, numeric[0], groups, gkey, glabel))
    files += plot_limit_sweep(summary, folder, title)
    return files


def _curves(ax, rows, stat, x, groups, gkey, glabel, **style) -> None:
    """``stat`` over ``x`` with error bars, one line per group; log x when it fits."""
    for g in groups:
        rs = sorted((r for r in rows if gkey(r) == g and stat in r), key=lambda r: r[x])
        ax.errorbar([r[x] for r in rs], [r[stat] for r in rs],
                    yerr=[r.get(stat + "_se", 0.0) or 0.0 for r in rs], marker="o",
                    label=glabel(g), **style)
    _log_x(ax, [r[x] for r in rows])


def log_spaced(xs) -> bool:
    """Whether positive grid values are best drawn on a log axis: they span a decade or so,
    or at least three distinct values are spaced evenly in log and not evenly (a geometric
    grid such as 0.25, 0.5, 1, 2)."""
    v = np.unique(np.asarray(xs, dtype=float))
    if v.size < 2 or v[0] <= 0:
        return False
    if v[-1] / v[0] >= 8:
        return True
    if v.size < 3:
        return False
    steps, ratios = np.diff(v), np.diff(np.log(v))
    return bool(np.ptp(ratios) <= 0.05 * ratios.mean() and np.ptp(steps) > 0.05 * steps.mean())


def _log_x(ax, xs) -> None:
    """Log x axis labelled at the data values where `log_spaced` says so."""
    from matplotlib.ticker import NullFormatter
    if log_spaced(xs):
        ax.set_xscale("log")
        ticks = sorted(set(xs))
        ax.set_xticks(ticks, [f"{v:g}" for v in ticks], fontsize=7)
        ax.xaxis.set_minor_formatter(NullFormatter())


def _overview(summary, folder, title, x, groups, gkey, glabel) -> str:
    """One figure with a panel per headline statistic (exponents, fraction of positive
    curvature in any velocity plane, minimum angles) over the one numeric parameter."""
    stats = [c for c in summary["stats"] if c.startswith("lambda_")
             or (c.startswith("Kpos_") and c.endswith("_any")) or c.endswith("_min")
             or c == "phi_restricted_p001"]
    exact = [c for c in stats if c.startswith("Kpos_exact")]
    stats = [c for c in stats if not (c.startswith("Kpos_numerical") and exact)]
    ncol = min(3, len(stats))
    nrow = -(-len(stats) // ncol)
    fig, axs = new_figure(nrow, ncol, figsize=(4.0 * ncol, 2.9 * nrow), squeeze=False)
    for ax, stat in zip(axs.flat, stats):
        _curves(ax, summary["rows"], stat, x, groups, gkey, glabel, ms=3, capsize=2)
        if stat.startswith("phi_") and not stat.endswith("frac_small"):
            ax.set_yscale("log")
        ax.set_title(_label(stat), fontsize=8)
        ax.set_xlabel(x, fontsize=8)
        ax.set_ylabel(_axis_label(stat), fontsize=7)
    for ax in list(axs.flat)[len(stats):]:
        ax.set_visible(False)
    if len(groups) > 1:
        axs.flat[0].legend(fontsize=7)
    fixed = _fixed(summary["rows"], summary["params"])
    fig.suptitle(title + (f" ({fixed})" if fixed else ""), fontsize=10)
    path = folder / "overview.png"
    save_png(fig, path)
    return str(path)
