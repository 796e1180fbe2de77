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

Starting over (``force=True``, ``charts run --force``).  Only once the folder's lock is held
(a run refused because another process holds it deletes nothing), and only after the scene's
run is set up, the files an earlier run wrote are removed (:func:`clear_run_outputs`): those
its ``result.json`` lists and every name a scene run can write (:data:`RUN_FILES`,
:data:`SCENE_FIGURES`), so no figure of the old scene stays beside the new results; the
user's other files in the folder are left alone.

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

from ..jit.compilation import NOTE_SECONDS, announce, compile_timer, compiling_said
from ..analyses.arguments import flag
from ..analyses.lyapunov import end_transient
from ..geometry.checks import callback, instance
from .engines import IntegrateEngine, KernelEngine, chunk_bounds, lyapunov_batch_ends
from .io import atomic_write, npz_bytes
from .netcdf_results import SCENE_NETCDF
from .outdir import OutputLock, prepare_output
from .paper import PAPER_EXPONENTS
from .plan import Plan, plan_scene, ticks
from .recorders import make_recorders
from .run_state import (CHECKPOINT, CheckpointError, RunError, RunState, read_checkpoint,
                        scene_hash, units_done)
from .checkpoint_checks import check_checkpoint
from .scene_kind import scene_kind
from .scene import Scene
from .scene_results import (FTLE_STATS, finalize, progress_of, result_header, resume_command,
                            write_result)

__all__ = ["Plan", "plan_scene", "run_scene", "SceneRun", "RunError", "CheckpointError",
           "PAPER_EXPONENTS",
           "clear_run_outputs", "RUN_FILES", "SCENE_FIGURES"]

#: The files of a scene run besides its figures (``charts.runs.scene_results``).
RUN_FILES = ("result.json", CHECKPOINT, "arrays.npz", SCENE_NETCDF)
#: Every figure a scene run can write (``charts.runs.scene_results``; a test keeps the two
#: lists in step).
SCENE_FIGURES = ("waveforms.png", "spectrum.png", "drift.png", "lyapunov.png", "angles.png",
                 "clv.png", "curvature.png")


def clear_run_outputs(outdir, lock) -> list:
    """Remove what earlier scene runs wrote into ``outdir``: the files its ``result.json``
    lists (plain names in the folder) and `RUN_FILES` and `SCENE_FIGURES`, ``result.json``
    last.  Only while ``lock`` (the folder's `OutputLock`) is held: RuntimeError otherwise.
    Returns the names removed."""
    outdir = Path(outdir)
    if not (lock.held and lock.path.parent == outdir):
        raise RuntimeError(f"clear_run_outputs: the lock of {outdir} is not held")
    names = set(RUN_FILES) | set(SCENE_FIGURES)
    try:
        listed = json.loads((outdir / "result.json").read_text()).get("files", [])
    except (OSError, ValueError, AttributeError):
        listed = []
    for name in listed if isinstance(listed, list) else []:
        if isinstance(name, str) and name == Path(name).name and name not in ("", ".", ".."):
            names.add(name)
    names.discard(lock.path.name)
    removed = []
    for name in sorted(names - {"result.json"}) + ["result.json"]:
        path = outdir / name
        if path.is_file() or path.is_symlink():
            path.unlink()
            removed.append(name)
    return removed


