"""Checkpoints a resume cannot trust (docs/reliability.md, "Interrupted work resumes
identically"): a sweep's point whose checkpoint is empty, torn or foreign is computed again,
with a one-line notice, to the uninterrupted row; ``charts run --resume`` refuses a
checkpoint that cannot be read, or whose counters or state disagree with what it holds or
with the run, naming the file and the field; so does the angle tally's checkpoint."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
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


# ------------------------------------------------------------------ a run's checkpoint
#: N = 3, 4 chunks, the Lyapunov effect (the kernel engine: a tangent flow), drift records
KERNEL = ('[system]\nn = 3\n[run]\nt_final = 4.0\nt_transient = 0.0\ncheckpoint_every = 1.0\n'
          'sample_dt = 0.5\n[effects.lyapunov]\nn_batches = 2\n[effects.drift]\n'
          'sample_every = 0.5\n')
#: the same through ``integrate`` (chart formulation): a state y, no tangent flow
CHART = ('[system]\nn = 3\n[integrator]\nformulation = "chart"\n[run]\nt_final = 4.0\n'
         't_transient = 0.0\ncheckpoint_every = 1.0\nsample_dt = 0.5\n[effects.drift]\n'
         'sample_every = 0.5\n')


def _interrupted_run(tmp_path, text):
    """A scene run stopped after 2 of its 4 chunks: (scene file, folder, its arrays)."""
    from charts.runs.scene import load_scene
    scene = tmp_path / "s.toml"
    scene.write_text(text)
    out = tmp_path / "out"

    def halfway(index, n_chunks):
        if index == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        runner.run_scene(load_scene(scene), out, quiet=True, on_chunk=halfway)
    with np.load(out / runner.CHECKPOINT) as a:
        return scene, out, {k: a[k] for k in a.files}


def _with(a, **changes):
    """The arrays ``a`` with ``changes`` (None: the field left out)."""
    out = {k: v.copy() for k, v in a.items()}
    for k, v in changes.items():
        if v is None:
            out.pop(k)
        else:
            out[k] = v
    return out


def _scalars(a, **counters):
    from charts.runs.checkpoint_checks import SCALARS
    s = a["scalars"].copy()
    for name, v in counters.items():
        s[SCALARS.index(name)] = v
    return s


def _nan_at_start(x):
    x = x.astype(float)
    x.flat[0] = np.nan
    return x


#: (scene, how the checkpoint is changed, what the one line must say)
FOREIGN = {
    "chunk counter past the end": (KERNEL, lambda a: _with(a, scalars=_scalars(
        a, chunk_index=9)), "its chunk counter is 9, past the end of this run's 4 chunks"),
    "complete with a quarter of the window": (KERNEL, lambda a: _with(a, scalars=_scalars(
        a, chunk_index=4, done=1)), "its step counter (flow_counter) is 200 where 4 of the "
        "run's 4 chunks end at step 400"),
    "done before the end": (KERNEL, lambda a: _with(a, scalars=_scalars(a, done=1)),
                            "it says the run is done after 2 of 4 chunks"),
    "NaN state": (KERNEL, lambda a: _with(a, flow_Z=_nan_at_start(a["flow_Z"])),
                  "the field 'flow_Z' holds 1 non-finite value(s)"),
    "scalar state": (KERNEL, lambda a: _with(a, flow_Z=np.array(0.5)),
                     "the field 'flow_Z' is a scalar, this run's has shape (2, 6)"),
    "missing field": (KERNEL, lambda a: _with(a, flow_logsum=None),
                      "the field 'flow_logsum' is missing"),
    "another N's state": (KERNEL, lambda a: _with(a, flow_Z=np.zeros((2, 8)),
                                                  flow_sc=np.zeros((2, 4))),
                          "the field 'flow_Z' has shape (2, 8), this run's has shape (2, 6)"),
    "Lyapunov marks": (KERNEL, lambda a: _with(a, lyap_ticks=a["lyap_ticks"][:0],
                                               lyap_logsums=a["lyap_logsums"][:0]),
                       "it holds 0 Lyapunov batch marks (lyap_ticks) where 2 chunks end 1"),
    "records": (KERNEL, lambda a: _with(a, rec_drift=a["rec_drift"][:-1],
                                        rect_drift=a["rect_drift"][:-1]),
                "it holds 3 rows of rec_drift where 2 chunks record 4"),
    "NaN state, chart formulation": (CHART, lambda a: _with(a, y=_nan_at_start(a["y"])),
                                     "the field 'y' holds 1 non-finite value(s)"),
    "another N's state, chart formulation": (CHART, lambda a: _with(a, y=np.zeros(8)),
                                             "the field 'y' has shape (8,), this run's has "
                                             "shape (6,)"),
    "state of text": (CHART, lambda a: _with(a, y=np.array(["a"] * 6)),
                      "the field 'y' holds <U1 values, not numbers"),
}


@pytest.mark.parametrize("case", list(FOREIGN))
def test_a_run_checkpoint_from_outside_is_refused_naming_the_file_and_field(tmp_path, case,
                                                                            capsys):
    """A checkpoint whose counters disagree with what it holds or with the run's settings,
    or whose state is NaN, a scalar, missing or another N's: ``charts run --resume`` refuses
    it in one line naming the file and the field (exit 2).  Before: a chunk counter at the
    end resumed to "complete" with a quarter of the averaging window, a counter past it
    too; a NaN state failed later as if the step were too large; a scalar was broadcast
    into every component."""
    from charts.cli.main import main
    from charts.runs.io import npz_bytes
    text, change, said = FOREIGN[case]
    scene, out, arrays = _interrupted_run(tmp_path, text)
    ck = out / runner.CHECKPOINT
    ck.write_bytes(npz_bytes(change(arrays)))
    capsys.readouterr()
    assert main(["run", str(scene), "-o", str(out), "--resume", "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith(f"charts: error: --resume: {ck} is not a usable checkpoint: "), err
    assert said in err[0], err


@pytest.mark.parametrize("text", [KERNEL, CHART], ids=["kernel", "chart"])
def test_a_checkpoint_of_the_run_itself_resumes_to_the_whole_run(tmp_path, text):
    """The checks pass the run's own checkpoint: the resume gives the uninterrupted result."""
    from charts.runs.scene import load_scene
    scene, out, _ = _interrupted_run(tmp_path, text)
    resumed = runner.run_scene(load_scene(scene), out, quiet=True, resume=True)
    whole = runner.run_scene(load_scene(scene), tmp_path / "whole", quiet=True)
    assert resumed["results"] == whole["results"] and resumed["drift"] == whole["drift"]


