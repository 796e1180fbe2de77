"""``charts sweep``: run a sweep file on Dask (see :mod:`charts.runs.sweep`)."""
from __future__ import annotations

import shlex
import sys
from pathlib import Path

from ..io.result_words import counted
from ..runs.cli_parser import positive_count
from ..runs.sweep import (TABLE, SweepError, bundled_sweeps, load_sweep, resolve_sweep,
                          run_sweep)

__all__ = ["add_parser", "cmd_sweep"]

EXIT_USAGE = 2
EXIT_INTERRUPTED = 130


def add_parser(sub) -> None:
    """Register ``charts sweep`` on the ``charts`` subparsers (called by charts.cli)."""
    p = sub.add_parser(
        "sweep", help="evaluate a grid or random sample of scenes on Dask into one table",
        description="Run a sweep file (TOML; a base scene plus the parameters to vary: masses, "
        "weights, N, speed, level, seeds, any scene key) on a Dask cluster: a local one using every core by "
        "default, or an existing one with --scheduler. Each point's statistics are appended to "
        "DIR/sweep.csv as it finishes; Ctrl-C keeps them and --resume computes only the rest. "
        "At the end: DIR/summary.csv (mean over seeds) and DIR/figures/*.png. See docs/sweeps.md.")
    p.add_argument("sweep", metavar="SWEEP", nargs="?",
                   help="path to a sweep .toml, or a bundled sweep name (see --list)")
    p.add_argument("-o", "--output", type=Path, metavar="DIR", help="output folder")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="address of an existing Dask scheduler (e.g. tcp://host:8786)")
    p.add_argument("--workers", type=positive_count, metavar="N",
                   help="worker processes of the local cluster (default: every core)")
    p.add_argument("--device", choices=("cpu", "cuda", "auto"), default="cpu",
                   help="where the seeds of a point advance together: the CPU's vector lanes "
                   "where they pay for their compilation (default), one GPU thread per seed "
                   "(cuda; pip install 'charts[gpu]'), or the GPU when there is one (auto)")
    p.add_argument("--resume", action="store_true",
                   help="continue the table in DIR without recomputing finished points")
    p.add_argument("--no-plots", action="store_true", help="skip DIR/figures")
    p.add_argument("--list", action="store_true", help="list the bundled sweeps and exit")
    p.add_argument("--print", action="store_true", dest="print_sweep",
                   help="print the sweep file (e.g. a bundled one, to copy and edit) and exit")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")
    p.set_defaults(func=cmd_sweep)


def _fail(msg: str, code: int = EXIT_USAGE) -> int:
    print(f"charts: error: {msg}", file=sys.stderr)
    return code


def cmd_sweep(args) -> int:
    """``charts sweep``: 0 when every point is in the table, 1 when a worker lost points,
    2 for an input error, 130 when interrupted."""
    if args.list:
        for name, path in bundled_sweeps().items():
            try:
                desc = load_sweep(path).description.strip().splitlines()[0]
            except (SweepError, IndexError):
                desc = ""
            print(f"{name}  {desc}")
        return 0
    if args.print_sweep:
        if args.sweep is None:
            return _fail("charts sweep --print needs SWEEP (a bundled name or a path)")
        try:
            sys.stdout.write(Path(resolve_sweep(args.sweep)).read_text(encoding="utf-8"))
        except (SweepError, OSError) as exc:
            return _fail(str(exc))
        return 0
    if args.sweep is None or args.output is None:
        return _fail("charts sweep needs SWEEP and -o DIR (see `charts sweep --help`)")
    try:
        sweep = load_sweep(resolve_sweep(args.sweep))
        info = run_sweep(sweep, args.output, scheduler=args.scheduler, workers=args.workers,
                         resume=args.resume, quiet=args.quiet, plots=not args.no_plots,
                         device=args.device)
    except SweepError as exc:
        return _fail(str(exc))
    except KeyboardInterrupt:
        extra = ("" if args.device == "cpu" else f" --device {args.device}") + (
            f" --workers {args.workers}" if args.workers else "") + (
            f" --scheduler {shlex.quote(args.scheduler)}" if args.scheduler else "")
        print(f"\ninterrupted: the finished points are in {args.output / TABLE} (and the "
              f"checkpoints of a long point in {args.output / 'points'}); continue "
              f"with:\n  charts sweep {shlex.quote(str(args.sweep))} -o "
              f"{shlex.quote(str(args.output))} --resume{extra}", file=sys.stderr)
        return EXIT_INTERRUPTED
    if not args.quiet:
        _report(sweep.name, info, args.output, plots=not args.no_plots)
    return 1 if info["lost"] else 0


def _report(name: str, info: dict, outdir: Path, plots: bool = True) -> None:
    print(f"{name}: {counted(info['points'], 'point')}, {info['skipped']} finished before, "
          f"{len(info['computed'])} computed now, {len(info['failed'])} failed -> "
          f"{info['table']}")
    for idx, err in info["failed"] + info["lost"]:
        print(f"  point {idx}: {err}")
    if "summary" in info:
        figures = (f"figures: {len(info.get('figures', []))} in {outdir / 'figures'}" if plots
                   else "no figures (--no-plots)")
        print(f"  summary: {info['summary']}; {figures}")
