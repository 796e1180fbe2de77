"""The ``charts`` command line: help everywhere, one-line errors (never a traceback), bundled
scenes, and a real Ctrl-C (SIGINT) or SIGTERM followed by ``--resume``."""
from __future__ import annotations

import json
import shlex
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from charts.cli.main import bundled_scenes, main
from charts.runs.runner import run_scene
from charts.runs.scene import load_scene

from process_events import HOOKED_RUN, read_until
from scenarios import THROUGH_SINGULAR_N4

CHARTS = [sys.executable, "-m", "charts.cli.main"]

MALFORMED = {
    "unknown key": ("[system]\nn = 3\ncolour = 1\n[run]\nt_final = 1\n[effects.drift]\n",
                    "unknown key 'colour' in [system]"),
    "typo": ("[system]\nn = 3\n[run]\nt_finl = 1\n[effects.drift]\n",
             "did you mean 't_final'"),
    "wrong type": ("[system]\nn = \"three\"\n[run]\nt_final = 1\n[effects.drift]\n",
                   "[system] n = 'three' is not allowed: expected an integer"),
    "N = 2": ("[system]\nn = 2\n[run]\nt_final = 1\n[effects.drift]\n",
              "[system] n = 2 is not allowed: expected an integer in 3..1048576"),
    "negative mass": ("[system]\nn = 3\nmasses = [1, -2, 1]\n[run]\nt_final = 1\n"
                      "[effects.drift]\n", "[system] masses = [1.0, -2.0, 1.0] is not allowed"),
    "off-manifold": ("[system]\nn = 3\n[initial]\ntheta = [0.1, 0.2, 0.3]\nu = [1, 0, 0]\n"
                     "[run]\nt_final = 1\n[effects.drift]\n", "theta is off the manifold"),
    "NaN": ("[system]\nn = 3\n[run]\nt_final = nan\n[effects.drift]\n",
            "[run] t_final = nan is not allowed: expected a finite number"),
    "bad TOML": ("[system\nn = 3\n", "not valid TOML"),
}


@pytest.mark.parametrize("case", sorted(MALFORMED))
def test_malformed_scene_one_line_error(tmp_path, capsys, case):
    text, expected = MALFORMED[case]
    path = tmp_path / "bad.toml"
    path.write_text(text)
    rc = main(["run", str(path), "-o", str(tmp_path / "out"), "--quiet"])
    err = capsys.readouterr().err
    assert rc == 2
    assert err.startswith("charts: error: ") and err.count("\n") == 1, err
    assert expected in err, err
    assert not (tmp_path / "out").exists(), "nothing runs before validation passes"


def test_malformed_scene_through_the_console_entry_has_no_traceback(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(MALFORMED["N = 2"][0])
    p = subprocess.run(CHARTS + ["run", str(path), "-o", str(tmp_path / "o")],
                       capture_output=True, text=True)
    assert p.returncode == 2
    assert "Traceback" not in p.stderr and "expected an integer in 3..1048576" in p.stderr


def test_unknown_scene_name_suggests_a_bundled_one(tmp_path, capsys):
    rc = main(["run", "fig2-n6", "-o", str(tmp_path / "o")])
    err = capsys.readouterr().err
    assert rc == 2 and "did you mean 'fig2-n" in err and "charts scenes" in err


@pytest.mark.parametrize("argv", [[], ["run"], ["scenes"], ["generate"], ["bench"]])
def test_help_everywhere(capsys, argv):
    assert main(argv + ["--help"]) == 0         # main returns the status, never raises
    assert "usage: charts" in capsys.readouterr().out


def test_no_command_prints_help(capsys):
    assert main([]) == 2
    assert "COMMAND" in capsys.readouterr().out


def test_scenes_lists_and_prints(capsys):
    assert main(["scenes"]) == 0
    out = capsys.readouterr().out
    for name in bundled_scenes():
        assert name in out
    assert main(["scenes", "table-n4"]) == 0
    assert "[effects.lyapunov]" in capsys.readouterr().out
    assert main(["scenes", "nope"]) == 2


def test_run_bundled_scene_writes_outputs(tmp_path, capsys):
    out = tmp_path / "fig2"
    assert main(["run", "fig2-n3", "-o", str(out)]) == 0
    summary = capsys.readouterr().out
    assert "6 state variables, 0 tangent vectors" in summary
    res = json.loads((out / "result.json").read_text())
    assert res["status"] == "complete" and res["scene"]["name"] == "fig2-n3"
    assert set(res["versions"]) >= {"charts", "numpy", "numba", "python"}
    assert (out / "waveforms.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list(out.glob(".*tmp*")), "no temporary files left behind"


def test_reproduce_dispatch(capsys):
    """`charts reproduce` reaches charts.runs.reproduce (its own help and usage errors)."""
    assert main(["reproduce", "--help"]) == 0
    out = capsys.readouterr().out
    assert "usage: charts reproduce" in out and "--quick" in out and "--full" in out
    assert main(["reproduce", "--quick", "--full"]) == 2           # mutually exclusive
    assert "not allowed with argument" in capsys.readouterr().err


def test_bench_accuracy_help(capsys):
    assert main(["bench", "accuracy", "--help"]) == 0
    assert "--quick" in capsys.readouterr().out
    assert main(["bench", "accuracy", "--n", "2", "-q"]) == 2
    assert "--n 2: expected 3..6" in capsys.readouterr().err


LONG = """name = "long"
[system]
n = 3
[run]
t_final = 20000.0
t_transient = 0.0        # the first checkpoint is then after 500 time units of the run
sample_dt = 1.0
checkpoint_every = 500.0
[effects.lyapunov]
n_batches = 4
[effects.drift]
sample_every = 100.0
"""


@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)],
                         ids=["ctrl-c", "sigterm"])
