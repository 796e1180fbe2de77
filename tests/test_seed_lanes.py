"""Scenes that differ only in their seed, run together in lanes (``charts.runs.seed_lanes``),
against `run_scene` of each: the same result, record by record and bit for bit (the lanes
do the one-trajectory kernel's operations in the same order and the runs stop, record and
checkpoint at the same steps); a scene whose lane stops fails as it fails alone; sweeps cut
their points into lane blocks and give the same rows."""
from __future__ import annotations

import json

import numpy as np
import pytest

from charts import RotorSystem
from charts.analyses.lyapunov_members import LANE_BLOCK, MIN_LANES
from charts.runs.runner import RunError, run_scene
from charts.runs.plan import plan_scene
from charts.runs.scene import parse_scene
from charts.runs.seed_lanes import run_seed_lanes, seed_family
from charts.runs.sweep.execute import lane_blocks
from charts.runs.sweep.worker import evaluate_point, evaluate_points

from scenarios import THROUGH_SINGULAR_N4


def raw(seed, n=4, effects=None):
    return {"name": f"lanes-{seed}", "system": {"n": n, "masses": [1.0, 2.0, 1.0, 1.5][:n]},
            "integrator": {"project": True},
            "run": {"t_final": 3.0, "t_transient": 0.5, "checkpoint_every": 1.0},
            "initial": {"seed": seed},
            "effects": effects or {
                "lyapunov": {"n_batches": 2, "reorth_every": 0.1},
                "curvature": {"route": "both", "sample_every": 0.2},
                "waveforms": {"rotors": [0, 2]}, "drift": {"sample_every": 0.5},
                "angles": {"variant": "both", "sample_every": 0.5}}}


