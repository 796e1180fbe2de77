"""Every figure the library draws, opened and checked: axes with labels, visible tick labels
and finite limits; no log axis stretched by zeros; the paper's values drawn only where they
exist; error bars where there are errors; tails clipped with the share stated; legends off the
data; the global matplotlib backend never touched (pyplot never imported)."""
import io
import subprocess
import sys

import numpy as np
import pytest

import charts
from charts import plotting
from charts.runs import scene_figures

from figure_checks import check_axes

SYS3 = charts.RotorSystem(3)
TH3, U3 = SYS3.random_state(7)


@pytest.fixture(scope="module")
def run3():
    def section(t, y):
        return np.sin(y[0])
    section.direction = 1
    return charts.integrate(SYS3, TH3, U3, 60.0, events=[section], dense_output=True)


def test_trajectory_plots(run3):
    fig, ax = run3.plot("angles")
    check_axes(ax)
    assert ax.get_title() == f"angles against time, N = 3 ({len(run3.switches)} chart switches)"
    assert sum(1 for ln in ax.lines if ln.get_linestyle() == "--") == len(run3.switches) > 0
    w = np.concatenate([ln.get_ydata() for ln in ax.lines if ln.get_label().startswith("θ")])
    assert np.nanmax(np.abs(w)) <= np.pi                 # wrapped, lines broken at the wrap
    # rotors are numbered from 0 in figures as in the arrays, files and scenes
    assert [ln.get_label() for ln in ax.lines if ln.get_label().startswith("θ")] == \
        ["θ$_0$", "θ$_1$", "θ$_2$"]
    fig, ax = run3.plot("surface")
    check_axes(ax, z=True)
    assert [ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()] == ["θ₀ (rad)", "θ₁ (rad)", "θ₂ (rad)"]
    fig, ax = run3.plot("poincare", coords=(1, 4))
    check_axes(ax)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("θ$_1$ (rad)", "u$_1$ (rad / time)")
    assert len(ax.collections[0].get_offsets()) == len(run3.t_events[0]) > 0


def test_a_poincare_section_is_named_by_the_coordinate_its_crossings_fix():
    """`section_words` finds the component of [θ, u] that one or two values hold at every
    crossing (angles modulo 2π), with the direction of the crossing for an angle; nothing
    where no single component is fixed or too few crossings show it."""
    from charts.plotting.trajectory import section_words
    rng = np.random.default_rng(1)
    Y = rng.normal(size=(40, 8))
    assert section_words(Y, 4) is None
    Y[:, 2] = np.pi / 2 + 2 * np.pi * rng.integers(-3, 3, 40)      # θ₂ ≡ π/2, crossed both ways
    assert section_words(Y, 4) == "θ₂ = π/2"
    Y[:, 6] = np.abs(Y[:, 6])
    assert section_words(Y, 4) == "θ₂ = π/2, u₂ > 0"
    Y[::2, 2] = -np.pi + 1e-12                                      # a second sheet at π
    Y[::2, 6] *= -1
    assert section_words(Y, 4) == "θ₂ = π/2 (u₂ > 0) or π (u₂ < 0)"
    Y = rng.normal(size=(40, 8))
    Y[:, 5] = 1e-17                                                 # u₁ = 0: no direction known
    assert section_words(Y, 4) == "u₁ = 0"
    assert section_words(Y[:1], 4) is None and section_words(Y[:2, [0, 1, 2, 3, 4, 4, 6, 7]], 4) is None


def test_rotor_animation_gif(run3, tmp_path, monkeypatch):
    anim = run3.plot("animation", every=40)
    path = plotting.save_animation(anim, tmp_path / "rotors.gif", fps=10)
    assert path.read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    from matplotlib.animation import writers
    monkeypatch.setattr(writers, "is_available", lambda name: False)
    with pytest.raises(RuntimeError, match="no 'ffmpeg' animation writer"):
        plotting.save_animation(anim, tmp_path / "rotors.mp4")


