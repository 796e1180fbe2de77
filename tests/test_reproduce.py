"""``charts reproduce`` end to end and the paper figures module (figures 2-5)."""
from __future__ import annotations

import json
import re
import subprocess
import sys

import numpy as np
import pytest

from charts.cli.main import main

from scenarios import PAPER_EXPONENTS, REFERENCE_EXPONENTS, REFERENCE_STDERR, TOL

PNG = b"\x89PNG\r\n\x1a\n"
FIGURES = ("fig2.png", "fig3.png", "fig4.png", "fig5.png", "clv.png", "ftle.png")


def _png_image(path):
    """The decoded image of a PNG file (checks the signature first)."""
    import matplotlib.image

    data = path.read_bytes()
    assert data[:8] == PNG, path
    return matplotlib.image.imread(str(path))


def _assert_drawn(path, min_px=200):
    img = _png_image(path)
    assert img.shape[0] >= min_px and img.shape[1] >= min_px, img.shape
    assert np.ptp(img[..., :3]) > 0.5, f"{path.name} is blank"          # something is drawn


def _table_rows(text):
    """{(N, k): (ours, stderr, paper)} from table.md."""
    rows = {}
    for line in text.splitlines():
        m = re.match(r"\|\s*(\d+)\s*\|\s*λ(\d+)\s*\|\s*([-\d.]+)\s*\|\s*([-\d.]+)\s*\|\s*([-\d.]+)\s*\|",
                     line)
        if m:
            rows[int(m[1]), int(m[2])] = tuple(float(m[i]) for i in (3, 4, 5))
    return rows


# ------------------------------------------------------------------------ charts reproduce
@pytest.fixture(scope="module")
def quick_run(tmp_path_factory):
    """The output folder of one ``charts reproduce --quick`` run, shared by this module's
    tests of it."""
    out = tmp_path_factory.mktemp("reproduce") / "quick"
    assert main(["reproduce", "--quick", "-o", str(out), "--quiet", "--workers", "2"]) == 0
    return out


@pytest.mark.slow
def test_reproduce_quick_end_to_end(quick_run):
    """The quick preset (4 × t = 5·10³ per N for the exponents): every file is written, and
    the table's exponents agree with the project's full-preset reference within N_SIGMA
    combined two-sided standard errors, and with the paper within its ±0.004 band widened by
    N_SIGMA of the quick preset's standard error."""
    out = quick_run
    for name in ("report.md", "table.md", "results.json") + FIGURES:
        assert (out / name).stat().st_size > 0, name
    for name in FIGURES:
        _assert_drawn(out / name)
    rows = _table_rows((out / "table.md").read_text())
    assert set(rows) == {(n, k + 1) for n, lam in PAPER_EXPONENTS.items() for k in range(len(lam))}
    results = json.loads((out / "results.json").read_text())
    for (n, k), (ours, se, paper) in rows.items():
        assert paper == PAPER_EXPONENTS[n][k - 1]
        ref, ref_se = REFERENCE_EXPONENTS[n][k - 1], REFERENCE_STDERR[n][k - 1]
        assert 0 < se < 0.005, (n, k, se)
        assert abs(ours - ref) < TOL["n_sigma"] * np.hypot(se, ref_se), (n, k, ours, se)
        assert abs(ours - paper) < TOL["paper_band"] + TOL["n_sigma"] * se, (n, k, ours, se)
        # the table prints what results.json holds
        lyap = results["lyapunov"][str(n)]
        assert ours == pytest.approx(lyap["exponents"][k - 1], abs=5e-5)
        assert se == pytest.approx(lyap["stderr"][k - 1], abs=5e-5)
    report = (out / "report.md").read_text()
    for section in ("## Lyapunov exponents", "## Curvature", "## Hyperbolicity angles",
                    "## Hyperbolicity by a second route"):
        assert section in report
    # the two routes to the angles agree on the same samples (tests/test_covariant.py:
    # median below 1e-9 restricted, 1e-6 full), and N = 3 stays away from 0 in both
    for n in ("3", "4", "5"):
        for variant, median in (("restricted", 1e-9), ("full", 1e-6)):
            c = results["clv"][n][variant]
            assert c["median_rel"] < median and c["max_rel"] < 1e-3, (n, variant, c)
            assert c["clv"]["n"] == c["adjoint"]["n"] == 2 * 20000
    assert min(results["clv"]["3"][v]["clv"]["min"] for v in ("full", "restricted")) > 0.15
    assert (out / "table.md").read_text().strip() in report
    # N = 3: curvature negative everywhere, the numerical route within 'five digits' of eq (22)
    c3 = results["curvature"]["3"]
    assert c3["fraction_positive"] == [0.0] and c3["eq22_median_rel"] < 5e-5


