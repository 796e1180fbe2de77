#!/usr/bin/env bash
# The device check of the GPU route, run on a machine with an NVIDIA GPU from the repository
# root: installs this checkout without its dependencies (the machine has them, or carries
# them), runs the GPU tests' CPU twins, then `charts bench gpu --flops` (about 5 minutes on
# an H100); the table goes to stdout and, where $OUT is set, to $OUT/bench_gpu.md.
set -o pipefail
export PYTHONUNBUFFERED=1 NUMBA_CACHE_DIR=${NUMBA_CACHE_DIR:-/tmp/charts-numba-cache}
python3 -m pip install -q --no-deps --no-build-isolation --no-index -e . >/dev/null 2>&1 \
    || export PYTHONPATH=$PWD
nvidia-smi -L
python3 -c "import numpy, numba; print('numpy', numpy.__version__, 'numba', numba.__version__)"
python3 -m charts.cli.main bench gpu "${@:---flops}" 2>&1 | tee "${OUT:-/tmp}/bench_gpu.md"