def test_analysis_plots():
    system = charts.RotorSystem(4)
    th, u = system.random_state(0)
    lyap = charts.lyapunov_spectrum(system, th, u, 40.0, t_transient=1.0)
    fig, ax = lyap.plot()
    check_axes(ax)
    assert ax.get_xscale() == "log" and len(ax.containers) == 2      # error bars
    assert not [ln for ln in ax.lines if ln.get_linestyle() == ":"]  # no paper values given
    fig, ax = lyap.plot(paper=[0.385, 0.230])
    assert len([ln for ln in ax.lines if ln.get_linestyle() == ":"]) == 2
    curv = charts.curvature_along_trajectory(system, th, u, 20.0, t_transient=1.0)
    fig, axes = curv.plot()
    for a in axes:
        check_axes(a)
    fig, axes = charts.hyperbolicity_angles(system, th, u, 10.0, t_transient=5.0).plot()
    for a in axes:
        check_axes(a)
    fig, axes = charts.covariant_lyapunov_vectors(system, th, u, 10.0, t_transient=5.0).plot()
    for a in axes:
        check_axes(a)
    w = charts.waveform(system, th, u, 100.0)
    check_axes(w.plot()[1])
    assert w.plot()[1].get_title() == "angles against time, N = 4"   # no charts: no switch count
    fig, axes = w.plot(kind="velocities", rotors=[0, 2], window=(10.0, 60.0))
    assert [a.get_ylabel() for a in axes] == ["$u_{0}$ (rad / time)", "$u_{2}$ (rad / time)"]
    assert np.array_equal(axes[1].lines[0].get_ydata(), w.u[(w.t >= 10) & (w.t <= 60), 2])
    check_axes(axes[-1])                                 # the panels share the time axis
    assert lyap.plot()[1].get_title().startswith("Lyapunov exponents, N = 4\n")
    # the units of the labels are spelled as in the files: λ in 1 / time, u and ω in rad / time
    assert lyap.plot()[1].get_ylabel() == f"λ ({lyap.to_xarray()['exponents'].attrs['units']})"
    assert lyap.plot_spectrum()[1].get_ylabel() == "λᵢ (1 / time)"
    assert w.to_xarray()["u"].attrs["units"] == "rad / time"
    masses = charts.lyapunov_spectrum(charts.RotorSystem(4, masses=[1, 2, 3, 1]), th, u, 4.0,
                                      t_transient=1.0, n_batches=2)
    assert "N = 4, masses (1, 2, 3, 1)" in masses.plot_spectrum()[1].get_legend().get_texts()[0].get_text()
    fig, ax = charts.power_spectrum(w.u[:, 0], w.dt_sample, segment_time=20.0).plot()
    check_axes(ax)
    assert "rad" in ax.get_xlabel()


@pytest.fixture
def captured(monkeypatch):
    """The figures the scene figure functions make (instead of their PNG bytes)."""
    figs = []
    monkeypatch.setattr(scene_figures, "png_bytes", lambda fig: figs.append(fig) or b"")
    return figs


class _Scene:
    name = "test"
    system = {"n": 4}
    effects = {"spectrum": {"rotor": 1}, "waveforms": {"rotors": [1, 2]}}


def test_scene_drift_figure_robust_to_zeros(captured):
    t = np.linspace(1, 100, 200)
    D = np.abs(np.random.default_rng(0).normal(scale=1e-15, size=(200, 3)))
    D[::3, 0] = 0.0
    D[::5, 2] = 5e-312          # subnormal: the strip at 1e-312 the log axis must not show
    scene_figures.drift_png(_Scene, t, D)
    ax = captured[-1].axes[0]
    check_axes(ax)
    assert ax.get_ylim()[0] > 1e-19
    labels = [ln.get_label() for ln in ax.lines]
    assert "not drawn" in labels[0] and "not drawn" in labels[2]