def run_scene(scene: Scene, outdir, *, resume: bool = False, quiet: bool = False,
              on_chunk=None, force: bool = False) -> dict:
    """Run ``scene`` into ``outdir``; return the result dict (also in result.json).

    ``on_chunk(index, n_chunks)`` is called after each checkpoint (tests use it to simulate
    Ctrl-C by raising KeyboardInterrupt).  An interrupt writes a partial result with
    status "interrupted" and re-raises ``KeyboardInterrupt``.  ``outdir`` is checked before
    any work (:func:`~charts.runs.outdir.prepare_output`) and locked while the run writes
    into it: a second run into the same folder refuses (:class:`~charts.runs.outdir.OutputLock`).
    ``force=True`` starts over: once the lock is held and the run is set up, the outputs of
    an earlier run there are removed (:func:`clear_run_outputs`; module doc).
    """
    instance("scene", scene, Scene, "charts.Scene (load_scene, parse_scene)")
    resume, quiet, force = flag("resume", resume), flag("quiet", quiet), flag("force", force)
    callback("on_chunk", on_chunk)
    if force and resume:
        raise RunError("force=True and resume=True exclude each other (force starts over)")
    outdir = prepare_output(outdir, "outdir")
    with OutputLock(outdir, f"charts run {scene.name}") as lock:
        run = SceneRun(scene, outdir, resume, force=force)
        if force:
            clear_run_outputs(outdir, lock)
        bar = run.progress_bar(quiet)
        say = None if quiet else (lambda line: bar.write(line, file=sys.stderr))
        status, failure = "complete", None
        try:
            with compile_timer(run.st.add_compile_time), \
                    compiling_said(run.compile_label(), run.st.system, say or _silent) as first:
                try:
                    run.run_chunks(run.engine(), bar, on_chunk,
                                   lambda: run.note_compile_time(say, first))
                finally:
                    run.note_compile_time(say, first, last=True)
        except (KeyboardInterrupt, RunError) as exc:
            status, failure = run.stop(exc)
        finally:
            bar.close()
        return run.finish(status, failure)


def _silent(line) -> None:
    """Where a quiet run's notices go."""


class _QuietBar:
    """The progress bar of a quiet run: nothing.  Not a disabled tqdm bar, which still
    creates tqdm's lock, a named multiprocessing semaphore, in the process: a quiet run on a
    sweep's worker that is then killed (an interrupted sweep) would leave it to Python's
    resource tracker, which reports "There appear to be 1 leaked semaphore objects" when the
    sweep exits."""

    def update(self, _):
        pass

    def close(self):
        pass


QUIET_BAR = _QuietBar()