def test_a_sweep_point_takes_a_foreign_checkpoint_as_torn(tmp_path):
    """In a sweep's points/<id> the same checkpoint (a NaN state) is taken as torn, as the
    sweep takes every damaged checkpoint: the point is computed again, with the notice
    naming the file and the field, to the uninterrupted row."""
    from charts.runs.io import npz_bytes
    from charts.runs.sweep.worker import evaluate_point
    (point,) = [p for p in sweep_points(load_sweep(_two_file(tmp_path)))][:1]
    keep = tmp_path / POINTS / point.point_id

    def halfway(index, n_chunks):
        if index == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        runner.run_scene(point.scene, keep, quiet=True, on_chunk=halfway)
    ck = keep / runner.CHECKPOINT
    with np.load(ck) as a:
        arrays = {k: a[k] for k in a.files}
    ck.write_bytes(npz_bytes(_with(arrays, flow_Z=_nan_at_start(arrays["flow_Z"]))))
    redone = evaluate_point(point.raw, str(keep))
    assert redone["notice"].startswith(f"charts: {ck} is not a usable checkpoint: the field "
                                       "'flow_Z' holds 1 non-finite value(s)")
    assert redone["notice"].endswith("; computing the point again")
    fresh = evaluate_point(point.raw)
    assert redone["status"] == "complete" and redone["stats"] == fresh["stats"]
    assert redone["resumed_from"] is None


def _two_file(tmp_path):
    spec = tmp_path / "two.toml"
    spec.write_text(TWO)
    return spec


