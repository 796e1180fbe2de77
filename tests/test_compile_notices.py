"""The compile notices a reader sees (charts.jit.compilation): a line the moment a scene
starts compiling and its notice (the variant, the wall time spent compiling) as soon as
the chunk that compiled ends, above the progress bar; a sweep's line before its workers
compile and its notice before the first point's row."""
from __future__ import annotations

import numba

from charts.jit import compilation


def test_the_first_compile_event_says_so_once_until_rearmed():
    """`compiling_said`: one line at the first compile event in the block, none for the
    next until re-armed, none outside the block."""
    said = []
    with compilation.compiling_said("toy", 3, said.append) as first:
        numba.njit(lambda x: x + 11)(1)          # fresh functions: numba compiles each
        numba.njit(lambda x: x + 12)(1)
        assert said == ["charts: toy is compiling its kernels for N = 3 (once: numba caches "
                        "them on disk; kernels already there are only loaded) …"]
        first.rearm()
        numba.njit(lambda x: x + 13)(1)
        assert len(said) == 2
    numba.njit(lambda x: x + 14)(1)
    assert len(said) == 2


def test_a_scene_says_it_compiles_then_names_its_variant_and_wall_time(tmp_path, monkeypatch,
                                                                      capsys):
    """A scene whose first chunk compiles: the line when compiling starts, then, once a
    chunk has compiled nothing (not after the bar), one notice naming the scene and its
    variant with the wall time spent compiling; a quiet run says neither."""
    from charts.runs import runner
    from charts.runs.scene import parse_scene

    monkeypatch.setattr(compilation, "NOTE_SECONDS", 0.0)
    monkeypatch.setattr(runner, "NOTE_SECONDS", 0.0)
    fresh = iter(range(1000, 2000))
    real = runner.SceneRun.end_main_chunk

    def compiling(self, idx):                 # the first chunk compiles a fresh function
        if idx == 0:
            k = next(fresh)
            numba.njit(lambda x: x + k)(1)
        return real(self, idx)

    monkeypatch.setattr(runner.SceneRun, "end_main_chunk", compiling)
    scene = parse_scene({"name": "tiny", "system": {"n": 3},
                         "integrator": {"formulation": "ambient", "method": "rk4", "dt": 0.01},
                         "run": {"t_final": 2.0, "t_transient": 0.0, "checkpoint_every": 1.0},
                         "effects": {"lyapunov": {"n_batches": 2}}})
    seen = []
    capsys.readouterr()
    runner.run_scene(scene, tmp_path / "loud",
                     on_chunk=lambda i, n: seen.append(capsys.readouterr().err))
    notes = [[line[line.index("charts: "):] for line in err.splitlines() if "charts: " in line]
             for err in seen]
    assert notes[0] == ["charts: tiny (ambient, rk4) is compiling its kernels for N = 3 (once: "
                        "numba caches them on disk; kernels already there are only loaded) …"]
    assert len(notes) == 2 and len(notes[1]) == 1, notes
    assert notes[1][0].startswith("charts: tiny (ambient, rk4) compiled its kernels for N = 3 "
                                  "in ") and " s of wall time (once: " in notes[1][0]
    assert "charts: " not in capsys.readouterr().err
    runner.run_scene(scene, tmp_path / "quiet", quiet=True)
    assert capsys.readouterr().err == ""


def test_a_sweep_on_an_empty_cache_compiles_before_its_points_and_says_so(tmp_path,
                                                                         monkeypatch, capsys):
    """`charts sweep` with 2 Dask workers on an empty numba cache: the line that it compiles
    and the notice with the wall time come before the first point's row (the stream is read
    when that row is written), and the points then compile nothing (their compile_s in
    log.jsonl: numba's compile events in the point's run)."""
    import json

    from charts.runs.sweep import LOG, load_sweep, run_sweep
    from test_checkpoints import TWO         # two short points of one kind (N = 3, exponents)

    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "numba"))   # the workers' cache
    monkeypatch.setattr(compilation, "COMPILING_AFTER", 0.0)          # the line at once
    monkeypatch.setattr(compilation, "NOTE_SECONDS", 0.0)             # any compiling noted
    seen = []
    capsys.readouterr()
    (tmp_path / "two.toml").write_text(TWO)
    run_sweep(load_sweep(tmp_path / "two.toml"), tmp_path / "out", workers=2, plots=False,
              on_point=lambda done, total: seen.append(capsys.readouterr().err))
    notes = [line for line in seen[0].splitlines() if line.startswith("charts: ")]
    assert notes[0] == ("charts: sweep two is compiling its kernels in 2 Dask workers, before "
                        "the points (once: numba caches them on disk; kernels already there "
                        "are only loaded) …"), notes
    assert notes[1].startswith("charts: sweep two compiled its kernels in 2 Dask workers in ")
    assert " s of wall time (" in notes[1] and "each worker's compiling wall time, summed" \
        in notes[1] and len(notes) == 2, notes
    assert len(seen) == 2 and "charts: " not in seen[1]
    log = [json.loads(line) for line in (tmp_path / "out" / LOG).read_text().splitlines()]
    assert len(log) == 2 and all(r["status"] == "complete" and r["compile_s"] == 0.0
                                 for r in log), log


def test_reproduce_says_what_its_compile_seconds_are(monkeypatch, capsys):
    """``charts reproduce``'s notice: the wall time of its compiling, and beside it the
    workers' compiling wall times summed, said to be that (not CPU time), in one line; the
    wall time and the sum are returned (report.md's compiling share)."""
    from charts.runs import reproduce, warmup

    rows = [dict(analysis="lyapunov", n=3, compile=2.5, cpu=2.0),
            dict(analysis="angles", n=3, compile=1.5, cpu=1.0)]
    monkeypatch.setattr(warmup, "warmup", lambda *a, **k: rows)
    monkeypatch.setattr(compilation, "COMPILING_AFTER", 0.0)
    wall, summed = reproduce._compile_first(None, 2, quiet=False)
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith("charts: reproduce is compiling its kernels in its 2 worker "
                             "processes, before the tasks (once: ")
    assert err[1] == (f"charts: reproduce compiled its kernels in its 2 worker processes in "
                      f"{wall:.1f} s of wall time (4.0 s: each worker's compiling wall time, "
                      "summed; once: they are cached on disk for the next runs)")
    assert len(err) == 2 and wall >= 0.0 and summed == 4.0
    reproduce._compile_first(None, 2, quiet=True)
    assert capsys.readouterr().err == ""