def test_scene_lyapunov_figure(captured):
    T = np.arange(1, 21) * 10.0
    H = np.column_stack([0.385 + 0.1 / T, 0.23 - 0.1 / T])
    res = {"exponents": [0.386, 0.229], "stderr": [0.004, 0.003], "paper": [0.385, 0.230]}
    scene_figures.lyapunov_png(_Scene, T, H, res)
    ax = captured[-1].axes[0]
    check_axes(ax)
    dotted = [ln for ln in ax.lines if ln.get_linestyle() == ":"]
    assert len(dotted) == 2 and "dotted" in dotted[0].get_label()
    assert len(ax.containers) == 2                                     # the error bars
    scene_figures.lyapunov_png(_Scene, T, H, {"exponents": [0.386, 0.229]})
    ax = captured[-1].axes[0]
    assert not [ln for ln in ax.lines if ln.get_linestyle() == ":"]
    assert not any("paper" in ln.get_label() for ln in ax.lines)


def test_scene_curvature_figure_clips_tails(captured):
    rng = np.random.default_rng(1)
    K = -np.abs(rng.standard_cauchy(size=(4000, 2))) * 0.05 + 0.02
    K[0, 0] = -18.0
    scene_figures.curvature_png(_Scene, {"curvature_numerical": K, "curvature_exact": K})
    for ax in captured[-1].axes:
        check_axes(ax)
        lo, hi = ax.get_xlim()
        assert lo > -5.0 and lo < 0.0 < hi                             # the tail clipped
        assert "clipped" in ax.get_title()
        assert any(ln.get_xdata()[0] == 0.0 for ln in ax.lines)        # the K = 0 line
        assert ax.get_ylabel() == "probability density"


def test_scene_spectrum_and_angles_figures(captured):
    om = np.linspace(0, 10, 200)
    scene_figures.spectrum_png(_Scene, om, np.exp(-om), 200.0)
    ax = captured[-1].axes[0]
    check_axes(ax)
    assert ax.get_xlabel() == "ω (rad / time)" and "(rad / time)²" in ax.get_ylabel()
    phi = np.random.default_rng(2).uniform(0.1, 1.5, 500)
    scene_figures.angles_png(_Scene, {"angles_full": phi, "angles_restricted": phi})
    for ax in captured[-1].axes:
        check_axes(ax)
    scene_figures.waveforms_png(_Scene, np.linspace(0, 10, 50), np.ones((50, 2)))
    for ax in captured[-1].axes:
        assert ax.get_ylabel()


def test_plotting_never_touches_the_backend():
    # (reading rcParams['backend'] would resolve the backend through pyplot: read it raw)
    code = ("import sys, matplotlib; b = dict.__getitem__(matplotlib.rcParams, 'backend')\n"
            "import numpy as np\n"
            "from charts import plotting as p\n"
            "t = np.linspace(0, 10, 200); th = np.column_stack([t, -t, 2 * t])\n"
            "p.plot_angles_time(t, th, switches=[(1.0, 0, 1)]); p.plot_surface(th)\n"
            "anim = p.animate_rotors(t, th, every=50)\n"
            "p.plot_lyapunov([1, 2], [[0.5], [0.4]], [0.4], [0.01])\n"
            "p.plot_curvature({'a': np.random.default_rng(0).normal(size=(50, 2))})\n"
            "p.plot_drift(t, [np.abs(np.sin(t))], ['x'])\n"
            "assert 'matplotlib.pyplot' not in sys.modules, 'pyplot imported'\n"
            "assert dict.__getitem__(matplotlib.rcParams, 'backend') == b\n")
    subprocess.run([sys.executable, "-c", code], check=True, timeout=300)


def test_log_spaced_sweep_grids_get_a_log_axis():
    """A geometric grid (0.25, 0.5, 1, 2: a span below a decade) is drawn on a log axis as a
    wide one is; an even grid stays linear."""
    from charts.runs.sweep.report import log_spaced
    assert log_spaced([0.25, 0.5, 1.0, 2.0]) and log_spaced([1.0, 10.0]) and log_spaced([0.5, 1, 2])
    assert not log_spaced([1.0, 2.0, 3.0, 4.0]) and not log_spaced([1.0, 1.5])
    assert not log_spaced([-1.0, 1.0, 2.0]) and not log_spaced([2.0])
