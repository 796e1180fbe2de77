"""`charts bench performance`: see charts/runs/benchmarks/performance.py."""
from charts.runs.benchmarks.performance import main

if __name__ == "__main__":
    raise SystemExit(main())
