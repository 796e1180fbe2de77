"""Runs built on the analyses: declarative scenes, sweeps on Dask, the reproduction of the
paper, the accuracy study, benchmarks, figures and result files."""
