"""Run a validated :class:`~charts.runs.scene.Scene`: the smallest computation its effects
need (:func:`~charts.runs.plan.plan_scene`), in chunks, checkpointed.

What was assembled (state dimension, tangent vectors, stored samples, right-hand-side
evaluations) is written into ``result.json`` under ``"computation"``.

Chunks and checkpoints.  Time is cut into a deterministic list of chunks (every
``[run] checkpoint_every``, plus the Lyapunov batch boundaries).  After each chunk the
whole run state (y, tangent vectors, log-norm sums, everything recorded) is written to
``checkpoint.npz`` atomically.  Ctrl-C stops at the last finished chunk, writes a valid
partial ``result.json`` (status ``"interrupted"``) and keeps the checkpoint;
``run_scene(..., resume=True)`` continues from it.  Because an uninterrupted run walks the
same chunks, a resumed run gives bit-identical numbers.

Outputs (each written to a temporary file, then ``os.replace``): ``result.json``,
``arrays.npz``, one PNG per effect with a picture.

The parts: :mod:`~charts.runs.plan` (what runs), :mod:`~charts.runs.run_state` (the
checkpointed state), :mod:`~charts.runs.engines` (the integration of a chunk),
:mod:`~charts.runs.recorders` (what is recorded along the way),
:mod:`~charts.runs.scene_results` and :mod:`~charts.runs.scene_figures` (the outputs).
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np

from ..compilation import NOTE_SECONDS, compile_timer
from .engines import IntegrateEngine, KernelEngine, chunk_bounds, lyapunov_batch_ends
from .io import atomic_write, npz_bytes
from .outdir import OutputLock, prepare_output
from .paper import PAPER_EXPONENTS
from .plan import ANGLES_CHECKPOINT_STEPS, Plan, plan_scene, ticks
from .recorders import make_recorders
from .run_state import CHECKPOINT, RunError, RunState, scene_hash, scene_system, units_done
from .linkage_run import linkage_angles_pass
from .scene_linkage import is_linkage
from .scene import Scene
from .scene_results import FTLE_STATS, finalize, write_result

__all__ = ["Plan", "plan_scene", "run_scene", "RunError", "PAPER_EXPONENTS"]


#: Compile time above which a run says it compiled kernels (loading cached ones takes less).


def run_scene(scene: Scene, outdir, *, resume: bool = False, quiet: bool = False,
              on_chunk=None) -> dict:
    """Run ``scene`` into ``outdir``; return the result dict (also in result.json).

    ``on_chunk(index, n_chunks)`` is called after each checkpoint (tests use it to simulate
    Ctrl-C by raising KeyboardInterrupt).  An interrupt writes a partial result with
    status "interrupted" and re-raises ``KeyboardInterrupt``.  ``outdir`` is checked before
    any work (:func:`~charts.runs.outdir.prepare_output`) and locked while the run writes
    into it: a second run into the same folder refuses (:class:`~charts.runs.outdir.OutputLock`).
    """
    outdir = prepare_output(outdir)
    with OutputLock(outdir, f"charts run {scene.name}"):
        return _run_locked(scene, outdir, resume, quiet, on_chunk)


def _run_locked(scene: Scene, outdir: Path, resume: bool, quiet: bool, on_chunk) -> dict:
    system = scene_system(scene)
    plan = plan_scene(scene)
    st = RunState(scene, plan, system)
    ck = outdir / CHECKPOINT
    digest = scene_hash(scene)
    if resume:
        if not ck.exists():
            raise RunError(f"--resume: no checkpoint in {outdir} (nothing to resume; "
                           "run without --resume)")
        with np.load(ck) as a:
            if str(a["scene_hash"]) != digest:
                raise RunError(f"--resume: the checkpoint in {outdir} belongs to a different "
                               "scene (the scene file changed); run without --resume")
            st.load_arrays(a)
    elif ck.exists() or (outdir / "result.json").exists():
        prev = _read_status(outdir)
        if prev == "interrupted":
            raise RunError(f"{outdir} holds an interrupted run: continue it with --resume, or "
                           "choose another output folder")
    engine = KernelEngine(st) if plan.engine == "kernel" else IntegrateEngine(st)
    unit = scene.integrator["dt"] if plan.engine == "kernel" else scene.run["sample_dt"]
    transient = ticks(scene.run["t_transient"], unit)
    ends = [e + transient for e in chunk_bounds(scene, plan)]
    if transient:
        ends = [transient] + ends
    recorders = make_recorders(st, transient)
    lyap_ends = set()
    if "lyapunov" in scene.effects:
        lyap_ends = {transient + e for e in lyapunov_batch_ends(scene, plan)}

    n_main = len(ends) if plan.main_pass else 0
    passes = plan.passes
    n_units = n_main + len(passes)
    st.n_main = n_main

    from tqdm.auto import tqdm
    t_total = (scene.run["t_transient"] + scene.run["t_final"]) * (1 if plan.main_pass else 0)
    t_total += plan.pass_steps() * scene.integrator["dt"] if passes else 0.0
    bar = tqdm(total=round(t_total, 10), unit="t", desc=scene.name, disable=quiet,
               leave=False, initial=round(units_done(st, ends) * unit, 10))
    status = "complete"
    try:
        with compile_timer(st.add_compile_time):
            _run_chunks(st, engine, ends, transient, n_main, n_units, passes, recorders,
                        lyap_ends, unit, digest, ck, bar, on_chunk)
    except (KeyboardInterrupt, RunError) as exc:
        status = "interrupted" if isinstance(exc, KeyboardInterrupt) else "failed"
        failure = None if status == "interrupted" else str(exc)
        # roll back to the last checkpoint: the chunk in flight is discarded
        if st.chunk_index and ck.exists():
            with np.load(ck) as a:
                st.load_arrays(a)
        else:
            st = RunState(scene, plan, system)
        st.n_main = n_main
    finally:
        bar.close()
    if st.compile_s > NOTE_SECONDS and not quiet:
        print(f"{scene.name}: compiled the kernels for N = {system.n} in {st.compile_s:.1f} s "
              "(once: they are cached on disk for the next runs)", file=sys.stderr)
    result = finalize(st, status, ends, transient, unit, outdir)
    if status == "interrupted":
        raise KeyboardInterrupt(result)
    if status == "failed":
        result["error"] = failure
        write_result(outdir, result)
        raise RunError(f"{failure} (the finished part is in {outdir}/result.json)")
    return result


def _run_chunks(st, engine, ends, transient, n_main, n_units, passes, recorders, lyap_ends,
                unit, digest, ck, bar, on_chunk):
    """The chunks from ``st.chunk_index`` on, a checkpoint after each."""
    for idx in range(st.chunk_index, n_units):
        t_wall = time.perf_counter()
        if idx < n_main:
            start = ends[idx - 1] if idx else 0
            engine.run_chunk(start, ends[idx], recorders if ends[idx] > transient else [],
                             transient)
            if ends[idx] == transient:      # the transient does not count for exponents
                st.logsum[:] = 0.0
            if ends[idx] in lyap_ends:
                st.lyap_marks.append((ends[idx] - transient, st.logsum.copy()))
            advanced = (ends[idx] - start) * unit
        else:
            name = passes[idx - n_main]
            (_angles_pass if name == "angles" else _clv_pass)(st)
            advanced = getattr(st.plan, name)["steps"] * st.scene.integrator["dt"]
        st.chunk_index = idx + 1
        st.elapsed += time.perf_counter() - t_wall
        st.done = st.chunk_index == n_units
        arr = st.to_arrays()
        arr["scene_hash"] = np.array(digest)
        atomic_write(ck, npz_bytes(arr))
        bar.update(advanced)
        if on_chunk is not None:
            on_chunk(idx, n_units)


def _angles_pass(st: RunState):
    """The hyperbolicity test (section 4) from the initial state: forward tangent vectors,
    backward adjoint vectors along the re-integrated trajectory (``charts.analyses.hyperbolicity``)."""
    from ..analyses.hyperbolicity import hyperbolicity_angles

    if is_linkage(st.scene):                 # its own test, charts.analyses.linkage_angles
        return linkage_angles_pass(st)
    sc, sys_ = st.scene, st.system
    a = sc.effects["angles"]
    dt = sc.integrator["dt"]
    n = sys_.n
    res = hyperbolicity_angles(sys_, st.y0[:n], st.y0[n:], sc.run["t_final"], dt=dt,
                               n_unstable=a["n_vectors"], t_transient=sc.run["t_transient"],
                               sample_every=a["sample_every"],
                               checkpoint_every=ANGLES_CHECKPOINT_STEPS * dt,
                               project_every=st.flow.project_every * dt or None,
                               seed=sc.initial["seed"] or 0)
    st.rec["angles"] = [list(r) for r in np.column_stack([res.t, res.phi_full,
                                                          res.phi_restricted])]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.adjoint_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += 2 * st.plan.angles["steps"]


def _clv_pass(st: RunState):
    """Covariant Lyapunov vectors from the initial state, each variant asked for
    (``charts.analyses.covariant``): per sample t, φ and the angle between the leading
    unstable and stable CLVs; per variant the mean growth rates along the CLVs, the
    domination fractions and the finite-time exponents for each window."""
    from ..analyses.covariant import covariant_lyapunov_vectors

    sc, sys_ = st.scene, st.system
    c = sc.effects["clv"]
    dt = sc.integrator["dt"]
    n = sys_.n
    cols, dom, ftle, exps = [], [], [], []
    for iv, variant in enumerate(("full", "restricted")):
        if c["variant"] not in (variant, "both"):
            continue
        r = covariant_lyapunov_vectors(
            sys_, st.y0[:n], st.y0[n:], sc.run["t_final"], variant=variant, dt=dt,
            n_unstable=c["n_vectors"], t_transient=sc.run["t_transient"],
            sample_every=c["sample_every"], project_every=st.flow.project_every * dt or None,
            seed=sc.initial["seed"] or 0)
        cols += [r.phi, r.phi_vectors]

        def pad(x):            # rows of one length (2N) for both variants
            return list(x) + [np.nan] * (2 * n - len(x))
        exps.append([iv] + pad(r.exponents))
        for w, d in r.domination(c["windows"]).items():
            dom.append([iv, w, d["split"], d["count"]])
        for w, f in r.finite_time(c["windows"]).items():
            ftle.append([iv, w, f["count"], f["frac_nonpositive_leading"]]
                        + sum((pad(f[k]) for k in FTLE_STATS), []))
    st.rec["clv"] = [list(row) for row in np.column_stack([r.t] + cols)]
    st.rec["clv_exponents"] = exps
    st.rec["clv_domination"] = dom
    st.rec["clv_ftle"] = ftle
    st.rhs += st.plan.clv["rhs_evaluations"]
    st.steps += st.plan.clv["steps"]


def _read_status(outdir):
    try:
        return json.loads((outdir / "result.json").read_text()).get("status")
    except (OSError, ValueError):
        return None
