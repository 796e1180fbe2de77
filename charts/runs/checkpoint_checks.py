"""A scene run's checkpoint checked before a resume trusts it (docs/reliability.md).

A checkpoint that is not this package's own, whole, of this run -- edited, copied from
another run, or written by a tool -- would otherwise resume to wrong numbers without a word:
a chunk counter past the end resumed to "complete" with a quarter of the averaging window, a
NaN state failed later as if the step were too large, a scalar state was broadcast into
every component, another N's state failed in NumPy's words.  `check_checkpoint` refuses each
with one `CheckpointError` naming the file and the field:

* every field the run reads is there, numeric, of the run's shape (the state, the tangent
  flow, the counters, the Lyapunov marks, the records), and the state is finite;
* the counters agree with the run's settings (the chunk counter within the run's chunks,
  "done" exactly at the last) and with what the checkpoint holds: the integrator's step
  counter, the Lyapunov batch marks and the number of records of each recorder are those the
  run has after that many chunks, and a separate pass has records exactly when it has run.
"""
from __future__ import annotations

import numpy as np

from .run_state import CheckpointError

__all__ = ["check_checkpoint"]

#: the counters of ``scalars``, in its order (`RunState.to_arrays`).
SCALARS = ("rhs", "rhs_frame", "chunk_index", "elapsed", "done", "steps", "chart")


def _fail(path, what):
    raise CheckpointError(f"{path} is not a usable checkpoint: {what}")


def _shown(shape) -> str:
    return "is a scalar" if shape == () else f"has shape {shape}"


def _array(path, a, name, shape=None, kind="f", finite=False, ndim=(1, 2)):
    """``a[name]`` checked: present, of dtype kind ``kind`` ("f": real numbers, integers
    accepted; "i": integers), of ``shape`` (None: any with ``ndim`` axes), finite if
    ``finite``."""
    if name not in a:
        _fail(path, f"the field {name!r} is missing")
    x = np.asarray(a[name])
    if x.dtype.kind not in ("iu" if kind == "i" else "iuf"):
        _fail(path, f"the field {name!r} holds {x.dtype} values, not numbers")
    if shape is not None and x.shape != tuple(shape):
        _fail(path, f"the field {name!r} {_shown(x.shape)}, this run's {_shown(tuple(shape))} "
                    "(a checkpoint of another system or scene?)")
    if shape is None and x.ndim not in ndim:
        _fail(path, f"the field {name!r} {_shown(x.shape)}, not rows of numbers")
    if finite and not np.all(np.isfinite(x)):
        bad = np.flatnonzero(~np.isfinite(x.ravel()))
        _fail(path, f"the field {name!r} holds {bad.size} non-finite value(s) (first at flat "
                    f"index {bad[0]}: {x.ravel()[bad[0]]}): not a state a run reaches")
    return x


def check_checkpoint(path, a: dict, run) -> None:
    """`CheckpointError` naming ``path`` and the field unless the arrays ``a`` of a
    checkpoint are a state that ``run`` (a ``charts.runs.runner.SceneRun``, set up: its
    chunk ends, transient, passes) reaches after the chunks its counter says (module doc)."""
    st, plan = run.st, run.plan
    if "scene_hash" not in a:
        _fail(path, "the field 'scene_hash' is missing")
    scalars = _array(path, a, "scalars", (len(SCALARS),), finite=True)
    counters = dict(zip(SCALARS, scalars.tolist()))
    for name in ("rhs", "rhs_frame", "chunk_index", "done", "steps", "chart"):
        v = counters[name]
        if v != int(v) or v < (-1 if name == "chart" else 0):
            _fail(path, f"the counter {name} is {v:g}, not a count")
    chunk = int(counters["chunk_index"])
    if chunk > run.n_units:
        _fail(path, f"its chunk counter is {chunk}, past the end of this run's "
                    f"{run.n_units} chunks")
    if bool(counters["done"]) != (chunk == run.n_units):
        _fail(path, f"it says the run is {'done' if counters['done'] else 'not done'} after "
                    f"{chunk} of {run.n_units} chunks")
    if st.flow is not None:
        state = st.flow.state()
        for key, ref in state.items():
            if key == "shares" and "flow_shares" not in a:    # written before the shares
                continue
            _array(path, a, "flow_" + key, ref.shape, "i" if ref.dtype.kind in "iu" else "f",
                   finite=ref.dtype.kind == "f" and key != "health")
    else:
        _array(path, a, "y", st.y0.shape, finite=True)
    k = plan.tangent_vectors
    ticks = _array(path, a, "lyap_ticks", kind="i", ndim=(1,))
    _array(path, a, "lyap_logsums", (ticks.size, k), finite=True)
    for name in st.rec:
        _array(path, a, "rec_" + name)
    for name in st.rec_t:
        _array(path, a, "rect_" + name)
    _check_progress(path, a, run, chunk, ticks)


def _check_progress(path, a, run, chunk, ticks):
    """The counters against what the checkpoint holds: the step counter, the Lyapunov marks,
    the records and the passes, each what ``chunk`` chunks of ``run`` give."""
    st, plan = run.st, run.plan
    main = min(chunk, run.n_main)
    pos = run.ends[main - 1] if main else 0           # units of the main pass done
    if st.flow is not None:
        steps = int(np.asarray(a["flow_counter"]).ravel()[0])
        if steps != pos:
            _fail(path, f"its step counter (flow_counter) is {steps} where {chunk} of the "
                        f"run's {run.n_units} chunks end at step {pos}")
    marks = sorted(e - run.transient for e in run.lyap_ends if e <= pos)
    if ticks.tolist() != marks:
        _fail(path, f"it holds {ticks.size} Lyapunov batch marks (lyap_ticks) where {chunk} "
                    f"chunks end {len(marks)} batches")
    done = max(0, pos - run.transient)
    expected = {}
    for name, every in plan.every.items():
        count = done // every if every else 0
        if name == "waveforms":
            count = min(count, plan.stored.get("waveforms", count))
        expected[name] = count
    rows = {"waveforms": ("rec_waveforms", "rect_waveforms"), "spectrum": ("rec_spectrum",),
            "drift": ("rec_drift", "rect_drift"),
            "curvature": ("rec_curvature_y", "rect_curvature")}
    for name, count in expected.items():
        for field in rows.get(name, ()):
            have = len(np.asarray(a[field]))
            if have != count:
                _fail(path, f"it holds {have} rows of {field} where {chunk} chunks record "
                            f"{count}")
    for i, name in enumerate(run.passes):
        ran = chunk > run.n_main + i
        have = len(np.asarray(a[f"rec_{name}"]))
        if ran != (have > 0):
            _fail(path, f"its {name} pass {'ran' if ran else 'did not run'} by its chunk "
                        f"counter ({chunk}), but rec_{name} holds {have} rows")
