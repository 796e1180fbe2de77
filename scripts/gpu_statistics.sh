#!/usr/bin/env bash
# The statistics at scale of the angle test (docs/hyperbolicity.md), run on a machine with
# an NVIDIA GPU from the repository root: installs this checkout without its dependencies
# (the machine has them, or carries them), then `charts verdict --statistics` for each
# group of systems named on the command line, in order:
#   paper4    the paper's N = 4 manifold, 1e9 angles over 16384 members
#   paper35   N = 3 and N = 5 of the paper, 1e8 each
#   families  the 28 systems of the bundled sweep families-n4, 1e8 each
#   bench     `charts bench gpu --quick` (throughput and agreement with the CPU)
# Each group writes <group>.json (the reports of the systems done) and <group>.log under $OUT
# (default /tmp/out). The tallies (NetCDF) go to $TALLIES/<group> (default /tmp/tallies), where a
# second run reads the systems already done instead of running them again. A group that would
# run past $DEADLINE seconds from the start (default 540) is interrupted (the systems done are
# kept) and the later groups are skipped. $DEVICE (default cuda) and $EXTRA (more arguments,
# e.g. "--members 4 --samples 2000" for a trial on the CPU) are passed on.
set -o pipefail
export PYTHONUNBUFFERED=1 NUMBA_CACHE_DIR=${NUMBA_CACHE_DIR:-/tmp/charts-numba-cache}
python3 -m pip install -q --no-deps --no-build-isolation --no-index -e . >/dev/null 2>&1 \
    || export PYTHONPATH=$PWD${PYTHONPATH:+:$PYTHONPATH}
OUT=${OUT:-/tmp/out}
TALLIES=${TALLIES:-/tmp/tallies}
DEADLINE=${DEADLINE:-540}
mkdir -p "$OUT" "$TALLIES"
nvidia-smi -L 2>/dev/null || echo "no nvidia-smi"
python3 -c "import numpy, numba; print('numpy', numpy.__version__, 'numba', numba.__version__)"
left() { echo $((DEADLINE - SECONDS)); }
verdict() {   # group, then the arguments of charts verdict --statistics
    local group=$1; shift
    echo "== $group: charts verdict --statistics $* (at ${SECONDS} s, $(left) s left)"
    timeout -s INT -k 20 "$(left)" python3 -m charts.cli.main verdict --statistics \
        --device "${DEVICE:-cuda}" --out "$TALLIES/$group" "$@" $EXTRA 2>&1 | tee "$OUT/$group.log"
    cp "$TALLIES/$group/statistics.json" "$OUT/$group.json" 2>/dev/null
}
for group in ${@:-paper4 paper35 families bench}; do
    if [ "$(left)" -lt 60 ]; then echo "== $group skipped: $(left) s left"; continue; fi
    case $group in
        paper4)   verdict paper4 --n 4 --samples 1e9 ;;
        paper35)  verdict paper35 --n 3 5 --samples 1e8 ;;
        families) verdict families --family families-n4 --samples 1e8 ;;
        bench)    timeout -s INT -k 20 "$(left)" python3 -m charts.cli.main bench gpu --quick 2>&1 \
                      | tee "$OUT/bench.log" ;;
        *)        echo "unknown group $group (paper4, paper35, families, bench)"; exit 2 ;;
    esac
done
echo "== done at ${SECONDS} s"
