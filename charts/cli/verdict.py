"""``charts verdict``: the verdicts on hyperbolicity from exact invariants and certificates
(see :mod:`charts.runs.verdict`, docs/hyperbolicity.md)."""
from __future__ import annotations

import argparse
import json
import sys
import warnings
from pathlib import Path

import numpy as np

from ..runs.cli_parser import positive_count, transient_arg
from ..runs.io import atomic_text

__all__ = ["add_parser", "cmd_verdict", "radii_arg", "DEFAULT_RADII"]

#: The rim radii of ``--triple-linkage`` given without a list (about a minute on 2 cores with
#: the default grid and runs; docs/hyperbolicity.md).
DEFAULT_RADII = (0.05, 0.1, 0.2, 0.3)


def radii_arg(text: str) -> list:
    """argparse type of ``--triple-linkage``: rim radii r > 0, separated by commas."""
    out = []
    for item in text.split(","):
        try:
            r = float(item)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"the rim radii are numbers r > 0 separated by commas (e.g. 0.05,0.1), got "
                f"{item.strip()!r}") from None
        if not (np.isfinite(r) and r > 0):
            raise argparse.ArgumentTypeError(f"a rim radius must be a finite number r > 0 "
                                             f"(r -> 0 is the rotors': --n 3), got {item.strip()}")
        if r in out:
            raise argparse.ArgumentTypeError(f"the rim radius {item.strip()} is given twice "
                                             "(each r is a full case: list it once)")
        out.append(r)
    return out


