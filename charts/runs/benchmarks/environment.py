"""The machine, the software versions and the load, printed with every benchmark."""
from __future__ import annotations

import os
import platform
import statistics
from pathlib import Path

__all__ = ["machine", "load", "spread"]


def load() -> str:
    """The load averages over 1, 5 and 15 minutes, as printed by the benchmarks."""
    return "load average {:.1f} {:.1f} {:.1f}".format(*os.getloadavg())


def machine() -> str:
    """CPU model, core count, OS and the versions of the numerical packages."""
    cpu = "?"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    vers = [f"python {platform.python_version()}"]
    for mod in ("numpy", "numba", "scipy", "jitcode", "symengine"):
        try:
            vers.append(f"{mod} {__import__(mod).__version__}")
        except ImportError:
            pass
    return (f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; "
            + ", ".join(vers))


def spread(values) -> tuple[float, float, float]:
    """(median, min, max) of ``values``."""
    values = list(values)
    return statistics.median(values), min(values), max(values)
