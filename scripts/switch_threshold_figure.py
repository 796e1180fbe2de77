"""Measure the chart-switching threshold τ: error, metric condition number, switches, cost.

For each τ, chart-formulation DOP853 runs (rtol 1e-10, t = 20, unit speed) from several
states for N = 3, 4, 5 are compared with the ambient DOP853 at rtol 1e-13.  Reported per τ
(median over states): the error ratio chart/ambient at the same rtol, the largest 2-norm
condition number of g met in the chart in use (checked on 2001 samples per run), the number
of switches and of right-hand-side evaluations.  Writes docs/figures/switch_threshold.png
and prints the table.

    python scripts/switch_threshold_figure.py
"""
from __future__ import annotations

import os
import sys

import numpy as np

from charts import RotorSystem, integrate
from charts.plotting.style import new_figure, save_png
from charts.solvers.chart_formulation import DEFAULT_TAU, chart_condition_bound

TAUS = [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95, 0.99]
SEEDS = range(8)
T = 20.0


def chart_in_use(t, first, switches):
    """Chart in use at each sample time (the chart after a switch at exactly t)."""
    charts = np.full(t.size, first)
    for ts, _, to in switches:
        charts[t >= ts] = to
    return charts


def main(out="docs/figures/switch_threshold.png"):
    te = np.linspace(0, T, 2001)
    table = {n: [] for n in (3, 4, 5)}
    for n in (3, 4, 5):
        s = RotorSystem(n)
        states = [s.random_state(seed) for seed in SEEDS]
        refs = [integrate(s, th, u, T, formulation="ambient", rtol=1e-13, t_eval=te).theta for th, u in states]
        ambs = [integrate(s, th, u, T, formulation="ambient", rtol=1e-10, t_eval=te).theta for th, u in states]
        for tau in TAUS:
            ratios, conds, nsw, nrhs = [], [], [], []
            for (th, u), ref, amb in zip(states, refs, ambs):
                r = integrate(s, th, u, T, formulation="chart", rtol=1e-10, t_eval=te, tau=tau)
                ratios.append(np.abs(r.theta - ref).max() / np.abs(amb - ref).max())
                first = r.switches[0][1] if r.switches else s.best_chart(th)
                ch = chart_in_use(r.t, first, r.switches)
                conds.append(max(np.linalg.cond(s.metric(x, int(k))) for x, k in zip(r.theta[::10], ch[::10])))
                nsw.append(len(r.switches))
                nrhs.append(r.n_rhs)
            table[n].append((tau, np.median(ratios), np.max(ratios), np.max(conds),
                             chart_condition_bound(n, tau), np.median(nsw), np.median(nrhs)))
    print(f"{'N':>2} {'tau':>5} {'err ratio med':>13} {'max':>8} {'max cond(g)':>11} {'bound':>8} "
          f"{'switches':>8} {'rhs evals':>9}")
    for n, rows in table.items():
        for row in rows:
            print(f"{n:>2} {row[0]:>5.2f} {row[1]:>13.2f} {row[2]:>8.2f} {row[3]:>11.1f} {row[4]:>8.1f} "
                  f"{row[5]:>8.0f} {row[6]:>9.0f}")
    fig, ax = new_figure(1, 3, figsize=(13, 3.8))
    for i, (n, rows) in enumerate(table.items()):
        r = np.array(rows)
        c = f"C{i}"
        ax[0].semilogy(r[:, 0], r[:, 3], "o-", color=c, label=f"N={n} measured")
        ax[0].semilogy(r[:, 0], r[:, 4], ":", color=c, lw=0.8)
        ax[1].semilogy(r[:, 0], r[:, 1], "o-", color=c, label=f"N={n} median")
        ax[1].semilogy(r[:, 0], r[:, 2], "x--", color=c, alpha=0.5, label=f"N={n} max")
        ax[2].plot(r[:, 0], r[:, 5], "o-", color=c, label=f"N={n}")
    ax[0].set(xlabel="threshold τ", ylabel="max cond(g) in the chart in use",
              title="conditioning (dotted: 1+(N−1)/τ², at step ends)")
    ax[1].set(xlabel="threshold τ", ylabel="chart error / ambient error (same rtol)",
              title="accuracy, t = 20, rtol = 1e-10")
    ax[2].set(xlabel="threshold τ", ylabel="switches in t = 20 (median)", title="switching frequency")
    for a in ax:
        a.axvline(DEFAULT_TAU, color="grey", lw=0.8)
        a.legend(fontsize=7)
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    save_png(fig, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
