"""The runner simulates only what a scene asks for (checked from the metadata), its numbers
agree with the library's direct routes, and an interrupted run resumes to the same numbers."""
from __future__ import annotations

import json

import numpy as np
import pytest

from charts import RotorSystem
from charts.runs.runner import RunError, plan_scene, run_scene
from charts.runs.scene import parse_scene

from scenarios import (PAPER_EXPONENTS, REFERENCE_EXPONENTS, REFERENCE_STDERR, SEEDS,
                       THROUGH_SINGULAR_N4, TOL, gaussian_curvature_eq22)

#: Same RK4 arithmetic through two kernels: rounding differences (~1e-15) amplified by the
#: chaos, e^{λt} with λ ≈ 0.4 over t ≤ 6, stay far below this.
SAME_RK4 = 1e-10


def scene(n=3, effects=None, t_final=2.0, t_transient=0.0, sample_dt=0.05, **sections):
    d = {"system": {"n": n}, "run": {"t_final": t_final, "t_transient": t_transient,
                                     "sample_dt": sample_dt},
         "effects": effects or {"waveforms": {}}}
    d.update(sections)
    return parse_scene(d)


def run(sc, tmp_path, name="out", **kw):
    return run_scene(sc, tmp_path / name, quiet=True, **kw)


def test_a_quiet_run_makes_no_progress_bar(tmp_path, monkeypatch):
    """A quiet run (every sweep point on a worker) builds no tqdm bar: even a disabled one
    creates tqdm's lock, a named multiprocessing semaphore; a worker killed while it holds
    one (an interrupted sweep) leaves Python's resource tracker to report "There appear to
    be 1 leaked semaphore objects" as the sweep exits."""
    import tqdm.auto

    def bar(*args, **kwargs):
        raise AssertionError("a quiet run built a tqdm bar")

    monkeypatch.setattr(tqdm.auto, "tqdm", bar)
    assert run(scene(), tmp_path)["status"] == "complete"


# ----------------------------------------------------------------- only what is asked for
def test_waveform_only_n5_integrates_10_variables_no_tangent_vectors(tmp_path):
    sc = scene(n=5, effects={"waveforms": {"rotors": [0, 2], "t_window": 1.0}}, t_final=3.0,
               t_transient=0.5)
    comp = run(sc, tmp_path)["computation"]
    assert comp["state_dimension"] == 10
    assert comp["tangent_vectors"] == 0 and comp["transport_vectors"] == 0
    assert comp["adjoint_vectors"] == 0 and comp["stored_trajectory"] is False
    # only the window (1.0 / 0.05 = 20 samples) of the two rotors is stored
    assert comp["stored_samples"] == {"waveforms": 20}
    assert comp["stored_values"] == 40
    # RK4: 4 evaluations per step, (0.5 + 3.0) / 0.01 steps
    assert comp["steps"] == 350 and comp["rhs_evaluations"] == 1400
    assert comp["tangent_vector_evaluations"] == 0
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        assert set(a.files) == {"waveforms_t", "waveforms_u"}
        assert a["waveforms_u"].shape == (20, 2)
        np.testing.assert_allclose(a["waveforms_t"], 0.5 + 0.05 * np.arange(1, 21))


@pytest.mark.parametrize("effects, expect", [
    ({"spectrum": {"nperseg": 16}}, dict(tangent=0, transport=0, stored={"spectrum": 40})),
    ({"drift": {"sample_every": 0.5}}, dict(tangent=0, transport=0, stored={"drift": 4})),
    ({"lyapunov": {"n_batches": 2}}, dict(tangent=1, transport=0, stored={})),
    ({"lyapunov": {"n_exponents": 3, "n_batches": 2, "inner_product": "full"}},
     dict(tangent=3, transport=0, stored={})),
    ({"curvature": {"route": "exact", "sample_every": 0.5}},
     dict(tangent=1, transport=0, stored={"curvature": 4})),
    ({"curvature": {"route": "numerical", "sample_every": 0.5}},
     dict(tangent=1, transport=2, stored={"curvature": 4})),
    # combinations share one pass: the larger number of tangent vectors serves both
    ({"lyapunov": {"n_exponents": 2, "n_batches": 2}, "curvature": {"sample_every": 1.0},
      "drift": {"sample_every": 1.0}},
     dict(tangent=2, transport=2, stored={"curvature": 2, "drift": 2})),
    ({"waveforms": {"t_window": 0.5}, "spectrum": {"nperseg": 16}},
     dict(tangent=0, transport=0, stored={"waveforms": 10, "spectrum": 40})),
])
def test_each_effect_alone_and_combined(tmp_path, effects, expect):
    sc = scene(n=3, effects=effects)
    res = run(sc, tmp_path)
    comp = res["computation"]
    assert comp["state_dimension"] == 6
    assert comp["tangent_vectors"] == expect["tangent"]
    assert comp["transport_vectors"] == expect["transport"]
    assert comp["stored_samples"] == expect["stored"]
    assert comp["rhs_evaluations"] == 4 * 200
    assert comp["tangent_vector_evaluations"] == 4 * 200 * expect["tangent"]
    assert comp["main_pass"] and comp["angles_pass"] == {}
    # the numerical route costs 2 frame steps (8 evaluations) per curvature sample
    n_curv = expect["stored"].get("curvature", 0)
    assert comp["frame_rhs_evaluations"] == (8 * n_curv if expect["transport"] else 0)
    assert set(res["results"]) == set(effects) - {"drift"}


