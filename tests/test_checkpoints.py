"""Checkpoints a resume cannot trust (docs/reliability.md, "Interrupted work resumes
identically"): a sweep's point whose checkpoint is empty or torn is computed again, with a
one-line notice, to the uninterrupted row."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

from charts.runs import runner
from charts.runs.sweep import LOG, TABLE, load_sweep, read_table, run_sweep, sweep_points
from charts.runs.sweep.execute import POINTS

CHARTS = [sys.executable, "-m", "charts"]

#: two short points (N = 3, t = 4, a checkpoint every time unit)
TWO = """name = "two"
[scene.system]
n = 3
[scene.integrator]
dt = 0.01
[scene.run]
t_final = 4.0
t_transient = 0.0
checkpoint_every = 1.0
[scene.effects.lyapunov]
n_batches = 2
[sweep]
seeds = [1]
[sweep.parameters]
m = [0.5, 2.0]
[sweep.masses]
p = [1, "m", 1]
"""


@pytest.fixture(scope="module")
def two(tmp_path_factory):
    """The sweep file and its uninterrupted table."""
    root = tmp_path_factory.mktemp("two")
    spec = root / "two.toml"
    spec.write_text(TWO)
    run_sweep(load_sweep(spec), root / "ref", workers=1, quiet=True, plots=False)
    return spec, (root / "ref" / TABLE).read_bytes()


def _damaged(ck, damage):
    data = ck.read_bytes()
    ck.write_bytes(b"" if damage == "empty" else data[:len(data) // 2])


@pytest.mark.parametrize("damage, error", [("empty", "EOFError"), ("truncated", "BadZipFile")])
def test_a_sweep_point_whose_checkpoint_is_torn_is_computed_again(tmp_path, two, damage,
                                                                   error):
    """A sweep stopped after its first row, its second point half done in points/<id> and
    that checkpoint then emptied or cut in half: ``--resume -q`` computes the point again
    from the start, says so in one line (quiet or not) and in the log, and the table is the
    uninterrupted one, byte for byte.  Before, the EOFError (or BadZipFile) of the
    checkpoint lost the point on every resume (exit 1), silently under -q."""
    spec, reference = two
    sweep = load_sweep(spec)
    out = tmp_path / "out"

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(sweep, out, workers=1, quiet=True, plots=False, on_point=stop)
    finished = {r["point_id"] for r in read_table(out / TABLE)[1]}
    (second,) = [p for p in sweep_points(sweep) if p.point_id not in finished]
    keep = out / POINTS / second.point_id

    def halfway(index, n_chunks):
        if index == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):           # what a sweep killed in this point leaves
        runner.run_scene(second.scene, keep, quiet=True, on_chunk=halfway)
    ck = keep / runner.CHECKPOINT
    _damaged(ck, damage)
    p = subprocess.run(CHARTS + ["sweep", str(spec), "-o", str(out), "--resume", "--workers",
                                 "1", "-q", "--no-plots"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    notice = f"charts: {ck} is not a usable checkpoint ({error}: "
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(notice), p.stderr
    assert lines[0].endswith("; computing the point again")
    assert (out / TABLE).read_bytes() == reference
    log = [json.loads(x) for x in (out / LOG).read_text().splitlines()]
    assert [x["notice"] for x in log if x["point_id"] == second.point_id] == [lines[0]]


@pytest.mark.parametrize("damage", ["empty", "truncated"])
def test_charts_run_resume_refuses_a_torn_checkpoint_naming_it(tmp_path, damage, capsys):
    """``charts run --resume`` over an empty or torn checkpoint: one line naming the file,
    what is wrong and the remedy (exit 2), not NumPy's EOFError (exit 1)."""
    from charts.cli.main import main
    scene = tmp_path / "s.toml"
    scene.write_text('[system]\nn = 3\n[run]\nt_final = 4.0\nt_transient = 0.0\n'
                     'checkpoint_every = 1.0\n[effects.lyapunov]\nn_batches = 2\n')
    out = tmp_path / "out"

    def halfway(index, n_chunks):
        if index == 1:
            raise KeyboardInterrupt

    from charts.runs.scene import load_scene
    with pytest.raises(KeyboardInterrupt):
        runner.run_scene(load_scene(scene), out, quiet=True, on_chunk=halfway)
    _damaged(out / runner.CHECKPOINT, damage)
    assert main(["run", str(scene), "-o", str(out), "--resume", "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{out / runner.CHECKPOINT} is not a usable checkpoint" in err[0]
    assert "start it over with --force" in err[0]
