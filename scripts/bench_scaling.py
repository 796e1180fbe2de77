"""Cost per simulated time unit against N: see charts/runs/benchmarks/scaling.py."""
from charts.runs.benchmarks.scaling import main

if __name__ == "__main__":
    raise SystemExit(main())