# ------------------------------------------------------------------------ paper figures
@pytest.fixture(scope="module")
def small_inputs():
    """Small synthetic data in the layouts figures 2-5 take, for N = 3, 4, 5."""
    from charts.analyses.spectra import Waveform

    rng = np.random.default_rng(0)
    t = np.arange(1, 401) * 0.05
    waves = {n: Waveform(t, None, np.sin(np.outer(t, 1 + np.arange(n))), 0.05) for n in (3, 4, 5)}
    om = np.linspace(0, 10, 200)
    spectra = {n: (om, np.exp(-om) + 1e-3) for n in (3, 4, 5)}
    curv = {n: rng.normal(-0.5, 0.3, size=(300, n - 2)) for n in (3, 4, 5)}
    angles = {n: (rng.uniform(0, 1.5, 300), rng.uniform(0.1, 1.5, 300)) for n in (3, 4, 5)}
    return waves, spectra, curv, angles


def test_paper_figures_write_drawn_pngs(tmp_path, small_inputs):
    from charts.runs import paper_figures as pf

    waves, spectra, curv, angles = small_inputs
    calls = [(pf.figure2, waves), (pf.figure3, spectra), (pf.figure4, curv), (pf.figure5, angles)]
    for (fn, data), name in zip(calls, FIGURES):
        path = tmp_path / name
        returned = fn(data, path)
        assert str(returned) == str(path)
        _assert_drawn(path)
    # one panel per N (a, b, c): three stacked panels make figure 2 over twice as tall as one
    pf.figure2({4: waves[4]}, tmp_path / "one.png")
    assert _png_image(tmp_path / "fig2.png").shape[0] > 2 * _png_image(tmp_path / "one.png").shape[0]


def test_paper_figures_single_n(tmp_path, small_inputs):
    """A single N (one panel) works too, e.g. a run of N = 4 only."""
    from charts.runs import paper_figures as pf

    waves, spectra, curv, angles = small_inputs
    pf.figure2({4: waves[4]}, tmp_path / "a.png")
    pf.figure4({5: curv[5]}, tmp_path / "b.png")
    pf.figure5({3: angles[3]}, tmp_path / "c.png")
    for name in ("a.png", "b.png", "c.png"):
        _assert_drawn(tmp_path / name, min_px=100)


def test_importing_the_figures_leaves_the_users_backend_alone():
    """The figures never switch the user's matplotlib backend (no matplotlib.use, no pyplot)."""
    code = ("import matplotlib; matplotlib.use('svg'); import charts.runs.paper_figures; "
            "print(matplotlib.get_backend())")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip().lower() == "svg"


def test_the_package_quotes_the_papers_exponents():
    """charts.runs.paper (what reports and result.json print beside our numbers) against the
    transcription of section 2 in tests/scenarios.py."""
    from charts.runs.paper import PAPER_EXPONENTS as quoted

    assert {n: tuple(v) for n, v in quoted.items()} == PAPER_EXPONENTS


