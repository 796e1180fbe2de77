"""``charts verdict --statistics``: the angle test at scale as a verdict, each system's tally
run (or read back from its file), reported and judged (charts.runs.verdict_statistics;
docs/hyperbolicity.md)."""
from __future__ import annotations

import json
import sys
import warnings

import numpy as np

from ..runs.interrupts import EXIT_INTERRUPTED, interrupt_for
from ..runs.io import atomic_text

__all__ = ["statistics_command", "transient_of", "slug_of"]


def transient_of(t_transient, system) -> float:
    """``--t-transient`` for ``system``: a number as given; "scaled" and "auto" resolved as
    ``lyapunov_spectrum`` resolves them, "auto" from the first member's state (seed 0, unit
    speed), on the grid of the default step 0.01."""
    if not isinstance(t_transient, str):
        return t_transient
    from ..analyses.lyapunov import resolve_transient
    tr, _ = resolve_transient(t_transient, system, *system.random_state(seed=0, speed=1.0))
    return round(round(float(tr) / 0.01) * 0.01, 10)


def _plan_statistics(args, systems, t_final) -> None:
    """Every system and setting of ``--statistics`` checked before the first system runs:
    ``--t-transient``, the members' settings (``angle_settings``) and, on the CPU, the
    forward vectors each member keeps (``check_cpu_store``); ValueError naming the system."""
    from ..analyses.arguments import nonnegative_time
    from ..analyses.forward_pass import angle_settings
    from ..analyses.hyperbolicity import check_cpu_store
    from ..solvers.device import resolve_device
    rule = isinstance(args.t_transient, str)          # resolved per system, once checked
    if not rule:
        nonnegative_time("--t-transient", args.t_transient)
    cpu = getattr(args, "scheduler", None) or resolve_device(args.device) == "cpu"
    for label, system in systems:
        try:
            cfg = angle_settings(system, t_final, t_transient=0.0 if rule else args.t_transient,
                                 sample_every=0.1)
            if cpu:
                check_cpu_store(cfg, t_final)
        except ValueError as exc:
            raise ValueError(f"{label}: {exc}") from None


def _statistics(args) -> int:
    """``charts verdict --statistics``: `statistics_verdict` of each system in turn."""
    from ..analyses.transients import scaled_transient
    from ..io.archive import load
    from ..geometry.system import RotorSystem
    from ..runs.verdict import case_verdict
    from ..runs.verdict_statistics import (family_systems, format_statistics, members_window,
                                           statistics_verdict, tally_report)
    from ..solvers.device import resolve_device

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")           # critical levels: stops are reported
        if args.family:
            systems = family_systems(args.family)
        else:
            systems = [(f"N = {n}", RotorSystem(n, masses=args.masses, weights=args.weights,
                                                 level=args.level)) for n in args.n]
    if args.members < 2:
        raise ValueError(f"--members must be at least 2 (an ensemble), got {args.members}")
    if not (args.samples > 0 and np.isfinite(args.samples)):
        raise ValueError(f"--samples must be a number > 0, got {args.samples}")
    t_final = members_window(args.samples, args.members)
    _plan_statistics(args, systems, t_final)
    scheduler = getattr(args, "scheduler", None)
    if scheduler:
        from ..analyses.cluster import check_scheduler_address
        check_scheduler_address(scheduler)
        if args.device == "cuda":
            raise ValueError("--scheduler runs the members on the cluster's CPU workers; "
                             "leave out --device cuda (or --scheduler)")
        if getattr(args, "workers", None):
            raise ValueError("--workers sets the local processes; the cluster at --scheduler "
                             "has its own workers")
        print(f"charts: the angle test at scale runs on the Dask cluster at {scheduler}: "
              f"{args.members} members x T = {t_final:g} per system, in chunks tallied on its "
              "workers. With --out DIR the members done are kept: Ctrl-C, then the same "
              "command, goes on from them", file=sys.stderr, flush=True)
    elif resolve_device(args.device) == "cpu":
        tr = args.t_transient if not isinstance(args.t_transient, str) else max(
            scaled_transient(s.n, 1.0) for _, s in systems)       # "auto": about as much
        integrated = args.members * (2 * t_final + 3 * tr)
        print(f"charts: the angle test at scale runs on the CPU here: {args.members} members x "
              f"T = {t_final:g} per system, {integrated:.3g} time units to integrate (both "
              "passes; on an H100 10⁸ angles took about 5 s). With --out DIR the members done "
              "are kept: Ctrl-C, then the same command, goes on from them", file=sys.stderr,
              flush=True)
    done = {}
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        if (args.out / "statistics.json").exists():      # the reports of an earlier run
            done = {r.get("slug"): r for r in
                    json.loads((args.out / "statistics.json").read_text(encoding="utf-8"))}
    reports = []
    for label, system in systems:
        slug = slug_of(system)
        wanted = dict(members=args.members, t_final=t_final,
                      t_transient=transient_of(args.t_transient, system))
        path = None if args.out is None else args.out / f"{slug}.nc"
        if slug in done and all(done[slug][k] == v for k, v in wanted.items()):
            rep = dict(done[slug], **case_verdict(done[slug]))   # an earlier report: its verdict
        elif path is not None and path.exists() and _same_run(saved := load(path), wanted):
            rep = dict(tally_report(saved, label), file=str(path))
        else:
            rep = statistics_verdict(system, args.samples, members=args.members,
                                     device=args.device, t_transient=wanted["t_transient"],
                                     out=path, label=label, progress=_progress(label),
                                     workers=args.workers,
                                     checkpoint=None if args.out is None
                                     else args.out / f"{slug}.partial.nc",
                                     client=scheduler or None)
        rep["slug"] = slug
        print(format_statistics(rep) + "\n", flush=True)
        reports.append(rep)
        done[slug] = rep
        if args.out is not None:            # this run's reports and the earlier ones of others
            atomic_text(args.out / "statistics.json", json.dumps(list(done.values()), indent=1))
    if args.json is not None:
        atomic_text(args.json, json.dumps(reports, indent=1))
    return 0


