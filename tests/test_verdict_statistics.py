"""``charts verdict --statistics``: the angle test at scale as a command (tiny, on the CPU), its
reports kept and read back, the figure, and docs/hyperbolicity.md's tables against the
reports of the GPU run they quote."""
import json
from pathlib import Path

import pytest

import charts.runs.verdict_statistics as verdict
from charts.analyses.angle_tally import AngleTally
from charts.cli.main import main

ROOT = Path(__file__).resolve().parents[1]
REPORTS = ROOT / "docs" / "figures" / "verdict"


def test_the_command_runs_saves_and_reads_back(tmp_path, capsys, monkeypatch):
    """Two members of N = 3 on the CPU: a report per system, the tally saved; run again, the
    report is read from the folder, not computed."""
    pytest.importorskip("xarray")
    args = ["verdict", "--statistics", "--n", "3", "--samples", "400", "--members", "2",
            "--device", "cpu", "--t-transient", "1", "--out", str(tmp_path)]
    assert main(args) == 0
    first = capsys.readouterr().out
    assert "N = 3" in first and "2 members x T = 20" in first
    assert "verdict: open; evidence: statistics; why: " in first      # angles decide nothing
    reports = json.loads((tmp_path / "statistics.json").read_text())
    assert (reports[0]["verdict"], reports[0]["evidence"]) == ("open", "statistics")
    assert reports[0]["statistics"]["restricted"]["n"] == 400
    assert (tmp_path / f"{reports[0]['slug']}.nc").exists()

    def refuse(*a, **k):
        raise AssertionError("a system already done ran again")
    monkeypatch.setattr(verdict, "statistics_verdict", refuse)
    assert main(args) == 0
    assert json.loads((tmp_path / "statistics.json").read_text()) == reports


def test_a_family_of_the_paper_is_its_28_systems():
    systems = verdict.family_systems("families-n4")
    assert len(systems) == 28                          # 4 weight patterns × 7 levels
    assert systems[0][1].describe()["level"] == 0.0
    with pytest.raises(ValueError, match="unknown sweep"):
        verdict.family_systems("no-such-sweep")


def test_the_window_gives_the_samples_asked_for():
    assert verdict.members_window(1e9, 16384) == 6104.0       # 16384 × 61040 ≥ 1e9
    assert verdict.members_window(400, 2, 0.1) == 20.0


def test_the_docs_tables_are_the_reports():
    """The tables of docs/hyperbolicity.md are what scripts/verdict_statistics_tables.py
    prints from the reports in docs/figures/verdict (no number typed by hand)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "tables", ROOT / "scripts" / "verdict_statistics_tables.py")
    tables = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tables)
    doc = (ROOT / "docs" / "hyperbolicity.md").read_text(encoding="utf-8")
    paper = [r for f in tables.PAPER for r in json.loads((REPORTS / f).read_text())]
    assert tables.paper_table(paper) in doc
    assert tables.families_table(json.loads((REPORTS / tables.FAMILIES).read_text())) in doc


def test_the_figure_of_a_tally():
    import numpy as np
    t = AngleTally.empty(2, dict(n=4, sample_every=0.1))
    rng = np.random.default_rng(0)
    for v in ("full", "restricted"):
        t.add(np.abs(rng.normal(size=(2, 5000))), variant=v)
    fig, axes = t.plot()
    assert len(axes) == 2 and "P(φ < x)" in axes[0].get_ylabel()
    from charts.plotting import plot_angle_law
    bounded = dict(t.statistics(), cdf=[])                  # N = 3: no angle below 0.05
    fig, axes = plot_angle_law({"N = 3": bounded})
    assert "none below" in axes[0].get_legend().get_texts()[0].get_text()


def test_a_family_is_its_distinct_systems_of_rotors():
    assert len(verdict.family_systems("masses-n4")) == len(
        {json.dumps(s.describe(), sort_keys=True) for _, s in verdict.family_systems("masses-n4")})
    with pytest.raises(ValueError, match="linkage"):
        verdict.family_systems("linkage-epsilon")


def test_a_saved_run_is_reused_only_for_the_same_question(tmp_path, capsys):
    """A folder's tally or report answers a later call only with the same members, window
    and transient; other systems' reports stay in statistics.json; names keep every digit."""
    from charts.cli.verdict_statistics import slug_of as _slug
    from charts.geometry.system import RotorSystem
    pytest.importorskip("xarray")
    base = ["verdict", "--statistics", "--n", "3", "--device", "cpu", "--out", str(tmp_path)]
    assert main(base + ["--members", "2", "--samples", "40", "--t-transient", "1"]) == 0
    assert main(base + ["--members", "3", "--samples", "60", "--t-transient", "1"]) == 0
    assert "3 members x T = 2" in capsys.readouterr().out
    base[3] = "4"
    assert main(base + ["--members", "2", "--samples", "40", "--t-transient", "1"]) == 0
    slugs = {r["slug"]: r["members"] for r in
             json.loads((tmp_path / "statistics.json").read_text())}
    assert slugs == {"n3-c0-w1,1,1-m1,1,1": 3, "n4-c0-w1,1,1,1-m1,1,1,1": 2}
    assert _slug(RotorSystem(3, masses=[1, 1, 1.0000001])) != _slug(RotorSystem(3))