def _same(a, b, path="result"):
    """a == b exactly, through dicts and lists (NaN equal to NaN)."""
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            _same(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and np.isnan(a):
        assert isinstance(b, float) and np.isnan(b), path
    else:
        assert a == b, path


def test_lanes_equal_run_scene_bit_for_bit(tmp_path):
    """Three seeds of an N = 4 scene with masses (exponents, both curvature routes,
    waveforms, drift, the angle test): result.json and arrays.npz of each equal its own
    `run_scene` (timings and folder names aside)."""
    scenes = [parse_scene(raw(s), source=f"s{s}") for s in (3, 4, 5)]
    together = run_seed_lanes(scenes, [tmp_path / f"lanes{i}" for i in range(3)])
    for i, sc in enumerate(scenes):
        alone = run_scene(sc, tmp_path / f"alone{i}", quiet=True)
        got = together[i]
        assert got["status"] == "complete"
        for key in ("results", "computation", "final_state", "drift", "progress"):
            _same(got[key], alone[key], key)
        with np.load(tmp_path / f"lanes{i}" / "arrays.npz") as a, \
                np.load(tmp_path / f"alone{i}" / "arrays.npz") as b:
            assert set(a.files) == set(b.files)
            for k in a.files:
                assert np.array_equal(a[k], b[k], equal_nan=True), k
    # the seeds were run, not copies of one another
    assert together[0]["results"]["lyapunov"] != together[1]["results"]["lyapunov"]


def test_a_lane_that_stops_fails_as_alone_and_the_others_go_on(tmp_path, monkeypatch):
    """Seed 11's state is replaced by the N = 4 geodesic through a singular point: its scene
    fails with `run_scene`'s error and finished part; seeds 10 and 12 complete as alone."""
    real = RotorSystem.random_state

    def aimed(self, seed=0, speed=1.0):
        if seed == 11:
            return tuple(np.array(x) for x in THROUGH_SINGULAR_N4)
        return real(self, seed=seed, speed=speed)

    monkeypatch.setattr(RotorSystem, "random_state", aimed)
    eff = {"lyapunov": {"n_batches": 2}, "drift": {"sample_every": 0.1}}
    scenes = [parse_scene({**raw(s, effects=eff), "system": {"n": 4},
                           "integrator": {"project": False}}, source=f"s{s}")
              for s in (10, 11, 12)]
    together = run_seed_lanes(scenes, [tmp_path / f"lanes{i}" for i in range(3)])
    with pytest.raises(RunError) as alone_err:
        run_scene(scenes[1], tmp_path / "alone1", quiet=True)
    assert isinstance(together[1], RunError)
    assert str(together[1]).replace("lanes1", "alone1") == str(alone_err.value)
    assert "singular point" in str(together[1])
    a = json.loads((tmp_path / "lanes1" / "result.json").read_text())
    b = json.loads((tmp_path / "alone1" / "result.json").read_text())
    assert a["status"] == b["status"] == "failed"
    _same(a["progress"], b["progress"])
    _same(a["results"], b["results"])
    for i in (0, 2):
        alone = run_scene(scenes[i], tmp_path / f"alone{i}", quiet=True)
        _same(together[i]["results"], alone["results"])


def test_seed_family_and_refusals():
    a, b = (parse_scene(raw(s), source="x") for s in (1, 2))
    assert seed_family(a) == seed_family(b) is not None
    other = parse_scene({**raw(1), "system": {"n": 4, "masses": [1, 1, 1, 2]}}, source="x")
    assert seed_family(other) != seed_family(a)
    chart = parse_scene({**raw(1, effects={"waveforms": {}}),
                         "integrator": {"formulation": "chart"}}, source="x")
    assert seed_family(chart) is None
    with pytest.raises(ValueError, match="differ only in their seed"):
        run_seed_lanes([a, other], ["unused1", "unused2"])


class _P:
    """A sweep point's stand-in for `lane_blocks`: its scene."""

    def __init__(self, scene):
        self.scene = scene


@pytest.mark.parametrize("members, workers, sizes", [
    (MIN_LANES - 1, 2, [1] * (MIN_LANES - 1)),         # too few: one point per task
    (2 * MIN_LANES, 2, [MIN_LANES, MIN_LANES]),         # one block per worker
    (2 * MIN_LANES - 1, 2, [2 * MIN_LANES - 1]),        # two would be too small
    (LANE_BLOCK + 1, 1, [LANE_BLOCK // 2, LANE_BLOCK // 2 + 1]),   # at most LANE_BLOCK
])
def test_lane_blocks(members, workers, sizes, monkeypatch):
    """Where the lanes pay (asked with a block's seeds and the seeds of one worker's
    compilation), a family's seeds in blocks of MIN_LANES to LANE_BLOCK; where they do not,
    each seed a block of its own."""
    from charts.runs.sweep import execute

    asked = []
    for pay in (True, False):
        monkeypatch.setattr(execute, "seeds_pay", lambda scene, lanes, device, runs: asked.append(
            (lanes, device, runs)) or pay)
        groups = [[_P(parse_scene(raw(s), source="x"))] for s in range(members)]
        blocks = lane_blocks(groups, workers)
        assert [len(b) for b in blocks] == (sizes if pay or members < MIN_LANES
                                            else [1] * members)
        assert [g for b in blocks for g in b] == groups          # every group once, in order
    if members >= MIN_LANES:
        nb = len(sizes)
        assert asked == [(max(sizes), "cpu", -(-members // min(nb, workers)))] * 2


@pytest.mark.parametrize("pay", [True, False])
def test_sweep_worker_rows_are_the_points_rows(tmp_path, monkeypatch, pay):
    """`evaluate_points` on `MIN_LANES` seeds gives each point the statistics `evaluate_point`
    gives it alone, in lanes where they pay (``lanes_pay``, asked with N, k, the seeds and
    the steps of transient and run) and each alone where they do not."""
    from charts.runs.sweep import worker
    from charts.solvers import lanes

    asked, together_runs = [], []
    monkeypatch.setattr(lanes, "lanes_pay", lambda *a: asked.append(a) or pay)
    monkeypatch.setattr(worker, "run_seed_lanes",
                        lambda *a: together_runs.append(1) or run_seed_lanes(*a))
    eff = {"lyapunov": {"n_batches": 2}, "curvature": {"route": "numerical",
                                                       "sample_every": 0.5}}
    raws = [raw(s, effects=eff) for s in range(MIN_LANES)]
    together = evaluate_points(raws)
    sc = parse_scene(raws[0], source="x")
    steps = round((sc.run["t_final"] + sc.run["t_transient"]) / sc.integrator["dt"])
    assert asked == [(sc.system["n"], plan_scene(sc).tangent_vectors, MIN_LANES, steps, None)]
    assert together_runs == ([1] if pay else [])
    for r, got in zip(raws, together):
        alone = evaluate_point(r)
        assert got["status"] == alone["status"] == "complete"
        _same(got["stats"], alone["stats"])


def test_the_gpu_threads_give_the_lanes_rows(tmp_path):
    """``flows``: the seeds advanced by the GPU's driver (``DeviceFlows``, here its CPU twin,
    the same logic) give the lanes' results bit for bit; a sweep asked for a GPU that is not
    there says what is missing before any work."""
    from functools import partial

    from charts.runs.sweep import load_sweep
    from charts.runs.sweep.execute import SweepError, run_sweep
    from charts.solvers.device import DeviceFlows, cuda_available

    effects = {"lyapunov": {"n_batches": 2, "reorth_every": 0.1}, "drift": {"sample_every": 0.5}}
    scenes = [parse_scene(raw(s, effects=effects), source=f"s{s}") for s in (3, 4)]
    lanes = run_seed_lanes(scenes, [tmp_path / f"lanes{i}" for i in range(2)])
    twin = run_seed_lanes(scenes, [tmp_path / f"twin{i}" for i in range(2)],
                          partial(DeviceFlows.of_flows, backend="cpu"))
    for a, b in zip(lanes, twin):
        for key in ("results", "final_state", "drift"):
            _same(a[key], b[key], key)
    if not cuda_available():
        sweep_file = tmp_path / "s.toml"
        sweep_file.write_text('name = "s"\n[scene.run]\nt_final = 1.0\n[scene.effects.lyapunov]\n'
                              '[sweep]\nmode = "grid"\nseeds = [1, 2]\n'
                              '[sweep.parameters]\nn = [3]\n')
        with pytest.raises(SweepError, match=r"--device cuda needs.*Use --device cpu \(or auto\)"):
            run_sweep(load_sweep(sweep_file), tmp_path / "out", device="cuda", quiet=True)
        assert not (tmp_path / "out").exists()


def test_the_seeds_angle_tests_together_give_each_seeds_own(tmp_path):
    """A point's angle tests run together (the GPU route's twin on the CPU, one block):
    every seed's result and arrays are the ones its own pass gives, bit for bit."""
    from charts.analyses.hyperbolicity import angle_members
    raws = [raw(s) for s in (3, 4, 5)]
    for r in raws:              # the GPU route's transient: whole checkpoint segments
        r["effects"]["angles"]["t_transient"] = 1.0
    scenes = [parse_scene(r, source=r["name"]) for r in raws]
    alone = run_seed_lanes(scenes, [tmp_path / f"a{i}" for i in range(3)])
    twin = run_seed_lanes(scenes, [tmp_path / f"b{i}" for i in range(3)],
                          angles=lambda *a: angle_members(*a, backend="cpu"))
    for i, (x, y) in enumerate(zip(alone, twin)):
        assert y["status"] == "complete"
        for key in ("results", "computation"):
            _same(x[key], y[key], key)
        with np.load(tmp_path / f"a{i}" / "arrays.npz") as a, \
                np.load(tmp_path / f"b{i}" / "arrays.npz") as b:
            assert {"angles_t", "angles_full", "angles_restricted"} <= set(a.files)
            for k in a.files:
                assert np.array_equal(a[k], b[k], equal_nan=True), k


def test_an_angle_test_that_cannot_run_together_fails_the_seeds_with_its_reason(tmp_path):
    """The GPU route takes whole checkpoint segments of transient: a scene with 0.5 fails
    each seed with the route's reason (the main pass's part written)."""
    from charts.analyses.hyperbolicity import angle_members
    scenes = [parse_scene(raw(s), source=f"s{s}") for s in (3, 4, 5)]
    out = run_seed_lanes(scenes, [tmp_path / f"c{i}" for i in range(3)],
                         angles=lambda *a: angle_members(*a, backend="cpu"))
    assert all(isinstance(o, RunError) and "multiple of checkpoint_every" in str(o) for o in out)