def test_ctrl_c_keeps_a_valid_result_and_resume_finishes_it(tmp_path, signum, status):
    """Ctrl-C, or SIGTERM (what ``kill`` and job schedulers send, taken as Ctrl-C, exit 143),
    once the first checkpoint is written: the child says so and waits for the signal
    (`HOOKED_RUN`), so the signal never finds a run that already ended."""
    scene_file = tmp_path / "long.toml"
    scene_file.write_text(LONG)
    out = tmp_path / "out dir"                 # a space: the printed command must quote it
    proc = subprocess.Popen([sys.executable, "-c", HOOKED_RUN, "run", str(scene_file), "-o",
                             str(out), "--quiet"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    read_until(proc.stdout, r"checkpoint 1 of \d+ written", proc)
    proc.send_signal(signum)
    _, err = proc.communicate()
    assert proc.returncode == status, err
    assert "--resume" in err and "Traceback" not in err
    command = next(line for line in err.splitlines() if line.strip().startswith("charts run"))
    assert shlex.split(command)[4] == str(out)  # charts run SCENE -o DIR --resume
    partial = json.loads((out / "result.json").read_text())
    assert partial["status"] == "interrupted"
    assert 0 < partial["progress"]["t_done"] < 20000.0
    with np.load(out / "arrays.npz") as a:
        assert len(a["drift_t"]) == round(partial["progress"]["t_done"] / 100.0)

    p = subprocess.run(CHARTS + ["run", str(scene_file), "-o", str(out), "--resume", "--quiet"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    resumed = json.loads((out / "result.json").read_text())
    whole = run_scene(load_scene(scene_file), tmp_path / "whole", quiet=True)
    assert resumed["status"] == "complete"
    assert resumed["results"] == json.loads(json.dumps(whole["results"]))
    assert resumed["drift"] == json.loads(json.dumps(whole["drift"]))


def test_generate_check_delegates_to_the_generator(capsys):
    """`charts generate --check` runs scripts/generate.py from the checkout, whatever the
    working folder; staleness itself is tests/test_generated.py's business, so either
    verdict is accepted here, but it must be the generator's."""
    rc = main(["generate", "--check"])
    out = capsys.readouterr().out
    assert (rc, "generated/ is up to date" in out) in ((0, True), (1, False))
    assert rc == 0 or "Run: python scripts/generate.py" in out


def test_bundled_run_through_a_singular_point_exits_1_with_the_finished_part(tmp_path, capsys):
    out = tmp_path / "sing"
    assert main(["run", "hard-n4-through-singular", "-o", str(out), "--quiet"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("charts: error: ") and "singular point" in err
    res = json.loads((out / "result.json").read_text())
    assert res["status"] == "failed" and res["progress"]["t_done"] == pytest.approx(0.9)


def test_tangent_run_through_a_singular_point_fails_clearly_not_nan(tmp_path, capsys):
    """The Lyapunov engine (ambient RK4 + tangent vectors, no projection) driven exactly
    through the N = 4 singular point must stop with a clear error and keep the finished
    part, never report a 'complete' run with NaN exponents."""
    scene = tmp_path / "sing-lyap.toml"
    theta, u = (", ".join(repr(float(x)) for x in v) for v in THROUGH_SINGULAR_N4)
    scene.write_text(textwrap.dedent(f"""
        [system]
        n = 4
        [initial]
        theta = [{theta}]
        u = [{u}]
        [integrator]
        formulation = "ambient"
        method = "rk4"
        dt = 0.01
        [run]
        t_final = 2.0
        t_transient = 0.0
        sample_dt = 0.01
        checkpoint_every = 0.1
        [effects.lyapunov]
        n_exponents = 2
    """))
    out = tmp_path / "out"
    assert main(["run", str(scene), "-o", str(out), "--quiet"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("charts: error: ") and "reached a singular point" in err
    res = json.loads((out / "result.json").read_text())
    assert res["status"] == "failed"
    assert 0.5 <= res["progress"]["t_done"] < 1.1
    assert np.all(np.isfinite(res["results"]["lyapunov"]["exponents"]))


def test_run_refuses_a_non_empty_folder_without_force(tmp_path, capsys):
    out = tmp_path / "o"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    assert main(["run", "fig2-n3", "-o", str(out), "--quiet"]) == 2
    assert "is not empty: use --force" in capsys.readouterr().err
    assert main(["run", "fig2-n3", "-o", str(out), "--quiet", "--force", "--resume"]) == 2
    assert main(["run", "fig2-n3", "-o", str(out), "--quiet", "--force"]) == 0
    assert (out / "result.json").exists() and (out / "notes.txt").exists()


def test_sweep_prints_a_bundled_sweep(capsys):
    assert main(["sweep", "--print", "masses-n4-quick"]) == 0
    text = capsys.readouterr().out
    assert "[sweep" in text and "masses" in text
    assert main(["sweep", "--print", "no-such-sweep"]) == 2


def test_a_sweep_run_without_plots_does_not_count_figures(capsys, tmp_path):
    """The closing lines name the figures only where they were drawn: with --no-plots they
    say so, instead of "figures: 0 in DIR/figures" for a folder that does not exist."""
    from charts.cli.sweep import _report
    info = {"points": 2, "skipped": 1, "computed": [1], "failed": [], "lost": [],
            "table": tmp_path / "sweep.csv", "summary": tmp_path / "summary.csv"}
    _report("s", info, tmp_path, plots=False)
    out = capsys.readouterr().out
    assert "no figures (--no-plots)" in out and "figures: 0" not in out
    _report("s", {**info, "figures": ["a.png", "b.png"]}, tmp_path)
    assert f"figures: 2 in {tmp_path / 'figures'}" in capsys.readouterr().out
