"""The on-demand geometry cache checks what it loads: a corrupt, stale or hash-less module
is derived again with a message (never a bare SyntaxError), and two processes that need the
same N at once derive it once and both succeed (file lock).  N = 3 derived into a private
cache folder keeps it fast (0.6 s per derivation); the shipped N = 3 is never touched."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

from charts.codegen.emit import module_name, module_source

N = 3


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("CHARTS_CACHE_DIR", str(tmp_path / "cache"))
    from charts.codegen.cache import cache_dir
    return cache_dir()


def _load():
    from charts.codegen.cache import load_or_generate
    return load_or_generate(N)


@pytest.mark.parametrize("damage", ["truncated", "garbage", "edited", "no hash"])
def test_a_damaged_module_is_derived_again_with_a_message(cache, capsys, damage):
    _load()
    path = cache / f"{module_name(N)}.py"
    sidecar = path.with_name(path.name + ".sha256")
    text = path.read_text()
    if damage == "truncated":                   # a full disk: half a file
        path.write_text(text[: len(text) // 2])
    elif damage == "garbage":
        path.write_bytes(b"\x00\xff def (")
    elif damage == "edited":                    # valid Python, wrong numbers: stale
        path.write_text(text.replace("def metric", "def metric_old", 1))
    else:
        sidecar.unlink()
    capsys.readouterr()
    mod = _load()
    err = capsys.readouterr().err
    assert f"cached geometry for N={N}" in err and "deriving it again" in err
    assert path.read_text() == module_source(N)
    assert mod.N == N and hasattr(mod, "metric")
    _load()                                     # repaired: silent from now on
    assert capsys.readouterr().err == ""


def test_a_hash_valid_module_that_does_not_import_is_derived_again(cache, capsys):
    import hashlib
    _load()
    path = cache / f"{module_name(N)}.py"
    bad = b"raise ImportError('broken on purpose')\n"
    path.write_bytes(bad)
    path.with_name(path.name + ".sha256").write_text(hashlib.sha256(bad).hexdigest())
    capsys.readouterr()
    assert _load().N == N
    assert "does not import" in capsys.readouterr().err
    assert path.read_text() == module_source(N)


def test_two_processes_needing_the_same_n_derive_it_once(tmp_path):
    go = tmp_path / "go"
    env = dict(os.environ, CHARTS_CACHE_DIR=str(tmp_path / "cache"))
    code = ("import os, sys, time\n"
            "from charts.codegen.cache import load_or_generate\n"
            "print('ready', flush=True)\n"
            f"while not os.path.exists({str(go)!r}): time.sleep(0.001)\n"
            f"print(load_or_generate({N}).N)\n")
    procs = [subprocess.Popen([sys.executable, "-c", code], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True) for _ in range(2)]
    assert [p.stdout.readline().strip() for p in procs] == ["ready", "ready"]
    go.write_text("")                   # both call load_or_generate within a millisecond
    outs = [p.communicate(timeout=300) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], outs
    assert [o.strip() for o, _ in outs] == [str(N), str(N)]
    err = "".join(e for _, e in outs)
    assert err.count(f"deriving geometry for N={N}") == 1, err
    assert "waiting for another process" in err, err


@pytest.mark.parametrize("damage", ["module is a folder", "hash is a folder", "lock is a folder",
                                    "folder is a file"])
def test_cache_entries_of_the_wrong_kind_are_replaced(cache, capsys, damage):
    _load()
    path = cache / f"{module_name(N)}.py"
    target = {"module is a folder": path,
              "hash is a folder": path.with_name(path.name + ".sha256"),
              "lock is a folder": cache / f"{module_name(N)}.lock",
              "folder is a file": cache}[damage]
    import shutil
    shutil.rmtree(target) if target.is_dir() else target.unlink()
    if damage == "folder is a file":
        target.write_text("not a folder")
    else:
        (target / "inside").mkdir(parents=True)
    capsys.readouterr()
    assert _load().N == N
    assert "deriving" in capsys.readouterr().err or damage == "lock is a folder"
    assert path.read_text() == module_source(N)
    _load()
    assert capsys.readouterr().err == ""


def test_a_cache_root_that_is_a_file_is_named(tmp_path, monkeypatch):
    root = tmp_path / "root"
    root.write_text("")
    monkeypatch.setenv("CHARTS_CACHE_DIR", str(root))
    with pytest.raises(ValueError, match=f"the geometry cache {root} is not a folder"):
        _load()
