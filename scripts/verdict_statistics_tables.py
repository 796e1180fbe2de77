"""The tables and the figure of docs/hyperbolicity.md's statistics at scale, from the reports
that ``charts verdict --statistics`` wrote (``scripts/gpu_statistics.sh`` on a GPU machine; the
reports of the run quoted there are in docs/figures/verdict/).

    python scripts/verdict_statistics_tables.py [--folder docs/figures/verdict]

Prints the markdown tables (the paper's manifolds; the families-n4 systems) and redraws
law-paper.png in the folder."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from charts.plotting import plot_angle_law, save_png

PAPER = ("paper-n3-n5.json", "paper-n4.json", "paper-n3-n5-1e9.json")
FAMILIES = "families-n4.json"


def _law(st, x0=0.01):
    """Hill's β̂ ± 1.96 se at ``x0`` (a 95 % interval), or a dash."""
    d = next(d for d in st["law"] if d["x0"] == x0)
    if not d["count"]:
        return "—"
    if d["exponent_se"] is None:
        return f"{d['exponent']:.3f}"
    return f"{d['exponent']:.3f} ± {1.96 * d['exponent_se']:.3f}"


def _p(st, x=0.005):
    """P(φ < x) ± 1.96 se on the grid edge nearest ``x``."""
    rows = [r for r in st["cdf"] if abs(r[0] / x - 1) < 1e-6]
    return f"{rows[0][1]:.3g} ± {1.96 * rows[0][2]:.1g}" if rows else "0"


def _slope(st, dt):
    """The last block-minima slope ± 1.96 jackknife se, with its sizes in time units (``dt``
    per sample)."""
    if not st["slopes"]:
        return "—"
    a, b, s, se = st["slopes"][-1]
    return f"{s:.3f} ± {1.96 * se:.1g} ({a * dt:g}–{b * dt:g})"


def paper_table(reports) -> str:
    lines = ["| N | angles | members × T | variant | min φ (rad) | P(φ < 0.005) | β̂ at x₀ = 0.01 "
             "| mean block minimum (rad) | last slope (time units) | episodes per 10³ time "
             "units | GPU wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(reports, key=lambda r: (r["system"]["n"], r["statistics"]["restricted"]["n"])):
        for v in ("restricted", "full"):
            st = r["statistics"][v]
            mins = ", ".join(f"{m:.3g}" for _, m, _ in st["block_minima"][-2:])
            lines.append(
                f"| {r['system']['n']} | {st['n']:.2g} | {r['members']} × {r['t_final']:g} | {v} "
                f"| {st['min']:.3g} | {_p(st)} | {_law(st)} | {mins} | {_slope(st, r['sample_every'])} "
                f"| {1e3 * st['episode_rate']:.3g} | {r['seconds']:.0f} |")
    return "\n".join(lines)


def families_table(reports) -> str:
    lines = ["| weights | level | min φ restricted | P(φ < 0.005) | β̂ at 0.01 | slope 10–100 "
             "time units | episodes per 10³ | min φ full |",
             "|---|---|---|---|---|---|---|---|"]
    for r in reports:
        st, full = r["statistics"]["restricted"], r["statistics"]["full"]
        w = "(" + ",".join(f"{x:g}" for x in r["system"]["weights"]) + ")"
        lines.append(f"| {w} | {r['system']['level']:g} | {st['min']:.2g} | {_p(st)} | "
                     f"{_law(st)} | {_slope(st, r['sample_every']).split(' (')[0]} | "
                     f"{1e3 * st['episode_rate']:.3g} | {full['min']:.2g} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--folder", type=Path, default=Path("docs/figures/verdict"))
    a = p.parse_args(argv)
    paper = [r for f in PAPER for r in json.loads((a.folder / f).read_text())]
    print(paper_table(paper), "\n")
    print(families_table(json.loads((a.folder / FAMILIES).read_text())))
    largest = {}
    for r in paper:                      # the largest run of each N
        key = f"N = {r['system']['n']}"
        if key not in largest or r["statistics"]["restricted"]["n"] > largest[key]["n"]:
            largest[key] = r["statistics"]["restricted"]
    fig, _ = plot_angle_law(dict(sorted(largest.items())),
                            title="the paper's manifolds: smallest restricted angles, 10⁹ angles "
                                  "each (16384 members, GPU)")
    save_png(fig, a.folder / "law-paper.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