def statistics_command(args) -> int:
    """`_statistics`; interrupted (Ctrl-C, SIGTERM: a ``BrokenProcessPool`` after one is
    that interrupt, ``charts.runs.interrupts``): what is kept and how to go on, exit 130
    (143 for SIGTERM, by ``charts.cli.main``)."""
    from concurrent.futures.process import BrokenProcessPool
    try:
        return _statistics(args)
    except (KeyboardInterrupt, BrokenProcessPool) as exc:
        if not isinstance(exc, KeyboardInterrupt) and interrupt_for(exc) is None:
            raise                           # a worker lost, not an interrupt
    if args.out is None:
        kept = ("the systems finished are reported above; without --out DIR the members "
                "done of the one in progress are not kept: run the same command again to "
                "start it over")
    else:
        kept = (f"the systems finished are reported above and in "
                f"{args.out / 'statistics.json'}, the members done of the one in progress in "
                f"{args.out} (on the CPU: *.partial.nc); run the same command again to "
                "continue")
    print(f"\ninterrupted: {kept}", file=sys.stderr, flush=True)
    return EXIT_INTERRUPTED


def _progress(label):
    """The progress of a system's run: a bar on a terminal; elsewhere (a log, a pipe, a
    batch job) a line the first time members are done and then at each further tenth of
    the members' time, so that a log shows the run going."""
    if sys.stderr.isatty():
        return True
    shown = [-1]

    def line(t_done, t_total):
        tenth = int(10 * t_done / t_total) if t_total > 0 else 10
        if tenth > shown[0]:
            shown[0] = tenth
            print(f"charts: {label}: {100 * t_done / t_total:.0f} % of the members' time done",
                  file=sys.stderr, flush=True)
    return line


def _same_run(tally, wanted) -> bool:
    """Whether a saved result is the tally of the run ``wanted`` (members, window, transient)
    asks for."""
    from ..analyses.angle_tally import AngleTally
    return isinstance(tally, AngleTally) and tally.n_members == wanted["members"] and \
        tally.params.get("t_final") == wanted["t_final"] and \
        tally.params.get("t_transient") == wanted["t_transient"]


def slug_of(system) -> str:
    """A file name for a system, every number to its last digit: n4-c0-w1,1,1,1-m1,1,1,1."""
    d = system.describe()

    def num(x):
        return np.format_float_positional(float(x), trim="-")
    return (f"n{d['n']}-c{num(d['level'])}-w{','.join(num(x) for x in d['weights'])}"
            f"-m{','.join(num(x) for x in d['masses'])}")
