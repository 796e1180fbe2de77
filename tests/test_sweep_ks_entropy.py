"""The sweep's Kolmogorov–Sinai entropy column (Pesin's formula, h_KS = Σ λᵢ over the positive
exponents): ``h_ks`` and ``h_ks_se`` in sweep.csv (one run: the sum and the batch-means error
of the per-batch sums), in summary.csv (over seeds: the mean of the seeds' sums and their
standard error) and in the NetCDF table, each checked against numbers computed here
independently (the direct API call with the point's seed, the seeds' exponents)."""
import json

import numpy as np
import pytest

import charts
from charts.analyses.spectrum_quantities import leading_entropy_with_error
from charts.runs.sweep import SUMMARY, TABLE, parse_sweep, read_table, run_sweep, sweep_points
from charts.runs.sweep.report import summarize, summary_markdown
from charts.runs.sweep.statistics import stat_columns
from charts.runs.sweep.table import point_columns, point_row

SEEDS = [1, 2, 3]
T, T0, BATCHES = 4.0, 1.0, 3
BASE = {"system": {"n": 4}, "integrator": {"dt": 0.01},
        "run": {"t_final": T, "t_transient": T0},
        "effects": {"lyapunov": {"n_batches": BATCHES}}}


def _sweep(base=BASE, seeds=SEEDS):
    return parse_sweep({"name": "ks", "scene": base,
                        "sweep": {"seeds": seeds, "parameters": {"n": [4]}}}, source="ks.toml")


def test_h_ks_columns_of_a_sweep_equal_the_sums_computed_independently(tmp_path):
    sweep = _sweep()
    res = run_sweep(sweep, tmp_path, workers=1, quiet=True)
    assert not res["failed"] and not res["lost"]
    header, rows = read_table(tmp_path / TABLE)
    assert header[header.index("lambda_2_se") + 1:][:2] == ["h_ks", "h_ks_se"]

    # each row (one seed): the sum of its positive exponents, the batch-means error of the
    # per-batch sums, from the API call the point's scene is (same seed, same settings)
    system = charts.RotorSystem(4)
    members = []
    for seed, row in zip(SEEDS, rows):
        api = charts.lyapunov_spectrum(system, *system.random_state(seed=seed), T, dt=0.01,
                                       t_transient=T0, n_batches=BATCHES, seed=seed)
        lam = np.array([float(row["lambda_1"]), float(row["lambda_2"])])
        assert lam.tolist() == api.exponents.tolist()
        pos = api.exponents > 0
        assert pos.any()
        per_batch = api.batches[:, pos].sum(axis=1)
        assert float(row["h_ks"]) == pytest.approx(api.exponents[pos].sum(), rel=1e-12)
        assert float(row["h_ks_se"]) == pytest.approx(
            per_batch.std(ddof=1) / np.sqrt(BATCHES), rel=1e-10)
        # not the exponents' errors added in quadrature (the batches' sums are correlated)
        assert float(row["h_ks_se"]) != pytest.approx(np.hypot(*api.stderr), rel=1e-6)
        members.append(lam)

    # the summary (one parameter point, three seeds): the mean over the seeds of each seed's
    # sum, over the exponents positive in the seeds' mean; its error the standard error of
    # those sums (or the propagated batch-means errors of the rows, where larger: the rule of
    # every summary column)
    E = np.array(members)
    sums = E[:, E.mean(axis=0) > 0].sum(axis=1)
    spread = sums.std(ddof=1) / np.sqrt(len(sums))
    own = np.sqrt(sum(float(r["h_ks_se"]) ** 2 for r in rows)) / len(rows)
    _, summary = read_table(tmp_path / SUMMARY)
    assert len(summary) == 1
    assert float(summary[0]["h_ks"]) == pytest.approx(sums.mean(), rel=1e-12)
    assert float(summary[0]["h_ks_se"]) == pytest.approx(max(spread, own), rel=1e-10)
    md = (tmp_path / "summary.md").read_text()
    assert "| n | seeds | lambda_1 | lambda_2 | h_ks |" in md
    assert f"| {sums.mean():.4f} ± {max(spread, own):.4f} |" in md
    assert (tmp_path / "figures" / "h_ks.png").exists()

    # the NetCDF table: the same column, its units and how it was obtained
    pytest.importorskip("xarray")
    from charts.runs.netcdf_results import SweepTable
    path = SweepTable.from_csv(tmp_path / TABLE).save(tmp_path / "sweep.nc")
    back = charts.load(path)
    assert back.columns["h_ks"].tolist() == [float(r["h_ks"]) for r in rows]
    assert back.columns["h_ks_se"].tolist() == [float(r["h_ks_se"]) for r in rows]
    ds = SweepTable.from_csv(tmp_path / TABLE).to_xarray()
    assert ds["h_ks"].attrs["units"] == ds["lambda_1"].attrs["units"]
    assert "Pesin" in ds["h_ks"].attrs["long_name"]
    assert "batch" in ds["h_ks_se"].attrs["long_name"]


