"""The pace benchmark's rows (``charts.runs.benchmarks.pace``): every analysis named, the
base first with ratio 1, costs positive and finite, and the Markdown table of the docs."""
import math

from charts.runs.benchmarks.pace import analysis_pace, format_rows


def test_rows_name_every_analysis_with_the_kernel_as_base():
    seen = []
    rows = analysis_pace(2.0, n=3, repeats=1, progress=seen.append)
    names = [r[0] for r in rows]
    assert names == seen and names[0] == "lyapunov_spectrum, 1 exponents" and len(rows) == 8
    assert rows[0][2] == 1.0
    assert all(us > 0 and math.isfinite(us) and ratio > 0 for _, us, ratio in rows)
    table = format_rows(rows, 2.0, 3).splitlines()
    assert table[0].startswith("| N = 3, T = 2 ") and len(table) == 2 + len(rows)
