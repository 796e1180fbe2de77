"""``charts verdict``: the verdicts on hyperbolicity from exact invariants and certificates
(see :mod:`charts.runs.verdict`, docs/hyperbolicity.md)."""
from __future__ import annotations

import json
import warnings
from pathlib import Path

from ..runs.cli_parser import positive_count

__all__ = ["add_parser", "cmd_verdict"]


def add_parser(sub) -> None:
    """Register ``charts verdict`` on the ``charts`` subparsers (called by charts.cli)."""
    p = sub.add_parser(
        "verdict", help="the hyperbolicity verdicts from exact invariants and certificates "
        "(N = 3: Gauss-Bonnet, entropy bracket, curvature sign; N >= 4: a flat torus)",
        description="For N = 3 (the paper's surface, or a member of the family with masses, "
        "weights, level): the Euler characteristic by a Morse count, the area and the integral "
        "of K by both curvature routes against 2 pi chi (Gauss-Bonnet), the leading exponent "
        "at unit speed against Katok's and Osserman-Sarnak's bounds, and the sign of K proved "
        "by exact algebra and interval arithmetic. For N >= 4: the flat totally geodesic torus "
        "of antipodal pairs, proved symbolically, that rules out the Anosov property, and the "
        "monodromy of its closed geodesic. Default: N = 3, 4, 5 of the paper. See "
        "docs/hyperbolicity.md.")
    p.add_argument("--n", type=int, nargs="+", default=[3, 4, 5], metavar="N",
                   help="rotor counts (default 3 4 5)")
    p.add_argument("--masses", type=float, nargs="+", metavar="M",
                   help="masses (one N only; default all 1)")
    p.add_argument("--weights", type=float, nargs="+", metavar="A",
                   help="weights of the constraint sum(a cos theta) = level (one N only; "
                   "default all 1)")
    p.add_argument("--level", type=float, default=0.0, help="level of the constraint (default 0)")
    p.add_argument("--grid", type=positive_count, default=256, metavar="G",
                   help="quadrature points per chart axis (default 256)")
    p.add_argument("--t-final", type=float, default=3000.0, metavar="T",
                   help="length of each exponent's run (default 3000)")
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2], metavar="S",
                   help="seeds of the exponent's runs (default 1 2)")
    p.add_argument("--json", type=Path, metavar="FILE", help="also write the reports as JSON")
    p.set_defaults(func=cmd_verdict)


def cmd_verdict(args) -> int:
    """Print the verdicts; 0 when every check holds (`charts.runs.verdict.verdict_passed`),
    1 otherwise, 2 for bad input."""
    from ..geometry.system import RotorSystem
    from ..runs.verdict import format_verdict, surface_verdict, torus_verdict, verdict_passed

    if len(args.n) > 1 and (args.masses or args.weights or args.level != 0.0):
        raise ValueError("--masses, --weights and --level describe one system: give one --n")
    reports = []
    for n in args.n:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")           # a critical level is refused below
            system = RotorSystem(n, masses=args.masses, weights=args.weights, level=args.level)
        if n == 3:
            rep = surface_verdict(system, n_grid=args.grid, t_final=args.t_final,
                                  seeds=args.seeds)
        else:
            rep = torus_verdict(system)
        print(format_verdict(rep) + "\n", flush=True)
        reports.append(rep)
    if args.json is not None:
        args.json.write_text(json.dumps(reports, indent=1), encoding="utf-8")
    return 0 if all(verdict_passed(r) for r in reports) else 1