def _summary_of(exponents, own_se=0.01):
    """summarize() of one parameter point whose seeds have the leading exponents
    ``exponents`` (rows (λ₁, λ₂)), each row's h_ks as the sweep's worker gives it."""
    pts = sweep_points(_sweep(seeds=list(range(len(exponents)))))
    cols = point_columns(pts)
    rows = []
    for p, lam in zip(pts, exponents):
        h, _ = leading_entropy_with_error(lam, [lam, lam], 2)
        stats = {"lambda_1": lam[0], "lambda_2": lam[1], "lambda_1_se": own_se,
                 "lambda_2_se": own_se, "h_ks": h, "h_ks_se": own_se}
        rows.append(dict(zip(cols, point_row(p, {"status": "complete", "stats": stats,
                                                 "t_final": T}, cols))))
    return summarize(cols, rows, pts)["rows"][0]


def test_an_exponent_consistent_with_zero_counts_for_every_seed_or_for_none():
    """Which exponents are positive is decided by the mean over the seeds: a λ₂ that is
    positive on average counts with its sign for every seed (also where it came out
    negative); one negative on average counts for none (also where it came out positive)."""
    up = [[0.40, 0.03], [0.42, -0.01], [0.38, 0.01]]
    e = _summary_of(up)
    sums = np.array([0.43, 0.41, 0.39])
    assert e["h_ks"] == pytest.approx(sums.mean(), rel=1e-12)
    assert e["h_ks_se"] == pytest.approx(sums.std(ddof=1) / np.sqrt(3), rel=1e-12)
    down = [[0.40, 0.01], [0.42, -0.03], [0.38, -0.01]]
    e = _summary_of(down)
    lead = np.array([0.40, 0.42, 0.38])
    assert e["h_ks"] == pytest.approx(lead.mean(), rel=1e-12)
    assert e["h_ks_se"] == pytest.approx(lead.std(ddof=1) / np.sqrt(3), rel=1e-12)
    # the propagated batch-means errors where they are the larger
    e = _summary_of(up, own_se=0.5)
    assert e["h_ks_se"] == pytest.approx(np.sqrt(3 * 0.25) / 3, rel=1e-12)
    # a single seed: its own sum and batch-means error
    e = _summary_of([[0.4, 0.2]])
    assert e["h_ks"] == pytest.approx(0.6) and e["h_ks_se"] == 0.01


def test_the_column_needs_every_positive_exponent():
    """With fewer than the N − 2 positive exponents computed there is no sum to give: no
    column (and no h_ks in the run's result)."""
    few = json.loads(json.dumps(BASE))
    few["effects"]["lyapunov"]["n_exponents"] = 1
    assert "h_ks" not in stat_columns(sweep_points(_sweep(few))[0].scene)
    more = json.loads(json.dumps(BASE))
    more["effects"]["lyapunov"]["n_exponents"] = 3                  # λ₃ ≈ 0: never counted
    assert stat_columns(sweep_points(_sweep(more))[0].scene)[-2:] == ["h_ks", "h_ks_se"]


def test_markdown_of_a_summary_shows_h_ks_like_the_exponents():
    e = _summary_of([[0.40, 0.03], [0.42, -0.01], [0.38, 0.01]])
    md = summary_markdown({"params": ["n"], "stats": ["lambda_1", "lambda_2", "h_ks"],
                           "rows": [e]})
    assert f"| {e['h_ks']:.4f} ± {e['h_ks_se']:.4f} |" in md
