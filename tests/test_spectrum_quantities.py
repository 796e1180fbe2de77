"""Kolmogorov–Sinai entropy and Kaplan–Yorke dimension against closed forms: a spectrum in ±
pairs (a geodesic flow: the whole space), N = 3's single exponent, a dissipative textbook
spectrum (Lorenz); their errors from the batches of a run and the members of an ensemble; the
spectrum plot against i/(N − 2)."""
import numpy as np
import pytest

import charts
from charts.analyses.spectrum_quantities import (kaplan_yorke_dimension,
                                                 kolmogorov_sinai_entropy,
                                                 reconstructed_spectra)


def test_closed_forms():
    assert kolmogorov_sinai_entropy([0.5, 0.0, 0.0, -0.5]) == 0.5
    assert kaplan_yorke_dimension([0.5, 0.0, 0.0, -0.5]) == 4.0
    pairs = [0.3, 0.2, 0.1, 0.0, 0.0, -0.1, -0.2, -0.3]
    assert kolmogorov_sinai_entropy(pairs) == pytest.approx(0.6)
    assert kaplan_yorke_dimension(pairs) == 8.0
    # Lorenz (σ = 10, ρ = 28, β = 8/3): D = 2 + 0.906 / 14.572
    assert kaplan_yorke_dimension([0.906, 0.0, -14.572]) == pytest.approx(2 + 0.906 / 14.572)
    assert kaplan_yorke_dimension([-0.1, -0.2]) == 0.0
    assert kaplan_yorke_dimension([0.3, 0.1]) == 2.0
    assert kaplan_yorke_dimension([-1.5, 1.0, 0.0]) == pytest.approx(2 + 1 / 1.5)  # sorted first
    np.testing.assert_array_equal(reconstructed_spectra([[0.3, 0.1]], 2, 6),
                                  [[0.3, 0.1, 0.0, 0.0, -0.1, -0.3]])


def test_n3_single_exponent():
    """N = 3: h_KS = λ₁ with λ₁'s own batch error, D_KY = 4 (the restricted space)."""
    s = charts.RotorSystem(3)
    r = charts.lyapunov_spectrum(s, *s.random_state(seed=2), 400.0)
    h, se = r.kolmogorov_sinai_entropy()
    assert h == pytest.approx(r.exponents[0], rel=1e-14)
    assert se == pytest.approx(r.stderr[0], rel=1e-12)
    assert r.kaplan_yorke_dimension() == (4.0, 0.0)


def test_entropy_of_a_run_and_of_an_ensemble():
    s = charts.RotorSystem(5)
    r = charts.lyapunov_spectrum(s, *s.random_state(seed=1), 400.0)
    h, se = r.kolmogorov_sinai_entropy()
    assert h == pytest.approx(r.exponents.sum(), rel=1e-14) and 0 < se < 0.1 * h
    assert r.kaplan_yorke_dimension()[0] == 8.0
    e = charts.lyapunov_ensemble(s, 3, 200.0, workers=1)
    per = np.array([m.exponents.sum() for m in e.members])
    he, see = e.kolmogorov_sinai_entropy()
    assert he == pytest.approx(per.mean(), rel=1e-12)
    assert see == pytest.approx(per.std(ddof=1) / np.sqrt(3), rel=1e-12)


def test_a_partial_spectrum_is_refused():
    s = charts.RotorSystem(5)
    r = charts.lyapunov_spectrum(s, *s.random_state(seed=1), 50.0, n_exponents=1)
    with pytest.raises(ValueError, match="whole relevant spectrum"):
        r.kolmogorov_sinai_entropy()


def test_spectrum_plot_overlays_several_n():
    ax = None
    for n in (4, 6):
        s = charts.RotorSystem(n)
        r = charts.lyapunov_spectrum(s, *s.random_state(seed=1), 50.0, t_transient=0.0)
        _, ax = r.plot_spectrum(ax=ax)
    lines = ax.get_legend_handles_labels()[1]
    assert lines == ["N = 4", "N = 6"]
    x = ax.containers[1][0].get_xdata()             # the second errorbar: N = 6, i/(N−2)
    np.testing.assert_allclose(x, [0.25, 0.5, 0.75, 1.0])
    assert ax.get_xlabel() == "i / (N − 2)"


def test_convergence_plot_colours_stay_distinct_past_ten_exponents():
    """N = 14 (12 exponents): every line its own colour, the title not one clipped line."""
    from matplotlib.colors import to_rgba

    from charts.plotting import plot_lyapunov
    T = np.array([1.0, 10.0, 100.0])
    H = np.tile(np.linspace(0.3, 0.01, 12), (3, 1))
    fig, ax = plot_lyapunov(T, H, H[-1], np.full(12, 0.01))
    colours = {to_rgba(line.get_color()) for line in ax.get_lines()}
    assert len(colours) == 12
    assert "\n" in ax.get_title()


