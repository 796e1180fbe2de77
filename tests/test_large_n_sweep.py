"""The bundled large-N sweep and a sweep speed given as an expression in n (the speed
normalisation "kinetic energy ½ per rotor": speed = √N for unit masses)."""
import pytest

from charts.runs.sweep import SweepError, bundled_sweeps, load_sweep, parse_sweep, sweep_points

BASE = {"system": {"n": 4}, "run": {"t_final": 10.0, "t_transient": 0.0},
        "effects": {"lyapunov": {"n_batches": 2}}}


def test_bundled_large_n_points():
    pts = sweep_points(load_sweep(bundled_sweeps()["large-n"]))
    by = {(p.params["n"], p.params["speed"], p.params["seed"]): p.scene for p in pts}
    assert len(pts) == 12 * 2 * 2
    assert by[(64, "n ** 0.5", 1)].system["speed"] == 8.0
    assert by[(64, 1.0, 2)].system["speed"] == 1.0
    assert by[(3, "n ** 0.5", 1)].system["speed"] == pytest.approx(3 ** 0.5, rel=1e-15)
    assert by[(64, 1.0, 1)].system["n"] == 64


@pytest.mark.parametrize("speed", ["m * 2", "sqrt(n)", "n +"])
def test_speed_expression_must_be_arithmetic_in_n(speed):
    data = {"name": "s", "scene": BASE,
            "sweep": {"parameters": {"n": [4], "speed": [1.0, speed]}}}
    with pytest.raises(SweepError, match=r"speed = .*expression in n"):
        parse_sweep(data)
