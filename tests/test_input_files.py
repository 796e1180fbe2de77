"""Scene and sweep files that are not regular, too large or nested too deeply are refused at
once in one line naming the file (charts.runs.input_files), and sweep expressions are bounded."""
import os
import subprocess
import sys

import pytest

from charts.runs.input_files import MAX_BYTES, MAX_DEPTH, nesting_depth
from charts.runs.scene import SceneError, load_scene
from charts.runs.sweep.expressions import ExpressionError, MAX_LENGTH, evaluate_expression, \
    expression_symbols
from charts.runs.sweep.spec import SweepError, load_sweep

LOADERS = [(load_scene, SceneError, "scene"), (load_sweep, SweepError, "sweep")]


@pytest.mark.parametrize("load, error, what", LOADERS)
def test_a_fifo_a_device_and_a_folder_are_refused_without_reading(tmp_path, load, error, what):
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)                 # nobody writes it: reading would block for ever
    for path, kind in [(fifo, "a FIFO"), ("/dev/zero", "a character device"),
                       (tmp_path, "a folder")]:
        with pytest.raises(error, match=f"the {what} is not a regular file \\(it is {kind}\\)"):
            load(path)


@pytest.mark.parametrize("load, error, what", LOADERS)
def test_an_oversized_file_is_refused_by_its_size(tmp_path, load, error, what):
    big = tmp_path / "big.toml"
    with open(big, "wb") as fh:
        fh.truncate(MAX_BYTES + 1)   # sparse: costs no disk
    with pytest.raises(error, match=f"{MAX_BYTES + 1} bytes, more than the {MAX_BYTES}"):
        load(big)


@pytest.mark.parametrize("depth", [3000, MAX_DEPTH + 1])
@pytest.mark.parametrize("load, error, what", LOADERS)
def test_deep_nesting_is_refused_in_one_line(tmp_path, load, error, what, depth):
    f = tmp_path / "deep.toml"
    f.write_text("a = " + "{b = " * depth + "1" + "}" * depth + "\n")
    with pytest.raises(error, match="nests its tables or arrays") as info:
        load(f)
    assert str(f) in str(info.value) and "\n" not in str(info.value)


def test_nesting_depth_counts_tables_and_arrays_without_recursion():
    assert nesting_depth(1) == 0 and nesting_depth({"a": [1, {"b": 2}]}) == 3
    deep = 1
    for _ in range(50_000):
        deep = [deep]
    assert nesting_depth(deep) == 50_000


def test_bundled_scenes_and_sweeps_are_far_inside_the_bounds():
    from charts.runs.bundled import bundled_files
    from charts.runs.input_files import read_toml
    for kind in ("scenes", "sweeps"):
        for path in bundled_files(f"charts.data.{kind}").values():
            assert path.stat().st_size < MAX_BYTES // 100
            assert nesting_depth(read_toml(path, kind, ValueError)) <= 4


def test_expressions_are_bounded_in_length():
    long = "+".join(["m"] * 30_000)    # Python's parser would recurse past its limit
    for f in (expression_symbols, lambda e: evaluate_expression(e, {"m": 1.0})):
        with pytest.raises(ExpressionError, match=f"at most {MAX_LENGTH}"):
            f(long)
    assert evaluate_expression("(" * 100 + "m" + ")" * 100, {"m": 2.0}) == 2.0
    with pytest.raises(ExpressionError, match="not a finite|cannot be computed"):
        evaluate_expression("9**9**9", {})


def test_the_command_line_refuses_a_fifo_at_once(tmp_path):
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    r = subprocess.run([sys.executable, "-m", "charts", "run", str(fifo), "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [
        f"charts: error: {fifo}: the scene is not a regular file (it is a FIFO); give the path "
        "of a .toml file"]
    assert not (tmp_path / "out").exists()