class SceneRun:
    """One scene's run into its output folder (checked and locked by the caller): the run
    state, the chunk ends, the recorders and the checkpoint.  `run_scene` drives one;
    ``charts.runs.seed_lanes`` drives several in the lanes of one kernel."""

    def __init__(self, scene: Scene, outdir: Path, resume: bool, *, force: bool = False):
        self.scene, self.outdir = scene, outdir
        system = scene_kind(scene).system(scene)
        self.plan = plan = plan_scene(scene)
        self.st = st = RunState(scene, plan, system)
        self.ck = outdir / CHECKPOINT
        self.digest = scene_hash(scene)
        if resume:
            if not self.ck.exists():
                raise RunError(f"--resume: no checkpoint in {outdir} (nothing to resume; "
                               "run without --resume)")
            a = _checkpoint_of(self.ck)
            if "scene_hash" in a and str(a["scene_hash"]) != self.digest:
                raise RunError(f"--resume: the checkpoint in {outdir} belongs to a "
                               "different scene (the scene file changed); run without "
                               "--resume")
        elif not force and (self.ck.exists() or (outdir / "result.json").exists()):
            if _read_status(outdir) == "interrupted":
                raise RunError(f"{outdir} holds an interrupted run: continue it with --resume, "
                               "or choose another output folder")
        self.unit = scene.integrator["dt"] if plan.engine == "kernel" else scene.run["sample_dt"]
        self.transient = transient = ticks(scene.run["t_transient"], self.unit)
        self.ends = [e + transient for e in chunk_bounds(scene, plan)]
        if transient:
            self.ends = [transient] + self.ends
        self.recorders = make_recorders(st, transient)
        self.lyap_ends = set()
        if "lyapunov" in scene.effects:
            self.lyap_ends = {transient + e for e in lyapunov_batch_ends(scene, plan)}
        self.n_main = len(self.ends) if plan.main_pass else 0
        self.passes = plan.passes
        self.n_units = self.n_main + len(self.passes)
        st.n_main = self.n_main
        if resume:
            try:                        # checked against itself and this run, then trusted
                check_checkpoint(self.ck, a, self)
            except CheckpointError as exc:
                raise _resume_error(exc) from None
            st.load_arrays(a)
            progress = progress_of(st, self.ends, transient, self.unit)
            st.resumed_from = {key: progress[key] for key in ("t_done", "chunks_done")}
        #: the compiling already announced, and already seen (`note_compile_time`)
        self.compile_noted = self.compile_seen = 0.0

    def engine(self):
        """The engine of the main pass (``charts.runs.engines``)."""
        return KernelEngine(self.st) if self.plan.engine == "kernel" else IntegrateEngine(self.st)

    def progress_bar(self, quiet: bool):
        """A tqdm bar over the run's time units (main pass and separate passes); `QUIET_BAR`
        if ``quiet``."""
        if quiet:
            return QUIET_BAR
        from tqdm.auto import tqdm

        sc, plan = self.scene, self.plan
        t_total = (sc.run["t_transient"] + sc.run["t_final"]) * (1 if plan.main_pass else 0)
        t_total += plan.pass_steps() * sc.integrator["dt"] if self.passes else 0.0
        return tqdm(total=round(t_total, 10), unit="t", desc=sc.name, disable=quiet,
                    leave=False, initial=round(units_done(self.st, self.ends) * self.unit, 10))

    def chunk_start(self, idx: int) -> int:
        """The unit at which main chunk ``idx`` starts."""
        return self.ends[idx - 1] if idx else 0

    def recorders_of(self, idx: int):
        """The recorders that run in main chunk ``idx`` (none inside the transient)."""
        return self.recorders if self.ends[idx] > self.transient else []

    def end_main_chunk(self, idx: int) -> float:
        """After main chunk ``idx``: the transient does not count for the exponents; the
        Lyapunov batch marks.  Returns the time advanced."""
        st, end = self.st, self.ends[idx]
        if end == self.transient and st.flow is not None:
            end_transient(st.flow)
        if end in self.lyap_ends:
            st.lyap_marks.append((end - self.transient, st.logsum.copy()))
        return (end - self.chunk_start(idx)) * self.unit

    def checkpoint(self, idx: int, wall_s: float) -> None:
        """Chunk ``idx`` is done (``wall_s`` seconds): the whole state into checkpoint.npz."""
        st = self.st
        st.chunk_index = idx + 1
        st.elapsed += wall_s
        st.done = st.chunk_index == self.n_units
        arr = st.to_arrays()
        arr["scene_hash"] = np.array(self.digest)
        atomic_write(self.ck, npz_bytes(arr))

    def run_chunks(self, engine, bar, on_chunk=None, after=None) -> None:
        """The chunks from ``st.chunk_index`` on, a checkpoint after each (``engine`` runs the
        main pass; None if it is done); ``after()`` after each chunk (the compile notice)."""
        st = self.st
        for idx in range(st.chunk_index, self.n_units):
            t_wall = time.perf_counter()
            if idx < self.n_main:
                engine.run_chunk(self.chunk_start(idx), self.ends[idx], self.recorders_of(idx),
                                 self.transient)
                advanced = self.end_main_chunk(idx)
            else:
                name = self.passes[idx - self.n_main]
                (_angles_pass if name == "angles" else _clv_pass)(st)
                advanced = getattr(self.plan, name)["steps"] * self.scene.integrator["dt"]
            self.checkpoint(idx, time.perf_counter() - t_wall)
            if after is not None:
                after()
            bar.update(advanced)
            if on_chunk is not None:
                on_chunk(idx, self.n_units)

    def stop(self, exc):
        """An interrupt or a `RunError` stopped the run: roll back to the last checkpoint
        (the chunk in flight is discarded).  Returns (status, failure message or None)."""
        status = "interrupted" if isinstance(exc, KeyboardInterrupt) else "failed"
        failure = None if status == "interrupted" else str(exc)
        if self.st.chunk_index and self.ck.exists():
            with np.load(self.ck) as a:
                self.st.load_arrays(a)
        else:
            compile_s = self.st.compile_s
            self.st = RunState(self.scene, self.plan, self.st.system)
            self.st.compile_s = compile_s
        self.st.n_main = self.n_main
        return status, failure

    def compile_label(self) -> str:
        """The run's name in its compile notices: the scene and its variant (formulation,
        method), as `integrate`'s notices name theirs."""
        variant = [str(self.scene.integrator[k]) for k in ("formulation", "method")
                   if self.scene.integrator.get(k)]
        return f"{self.scene.name} ({', '.join(variant)})" if variant else self.scene.name

    def note_compile_time(self, say, first, last=False) -> None:
        """After a chunk: once a chunk has compiled nothing (or after the ``last``), the
        compile notice (``say``; None: quiet) for the compiling of the chunks before it since
        the last notice, one notice for consecutive chunks that compiled, when it exceeds
        `NOTE_SECONDS`; ``first``: the listener of `compiling_said`, whose ``spent`` counts
        numba's compile events (the wall time spent compiling, the rest of the chunks not
        counted), re-armed after the notice, so that a later chunk's compiling says so too."""
        if first.spent > self.compile_seen and not last:      # this chunk compiled: wait
            self.compile_seen = first.spent
            return
        spent = first.spent - self.compile_noted
        if spent > NOTE_SECONDS:
            first.rearm()
            if say is not None:
                announce(self.compile_label(), spent, self.st.system, say=say)
        self.compile_noted = self.compile_seen = first.spent

    def finish(self, status: str, failure=None) -> dict:
        """The result (every output file written); raises KeyboardInterrupt (interrupted) or
        `RunError` (failed, the finished part written) after writing it.  An interrupt while
        the outputs are written leaves the checkpoint and an "interrupted" result.json
        (`interrupted_while_writing`)."""
        try:
            result = finalize(self.st, status, self.ends, self.transient, self.unit,
                              self.outdir)
        except KeyboardInterrupt:
            raise KeyboardInterrupt(self.interrupted_while_writing()) from None
        if status == "interrupted":
            raise KeyboardInterrupt(result)
        if status == "failed":
            result["error"] = failure
            write_result(self.outdir, result)
            raise RunError(f"{failure} (the finished part is in {self.outdir}/result.json)")
        return result


    def interrupted_while_writing(self) -> dict:
        """Ctrl-C while the outputs were written: the partly written outputs are removed (the
        checkpoint, already complete, stays) and result.json says "interrupted", with the
        progress and the command whose ``--resume`` writes them all."""
        for name in sorted((set(RUN_FILES) | set(SCENE_FIGURES)) - {CHECKPOINT}):
            path = self.outdir / name
            if path.is_file() or path.is_symlink():
                path.unlink()
        result = result_header(self.st, "interrupted", self.ends, self.transient, self.unit)
        result.update(files=["result.json", CHECKPOINT], resume=resume_command(self.st,
                                                                               self.outdir),
                      note="interrupted while the outputs were written; --resume writes them")
        write_result(self.outdir, result)
        return result


def _angles_pass(st: RunState):
    """The hyperbolicity test (section 4) of the scene's kind (`SceneKind.angles_pass`)."""
    scene_kind(st.scene).angles_pass(st)


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
            n_unstable=c["n_vectors"], t_transient=c["t_transient"],
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


def _checkpoint_of(path) -> dict:
    """The arrays of the checkpoint ``path`` for a resume; `CheckpointError` naming it, with
    the remedy, where it cannot be read."""
    try:
        return read_checkpoint(path)
    except CheckpointError as exc:
        raise _resume_error(exc) from None


def _resume_error(exc) -> CheckpointError:
    """The `CheckpointError` of ``charts run --resume``: ``exc``'s words and the remedy."""
    return CheckpointError(f"--resume: {exc}; its run cannot be continued: start it over "
                           "with --force (or choose another output folder)")


def _read_status(outdir):
    try:
        return json.loads((outdir / "result.json").read_text()).get("status")
    except (OSError, ValueError):
        return None