def add_parser(sub) -> None:
    """Register ``charts verdict`` on the ``charts`` subparsers (called by charts.cli)."""
    p = sub.add_parser(
        "verdict", help="the hyperbolicity verdicts from exact invariants and certificates "
        "(N = 3: Gauss-Bonnet, entropy bracket, curvature sign; N >= 4: a flat torus; the "
        "triple linkage at each rim radius)",
        description="For N = 3 (the paper's surface, or a member of the family with masses, "
        "weights, level): the Euler characteristic by a Morse count, the area and the integral "
        "of K by both curvature routes against 2 pi chi (Gauss-Bonnet), the leading exponent "
        "at unit speed against Katok's and Osserman-Sarnak's bounds, and the sign of K proved "
        "by exact algebra and interval arithmetic. For N >= 4: the flat totally geodesic torus "
        "of antipodal pairs, proved symbolically, that rules out the Anosov property, and the "
        "monodromy of its closed geodesic. Each case ends in one verdict line: 'hyperbolic "
        "(Anosov)', 'not hyperbolic' or 'open', the class of its evidence ('theorem with "
        "certificate', 'theorem', 'statistics', 'no proof') and why (in the JSON: verdict, "
        "evidence, reason). Default: N = 3, 4, 5 of the paper. --triple-linkage: the triple "
        "linkage at each rim radius r (its surface integrals and lambda1; no theorem is "
        "certified at a finite r). --mechanism: any 2-dimensional mechanism, a user's own "
        "among them, the same measurements (only chi > 0 decides). See "
        "docs/hyperbolicity.md and docs/mechanisms.md.")
    p.add_argument("--n", type=int, nargs="+", default=None, metavar="N",
                   help="rotor counts (default 3 4 5, none with --triple-linkage or "
                   "--mechanism)")
    p.add_argument("--masses", type=float, nargs="+", metavar="M",
                   help="masses (one N only; default all 1)")
    p.add_argument("--weights", type=float, nargs="+", metavar="A",
                   help="weights of the constraint sum(a cos theta) = level (one N only; "
                   "default all 1)")
    p.add_argument("--level", type=float, default=0.0, help="level of the constraint (default 0)")
    p.add_argument("--grid", type=positive_count, default=None, metavar="G",
                   help="quadrature points per chart axis (default 256; 96 for the triple "
                   "linkage and --mechanism)")
    p.add_argument("--t-final", type=float, default=3000.0, metavar="T",
                   help="length of each exponent's run (default 3000)")
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2], metavar="S",
                   help="seeds of the exponent's runs (default 1 2)")
    p.add_argument("--json", type=Path, metavar="FILE", help="also write the reports as JSON")
    t = p.add_argument_group(
        "the triple linkage and other 2-dimensional mechanisms",
        "--triple-linkage R1,R2,... reports the triple linkage "
        "(charts.triple_linkage, R = 1, unit inertias) at each rim radius r: chi read from "
        "Gauss-Bonnet by both curvature routes, the area, K's range and the share of area "
        "with K > 0 at the nodes, lambda1 at unit speed (--t-final, --seeds) against Katok's "
        "bound, and the verdict: 'open' wherever chi < 0 (K > 0 somewhere, and Hunt-MacKay's "
        "theorem gives no bound on r), 'not hyperbolic' where the surface has chi > 0")
    t.add_argument("--triple-linkage", type=radii_arg, nargs="?", metavar="R1,R2,...",
                   const=list(DEFAULT_RADII),
                   help="rim radii r > 0 (default, without a list: "
                   + ",".join(f"{r:g}" for r in DEFAULT_RADII) + ")")
    t.add_argument("--mechanism", nargs="+", metavar=("SPEC", "KEY=VALUE"),
                   help="a 2-dimensional mechanism named as a scene's [mechanism] table names "
                   "it: an instance (triple_linkage, rotors, linkage) or your "
                   "package.module:factory, then its keyword parameters as KEY=VALUE (TOML "
                   "values, e.g. --mechanism triple_linkage r=0.2), or a TOML file with a "
                   "[mechanism] table; the same measurements as --triple-linkage, "
                   "its chi read from Gauss-Bonnet (Newton's sheets for a mechanism of your "
                   "own): 'not hyperbolic' where chi > 0, 'open' otherwise, never "
                   "'hyperbolic' (no certificate of K's sign exists for a general mechanism)")
    t.add_argument("--angles", type=float, default=None, metavar="T",
                   help="also the restricted-angle test (section 4) over a window T from each "
                   "seed's state: the smallest angle and the share below 0.05 rad, statistics "
                   "like lambda1 (about 20 s per seed for T = 1000; default: not run)")
    t.add_argument("--rod-length", type=float, default=1.0, metavar="L",
                   help="the rods' length l (default 1 = R; the limit r -> 0 is then "
                   "sum cos theta = 3 (l - R) / r)")
    t.add_argument("--joint-mass", type=float, default=0.0, metavar="M",
                   help="mass of the joint (default 0)")
    t.add_argument("--rod-mass", type=float, default=0.0, metavar="MU",
                   help="mass of each uniform rod (default 0; > 0 makes the metric depend on "
                   "the configuration, and only the chart route of K runs)")
    g = p.add_argument_group(
        "statistics at scale", "--statistics runs the angle test (restricted and full angles) "
        "on many members instead of the certificates, tallied as it goes (on a GPU the memory "
        "does not grow with the run's length), and reports the smallest angle, the law of the "
        "small angles, the block minima and the episodes with error bars from the spread "
        "between members")
    g.add_argument("--statistics", action="store_true",
                   help="the angle test at scale for each system (see the group's description)")
    g.add_argument("--samples", type=float, default=1e8, metavar="S",
                   help="angles per system, all members together (default 1e8)")
    g.add_argument("--members", type=positive_count, default=16384, metavar="M",
                   help="independent trajectories, seeds 0 … M-1 (default 16384)")
    g.add_argument("--device", choices=("cpu", "cuda", "auto"), default="auto",
                   help="where the members run (default auto: the GPU when there is one)")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the members on the Dask cluster of this scheduler (e.g. "
                   "tcp://host:8786; its workers must import charts), in chunks tallied on the "
                   "workers; the same numbers as a local run (docs/cluster.md)")
    g.add_argument("--family", metavar="SWEEP",
                   help="the distinct systems of a bundled sweep (e.g. families-n4) instead "
                   "of --n")
    g.add_argument("--t-transient", type=transient_arg, default=100.0, metavar="T",
                   help="transient of both passes (default 100), or a rule of each system: "
                   "'scaled' (5 N^2 time units, at least 50) or 'auto' (from a pilot run "
                   "of the first member)")
    g.add_argument("--workers", type=positive_count, default=None, metavar="W",
                   help="processes on the CPU (default: one per core)")
    g.add_argument("--out", type=Path, metavar="DIR",
                   help="save each system's tally there (NetCDF) and statistics.json after "
                   "each system; a system whose tally or report is there already is read, not "
                   "run again; on the CPU the members done are kept there too, and an "
                   "interrupted system goes on from them")
    p.set_defaults(func=cmd_verdict)