def test_poincare_select_keeps_one_sheet():
    """sin θ₁ = 0 upwards holds on θ₁ ≡ 0 (u₁ > 0) and θ₁ ≡ π (u₁ < 0): ``select`` plots one."""
    def section(t, y):
        return np.sin(y[0])
    section.direction = 1
    s = charts.RotorSystem(3)
    res = charts.integrate(s, *s.random_state(seed=3), 300.0, events=section)
    Y = res.y_events[0]
    both = (np.cos(Y[:, 0]) > 0).sum(), (np.cos(Y[:, 0]) < 0).sum()
    assert min(both) > 0                                   # the event fires on both sheets
    assert np.all(Y[np.cos(Y[:, 0]) > 0, 3] > 0) and np.all(Y[np.cos(Y[:, 0]) < 0, 3] < 0)
    _, ax = res.plot("poincare", select=lambda Z: np.cos(Z[:, 0]) > 0)
    assert len(ax.collections[0].get_offsets()) == both[0]
    # the title says which section: the coordinate fixed, its value, the direction
    assert ax.get_title() == f"Poincaré section θ₀ = 0, u₀ > 0: {both[0]} crossings"
    _, ax = res.plot("poincare")
    assert ax.get_title() == f"Poincaré section θ₀ = 0 (u₀ > 0) or π (u₀ < 0): {len(Y)} crossings"
    _, ax = res.plot("poincare", section="sin θ₀ = 0 upwards")
    assert ax.get_title().startswith("Poincaré section sin θ₀ = 0 upwards: ")


def test_angles_of_a_long_run_take_a_window_and_are_thinned():
    from charts.plotting import plot_angles_time
    t = np.linspace(0.0, 1000.0, 100001)
    theta = np.stack([0.3 * t, -0.2 * t, 0.1 * t], axis=1)
    _, ax = plot_angles_time(t, theta, switches=[(5.0, 0, 1), (500.0, 1, 2)])
    assert max(len(line.get_xdata()) for line in ax.get_lines()) < 20000 * 1.1
    assert "every 6th sample" in ax.get_title()
    _, ax = plot_angles_time(t, theta, switches=[(5.0, 0, 1), (500.0, 1, 2)], window=(400, 600))
    x = np.concatenate([np.asarray(line.get_xdata(), float) for line in ax.get_lines()[:3]])
    assert np.nanmin(x) >= 400 and np.nanmax(x) <= 600
    assert "1 chart switch" in ax.get_title() and "switches" not in ax.get_title()
    with pytest.raises(ValueError, match="holds no sample"):
        plot_angles_time(t, theta, window=(2000, 3000))


def test_the_angle_test_plots_phi_against_time_in_a_window():
    """`AngleResult.plot(kind="time")`: φ(t) of both variants, a window and the thinning of
    `plot_angles_time` (one helper: `charts.plotting.style.time_window`)."""
    import types

    from charts.analyses.hyperbolicity import AngleResult
    t = np.linspace(0.0, 1000.0, 100001)
    phi = 0.1 + 0.05 * np.sin(t)
    res = types.SimpleNamespace(t=t, phi_full=phi, phi_restricted=0.5 * phi)
    _, ax = AngleResult.plot(res, kind="time")
    assert len(ax.get_lines()) == 2 and "every 6th sample" in ax.get_title()
    _, ax = AngleResult.plot(res, kind="time", window=(100, 200))
    for line in ax.get_lines():
        x = np.asarray(line.get_xdata(), float)
        assert x.min() >= 100 and x.max() <= 200
    assert ax.get_yscale() == "log"
    with pytest.raises(ValueError, match="kind must be"):
        AngleResult.plot(res, kind="series")
    with pytest.raises(ValueError, match="holds no sample"):
        AngleResult.plot(res, kind="time", window=(2000, 3000))


def test_the_error_ratio_compares_claimed_and_measured_errors():
    """Members whose batch errors equal the spread of their exponents give a ratio near 1;
    members claiming a tenth of it give 0.1 and an `ErrorBarWarning` (from 8 members on);
    fewer members are not judged."""
    import types
    import warnings

    from charts.analyses.ensemble import ErrorBarWarning, ensemble_result, error_ratio_of

    rng = np.random.default_rng(5)
    E = 0.3 + 0.01 * rng.normal(size=(400, 2))
    honest = error_ratio_of(E, np.full((400, 2), 0.01))
    assert np.allclose(honest, 1.0, atol=0.1)    # the spread's own error: 1/√(2·399) ≈ 3.5 %
    system = charts.RotorSystem(4)

    def members(n, claimed):
        return [types.SimpleNamespace(exponents=e, stderr=np.full(2, claimed)) for e in E[:n]]

    with pytest.warns(ErrorBarWarning, match=r"exponent \d.* 0\.\d\d of the members' standard"):
        res = ensemble_result(members(8, 0.001), system, 0, 1.0, 10.0, {})
    assert np.all(res.error_ratio < 0.5)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ensemble_result(members(7, 0.001), system, 0, 1.0, 10.0, {})    # too few to judge
        ok = ensemble_result(members(50, 0.01), system, 0, 1.0, 10.0, {})
    assert np.all(np.abs(ok.error_ratio - 1) < 0.35)
    assert np.all(np.isnan(error_ratio_of(E[:1], np.ones((1, 2)))))