def test_spectrum_in_angular_frequency_and_a_note_when_too_short(tmp_path):
    """The scene spectrum is ``charts.power_spectrum``'s: ω in rad per unit time, density
    per unit ω, segments of nperseg samples; fewer than 4 segments give a note."""
    res = run(scene(n=3, effects={"spectrum": {"nperseg": 16}}, t_final=8.0), tmp_path)
    spec = res["results"]["spectrum"]
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        omega, psd = a["spectrum_omega"], a["spectrum_psd"]
    np.testing.assert_allclose(omega[1], 2 * np.pi / (16 * 0.05))
    assert spec["peak_frequency"] == omega[np.argmax(psd)]
    short = run(scene(n=3, effects={"spectrum": {"nperseg": 16}}), tmp_path, "short")
    assert "4 × nperseg = 64" in short["results"]["spectrum"]["note"]
    assert "spectrum.png" not in short["files"]


def test_angles_only_skips_the_main_pass(tmp_path):
    sc = scene(n=4, effects={"angles": {"sample_every": 0.5}}, t_final=2.0, t_transient=1.0)
    res = run(sc, tmp_path)
    comp = res["computation"]
    assert comp["main_pass"] is False and comp["rhs_evaluations"] == comp["angles_pass"][
        "rhs_evaluations"]
    assert comp["angles_pass"]["forward_vectors"] == 2 == comp["adjoint_vectors"]
    assert comp["stored_samples"] == {"angles": 4}
    ang = res["results"]["angles"]
    assert ang["full"]["n"] == ang["restricted"]["n"] == 4
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        full, restricted = a["angles_full"], a["angles_restricted"]
        np.testing.assert_allclose(a["angles_t"], 1.0 + 0.5 * np.arange(4), rtol=0, atol=1e-12)
    # E_cs ∩ T_r ⊂ E_cs: the restricted angle is never below the full one, sample by sample
    assert np.all(restricted >= full - 1e-9)
    assert ang["full"]["min"] == full.min() > 0 and ang["restricted"]["min"] == restricted.min()


def test_clv_scene_equals_the_api_and_agrees_with_the_angles_pass(tmp_path):
    """A scene asking for the CLV effect (and the angles) runs the two separate passes only;
    its CLV angles are the API's (``covariant_lyapunov_vectors``, same state and settings)
    bit for bit, close to the scene's adjoint-route angles, and its statistics are those of
    the API result."""
    from charts.analyses.covariant import covariant_lyapunov_vectors

    sc = scene(n=4, effects={"angles": {}, "clv": {"windows": [1.0, 5.0]}}, t_final=20.0,
               t_transient=60.0)
    res = run(sc, tmp_path)
    comp = res["computation"]
    assert comp["main_pass"] is False and comp["clv_pass"]["vectors"] == {"full": 8,
                                                                         "restricted": 6}
    assert comp["stored_samples"] == {"angles": 200, "clv": 200}
    clv = res["results"]["clv"]
    s = RotorSystem(4)
    th, u = s.random_state(seed=0)
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        for v in ("full", "restricted"):
            api = covariant_lyapunov_vectors(s, th, u, 20.0, variant=v, t_transient=60.0)
            np.testing.assert_array_equal(a[f"clv_phi_{v}"], api.phi)
            np.testing.assert_array_equal(a[f"clv_phi_vectors_{v}"], api.phi_vectors)
            # after 60 time units of transients: measured 1e-4 (full), 3e-8 (restricted)
            np.testing.assert_allclose(a[f"clv_phi_{v}"], a[f"angles_{v}"], rtol=1e-3)
            assert clv[v]["exponents"] == api.exponents.tolist()
            assert clv[v]["domination"]["5"]["split"] == api.domination([5.0])[5.0]["split"]
            ft = api.finite_time([1.0])[1.0]
            assert clv[v]["finite_time"]["1"]["std"] == ft["std"].tolist()
            assert clv[v]["finite_time"]["1"]["windows"] == ft["count"] == 20
    assert (tmp_path / "out" / "clv.png").stat().st_size > 0


