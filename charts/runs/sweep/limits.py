"""Sweeps toward a limit: a mechanism's parameter that tends to a system the paper measured —
the linkage's crank length ε → 0 (Σ cos θᵢ = 0, N = 4, docs/linkage.md) and the triple
linkage's rim radius r → 0 with l = R and unit disc inertias (Σ cos θᵢ = 0, N = 3,
docs/triple-linkage.md).  Such a sweep's summary table gains the limit's row (the paper's
exponents at unit speed) and its figures the limit study (``charts.plotting.limit_study``:
exponents against the parameter with the limit, and the linkage's curvature and cone-point
columns where the sweep has them)."""
from __future__ import annotations

from pathlib import Path
from typing import Callable, NamedTuple

from ...analyses.spectrum_quantities import kolmogorov_sinai_entropy
from ..paper import PAPER_EXPONENTS
from .statistics import KS_ENTROPY
from ...plotting.style import save_png

__all__ = ["Limit", "LIMITS", "limit_of", "limit_row", "plot_limit_sweep"]


class Limit(NamedTuple):
    """A parameter's limit: the sweep axes that name it, whether a point's scene is of the
    family (`applies`), the paper's exponents there, the row's words, the figure's file
    name in ``DIR/figures`` and the words of its axis."""
    axes: tuple
    applies: Callable
    paper: tuple
    words: str
    figure: str
    system: str
    symbol: str
    xlabel: str


def _triple_linkage_at_rotors(scene) -> bool:
    """A triple linkage whose r → 0 limit is the paper's N = 3 rotors: l = R (δ = 0) and
    unit disc inertias (the rotors' unit masses); the joint's and rods' masses leave no
    trace there (their speeds are O(r))."""
    s = scene.system
    p = s.get("parameters", {})
    return (s.get("mechanism") == "triple_linkage" and p.get("l") == p.get("R")
            and p.get("inertia") == 1.0)


#: The known limits by name.
LIMITS = {
    "linkage": Limit(("eps", "system.eps", "mechanism.eps"),
                     lambda sc: sc.system.get("kind") == "linkage", PAPER_EXPONENTS[4],
                     "→ 0: paper, Σ cos θᵢ = 0 (unit speed)", "linkage_eps.png", "linkage",
                     "ε", "ε (crank length; rods R = 1)"),
    "triple_linkage": Limit(("r", "mechanism.r"), _triple_linkage_at_rotors,
                            PAPER_EXPONENTS[3], "→ 0 (l = R): paper N = 3, Σ cos θᵢ = 0 "
                            "(unit speed)", "triple_linkage_r.png", "triple linkage", "r",
                            "r (rim radius; l = R)"),
}


def limit_of(params, points) -> str | None:
    """The name of the `LIMITS` entry whose axis is one of the summary's ``params`` and whose
    family holds every point's scene; None otherwise."""
    for name, lim in LIMITS.items():
        if any(p in lim.axes for p in params) and all(lim.applies(p.scene) for p in points):
            return name
    return None


def _axis(summary: dict):
    lim = LIMITS.get(summary.get("limit"))
    x = next((p for p in summary["params"] if lim is not None and p in lim.axes), None)
    return lim, x


def limit_row(summary: dict, stats: list) -> list:
    """The markdown row of the summary's limit (the paper's exponents and their Pesin sum,
    unit speed) under the columns ``params + seeds + stats``; [] without one."""
    lim, x = _axis(summary)
    if x is None:
        return []
    paper = lim.paper
    cells = [lim.words if p == x else "" for p in summary["params"]]
    cells.append("")
    for c in stats:
        if c == KS_ENTROPY[0]:                  # Pesin's sum of the paper's exponents
            cells.append(f"{kolmogorov_sinai_entropy(paper):.3f}")
            continue
        i = int(c.split("_")[1]) if c.startswith("lambda_") else 0
        cells.append(f"{paper[i - 1]:.3f}" if 1 <= i <= len(paper) else "")
    return ["| " + " | ".join(cells) + " |"]


def plot_limit_sweep(summary: dict, folder, title: str = "") -> list:
    """``folder/<the limit's figure>`` (`Limit.figure`: exponents with the paper's limit, and
    the linkage's positive curvature, cone points and angles) when the summary has a limit;
    the files written."""
    from ...plotting.limit_study import plot_limit_study

    lim, x = _axis(summary)
    if x is None or not summary["rows"]:
        return []
    what = f"the {lim.system} against {lim.symbol}"
    fig, _ = plot_limit_study(summary["rows"], x, paper=lim.paper, system=lim.system,
                              symbol=lim.symbol, xlabel=lim.xlabel,
                              title=f"{title}: {what}" if title else what)
    Path(folder).mkdir(parents=True, exist_ok=True)
    path = Path(folder) / lim.figure
    save_png(fig, path)
    return [str(path)]
