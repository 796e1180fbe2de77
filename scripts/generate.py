#!/usr/bin/env python
"""Write the generated chart kernels into ``generated/`` (the only writer of it).

    python scripts/generate.py            # regenerate N = 3..6 (the family Σ aᵢ cos θᵢ = c and its
                                          # paper member a = 1, c = 0) and the mechanisms' jets
                                          # (charts/codegen/mechanism.py: rotors(3..6), the triple
                                          # linkage with and without rods, the Appendix linkage)
    python scripts/generate.py --check    # regenerate into a temp folder, diff, exit 1 if stale
"""
from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def main(argv=None) -> int:
    from charts.codegen.emit import SHIPPED_N
    from charts.codegen.regenerate import compare, write_all

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
