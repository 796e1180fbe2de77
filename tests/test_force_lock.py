"""``charts run --force`` deletes nothing before it holds the folder's lock, and then only
what an earlier run wrote; a lock path that charts did not write (a folder, a pid that is
not a process id) is refused in one line, never broken and never a traceback."""
from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from charts.cli.main import main
from cli_checks import one_line_error
from charts.runs.outdir import LOCK, OutputError, OutputLock, prepare_output
from charts.runs.runner import SCENE_FIGURES, clear_run_outputs

SCENE = """name = "{name}"
[system]
n = 3
[run]
t_final = 2.0
sample_dt = 0.5
[effects.{effect}]
{extra}"""


@pytest.fixture
def scenes(tmp_path):
    (tmp_path / "a.toml").write_text(SCENE.format(name="drifty", effect="drift",
                                                  extra="sample_every = 1.0\n"))
    (tmp_path / "b.toml").write_text(SCENE.format(name="wavy", effect="waveforms", extra=""))
    return tmp_path


def _snapshot(folder: Path) -> dict:
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.name != LOCK}


def test_a_refused_force_deletes_nothing(scenes, capsys):
    """Another live process holds the lock: --force is refused and every file of the
    earlier run (result, checkpoint, figures, arrays) is still there, byte for byte."""
    out = scenes / "o"
    assert main(["run", str(scenes / "a.toml"), "-o", str(out), "--quiet"]) == 0
    (out / "notes.txt").write_text("mine")
    before = _snapshot(out)
    assert {"result.json", "checkpoint.npz", "drift.png", "arrays.npz"} <= set(before)
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import signal, sys; sys.path[:0] = [sys.argv[1]]; "
         "from charts.runs.outdir import OutputLock; "
         "l = OutputLock(sys.argv[2], 'holder').acquire(); print('held', flush=True); "
         "signal.pause()",
         os.path.dirname(os.path.dirname(__import__("charts").__file__)), str(out)],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        capsys.readouterr()
        for scene in ("a.toml", "b.toml"):          # the same scene and another one
            code = main(["run", str(scenes / scene), "-o", str(out), "--force", "--quiet"])
            err = one_line_error(capsys, code, 2)
            assert "another process is writing" in err and f"pid {holder.pid}" in err
            assert _snapshot(out) == before
    finally:
        holder.send_signal(signal.SIGKILL)
        holder.wait()


def test_a_lock_with_a_live_pid_refuses_force_and_deletes_nothing(scenes, capsys):
    """The same with the lock held by this very process (a live pid on this host)."""
    out = scenes / "o"
    assert main(["run", str(scenes / "a.toml"), "-o", str(out), "--quiet"]) == 0
    before = _snapshot(out)
    capsys.readouterr()
    with OutputLock(out, "test"):
        code = main(["run", str(scenes / "b.toml"), "-o", str(out), "--force", "--quiet"])
        assert "another process is writing" in one_line_error(capsys, code, 2)
        assert _snapshot(out) == before


def test_force_with_another_scene_leaves_none_of_the_old_scenes_files(scenes, capsys):
    out = scenes / "o"
    assert main(["run", str(scenes / "a.toml"), "-o", str(out), "--quiet"]) == 0
    assert (out / "drift.png").exists()
    (out / "notes.txt").write_text("mine")
    (out / "extra.png").write_text("the user's own picture")
    assert main(["run", str(scenes / "b.toml"), "-o", str(out), "--force", "--quiet"]) == 0
    result = json.loads((out / "result.json").read_text())
    assert result["scene"]["name"] == "wavy" and result["status"] == "complete"
    assert not (out / "drift.png").exists()           # the old scene's figure is gone
    assert (out / "waveforms.png").exists()
    assert (out / "notes.txt").read_text() == "mine"   # files charts did not write are kept
    assert (out / "extra.png").exists()
    assert not (out / LOCK).exists()
    names = {p.name for p in out.iterdir()}
    assert names == set(result["files"]) | {"results.nc", "notes.txt", "extra.png"}


def test_clear_run_outputs_needs_the_lock_and_removes_only_run_files(tmp_path):
    out = prepare_output(tmp_path / "o")
    for name in ("result.json", "checkpoint.npz", "lyapunov.png", "mine.txt", "old.png"):
        (out / name).write_text("{}" if name == "result.json" else "x")
    (out / "result.json").write_text(json.dumps({"files": ["old.png", "../escape", "/etc/x"]}))
    (tmp_path / "escape").write_text("outside")
    lock = OutputLock(out)
    with pytest.raises(RuntimeError, match="not held"):
        clear_run_outputs(out, lock)
    assert (out / "result.json").exists()
    with lock:
        removed = clear_run_outputs(out, lock)
    assert removed[-1] == "result.json"
    assert set(removed) == {"result.json", "checkpoint.npz", "lyapunov.png", "old.png"}
    assert {p.name for p in out.iterdir()} == {"mine.txt"}
    assert (tmp_path / "escape").exists()


def test_every_figure_a_scene_run_writes_is_known_to_force():
    src = (Path(__import__("charts").__file__).parent / "runs" / "scene_results.py").read_text()
    written = set(re.findall(r'figures\["([^"]+)"\]', src))
    assert written and written <= set(SCENE_FIGURES), written - set(SCENE_FIGURES)


@pytest.mark.parametrize("content, words", [
    ("folder", ["is a folder", "remove it"]),
    ('{"pid": "abc", "host": "HOST", "command": "x"}', ["pid 'abc'", "not a process id"]),
    ('{"pid": [1, 2], "host": "HOST"}', ["not a process id"]),
    ('{"pid": null, "host": "HOST"}', ["not a process id"]),
    ('{"pid": 0, "host": "HOST"}', ["not a process id"]),
    ('{"pid": -5, "host": "HOST"}', ["not a process id"]),
    ('{"pid": 99999999999999999999, "host": "HOST"}', ["not a process id"]),
])
def test_a_lock_charts_did_not_write_is_one_line_and_kept(scenes, capsys, content, words):
    import socket

    out = scenes / "o"
    out.mkdir()
    lock = out / LOCK
    if content == "folder":
        lock.mkdir()
    else:
        lock.write_text(content.replace("HOST", socket.gethostname()))
        old = os.stat(lock).st_mtime - 3600               # past any grace period
        os.utime(lock, (old, old))
    (out / "result.json").write_text("{}")
    for argv in (["run", str(scenes / "a.toml"), "-o", str(out), "--force"],
                 ["reproduce", "-o", str(out)]):
        err = one_line_error(capsys, main(argv), 2)
        assert all(w in err for w in words), err
        assert str(lock) in err
    with pytest.raises(OutputError):
        OutputLock(out).acquire()
    assert lock.is_dir() if content == "folder" else lock.read_text().startswith("{")
    assert (out / "result.json").exists()
