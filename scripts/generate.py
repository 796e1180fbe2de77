#!/usr/bin/env python
"""Write the generated chart kernels into ``generated/`` (the only writer of it).

    python scripts/generate.py            # regenerate N = 3..6 (the family Σ aᵢ cos θᵢ = c and its
                                          # paper member a = 1, c = 0) and the linkage of the Appendix
    python scripts/generate.py --check    # regenerate into a temp folder, diff, exit 1 if stale
"""
from __future__ import annotations

import argparse
import difflib
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def write_all(outdir: Path, ns, verbose=True) -> dict[str, float]:
    from charts.atomic import atomic_write
    from charts.codegen.emit import init_source, linkage_source, module_name, module_source
    from charts.codegen.symbolic import ChartGeometry

    outdir.mkdir(parents=True, exist_ok=True)
    timings = {}
    atomic_write(outdir / "__init__.py", init_source().encode("utf-8"))
    for n in ns:
        t0 = time.perf_counter()
        G = ChartGeometry(n, n - 1)  # one derivation, two modules (the family, its paper member)
        for paper in (False, True):
            atomic_write(outdir / f"{module_name(n, paper)}.py",
                         module_source(n, paper, G).encode("utf-8"))
        timings[f"N={n}"] = time.perf_counter() - t0
        if verbose:
            print(f"  N={n}: {timings[f'N={n}']:.1f} s", flush=True)
    t0 = time.perf_counter()
    atomic_write(outdir / "linkage.py", linkage_source().encode("utf-8"))  # the Appendix's linkage
    timings["linkage"] = time.perf_counter() - t0
    if verbose:
        print(f"  linkage: {timings['linkage']:.1f} s", flush=True)
    return timings


def compare(new: Path, old: Path) -> list[str]:
    """Unified diff lines between two generated folders (empty when equal)."""
    diff = []
    names = sorted({p.name for p in new.glob("*.py")} | {p.name for p in old.glob("*.py")})
    for name in names:
        a = (old / name).read_text().splitlines(keepends=True) if (old / name).exists() else []
        b = (new / name).read_text().splitlines(keepends=True) if (new / name).exists() else []
        diff += list(difflib.unified_diff(a, b, f"generated/{name}", f"regenerated/{name}"))
    return diff


def main(argv=None) -> int:
    from charts.codegen.emit import SHIPPED_N

    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true",
                    help="regenerate into a temporary folder and exit 1 with a diff if generated/ is stale")
    ap.add_argument("--out", type=Path, default=ROOT / "generated", help="output folder (default: generated/)")
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            write_all(Path(tmp), SHIPPED_N, verbose=False)
            diff = compare(Path(tmp), args.out)
        if diff:
            sys.stdout.writelines(diff[:400])
            print(f"\ngenerated/ is stale ({len(diff)} diff lines). Run: python scripts/generate.py")
            return 1
        print(f"generated/ is up to date ({time.perf_counter() - t0:.1f} s)")
        return 0
    print(f"writing {args.out}")
    write_all(args.out, SHIPPED_N)
    print(f"done in {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))  # run from a checkout without installing
    sys.exit(main())