def test_chart_formulation_state_dimension_and_switch_log(tmp_path):
    sc = scene(n=4, effects={"switches": {}}, t_final=4.0,
               integrator={"formulation": "chart", "method": "dop853"})
    res = run(sc, tmp_path)
    comp = res["computation"]
    assert comp["engine"] == "integrate" and comp["state_dimension"] == 6
    assert comp["tangent_vectors"] == 0 and comp["stored_samples"] == {}
    assert comp["rhs_evaluations"] > 0
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        S = a["switches"]
    assert res["results"]["switches"]["count"] == len(S)
    assert len(S) >= 1                        # this run does switch (measured: twice)
    assert np.all(np.diff(S[:, 0]) >= 0) and np.all(S[:, 1] != S[:, 2])
    assert np.all((S[:, 0] > 0) & (S[:, 0] <= 4.0))


# ----------------------------------------------------------------- agreement with direct routes
def test_waveforms_match_charts_integrate(tmp_path):
    """The fused kernel route and ``charts.solvers.integrate`` (ambient RK4, same dt) are the same
    method: their samples agree to rounding amplified by the chaos."""
    from charts.solvers.integrate import integrate

    sc = scene(n=5, effects={"waveforms": {"t_window": 5.0}}, t_final=5.0, sample_dt=0.1)
    run(sc, tmp_path)
    system = RotorSystem(5)
    theta0, u0 = system.random_state(seed=0, speed=1.0)
    ref = integrate(system, theta0, u0, 5.0, formulation="ambient", method="rk4", dt=0.01,
                    t_eval=0.1 * np.arange(1, 51))
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        np.testing.assert_allclose(a["waveforms_u"], ref.u, rtol=0, atol=SAME_RK4)


def test_chunked_lyapunov_equals_one_go(tmp_path):
    """Chunked and checkpointed, the scene's exponents equal — bit for bit — those of
    ``charts.lyapunov_spectrum`` run in one go from the same state, vectors and settings.
    The same kernel on both sides: this checks the chunking and bookkeeping, not the
    exponents (test_scene_exponents_agree_with_the_reference_values does)."""
    from charts import lyapunov_spectrum

    sc = scene(n=4, effects={"lyapunov": {"n_exponents": 2, "n_batches": 4}}, t_final=8.0,
               t_transient=2.0, initial={"seed": 3})
    res = run(sc, tmp_path)["results"]["lyapunov"]
    system = RotorSystem(4)
    theta0, u0 = system.random_state(seed=3, speed=1.0)
    ref = lyapunov_spectrum(system, theta0, u0, 8.0, dt=0.01, n_exponents=2, t_transient=2.0,
                            n_batches=4, seed=3)
    np.testing.assert_array_equal(res["exponents"], ref.exponents)
    np.testing.assert_array_equal(res["stderr"], ref.stderr)
    assert len(res["stderr"]) == 2 and res["batches"] == 4
    assert res["paper"] == list(PAPER_EXPONENTS[4])


@pytest.mark.parametrize("n", [3, 4])
def test_scene_exponents_agree_with_the_reference_values(tmp_path, n):
    """An independent check of the runner's numbers: t = 4000 from the paper's seed gives
    exponents within N_SIGMA combined two-sided standard errors of the project's full-preset
    reference (8 × 2.5·10⁴), and the paper's value is reported beside them."""
    sc = scene(n=n, effects={"lyapunov": {"n_exponents": n - 2, "n_batches": 20}},
               t_final=4000.0, t_transient=50.0, sample_dt=1.0, initial={"seed": SEEDS["paper"]})
    res = run(sc, tmp_path)["results"]["lyapunov"]
    lam, se = np.array(res["exponents"]), np.array(res["stderr"])
    ref, ref_se = np.array(REFERENCE_EXPONENTS[n]), np.array(REFERENCE_STDERR[n])
    assert np.all(se > 0) and np.all(se < 0.01)
    assert np.all(np.abs(lam - ref) < TOL["n_sigma"] * np.hypot(se, ref_se)), res
    assert res["paper"] == list(PAPER_EXPONENTS[n])


