"""What a Dask worker does for one point: run its scene quietly in a temporary folder and
return one row of statistics (a point that fails to integrate is a row too)."""
from __future__ import annotations

import json
import math
import os
import socket
import tempfile
import time
from pathlib import Path

import numpy as np

from .. import runner
from ..scene import parse_scene
from .statistics import result_statistics

__all__ = ["evaluate_point"]


def evaluate_point(raw: dict) -> dict:
    """Run one point (on a Dask worker): the scene in a temporary folder, quietly.
    Returns {'status', 'error', 'stats', 'wall_s', 'worker', 't_final'}; never raises for
    a point that fails to integrate (status 'failed' with the message)."""
    scene = parse_scene(raw, source=raw.get("name", "<point>"))
    t0 = time.perf_counter()
    status, error, arrays = "complete", "", None
    with tempfile.TemporaryDirectory(prefix="charts-sweep-") as td:
        try:
            result = runner.run_scene(scene, td, quiet=True)
        except runner.RunError as exc:
            status, error = "failed", str(exc).replace(td, "<point>")
            try:
                result = json.loads((Path(td) / "result.json").read_text())
            except (OSError, ValueError):
                result = {}
        if (Path(td) / "arrays.npz").exists():
            with np.load(Path(td) / "arrays.npz") as a:
                arrays = {k: a[k] for k in a.files if k.startswith("curvature_")}
    stats = result_statistics(result, arrays)
    bad = sorted(k for k, v in stats.items() if v is not None and not math.isfinite(v))
    drift = result.get("drift", {})
    if status == "complete" and (bad or not all(math.isfinite(v) for v in drift.values())):
        # the runner's ambient kernel does not stop on a non-finite state (e.g. N = 4 close
        # to a singular point without projection): such a point failed
        status = "failed"
        error = (f"non-finite results ({', '.join(bad) or 'drift'}): the trajectory left the "
                 "manifold; set [scene.integrator] project = true or a smaller dt")
    return {"status": status, "error": error, "stats": stats,
            "t_final": result.get("progress", {}).get("t_done"),
            "wall_s": round(time.perf_counter() - t0, 3),
            "worker": f"{socket.gethostname()}:{os.getpid()}"}
