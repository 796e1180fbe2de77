"""The warm-up facility (`charts warmup`, charts.runs.warmup) and the cold-start benchmark
(charts.runs.benchmarks.coldstart): what they do, not how fast (docs/performance.md)."""
import pytest

from charts.cli.main import build_parser, main
from charts.runs import warmup as warm
from charts.runs.benchmarks import coldstart


def test_warmup_calls_each_analysis_once_per_n_and_reports_compile_time():
    seen = []
    rows = warm.warmup((3,), ["lyapunov", "angles"], report=seen.append)
    assert [(r["analysis"], r["n"]) for r in rows] == [("lyapunov", 3), ("angles", 3)]
    assert seen == rows
    for r in rows:
        assert 0.0 <= r["compile"] and r["cpu"] > 0.0
    # a second time everything is compiled in this process: no compilation at all
    again = warm.warmup((3,), ["lyapunov"])
    assert again[0]["compile"] == 0.0


def test_warmup_leaves_the_lanes_to_the_runs_that_pay_for_them():
    """By default every analysis's first call, not the ensembles' lanes (compiled per N and
    k where a run pays for them: ``charts.solvers.lanes.lanes_pay``), which stay a task."""
    assert set(warm.DEFAULT_ANALYSES) == set(warm.TASKS) - {"lanes"}
    seen = []
    warm.warmup((3,), workers=1, report=lambda row: seen.append(row["analysis"]))
    assert sorted(seen) == sorted(warm.DEFAULT_ANALYSES)


def test_warmup_refuses_unknown_analyses():
    with pytest.raises(ValueError, match="unknown \\['lyapunv'\\]; choose from"):
        warm.warmup((3,), ["lyapunv"])


def test_warmup_command_line(capsys):
    assert main(["warmup", "--n", "3", "--analysis", "lyapunov"]) == 0
    out = capsys.readouterr().out
    assert "lyapunov  N = 3:" in out and "kernels ready" in out
    assert main(["warmup", "--n", "2"]) == 2
    assert "--n: N must be at least 3, got 2" in capsys.readouterr().err
    assert main(["warmup", "--analysis", "lyap"]) == 2
    assert "unknown 'lyap'; choose from lyapunov," in capsys.readouterr().err
    # the help names every analysis the warm-up knows
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    helptext = sub.choices["warmup"].format_help()
    assert all(name in helptext for name in warm.TASKS)


def _fake_run(scale):
    phases = [("import numpy", 0.1, 0.1 * scale), ("import numba", 0.2, 0.2 * scale),
              ("import charts", 0.3, 0.3), ("first call", 1.0, 1.0 * scale)]
    compiles = [(1, "charts.inner", 0.5 * scale, 0.5 * scale, 0.6),
                (0, "charts.outer", 0.4 * scale, 0.9 * scale, 1.0)]
    return {"phases": phases, "compiles": compiles, "loaded": ["charts.x"] * int(scale)}


def test_coldstart_rows_are_medians_per_case(monkeypatch):
    runs = iter([_fake_run(1.0), _fake_run(3.0), _fake_run(2.0)] * 2)
    monkeypatch.setattr(coldstart, "probe", lambda cache, path=None: next(runs))
    monkeypatch.setattr(coldstart.subprocess, "run", lambda *a, **k: None)  # byte-code import
    rows = coldstart.coldstart_rows(repeat=3)
    empty = [r for r in rows if r["case"] == "empty cache"]
    assert [r["name"] for r in empty if r["kind"] == "phase"] == [
        "import numpy", "import numba", "import charts", "first call"]
    first = next(r for r in empty if r["name"] == "first call")
    assert first["cpu"] == pytest.approx(2.0)                          # median of 1, 3, 2
    total = next(r for r in empty if r["kind"] == "total")
    assert total["cpu"] == pytest.approx(0.3 + 1.3 * 2.0)                # the median run
    assert total["range"] == pytest.approx((0.3 + 1.3, 0.3 + 1.3 * 3.0))
    assert next(r for r in empty if r["kind"] == "loaded")["count"] == 2
    comp = [r for r in empty if r["kind"] == "compile"]
    assert [(r["name"], r["depth"]) for r in comp] == [("charts.inner", 1), ("charts.outer", 0)]
    assert comp[1]["own"] == pytest.approx(0.8) and comp[1]["cpu"] == pytest.approx(1.8)
    lines = coldstart.format_rows(rows)
    assert any("target 2 s: not met" in line for line in lines)
    assert any("compile   inner" in line for line in lines)


def test_probe_times_a_real_first_call():
    """The probe script itself, against this installation's numba cache (filled by the other
    tests or compiled here: ~1 s, or 15 s of compilation on a fresh checkout)."""
    got = coldstart.probe(None)
    names = [p[0] for p in got["phases"]]
    assert names[0] == "import numpy" and names[-1].startswith("first lyapunov_spectrum")
    assert all(cpu >= 0.0 for _, _, cpu in got["phases"])
    compiled = {name for _, name, *_ in got["compiles"]}
    # the tangent kernel was either compiled or loaded from the cache, and not both
    assert ("charts.solvers.tangent.tangent_kernel" in compiled) != (
        "charts.solvers.tangent.tangent_kernel" in got["loaded"])


def test_warmup_stages_compile_each_shared_kernel_before_its_users():
    """The tangent kernel's first user (lyapunov) comes before the analyses that call it;
    clv after angles; further N of the chart-kernel analyses one stage after their first N;
    the loads of N-generic kernels for further N last."""
    plan = warm.stages([3, 4], list(warm.TASKS))
    where = {task: i for i, stage in enumerate(plan) for task in stage}
    assert sorted(where) == sorted((a, n) for a in warm.TASKS for n in (3, 4))
    for user in ("angles", "curvature", "clv", "lanes"):
        assert where[("lyapunov", 3)] < where[(user, 3)]
    assert where[("angles", 3)] < where[("clv", 3)]
    assert max(where[("lyapunov", 3)], where[("integrate", 3)]) < where[("integrate_ambient", 3)]
    for name in warm.PER_N:
        assert where[(name, 4)] == where[(name, 3)] + 1
    assert where[("lyapunov", 4)] == where[("angles", 4)] == len(plan) - 1


def test_warmup_runs_its_stages_in_a_pool(monkeypatch):
    """With two workers the calls go through a process pool, stage after stage; the rows
    come back in the order of N, then analyses."""
    monkeypatch.setattr(warm, "TASKS", {"lyapunov": lambda S, th, u: None,
                                        "integrate": lambda S, th, u: None})
    seen = []
    rows = warm.warmup((3, 4), ["lyapunov", "integrate"], report=seen.append, workers=2)
    assert [(r["analysis"], r["n"]) for r in rows] == [
        ("lyapunov", 3), ("integrate", 3), ("lyapunov", 4), ("integrate", 4)]
    assert sorted(map(str, seen)) == sorted(map(str, rows))
    assert all(r["compile"] == 0.0 and r["cpu"] >= 0.0 for r in rows)