def test_scene_and_api_give_identical_exponents_with_masses(tmp_path):
    """N = 4, m = (1, 2, 1, 2), seed 0: the scene below and the API call the docs give for it
    (docs/scene-runs.md) agree exactly, exponents and standard errors, although the scene runs
    in checkpointed chunks that do not line up with the batches."""
    from charts import lyapunov_spectrum

    sc = parse_scene({"system": {"n": 4, "masses": [1, 2, 1, 2]}, "initial": {"seed": 0},
                      "run": {"t_final": 300.0, "t_transient": 20.0, "checkpoint_every": 7.0},
                      "effects": {"lyapunov": {}}})
    res = run(sc, tmp_path)["results"]["lyapunov"]
    system = RotorSystem(4, [1, 2, 1, 2])
    theta0, u0 = system.random_state(seed=0)
    api = lyapunov_spectrum(system, theta0, u0, 300.0, t_transient=20.0, seed=0)
    assert res["exponents"] == api.exponents.tolist()
    assert res["stderr"] == api.stderr.tolist()
    assert res["batches"] == api.batches.shape[0] == 20


def test_n3_curvature_routes_against_eq22(tmp_path):
    """N = 3: the stored exact-route curvatures equal eq (22) (scenarios) evaluated on the
    same trajectory computed by ``charts.integrate`` (ambient RK4, same dt), to the rounding
    of the unprojected state; the numerical route to the paper's 'five digits' in the median."""
    from charts import integrate

    sc = scene(n=3, effects={"curvature": {"route": "both", "sample_every": 0.1}}, t_final=5.0,
               t_transient=1.0)
    c = run(sc, tmp_path)["results"]["curvature"]
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        t, Kex, Knum = a["curvature_t"], a["curvature_exact"][:, 0], a["curvature_numerical"][:, 0]
    assert t.size == 50 and t[0] == pytest.approx(1.1) and t[-1] == pytest.approx(6.0)
    system = RotorSystem(3)
    theta0, u0 = system.random_state(seed=0, speed=1.0)
    traj = integrate(system, theta0, u0, 6.0, formulation="ambient", method="rk4", dt=0.01,
                     t_eval=t)
    K22 = gaussian_curvature_eq22(traj.theta)
    assert np.max(np.abs(Kex - K22) / np.abs(K22)) < 1e-7
    assert np.median(np.abs(Knum - K22) / np.abs(K22)) < 1e-4
    assert c["exact"]["max"][0] < 0 and c["numerical"]["fraction_positive"] == [0.0]


# ----------------------------------------------------------------- interrupt and resume
class Stop(Exception):
    pass


@pytest.mark.parametrize("over", [
    {"effects": {"waveforms": {"t_window": 3.0}, "drift": {"sample_every": 0.5},
                 "lyapunov": {"n_exponents": 2, "n_batches": 3},
                 "curvature": {"sample_every": 0.2}}},
    {"effects": {"waveforms": {"t_window": 3.0}, "spectrum": {"nperseg": 16}, "switches": {}},
     "integrator": {"formulation": "chart", "method": "dop853"}},
])
def test_interrupt_then_resume_gives_the_same_numbers(tmp_path, over):
    d = {"system": {"n": 4}, "run": {"t_final": 6.0, "t_transient": 0.5, "sample_dt": 0.05,
                                     "checkpoint_every": 0.5}}
    d.update(over)
    sc = parse_scene(d, source="s.toml")
    full = run(sc, tmp_path, "full")

    def stop(idx, total):
        if idx == 5:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt) as exc:
        run(sc, tmp_path, "cut", on_chunk=stop)
    partial = exc.value.args[0]
    out = tmp_path / "cut"
    on_disk = json.loads((out / "result.json").read_text())
    assert on_disk["status"] == partial["status"] == "interrupted"
    assert on_disk["progress"]["chunks_done"] == 6 < on_disk["progress"]["chunks"]
    assert 0 < on_disk["progress"]["t_done"] < 6.0
    assert "--resume" in on_disk["resume"]
    with np.load(out / "arrays.npz") as a:        # a valid, readable partial result
        assert len(a["waveforms_t"]) == round(on_disk["progress"]["t_done"] / 0.05)
    # starting afresh over an interrupted run is refused; resuming finishes it
    with pytest.raises(RunError, match="--resume"):
        run(sc, tmp_path, "cut")
    done = run(sc, tmp_path, "cut", resume=True)
    assert done["status"] == "complete"
    assert done["results"] == full["results"]
    assert done["computation"] == full["computation"]
    with np.load(tmp_path / "full" / "arrays.npz") as a, np.load(out / "arrays.npz") as b:
        assert a.files == b.files
        for k in a.files:
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)


PASSES = {"lyapunov": {"n_batches": 2}, "angles": {"sample_every": 0.5, "t_transient": 1.0},
          "clv": {}}


