"""`charts bench integrators`: see charts/runs/benchmarks/integrators.py."""
from charts.runs.benchmarks.integrators import main

if __name__ == "__main__":
    raise SystemExit(main())
