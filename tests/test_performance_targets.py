"""The target table of `charts bench performance` (``charts.runs.benchmarks.targets``): each
measured number judged against its target on the right side of the bound, numbers that were
not measured left out, and the reproduce target judged on the full preset only."""
from charts.runs.benchmarks.performance import SECTIONS, main
from charts.runs.benchmarks.targets import (ENSEMBLE_TARGET, PACE_JUDGED, PACE_TARGET,
                                            REPRODUCE_TARGET, format_targets, target_rows)
import pytest


def test_each_target_is_judged_on_the_right_side_of_its_bound():
    pace = {PACE_JUDGED[0]: PACE_TARGET, PACE_JUDGED[1]: PACE_TARGET * 1.01, "other": 9.0}
    rows = target_rows(ENSEMBLE_TARGET - 0.01, pace, (REPRODUCE_TARGET, 300.0), "full",
                       {"empty cache": 17.0, "filled cache": 1.5})
    verdicts = [ok for _, _, ok in rows]
    assert verdicts == [False, True, False, True, False, True]
    assert "3.00x" not in rows[0][1] and rows[0][1] == f"{ENSEMBLE_TARGET - 0.01:.2f}x"
    assert not any("other" in t for t, _, _ in rows)      # only the analyses the target names


def test_unmeasured_numbers_are_left_out_and_quick_reproduce_is_not_judged():
    assert target_rows() == []
    (row,) = target_rows(reproduce=(30.0, 50.0), reproduce_preset="quick")
    assert row[2] is None and "--quick" in row[0]
    table = format_targets([row]).splitlines()
    assert table[:2] == ["| target | measured | verdict |", "|---|---:|---|"]
    assert table[2].endswith("| not judged |")


def test_unknown_section_is_refused_in_one_line(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--skip", "everything"])
    assert exc.value.code == 2 and set(SECTIONS) <= set(capsys.readouterr().err.split("'"))