@pytest.mark.parametrize("where", ["_angles_pass", "_clv_pass", "finalize"])
def test_an_interrupt_in_a_pass_or_while_writing_resumes_to_the_same_result(
        tmp_path, monkeypatch, where):
    """Ctrl-C in the separate angle or CLV pass or while the outputs are written: an
    "interrupted" result.json with the progress and the quoted resume command, no output it
    does not list, and --resume gives the uninterrupted run's numbers."""
    import charts.runs.runner as runner
    sc = scene(n=3, effects=PASSES, t_final=12.0, t_transient=0.5,
               run={"t_final": 12.0, "t_transient": 0.5, "sample_dt": 0.05,
                    "checkpoint_every": 4.0})
    full = run(sc, tmp_path, "full")
    real = getattr(runner, where)
    calls = []

    def interrupted(*args, **kw):
        calls.append(1)
        if len(calls) == 1:
            raise KeyboardInterrupt
        return real(*args, **kw)

    monkeypatch.setattr(runner, where, interrupted)
    out = tmp_path / "cut here"
    with pytest.raises(KeyboardInterrupt) as exc:
        run(sc, tmp_path, "cut here")
    partial = exc.value.args[0]
    on_disk = json.loads((out / "result.json").read_text())
    assert on_disk["status"] == partial["status"] == "interrupted"
    assert on_disk["resume"].endswith(f"-o '{out}' --resume")
    done = on_disk["progress"]["chunks_done"]
    left = {"_angles_pass": 2, "_clv_pass": 1, "finalize": 0}[where]   # the passes not run
    assert done == on_disk["progress"]["chunks"] - left
    outputs = {p.name for p in out.iterdir() if not p.name.startswith(".")}
    assert outputs == set(on_disk["files"])
    monkeypatch.setattr(runner, where, real)
    resumed = run(sc, tmp_path, "cut here", resume=True)
    assert resumed["status"] == "complete" and resumed["results"] == full["results"]
    assert {p.name for p in out.iterdir() if not p.name.startswith(".")} == set(resumed["files"])


def test_interrupt_in_the_first_chunk_leaves_an_empty_valid_result(tmp_path):
    sc = scene(n=3, effects={"lyapunov": {"n_batches": 2}})

    def stop(idx, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run(sc, tmp_path, on_chunk=stop)
    res = json.loads((tmp_path / "out" / "result.json").read_text())
    assert res["status"] == "interrupted" and res["progress"]["chunks_done"] == 1


def test_resume_errors(tmp_path):
    sc = scene(n=3)
    with pytest.raises(RunError, match="no checkpoint"):
        run(sc, tmp_path, resume=True)
    run(sc, tmp_path)
    other = scene(n=3, t_final=3.0)
    with pytest.raises(RunError, match="different scene"):
        run(other, tmp_path, resume=True)


def test_plan_is_pure_and_matches_run(tmp_path):
    sc = scene(n=5, effects={"lyapunov": {"n_exponents": 2, "n_batches": 2},
                             "curvature": {"n_directions": 3, "route": "exact",
                                           "sample_every": 1.0}})
    plan = plan_scene(sc)
    assert (plan.state_dim, plan.tangent_vectors, plan.transport_vectors) == (10, 3, 0)
    assert not (tmp_path / "out").exists()
    comp = run(sc, tmp_path)["computation"]
    assert comp["tangent_vectors"] == 3 and comp["stored_samples"] == {"curvature": 2}


def test_run_through_a_singular_point_fails_clearly_and_keeps_the_finished_part(tmp_path):
    """N = 4: the straight line θ(t) = S + (t − 1)v through the singular point
    S = (0, 0, π, π), v = (a, b, a, b), lies on the manifold; the run must stop with a clear
    error at t ≈ 1, keeping the chunks finished before."""
    theta, v = THROUGH_SINGULAR_N4
    sc = parse_scene({"system": {"n": 4}, "initial": {"theta": list(theta), "u": list(v)},
                      "integrator": {"formulation": "chart", "method": "dop853"},
                      "run": {"t_final": 2.0, "sample_dt": 0.01, "checkpoint_every": 0.1},
                      "effects": {"drift": {"sample_every": 0.1}}})
    with pytest.raises(RunError, match="singular point"):
        run(sc, tmp_path)
    res = json.loads((tmp_path / "out" / "result.json").read_text())
    assert res["status"] == "failed" and "singular point" in res["error"]
    assert res["progress"]["t_done"] == pytest.approx(0.9)
    assert res["computation"]["stored_samples"] == {"drift": 9}
