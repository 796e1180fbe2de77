"""The linkage's sweeps over ε (``[system] kind = "linkage"``, axis ``eps`` or
``system.eps``): the paper's numbers as the limit row of the summary table, and the figure
of the ε-study (``charts.plotting.linkage``) beside the per-statistic figures."""
from __future__ import annotations

from pathlib import Path

from ...analyses.spectrum_quantities import kolmogorov_sinai_entropy
from ..paper import PAPER_EXPONENTS
from .statistics import KS_ENTROPY
from ...plotting.style import save_png

__all__ = ["LINKAGE_AXES", "LINKAGE_FIGURE", "linkage_axis", "paper_limit_row",
           "plot_linkage_sweep"]

#: Parameter names of an ε axis.
LINKAGE_AXES = ("eps", "system.eps")
#: The file name of the ε-study figure in ``DIR/figures``.
LINKAGE_FIGURE = "linkage_eps.png"


def linkage_axis(summary: dict):
    """The ε parameter of a summary (``charts.runs.sweep.report.summarize``), or None."""
    return next((p for p in summary["params"] if p in LINKAGE_AXES), None)


def paper_limit_row(summary: dict, stats: list) -> list:
    """The markdown row of the limit ε → 0 (the paper's N = 4 system Σ cos θᵢ = 0, section
    2, unit speed) under the columns ``params + seeds + stats``; [] without an ε axis."""
    x = linkage_axis(summary)
    if x is None:
        return []
    paper = PAPER_EXPONENTS[4]
    cells = ["→ 0: paper, Σ cos θᵢ = 0 (unit speed)" if p == x else "" for p in summary["params"]]
    cells.append("")
    for c in stats:
        if c == KS_ENTROPY[0]:                  # Pesin's sum of the paper's exponents
            cells.append(f"{kolmogorov_sinai_entropy(paper):.3f}")
            continue
        i = int(c.split("_")[1]) if c.startswith("lambda_") else 0
        cells.append(f"{paper[i - 1]:.3f}" if 1 <= i <= len(paper) else "")
    return ["| " + " | ".join(cells) + " |"]


def plot_linkage_sweep(summary: dict, folder, title: str = "") -> list:
    """``folder/linkage_eps.png`` (exponents with the paper's limit, positive curvature,
    cone points and angles against ε) when the summary has an ε axis; the files written."""
    from ...plotting.linkage import plot_linkage_epsilon

    x = linkage_axis(summary)
    if x is None or not summary["rows"]:
        return []
    fig, _ = plot_linkage_epsilon(summary["rows"], x, paper=PAPER_EXPONENTS[4],
                                  title=f"{title}: the linkage against ε" if title else
                                  "the linkage against ε")
    Path(folder).mkdir(parents=True, exist_ok=True)
    path = Path(folder) / LINKAGE_FIGURE
    save_png(fig, path)
    return [str(path)]
