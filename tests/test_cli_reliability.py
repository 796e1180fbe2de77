"""The command line under hostile use: every mistake a user can make is one line
``charts: error: …`` with exit status 2 (bad usage) or 1 (a failed run), never a traceback;
output folders are checked before any work; a folder another live process is writing is
refused (a lock), a lock left by a killed process is not; Ctrl-C exits 130 saying what was
kept and how to resume; a sweep whose mass expression divides by zero is refused."""
from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

from charts.cli.main import main
from cli_checks import one_line_error
from charts.runs.outdir import LOCK, OutputError, OutputLock, prepare_output

CHARTS = [sys.executable, "-m", "charts.cli.main"]

TINY = """name = "tiny"
[system]
n = 3
[run]
t_final = 2.0
sample_dt = 0.5
[effects.drift]
sample_every = 1.0
"""

SWEEP = """name = "div"
[scene.system]
n = 4
[scene.run]
t_final = 10.0
[scene.effects.lyapunov]
n_batches = 2
[sweep]
seeds = [1]
[sweep.parameters]
m = [1.0, 0.0]
[sweep.masses]
"1,1,1,1/m" = [1, 1, 1, "1/m"]
"""


@pytest.fixture
def files(tmp_path):
    (tmp_path / "afile").write_text("x")
    (tmp_path / "tiny.toml").write_text(TINY)
    (tmp_path / "div.toml").write_text(SWEEP)
    (tmp_path / "ok.toml").write_text(SWEEP.replace("m = [1.0, 0.0]", "m = [1.0]"))
    return tmp_path


BAD_USAGE = {
    "output is a file": (["run", "{t}/tiny.toml", "-o", "{t}/afile"], "exists and is a file"),
    "output under a file": (["run", "{t}/tiny.toml", "-o", "{t}/afile/sub"], "is a file, so no"),
    "name too long": (["run", "{t}/tiny.toml", "-o", "{t}/" + "x" * 300], "shorter name"),
    "path too long": (["run", "{t}/tiny.toml", "-o", "{t}/" + "x/" * 2500], "shorter path"),
    "not creatable": (["run", "{t}/tiny.toml", "-o", "/proc/charts-no/x"], "cannot create"),
    "sweep output is a file": (["sweep", "{t}/ok.toml", "-o", "{t}/afile"], "exists and is"),
    "reproduce output under a file": (["reproduce", "-o", "{t}/afile/x"], "is a file, so no"),
    "reproduce --workers -1": (["reproduce", "--workers", "-1"], "--workers: must be an integer"),
    "reproduce --workers 0": (["reproduce", "--workers", "0"], "--workers: must be an integer"),
    "sweep --workers 0": (["sweep", "{t}/ok.toml", "-o", "{t}/w", "--workers", "0"],
                          "--workers: must be an integer >= 1, got 0"),
    "sweep --workers x": (["sweep", "{t}/ok.toml", "-o", "{t}/w", "--workers", "x"],
                          "--workers: must be an integer >= 1, got 'x'"),
    "scheduler garbage": (["sweep", "{t}/ok.toml", "-o", "{t}/w", "--scheduler", "garbage"],
                          "--scheduler 'garbage' is not a Dask scheduler address"),
    "scheduler bad port": (["sweep", "{t}/ok.toml", "-o", "{t}/w", "--scheduler",
                            "tcp://localhost:notaport"], "tcp://localhost:notaport"),
    "division by zero": (["sweep", "{t}/div.toml", "-o", "{t}/w"],
                         "'1/m' cannot be computed with m=0.0: float division by zero"),
    "missing argument": (["run"], "the following arguments are required"),
    "unknown command": (["frobnicate"], "invalid choice"),
    "unknown option": (["run", "{t}/tiny.toml", "-o", "{t}/o", "--fast"], "unrecognized"),
    "bench option": (["bench", "compare", "--repeat", "x"], "invalid int value"),
}


@pytest.mark.parametrize("case", sorted(BAD_USAGE))
def test_bad_usage_is_one_line_with_status_2(files, capsys, case):
    argv, message = BAD_USAGE[case]
    code = main([a.replace("{t}", str(files)) for a in argv])
    assert message in one_line_error(capsys, code, 2)


def test_nothing_is_written_when_the_output_is_refused(files, capsys):
    assert main(["sweep", str(files / "div.toml"), "-o", str(files / "w")]) == 2
    assert not (files / "w").exists()


def test_unreachable_scheduler_fails_within_seconds_naming_the_address(files, capsys):
    with socket.socket() as s:                  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    addr = f"tcp://127.0.0.1:{port}"
    code = main(["sweep", str(files / "ok.toml"), "-o", str(files / "w"), "--scheduler", addr])
    assert addr in one_line_error(capsys, code, 2)


def test_an_unexpected_failure_is_one_line_status_1_and_debug_shows_the_traceback(
        files, capsys, monkeypatch):
    import charts.runs.runner as runner

    def boom(*a, **k):
        raise RuntimeError("disk on fire")
    monkeypatch.setattr(runner, "run_scene", boom)
    argv = ["run", str(files / "tiny.toml"), "-o", str(files / "o")]
    err = one_line_error(capsys, main(argv), 1)
    assert "RuntimeError: disk on fire" in err and "--debug" in err
    assert main(["--debug"] + argv) == 1
    assert "Traceback" in capsys.readouterr().err
    monkeypatch.setenv("CHARTS_DEBUG", "1")
    assert main(argv) == 1
    assert "Traceback" in capsys.readouterr().err


def test_a_folder_held_by_a_live_process_is_refused_a_killed_ones_lock_is_taken_over(
        files, capsys):
    out = prepare_output(files / "o")
    holder = subprocess.Popen([sys.executable, "-c",
                               "import signal, sys; sys.path[:0] = [sys.argv[1]]; "
                               "from charts.runs.outdir import OutputLock; "
                               "l = OutputLock(sys.argv[2], 'holder').acquire(); "
                               "print('held', flush=True); signal.pause()",
                               os.path.dirname(os.path.dirname(__import__("charts").__file__)),
                               str(out)], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        for argv in (["run", str(files / "tiny.toml"), "-o", str(out)],
                     ["sweep", str(files / "ok.toml"), "-o", str(out)],
                     ["reproduce", "-o", str(out)]):
            err = one_line_error(capsys, main(argv), 2)
            assert "another process is writing" in err and f"pid {holder.pid}" in err
    finally:
        holder.send_signal(signal.SIGKILL)
        holder.wait()
    assert (out / LOCK).exists()                       # SIGKILL leaves the lock behind ...
    assert main(["run", str(files / "tiny.toml"), "-o", str(out), "--quiet"]) == 0
    err = capsys.readouterr().err
    assert "removing a stale lock" in err and f"pid {holder.pid}" in err
    assert not (out / LOCK).exists()                   # ... and a finished run removes its own


def test_lock_from_another_host_is_never_broken(tmp_path):
    (tmp_path / LOCK).write_text(json.dumps({"pid": 1, "host": "elsewhere", "command": "x"}))
    with pytest.raises(OutputError, match=f"delete {tmp_path / LOCK}"):
        OutputLock(tmp_path).acquire()


def test_a_torn_lock_file_is_stale_only_after_a_grace_period(tmp_path):
    (tmp_path / LOCK).write_text("")
    with pytest.raises(OutputError, match="another process"):
        OutputLock(tmp_path).acquire()
    old = time.time() - 60
    os.utime(tmp_path / LOCK, (old, old))
    with OutputLock(tmp_path):
        assert json.loads((tmp_path / LOCK).read_text())["pid"] == os.getpid()

