"""``charts verdict``: the N = 3 surface's exact invariants and certified curvature sign
(see :mod:`charts.runs.verdict`, docs/verdict.md)."""
from __future__ import annotations

import json
import warnings
from pathlib import Path

from ..runs.cli_parser import positive_count

__all__ = ["add_parser", "cmd_verdict"]


def add_parser(sub) -> None:
    """Register ``charts verdict`` on the ``charts`` subparsers (called by charts.cli)."""
    p = sub.add_parser(
        "verdict", help="Gauss-Bonnet, the entropy bracket and a certified curvature sign of "
        "the N = 3 surface",
        description="For the surface of three rotors (the paper's, or a member of the family "
        "with masses, weights, level): the Euler characteristic by a Morse count, the area and "
        "the integral of K by both curvature routes against 2 pi chi (Gauss-Bonnet), the "
        "leading exponent at unit speed against Katok's and Osserman-Sarnak's bounds, and the "
        "sign of K proved by exact algebra and interval arithmetic. See docs/verdict.md.")
    p.add_argument("--masses", type=float, nargs=3, metavar="M", help="masses (default 1 1 1)")
    p.add_argument("--weights", type=float, nargs=3, metavar="A",
                   help="weights of the constraint sum(a cos theta) = level (default 1 1 1)")
    p.add_argument("--level", type=float, default=0.0, help="level of the constraint (default 0)")
    p.add_argument("--grid", type=positive_count, default=256, metavar="G",
                   help="quadrature points per chart axis (default 256)")
    p.add_argument("--t-final", type=float, default=3000.0, metavar="T",
                   help="length of each exponent's run (default 3000)")
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2], metavar="S",
                   help="seeds of the exponent's runs (default 1 2)")
    p.add_argument("--json", type=Path, metavar="FILE", help="also write the report as JSON")
    p.set_defaults(func=cmd_verdict)


def cmd_verdict(args) -> int:
    """Print the verdict; 0 when every check holds (Gauss-Bonnet to 1e-6 relative, no
    exponent outside the bracket by over 3 standard errors, a certificate that decided),
    1 otherwise."""
    from ..geometry.system import RotorSystem
    from ..runs.verdict import format_verdict, surface_verdict

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")               # a critical level is refused below
        system = RotorSystem(3, masses=args.masses, weights=args.weights, level=args.level)
    rep = surface_verdict(system, n_grid=args.grid, t_final=args.t_final, seeds=args.seeds)
    print(format_verdict(rep))
    if args.json is not None:
        args.json.write_text(json.dumps(rep, indent=1), encoding="utf-8")
    scale = 2 * 3.141592653589793 * max(abs(rep["routes"]["chart"]["euler_characteristic"]), 1)
    ok = all(abs(r["gauss_bonnet_error"]) <= 1e-6 * scale for r in rep["routes"].values())
    ok &= all(e["consistent"] for e in rep["exponents"])
    ok &= rep["certificate"]["verdict"] != "undecided"
    return 0 if ok else 1