def cmd_verdict(args) -> int:
    """Print the reports (the rotors' of ``--n``, then the triple linkage's of
    ``--triple-linkage`` and their table, then the mechanism's of ``--mechanism``), each
    ending in its verdict line (`charts.runs.verdict.case_verdict`: verdict, evidence,
    reason, also in the JSON); 0 when every check holds (`charts.runs.verdict.verdict_passed`),
    1 otherwise, 2 for bad input."""
    from ..geometry.system import RotorSystem
    from ..runs.verdict import surface_verdict, torus_verdict, verdict_passed
    from ..runs.verdict_format import format_verdict

    linkage = getattr(args, "triple_linkage", None)
    mechanism = getattr(args, "mechanism", None)
    if args.n is None:
        args.n = [] if linkage or mechanism else [3, 4, 5]
    if args.masses or args.weights or args.level != 0.0:
        if len(args.n) != 1:
            raise ValueError("--masses, --weights and --level describe one system of rotors: "
                             "give one --n")
    if not linkage and (args.rod_length != 1.0 or args.joint_mass or args.rod_mass):
        raise ValueError("--rod-length, --joint-mass and --rod-mass are the triple "
                         "linkage's: give --triple-linkage")
    if not (linkage or mechanism) and args.angles is not None:
        raise ValueError("--angles runs on a surface's flow: give --triple-linkage or "
                         "--mechanism")
    _check_outputs(args)
    if args.statistics:
        if linkage or mechanism:
            raise ValueError("--statistics runs the angle test of the rotors; leave out "
                             "--triple-linkage and --mechanism (--angles runs their angle "
                             "test)")
        from .verdict_statistics import statistics_command
        return statistics_command(args)
    grid = args.grid
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")               # a critical level is refused below
        systems = [RotorSystem(n, masses=args.masses, weights=args.weights, level=args.level)
                   for n in args.n]
    args.grid = 256 if grid is None else grid
    _plan_certificates(args, systems)
    if linkage:
        _plan_linkage(args, 96 if grid is None else grid)
    mech = _plan_mechanism(args, 96 if grid is None else grid) if mechanism else None
    reports = []
    for n, system in zip(args.n, systems):
        if n == 3:
            rep = surface_verdict(system, n_grid=args.grid, t_final=args.t_final,
                                  seeds=args.seeds)
        else:
            rep = torus_verdict(system)
        print(format_verdict(rep) + "\n", flush=True)
        reports.append(rep)
    if linkage:
        reports += _linkage_reports(args, 96 if grid is None else grid)
    if mechanism:
        reports.append(_mechanism_report(args, mech, 96 if grid is None else grid))
    if args.json is not None:
        atomic_text(args.json, json.dumps(reports, indent=1))
    return 0 if all(verdict_passed(r) for r in reports) else 1


def _check_outputs(args) -> None:
    """``--json`` (a file) and ``--statistics``' ``--out`` (a folder) checked writable before
    any work, creating nothing (``charts.runs.outdir.check_writable``): a finished report is
    never lost to a path that cannot take it."""
    from ..runs.outdir import check_writable
    if args.json is not None:
        check_writable(args.json, "--json")
    if args.statistics and args.out is not None:
        check_writable(args.out, "--out", folder=True)


def _plan_certificates(args, systems) -> None:
    """Every N and setting of the certificates checked before the first report starts
    (ValueError naming the flag or the N): N = 3's grid (`surface_plan`: its memory), its
    level (a critical one has no Euler characteristic), ``--t-final`` and ``--seeds`` (the
    exponents' runs), N >= 4's flat-torus proof (`torus_plan`: at most N = 12)."""
    from ..analyses.arguments import positive_time
    from ..analyses.flat_tori import torus_plan
    from ..analyses.lyapunov import lyapunov_settings
    from ..analyses.surface_integrals import surface_plan
    from ..geometry.checks import integer
    from ..geometry.topology import euler_characteristic
    for system in systems:
        if system.n == 3:
            surface_plan(system, integer("--grid", args.grid, 8, 1 << 14))
            euler_characteristic(system.weights, system.level)
            positive_time("--t-final", args.t_final)
            for seed in args.seeds:
                lyapunov_settings(system, args.t_final, seed=integer("--seeds", seed, 0))
        else:
            torus_plan(system)