# ------------------------------------------------------------------ the tally's checkpoint
@pytest.fixture(scope="module")
def partial_tally(tmp_path_factory):
    """The checkpoint of a CPU angle tally of 5 members (chunks of 2) interrupted while it
    merged its second chunk: 2 members done; and the uninterrupted tally."""
    pytest.importorskip("xarray")
    import charts.analyses.tally_run as hyp
    from charts import RotorSystem
    S = RotorSystem(3)
    kw = dict(t_transient=1.0, workers=1, chunk=2)
    whole = hyp.hyperbolicity_tally(S, 5, 3.0, **kw)
    real, calls = hyp._merge_chunk, []

    def cut(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(*a, **k)
    path = tmp_path_factory.mktemp("tally") / "partial.nc"
    hyp._merge_chunk = cut
    try:
        with pytest.raises(KeyboardInterrupt):
            hyp.hyperbolicity_tally(S, 5, 3.0, checkpoint=path, **kw)
    finally:
        hyp._merge_chunk = real
    return S, kw, path, whole


def _tally_changed(path, to, change):
    """The checkpoint at ``path`` with ``change(tally)`` applied, saved at ``to``."""
    from charts import load
    t = load(path)
    change(t)
    t.save(to)
    return to


TALLIES = {
    "members_done too small: members counted twice": (
        lambda t: t.params.update(members_done=1),
        "members_done = 1, but 2 of its members have angles (n > 0), the last member 1"),
    "members_done too large: members left out": (
        lambda t: t.params.update(members_done=4),
        "members_done = 4, but 2 of its members have angles (n > 0), the last member 1"),
    "members_done not a count": (lambda t: t.params.update(members_done=-3),
                                 "members_done = -3 is not a count of its 5 members"),
    "sums past members_done": (lambda t: t.episodes.__setitem__((0, 3), 7),
                               "episodes holds sums of members past members_done = 2"),
    "unequal counts": (lambda t: t.n.__setitem__(1, 29),
                       "the members done have unequal counts n (29 to 30)"),
    "NaN sum": (lambda t: t.law_logsum.__setitem__((1, 0, 0), np.nan),
                "law_logsum holds non-finite values"),
}


@pytest.mark.parametrize("case", list(TALLIES))
def test_a_tally_checkpoint_from_outside_is_refused_naming_the_file(tmp_path, partial_tally,
                                                                    case):
    """A tally checkpoint whose members_done disagrees with the sums it holds, or whose
    sums are not a tally's: ValueError naming the file and the field, before any member
    runs.  Before, a members_done below the members summed counted them twice (the route
    that added each chunk's angles) and one above left members out without a word."""
    from charts.analyses.tally_run import hyperbolicity_tally
    S, kw, path, _ = partial_tally
    change, said = TALLIES[case]
    bad = _tally_changed(path, tmp_path / "partial.nc", change)
    with pytest.raises(ValueError) as caught:
        hyperbolicity_tally(S, 5, 3.0, checkpoint=bad, **kw)
    assert str(caught.value).startswith(f"{bad} is not a usable checkpoint: "), caught.value
    assert said in str(caught.value)


def test_a_tally_checkpoint_missing_a_field_is_refused_naming_it(tmp_path, partial_tally):
    import xarray as xr
    from charts.analyses.tally_run import hyperbolicity_tally
    S, kw, path, _ = partial_tally
    bad = tmp_path / "partial.nc"
    with xr.load_dataset(path) as ds:
        ds.drop_vars("ladder_sum").to_netcdf(bad, engine="h5netcdf")
    # charts.load's layout check meets it first (the file and the variable named); the
    # checkpoint's own check names the field where a file passes that one
    with pytest.raises(ValueError, match=r"is not a usable (checkpoint: the field|charts result: "
                                         r"the angle_tally variable) 'ladder_sum' is missing"):
        hyperbolicity_tally(S, 5, 3.0, checkpoint=bad, **kw)


def test_the_tallys_own_checkpoint_resumes_to_the_whole_tally(tmp_path, partial_tally):
    import shutil
    from charts.analyses.angle_tally import SUMS
    from charts.analyses.tally_run import hyperbolicity_tally
    S, kw, path, whole = partial_tally
    mine = shutil.copy(path, tmp_path / "partial.nc")
    resumed = hyperbolicity_tally(S, 5, 3.0, checkpoint=mine, **kw)
    for k in SUMS:
        assert np.array_equal(getattr(resumed, k), getattr(whole, k)), k
