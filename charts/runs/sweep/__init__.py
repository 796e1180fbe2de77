"""Parameter sweeps: many scenes on a Dask cluster, one table, resumable.

Design note.  A sweep file (TOML) is a *base scene* plus the parameters to vary
(:mod:`~charts.runs.sweep.spec`).  Every parameter point becomes an ordinary scene
(:mod:`~charts.runs.sweep.points`), validated before anything runs, and is evaluated by
:func:`evaluate_point` — :func:`charts.runs.runner.run_scene` in a temporary folder on a
Dask worker (:mod:`~charts.runs.sweep.worker`) — which returns one row of statistics
(:mod:`~charts.runs.sweep.statistics`).  The main process (:mod:`~charts.runs.sweep.execute`)
appends each row to ``DIR/sweep.csv`` as soon as its point finishes (one line, flushed and
fsync'ed; :mod:`~charts.runs.sweep.table`), so an interrupted sweep keeps every finished
point and ``--resume`` computes only the others.  When the last point is in, the table is
rewritten in point order: it is then byte-identical to the table of an uninterrupted run
(rows hold only deterministic numbers; who computed what and when goes to
``DIR/log.jsonl``).

Layout of a sweep file::

    name = "masses-n4"
    description = "..."
    [scene]                       # the base scene: any key of a scene file (docs/scenes.md)
    [scene.run]                   #   except [initial] theta/u (points are seeded)
    t_final = 2000.0
    [scene.effects.lyapunov]
    [sweep]
    mode = "grid"                 # "grid": every combination; "random": n_points draws
    seeds = [1, 2]                # initial-state seeds (or a count k: seeds 0..k-1)
    n_points = 20                 # random mode only
    sample_seed = 0               # random mode only
    [sweep.parameters]            # the axes
    n = [4]                       # -> [system] n
    speed = [1.0]                 # -> [system] speed
    m = [0.25, 1.0, 4.0]          # a free symbol, used by the mass patterns
    "run.t_final" = [500.0, 1000.0]   # a dotted key overrides that scene key
    # random mode: a list is drawn uniformly, {min, max, log} a (log-)uniform number
    [sweep.masses]                # named mass patterns: numbers or expressions in symbols
    "1,1,1,m" = [1, 1, 1, "m"]
    "1,m,1,1/m" = [1, "m", 1, "1/m"]

With ``[sweep.masses]`` the pattern name is one more axis, ``masses``.  The table has one
row per point (parameters, seed, the resolved mass vector, the statistics, the full scene as
run in JSON) — see :func:`point_columns`.  ``DIR/summary.csv`` averages over seeds and
``DIR/figures/`` holds one curve or heat map per statistic over the swept parameters
(:mod:`~charts.runs.sweep.report`).  The command line is ``charts sweep``
(:mod:`charts.cli.sweep`).
"""
from .execute import META, dask_client, run_sweep
from .points import SweepPoint, sweep_points
from .report import PLOTTED, SUMMARY, plot_sweep, summarize, summary_markdown, write_summary
from .spec import Sweep, SweepError, bundled_sweeps, load_sweep, parse_sweep, resolve_sweep
from .table import LOG, TABLE, csv_line, point_columns, prepare_table, read_table
from .worker import evaluate_point

__all__ = ["Sweep", "SweepError", "SweepPoint", "load_sweep", "parse_sweep", "sweep_points",
           "evaluate_point", "point_columns", "run_sweep", "read_table", "bundled_sweeps",
           "resolve_sweep", "prepare_table", "csv_line", "dask_client",
           "summarize", "write_summary", "summary_markdown", "plot_sweep", "PLOTTED",
           "TABLE", "SUMMARY", "LOG", "META"]
