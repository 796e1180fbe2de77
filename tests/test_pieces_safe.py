"""``charts reproduce``'s pieces hold data only: a file planted in ``DIR/pieces/`` is never
executed (no pickle is ever read), a damaged or foreign piece is recomputed with one line
naming it, and a finished piece is still reused bit for bit."""
from __future__ import annotations

import io
import os
import pickle

import numpy as np
import pytest

from charts.runs import pieces as pc
from charts.runs import reproduce as rp

TINY = dict(lyap_members=1, lyap_t=20.0, lyap_batches=2, angle_members=1, angle_t=150.0,
            curv_t=5.0, wave_t=800.0, angle_transient=2.0)


class _Payload:
    """Unpickling this creates the marker file (what a planted file could do)."""

    def __init__(self, marker):
        self.marker = str(marker)

    def __reduce__(self):
        return (os.system, (f"touch '{self.marker}'",))


def _plant(path, marker):
    path.write_bytes(pickle.dumps({"args": "[]", "result": _Payload(marker)}))


def _clv_like():
    """The shapes of the real results: nested dicts with float keys, tuples, NumPy scalars,
    Python floats and ints, arrays of several dtypes."""
    return {"full": {"phi": np.linspace(0, 1, 7), "exponents": np.array([0.5, -0.5]),
                     "split": {0.1: (0.25, 40), 1.0: (np.float64(0.5), np.int64(4))}},
            "ftle": {1.0: np.arange(3.0), 10.0: np.zeros((0,))},
            "max_ab": 1.5e-7, "count": 3, "flag": True, "none": None, "label": "x",
            "ints": np.arange(4, dtype=np.int64), "mask": np.array([True, False]),
            "nan": float("nan"), "list": [np.ones((2, 2)), 2.0]}


def _assert_same(a, b):
    assert type(a) is type(b), (a, b)
    if isinstance(a, dict):
        assert list(a) == list(b)
        for k in a:
            _assert_same(a[k], b[k])
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            _assert_same(x, y)
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape
        np.testing.assert_array_equal(a, b)
    elif isinstance(a, float) and np.isnan(a):
        assert np.isnan(b)
    else:
        assert a == b


def test_a_piece_round_trips_its_result_exactly(tmp_path):
    res = _clv_like()
    pc.save_piece(tmp_path, ("clv", 4, 1), (4, 201, 150.0, 2.0), res)
    path = tmp_path / "clv-n4-1.npz"
    assert path.exists()
    with np.load(path, allow_pickle=False) as z:     # readable without pickle
        assert "piece" in z.files
    _assert_same(pc.load_piece(tmp_path, ("clv", 4, 1), (4, 201, 150.0, 2.0)), res)
    assert pc.load_piece(tmp_path, ("clv", 4, 1), (4, 201, 300.0, 2.0)) is None   # other args


def test_a_result_that_is_not_data_is_refused_when_written(tmp_path):
    with pytest.raises(TypeError, match="object arrays"):
        pc.save_piece(tmp_path, ("wave", 3, 0), (), {"x": np.array([object()])})
    with pytest.raises(TypeError, match="cannot hold"):
        pc.save_piece(tmp_path, ("wave", 3, 0), (), {"x": _Payload(tmp_path / "m")})
    assert not list(tmp_path.iterdir())


def test_planted_pickles_are_never_executed_and_are_named(tmp_path):
    marker = tmp_path / "marker"
    folder = tmp_path / "pieces"
    folder.mkdir()
    key, args = ("lyap", 3, 0), (3, [100], 20.0, 2)
    _plant(folder / "lyap-n3-0.pkl", marker)                # the old file name
    _plant(folder / "lyap-n3-0.npz", marker)                # a pickle under the new name
    lines = []
    assert pc.load_piece(folder, key, args, notice=lines.append) is None
    assert not marker.exists()
    assert len(lines) == 2, lines
    assert any("lyap-n3-0.pkl" in ln and "ignoring" in ln for ln in lines)
    assert any("lyap-n3-0.npz" in ln and "computing it again" in ln for ln in lines)
    assert all("\n" not in ln for ln in lines)
    # an .npz whose entry is an object array (np.save would pickle it): refused, not loaded
    buf = io.BytesIO()
    np.savez(buf, piece=np.array([_Payload(marker)], dtype=object))
    (folder / "wave-n3-0.npz").write_bytes(buf.getvalue())
    assert pc.load_piece(folder, ("wave", 3, 0), (3, 400, 800.0), notice=lines.append) is None
    assert not marker.exists() and "wave-n3-0.npz" in lines[-1]


@pytest.mark.parametrize("damage", ["torn", "empty", "foreign npz", "other task", "bad json"])
def test_a_damaged_or_foreign_piece_is_recomputed_with_one_line(tmp_path, damage):
    key, args = ("curv", 3, 0), (3, 300, 5.0)
    pc.save_piece(tmp_path, key, args, {"Ka": np.arange(3.0)})
    path = tmp_path / "curv-n3-0.npz"
    good = path.read_bytes()
    if damage == "torn":
        path.write_bytes(good[: len(good) // 2])
    elif damage == "empty":
        path.write_bytes(b"")
    elif damage == "foreign npz":
        buf = io.BytesIO()
        np.savez(buf, x=np.arange(3))
        path.write_bytes(buf.getvalue())
    elif damage == "other task":
        path.write_bytes(pc.encode_piece(("curv", 4, 0), args, {"Ka": np.arange(3.0)}))
    else:
        buf = io.BytesIO()
        np.savez(buf, piece=np.array("{not json"))
        path.write_bytes(buf.getvalue())
    lines = []
    assert pc.load_piece(tmp_path, key, args, notice=lines.append) is None
    assert len(lines) == 1 and str(path) in lines[0] and "computing it again" in lines[0]


def test_reproduce_recomputes_planted_pieces_and_then_reuses_its_own(tmp_path, capsys):
    """Every piece planted as a pickle with a payload (under both names): the run computes
    them all, executes none, says so per file; the next run reuses all of them unchanged."""
    marker = tmp_path / "marker"
    folder = tmp_path / "pieces"
    folder.mkdir()
    keys = list(rp._tasks(TINY))
    for key in keys:
        _plant(pc.piece_path(folder, key), marker)
        _plant(pc.piece_path(folder, key).with_suffix(".pkl"), marker)
    first = rp._run_all(TINY, 1, True, folder)
    err = capsys.readouterr().err
    assert not marker.exists()
    for key in keys:
        name = pc.piece_path(folder, key).name
        assert f"{folder / name} is not a usable piece" in err
        assert str(folder / name.replace(".npz", ".pkl")) in err
    stamp = {f.name: f.stat().st_mtime_ns for f in pc.kept_pieces(folder)}
    assert len(stamp) == len(keys)
    second = rp._run_all(TINY, 1, False, folder)
    assert f"reusing {len(keys)} of {len(keys)} finished pieces" in capsys.readouterr().err
    assert {f.name: f.stat().st_mtime_ns for f in pc.kept_pieces(folder)} == stamp
    for key in keys:
        _assert_same(second[key], first[key])
    assert not marker.exists()