def _linkage_settings(args) -> dict:
    return dict(l=args.rod_length, joint_mass=args.joint_mass, rod_mass=args.rod_mass)


def _plan_linkage(args, grid) -> None:
    """Every r of ``--triple-linkage`` and the settings of its reports checked before the
    first report starts (`charts.runs.verdict_linkage.linkage_plan`: the linkage's parameters, that it
    assembles and is regular; ``--grid``, ``--t-final``, ``--seeds``); ValueError naming the
    flag and the r."""
    from ..runs.verdict_linkage import linkage_plan
    from ..runs.verdict_mechanism import check_settings
    check_settings(grid, args.t_final, args.seeds, args.angles, _FLAGS)
    for name, value in (("--rod-length", args.rod_length), ("--joint-mass", args.joint_mass),
                        ("--rod-mass", args.rod_mass)):
        if not np.isfinite(value) or value < 0 or (name == "--rod-length" and value == 0):
            raise ValueError(f"{name} must be a finite number "
                             f"{'> 0' if name == '--rod-length' else '>= 0'}, got {value}")
    for r in args.triple_linkage:
        try:
            linkage_plan(r, **_linkage_settings(args))
        except ValueError as exc:
            raise ValueError(f"--triple-linkage {r:g}: {exc}") from None


#: The flags of `charts.runs.verdict_mechanism.check_settings`'s four settings.
_FLAGS = ("--grid", "--t-final", "--seeds", "--angles")


def _plan_mechanism(args, grid):
    """``--mechanism`` resolved (`charts.runs.verdict_mechanism.resolve_mechanism`: the scene's
    resolution of a [mechanism] table) and checked before the first report starts
    (`surface_plan`: dimension 2, angle charts, a regular surface; ``--grid``, ``--t-final``,
    ``--seeds``, ``--angles``); ValueError naming --mechanism or the flag."""
    from ..runs.verdict_mechanism import check_settings, resolve_mechanism, surface_plan
    check_settings(grid, args.t_final, args.seeds, args.angles, _FLAGS)
    spec, *settings = args.mechanism
    mech = resolve_mechanism(spec, settings)
    try:
        return surface_plan(mech)
    except ValueError as exc:
        raise ValueError(f"--mechanism {' '.join(args.mechanism)}: {exc}") from None


def _mechanism_report(args, mech, grid) -> dict:
    """``--mechanism``: `mechanism_verdict` of the mechanism, printed when done (progress on
    stderr before each step)."""
    from ..runs.verdict_format import format_verdict
    from ..runs.verdict_mechanism import mechanism_verdict

    def progress(line):
        print(f"charts: mechanism {mech.name}: {line}", file=sys.stderr, flush=True)
    rep = mechanism_verdict(mech, n_grid=grid, t_final=args.t_final, seeds=args.seeds,
                            angles_window=args.angles, progress=progress,
                            spec=" ".join(args.mechanism))
    print(format_verdict(rep) + "\n", flush=True)
    return rep


def _linkage_reports(args, grid) -> list:
    """``--triple-linkage``: `linkage_verdict` at each r, each printed when done (progress on
    stderr before each step), then the table of all of them."""
    from ..runs.verdict_format import format_verdict
    from ..runs.verdict_linkage import format_linkage_table, linkage_verdict
    reports = []
    for i, r in enumerate(args.triple_linkage):
        def progress(line, r=r, i=i):
            print(f"charts: triple linkage r = {r:g} ({i + 1} of {len(args.triple_linkage)}): "
                  f"{line}", file=sys.stderr, flush=True)
        rep = linkage_verdict(r, **_linkage_settings(args), n_grid=grid, t_final=args.t_final,
                              seeds=args.seeds, angles_window=args.angles, progress=progress)
        print(format_verdict(rep) + "\n", flush=True)
        reports.append(rep)
    print(format_linkage_table(reports) + "\n", flush=True)
    return reports