def test_clv_figures_write_drawn_pngs(tmp_path):
    """The second route's figures (charts.runs.reproduce_clv) on small synthetic data."""
    from charts.runs import reproduce_clv as rc

    rng = np.random.default_rng(1)
    pairs = {n: {v: (a, a * (1 + 1e-9 * rng.normal(size=a.size)))
                 for v in ("full", "restricted")
                 for a in [rng.uniform(1e-3, 1.5, 500)]} for n in (3, 4)}
    ftle = {n: {w: rng.normal(0.4, 0.2 / np.sqrt(w), int(1000 / w)) for w in rc.FTLE_WINDOWS}
            for n in (3, 4)}
    for fn, data, name in ((rc.figure_clv, pairs, "clv.png"), (rc.figure_ftle, ftle, "ftle.png")):
        assert str(fn(data, tmp_path / name)) == str(tmp_path / name)
        _assert_drawn(tmp_path / name)


@pytest.mark.slow
def test_quick_report_stands_alone(quick_run):
    """report.md of the quick run: the rule stated once; for each claim of
    ``charts.runs.reproduce_claims.claims`` (derived from results.json) a row with the paper's
    number, ours with its error, n and the verdict; the run lengths and seeds; what the
    preset cannot show, from its numbers; where the two curvature routes differ most."""
    from charts.runs.claim_rule import VERDICTS
    from charts.runs.reproduce_claims import claims

    results = json.loads((quick_run / "results.json").read_text())
    report = (quick_run / "report.md").read_text()
    assert report.count("**The rule**") == 1
    rows = claims(results)
    assert len(rows) == 22                 # 6 + 3 exponents, 1 + 1 + 5 curvature, 6 angles
    lines = report.splitlines()
    for c in rows:
        (line,) = [x for x in lines if x.startswith("| " + c["claim"].replace("|", "\\|") + " |")]
        cells = [x.strip() for x in line.replace("\\|", "¦").split("|")[1:-1]]
        assert len(cells) == 7, line
        claim, where, paper, ours, n, word, why = cells
        assert word == f"**{c['verdict']}**" and c["verdict"] in VERDICTS
        assert "±" in ours or " of " in ours or "no s.e." in ours, line     # the interval
        assert "samples" in n or "batch means" in n, line                   # the sample size
        assert where.startswith(("§", "abstract")) and paper and why
    # the run lengths and seeds, read from the preset
    cfg = results["config"]
    run = report.split("## Run lengths")[1].split("\n## ")[0]
    for part in (f"{cfg['lyap_members']} × {cfg['lyap_t']:g}",
                 f"{cfg['angle_members']} × {cfg['angle_t']:g}", f"{cfg['curv_t']:g}",
                 f"{cfg['angle_transient']:g} forward", "100, 101, 102, 103", "| 0.01 |"):
        assert part in run, part
    # what the quick preset cannot show: the exponents' last decimal, and N = 4's
    # tangencies in the restricted variant unless their fraction and law have error bars
    cannot = report.split("## What this preset cannot show")[1].split("\n## ")[0]
    assert "The third decimal of the exponents" in cannot
    a4 = results["angles"]["4"]["restricted"]
    if a4["law_coef2_se"] is None or a4["law_exponent_se"] is None:
        assert "N = 4's tangencies in the restricted variant" in cannot
        assert f"{a4['law_count']} of {a4['n']} samples" in cannot
    else:
        assert "N = 4 restricted (" in cannot
    # the two curvature routes: the row of N = 4 and its reason
    gap = results["curvature"]["4"]["route_gap"]
    assert gap["max_abs"] == pytest.approx(results["curvature"]["4"]["max_ab"], rel=1e-12) \
        or gap["max_abs"] < results["curvature"]["4"]["max_ab"]
    assert f"| 4 | {gap['max_abs']:.2g} | K_{gap['direction']}{gap['direction']} |" in report
    assert f"- N = 4: {gap['max_abs']:.2g} (relative" in report
