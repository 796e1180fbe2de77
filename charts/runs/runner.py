"""Run a validated :class:`~charts.scene.Scene`: the smallest computation its effects need.

Plan.  :func:`plan_scene` decides, from the requested effects alone, what is integrated:

* the state — 2N ambient variables (eq 8) or 2(N−1) chart variables (eq 14);
* tangent vectors (eq 17) — none unless ``lyapunov`` or ``curvature`` is requested, then
  max(n_exponents, n_directions) forward vectors, shared by both;
* the angles pass (``charts.hyperbolicity``) — only for ``angles``: m forward vectors, then
  the backward adjoint pass (m vectors) along the trajectory re-integrated from sparse
  checkpoints; it runs as one unit after the main pass (which is skipped when nothing
  else needs it);
* the parallel-transport frame (eq 19) — only for the numerical curvature route, N−1
  vectors moved one step back and forth at each curvature sample;
* stored samples — only the window of the requested waveforms, the one rotor of the
  spectrum, the drift records, the curvature samples; nothing for Lyapunov alone.

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
"""
from __future__ import annotations

import hashlib
import io
import json
import math
import os
import platform
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .paper import PAPER_EXPONENTS
from .io import atomic_write, json_default as _json_default, npz_bytes as _npz_bytes, versions as _versions
from .scene import Scene, scene_to_dict
from ..geometry.system import RotorSystem

__all__ = ["Plan", "plan_scene", "run_scene", "RunError", "PAPER_EXPONENTS"]

CHECKPOINT = "checkpoint.npz"
#: Steps between the stored trajectory checkpoints of the angles pass (its memory bound:
#: one state per checkpoint; the backward pass re-integrates each segment from it).
ANGLES_CHECKPOINT_STEPS = 100


class RunError(RuntimeError):
    """A scene that validated but cannot run in this installation or output folder."""


# ------------------------------------------------------------------------------- plan
@dataclass
class Plan:
    """What a scene's effects require.  All counts are per run.

    engine : "kernel" (fused ambient RK4 of eqs 8 + 17, ``charts.lyapunov``) or
        "integrate" (``charts.integrate``: chart formulation or adaptive method).
    state_dim : int   number of integrated state variables.
    tangent_vectors : int   forward tangent vectors (eq 17), 0 if none needed.
    transport_vectors : int   frame vectors transported (eq 19) at curvature samples.
    adjoint_vectors : int   vectors of the backward adjoint pass (angles pass only).
    angles : dict   the angles pass (forward/adjoint vectors, steps, stored checkpoints and
        samples), empty when not requested.
    main_pass : bool   whether the chunked main pass runs (False for an angles-only scene).
    stored : dict   name -> number of stored samples (rows).
    steps : dict   name -> recording interval in integrator steps (kernel engine) or
        samples (integrate engine).
    """
    engine: str
    formulation: str
    method: str
    state_dim: int
    tangent_vectors: int = 0
    transport_vectors: int = 0
    adjoint_vectors: int = 0
    stored: dict = field(default_factory=dict)
    every: dict = field(default_factory=dict)
    needs_trajectory_store: bool = False
    angles: dict = field(default_factory=dict)
    main_pass: bool = True

    def as_dict(self):
        return {"engine": self.engine, "formulation": self.formulation, "method": self.method,
                "state_dimension": self.state_dim, "tangent_vectors": self.tangent_vectors,
                "transport_vectors": self.transport_vectors,
                "adjoint_vectors": self.adjoint_vectors,
                "stored_samples": dict(self.stored),
                "stored_trajectory": self.needs_trajectory_store,
                "main_pass": self.main_pass, "angles_pass": dict(self.angles)}


def _ticks(t, unit):
    return int(round(t / unit))


def plan_scene(scene: Scene) -> Plan:
    """The smallest computation serving ``scene.effects`` (no integration happens here)."""
    n = scene.system["n"]
    integ, run, eff = scene.integrator, scene.run, scene.effects
    ambient_rk4 = integ["formulation"] == "ambient" and integ["method"] == "rk4"
    engine = "kernel" if ambient_rk4 else "integrate"
    state_dim = 2 * n if integ["formulation"] == "ambient" else 2 * (n - 1)
    plan = Plan(engine, integ["formulation"], integ["method"], state_dim)
    # the recording grid: integrator steps for the kernel engine, samples otherwise
    unit = integ["dt"] if engine == "kernel" else run["sample_dt"]
    sdt = _ticks(run["sample_dt"], unit)
    n_samples = _ticks(run["t_final"], run["sample_dt"])
    if "waveforms" in eff:
        w = eff["waveforms"]
        plan.every["waveforms"] = sdt
        plan.stored["waveforms"] = _ticks(w["t_window"], run["sample_dt"])
    if "spectrum" in eff:
        plan.every["spectrum"] = sdt
        plan.stored["spectrum"] = n_samples
    if "drift" in eff:
        plan.every["drift"] = _ticks(eff["drift"]["sample_every"], unit)
        plan.stored["drift"] = _ticks(run["t_final"], eff["drift"]["sample_every"])
    k = 0
    if "lyapunov" in eff:
        k = max(k, eff["lyapunov"]["n_exponents"])
    if "curvature" in eff:
        c = eff["curvature"]
        k = max(k, c["n_directions"])
        plan.every["curvature"] = _ticks(c["sample_every"], unit)
        plan.stored["curvature"] = _ticks(run["t_final"], c["sample_every"])
        if c["route"] in ("numerical", "both"):
            plan.transport_vectors = c["n_directions"] + 1
    if "angles" in eff:
        a = eff["angles"]
        dt = integ["dt"]
        m = a["n_vectors"]
        n_tr = _ticks(run["t_transient"], dt)
        ce = ANGLES_CHECKPOINT_STEPS
        nseg = -(-(2 * n_tr + _ticks(run["t_final"], dt)) // ce)
        plan.adjoint_vectors = m
        plan.needs_trajectory_store = True
        plan.angles = {"forward_vectors": m, "adjoint_vectors": m, "steps": nseg * ce,
                       "rhs_evaluations": 2 * 4 * nseg * ce,
                       "stored_trajectory_checkpoints": nseg + 1,
                       "stored_samples": _ticks(run["t_final"], a["sample_every"])}
    plan.tangent_vectors = k
    plan.main_pass = any(e != "angles" for e in eff)
    return plan


# ------------------------------------------------------------------------------- I/O
def _scene_hash(scene: Scene) -> str:
    blob = json.dumps(scene_to_dict(scene), sort_keys=True).encode()
    return hashlib.sha256(blob).hexdigest()[:16]


# ------------------------------------------------------------------------------- state
class _RunState:
    """Everything a run accumulates; saved whole in the checkpoint."""

    def __init__(self, scene: Scene, plan: Plan, system: RotorSystem):
        self.scene, self.plan, self.system = scene, plan, system
        n = system.n
        if scene.initial["theta"] is not None:
            theta, u = np.array(scene.initial["theta"]), np.array(scene.initial["u"])
        else:
            theta, u = system.random_state(seed=scene.initial["seed"],
                                           speed=scene.system["speed"])
        self.y0 = np.concatenate([theta, u])
        self.y = self.y0.copy()
        self.speed = float(system.speed(u))
        self.X = self._initial_vectors(plan.tangent_vectors)
        self.logsum = np.zeros(plan.tangent_vectors)
        self.lyap_marks = []           # (tick, logsum) at Lyapunov batch boundaries
        self.rhs = 0                   # evaluations of the (augmented) vector field
        self.rhs_frame = 0             # extra evaluations for the curvature frame steps
        self.steps = 0                 # accepted integrator steps
        self.chart = -1                # chart in use (chart formulation), -1: not yet chosen
        self.rec = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature_num",
                                          "curvature_exact", "curvature_y", "switches", "angles",
                                          "angles_exponents")}
        self.rec_t = {name: [] for name in ("waveforms", "spectrum", "drift", "curvature")}
        self.elapsed = 0.0
        self.done = False
        self.chunk_index = 0

    def _initial_vectors(self, k):
        n = self.system.n
        if k == 0:
            return np.empty((0, 2 * n))
        from ..analyses.lyapunov import _initial_vectors, inner_weights
        inner = self.scene.effects.get("lyapunov", {}).get("inner_product", "theta")
        return _initial_vectors(self.system, self.y, k, self.scene.initial["seed"] or 0, True,
                                inner_weights(self.system, inner))

    # -- checkpoint ------------------------------------------------------------------------
    def to_arrays(self) -> dict:
        a = {"y": self.y, "X": self.X, "logsum": self.logsum,
             "scalars": np.array([self.rhs, self.rhs_frame, self.chunk_index,
                                  self.elapsed, float(self.done), self.steps, self.chart]),
             "lyap_ticks": np.array([m[0] for m in self.lyap_marks], dtype=np.int64),
             "lyap_logsums": np.array([m[1] for m in self.lyap_marks]).reshape(
                 len(self.lyap_marks), self.plan.tangent_vectors)}
        for name, rows in self.rec.items():
            a["rec_" + name] = np.array(rows, dtype=float)
        for name, rows in self.rec_t.items():
            a["rect_" + name] = np.array(rows, dtype=float)
        return a

    def load_arrays(self, a):
        self.y, self.X, self.logsum = a["y"].copy(), a["X"].copy(), a["logsum"].copy()
        rhs, rhs_frame, chunk, elapsed, done, steps, chart = a["scalars"]
        self.steps, self.chart = int(steps), int(chart)
        self.rhs, self.rhs_frame = int(rhs), int(rhs_frame)
        self.chunk_index, self.elapsed, self.done = int(chunk), float(elapsed), bool(done)
        self.lyap_marks = [(int(t), l.copy()) for t, l in zip(a["lyap_ticks"], a["lyap_logsums"])]
        for name in self.rec:
            self.rec[name] = list(a["rec_" + name])
        for name in self.rec_t:
            self.rec_t[name] = list(a["rect_" + name])


# ------------------------------------------------------------------------------- engines
def _chunk_bounds(scene: Scene, plan: Plan) -> list[int]:
    """Chunk ends in units (steps for the kernel engine, samples otherwise) after the
    transient: every checkpoint_every, plus the Lyapunov batch boundaries."""
    run = scene.run
    unit = scene.integrator["dt"] if plan.engine == "kernel" else run["sample_dt"]
    total = _ticks(run["t_final"], unit)
    every = _ticks(run["checkpoint_every"], unit)
    ends = set(range(every, total, every)) | {total}
    if "lyapunov" in scene.effects:
        nb = scene.effects["lyapunov"]["n_batches"]
        ends |= {int(round(total * (b + 1) / nb)) for b in range(nb)}
    return sorted(e for e in ends if 0 < e <= total)


def _record_interval(plan: Plan) -> int:
    """The stepping unit of the kernel engine: gcd of every recording interval."""
    g = 0
    for v in plan.every.values():
        g = math.gcd(g, v)
    return g


class _KernelEngine:
    """Ambient RK4 of eq (8) with k tangent vectors (eq 17) re-orthonormalised every step
    (eq 18), via ``charts.lyapunov.advance_tangent``; k = 0 integrates the state alone."""

    def __init__(self, st: _RunState):
        from ..analyses.lyapunov import advance_tangent

        self.st = st
        self.adv = advance_tangent
        sc = st.scene
        self.dt = sc.integrator["dt"]
        self.inner = sc.effects.get("lyapunov", {}).get("inner_product", "theta")
        self.project_every = 1 if sc.integrator["project"] else 1 << 40
        self.step_unit = _record_interval(st.plan) or None

    def advance(self, nsteps: int):
        st = self.st
        st.logsum = self.adv(st.system, st.y, st.X, nsteps * self.dt, dt=self.dt, inner=self.inner,
                             space="restricted", reorth_every=1,
                             project_every=self.project_every, logsum=st.logsum)
        st.rhs += 4 * nsteps
        st.steps += nsteps
        if not (np.all(np.isfinite(st.y)) and np.all(np.isfinite(st.X)) and np.all(np.isfinite(st.logsum))):
            raise RunError(f"the state became non-finite within {nsteps} steps before step {st.steps}: "
                           "the trajectory came too close to a singular point of the manifold "
                           "(all sin θ ≈ 0) and left the constraint; set [integrator] project = true "
                           "or a smaller dt")

    def run_chunk(self, start: int, end: int, recorders, origin: int = 0):
        """Advance from unit ``start`` to ``end``, stopping at every multiple of the
        recording unit counted from ``origin`` (the end of the transient) to record."""
        unit = self.step_unit if (self.step_unit and recorders) else (end - start)
        pos = start
        while pos < end:
            nxt = min(end, origin + ((pos - origin) // unit + 1) * unit)
            self.advance(nxt - pos)
            pos = nxt
            for rec in recorders:
                rec(pos)


class _IntegrateEngine:
    """``charts.integrate`` (issue 3) for the chart formulation and adaptive methods,
    called once per chunk with output at the sample times of that chunk.  The chart in use
    at the end of a chunk is the one the next chunk starts in (no spurious switch)."""

    def __init__(self, st: _RunState):
        from ..solvers.integrate import integrate

        self.st = st
        self.integrate = integrate
        self.sdt = st.scene.run["sample_dt"]

    def run_chunk(self, start: int, end: int, recorders, origin: int = 0):
        from ..solvers.integrate import IntegrationError

        st, sc = self.st, self.st.scene
        n = st.system.n
        integ = sc.integrator
        m = end - start
        kw = dict(formulation=integ["formulation"], method=integ["method"],
                  project=integ["project"], t_eval=np.arange(1, m + 1) * self.sdt)
        if integ["method"] == "rk4":
            kw["dt"] = integ["dt"]
        else:
            kw.update(rtol=integ["rtol"], atol=integ["atol"])
        if integ["formulation"] == "chart" and st.chart >= 0:
            kw["chart"] = st.chart
        t_start = start * self.sdt
        try:
            res = self.integrate(st.system, st.y[:n], st.y[n:], m * self.sdt, **kw)
        except IntegrationError as exc:
            raise RunError(f"the integration failed in the chunk starting at t = {t_start:g} "
                           f"(the times below count from that chunk's start): {exc}") from None
        except ValueError as exc:  # e.g. the state reached a singular point exactly
            raise RunError(f"the integration could not continue at t = {t_start:g}: {exc}") from None
        st.rhs += int(res.n_rhs)
        st.steps += int(res.n_steps)
        for t_sw, a, b in res.switches:
            st.rec["switches"].append([t_start + float(t_sw), float(a), float(b)])
            st.chart = int(b)
        for i in range(m):
            st.y = np.concatenate([res.theta[i], res.u[i]])
            for rec in recorders:
                rec(start + i + 1)


# ------------------------------------------------------------------------------- recorders
def _make_recorders(st: _RunState, transient_units: int):
    """Functions called with the absolute unit position after each advance."""
    sc, plan = st.scene, st.plan
    n = st.system.n
    eff = sc.effects
    unit = sc.integrator["dt"] if plan.engine == "kernel" else sc.run["sample_dt"]
    recs = []

    def rel(pos):
        return pos - transient_units

    if "waveforms" in eff:
        rotors = np.array(eff["waveforms"]["rotors"])
        every, limit = plan.every["waveforms"], plan.stored["waveforms"]

        def rec_wave(pos, every=every, limit=limit, rotors=rotors):
            r = rel(pos)
            if r > 0 and r % every == 0 and r // every <= limit:
                st.rec_t["waveforms"].append(r * unit)
                st.rec["waveforms"].append(st.y[n + rotors])
        recs.append(rec_wave)
    if "spectrum" in eff:
        rot, every = eff["spectrum"]["rotor"], plan.every["spectrum"]

        def rec_spec(pos, every=every, rot=rot):
            r = rel(pos)
            if r > 0 and r % every == 0:
                st.rec["spectrum"].append(st.y[n + rot])
        recs.append(rec_spec)
    if "drift" in eff:
        every = plan.every["drift"]

        def rec_drift(pos, every=every):
            r = rel(pos)
            if r > 0 and r % every == 0:
                st.rec_t["drift"].append(r * unit)
                st.rec["drift"].append(_invariants(st))
        recs.append(rec_drift)
    if "curvature" in eff:
        c = eff["curvature"]
        every, kdir = plan.every["curvature"], c["n_directions"]
        routes = c["route"]

        def rec_curv(pos, every=every, kdir=kdir, routes=routes):
            r = rel(pos)
            if r > 0 and r % every == 0:
                Kn, Ke = _curvature_sample(st, kdir, routes)
                st.rec_t["curvature"].append(r * unit)
                st.rec["curvature_y"].append(st.y.copy())
                if Kn is not None:
                    st.rec["curvature_num"].append(np.diagonal(Kn).copy())
                if Ke is not None:
                    st.rec["curvature_exact"].append(np.diagonal(Ke).copy())
        recs.append(rec_curv)
    return recs


def _invariants(st: _RunState):
    n = st.system.n
    theta, u = st.y[:n], st.y[n:]
    E0 = 0.5 * st.speed ** 2
    return [float(np.cos(theta).sum()), float(u @ np.sin(theta)),
            float(st.system.energy(u) / E0 - 1.0)]


def _curvature_sample(st: _RunState, kdir: int, routes: str):
    """K matrices (route a numerical, route b exact) at the current point, in the frame of
    the velocity and the θ-parts of the first ``kdir`` Lyapunov vectors (eqs 19–21)."""
    from ..analyses.curvature import _frame, _rk4_frame_step, exact_curvature_matrix

    sys_, y = st.system, st.y
    n = sys_.n
    Xj = np.empty((kdir, 2 * n))
    P = np.empty((kdir + 1, n))
    uu = _frame(y, np.ascontiguousarray(st.X[:kdir]), sys_.minv, sys_.masses, Xj, P)
    Kn = Ke = None
    if routes in ("numerical", "both"):
        dt = st.scene.integrator["dt"]
        cs = np.zeros((kdir, kdir))
        for sign in (1.0, -1.0):
            y2, X2, P2 = y.copy(), Xj.copy(), P.copy()
            _rk4_frame_step(y2, X2, P2, sys_.minv, sign * dt)
            cs += (P2[1:] * sys_.masses) @ X2[:, :n].T
        Kn = -(cs - 2.0 * np.eye(kdir)) / (dt * dt * uu)
        st.rhs_frame += 8
    if routes in ("exact", "both"):
        Ke = exact_curvature_matrix(sys_, y[:n], P)
    return Kn, Ke


# ------------------------------------------------------------------------------- run
def run_scene(scene: Scene, outdir, *, resume: bool = False, quiet: bool = False,
              on_chunk=None) -> dict:
    """Run ``scene`` into ``outdir``; return the result dict (also in result.json).

    ``on_chunk(index, n_chunks)`` is called after each checkpoint (tests use it to simulate
    Ctrl-C by raising KeyboardInterrupt).  An interrupt writes a partial result with
    status "interrupted" and re-raises ``KeyboardInterrupt``.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    system = RotorSystem(scene.system["n"], scene.system["masses"])
    plan = plan_scene(scene)
    st = _RunState(scene, plan, system)
    ck = outdir / CHECKPOINT
    digest = _scene_hash(scene)
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
    engine = _KernelEngine(st) if plan.engine == "kernel" else _IntegrateEngine(st)
    unit = scene.integrator["dt"] if plan.engine == "kernel" else scene.run["sample_dt"]
    transient = _ticks(scene.run["t_transient"], unit)
    ends = [e + transient for e in _chunk_bounds(scene, plan)]
    if transient:
        ends = [transient] + ends
    recorders = _make_recorders(st, transient)
    lyap_ends = set()
    if "lyapunov" in scene.effects:
        total = ends[-1] - transient
        nb = scene.effects["lyapunov"]["n_batches"]
        lyap_ends = {transient + int(round(total * (b + 1) / nb)) for b in range(nb)}

    n_main = len(ends) if plan.main_pass else 0
    n_units = n_main + (1 if plan.angles else 0)
    st.n_main = n_main

    from tqdm.auto import tqdm
    t_total = (scene.run["t_transient"] + scene.run["t_final"]) * (1 if plan.main_pass else 0)
    if plan.angles:
        t_total += plan.angles["steps"] * scene.integrator["dt"]
    bar = tqdm(total=round(t_total, 10), unit="t", desc=scene.name, disable=quiet,
               leave=False, initial=round(_pos_of(st, ends) * unit, 10))
    status = "complete"
    try:
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
                _angles_pass(st)
                advanced = plan.angles["steps"] * scene.integrator["dt"]
            st.chunk_index = idx + 1
            st.elapsed += time.perf_counter() - t_wall
            st.done = st.chunk_index == n_units
            arr = st.to_arrays()
            arr["scene_hash"] = np.array(digest)
            atomic_write(ck, _npz_bytes(arr))
            bar.update(advanced)
            if on_chunk is not None:
                on_chunk(idx, n_units)
    except (KeyboardInterrupt, RunError) as exc:
        status = "interrupted" if isinstance(exc, KeyboardInterrupt) else "failed"
        failure = None if status == "interrupted" else str(exc)
        # roll back to the last checkpoint: the chunk in flight is discarded
        if st.chunk_index and ck.exists():
            with np.load(ck) as a:
                st.load_arrays(a)
        else:
            st = _RunState(scene, plan, system)
        st.n_main = n_main
    finally:
        bar.close()
    result = _finalize(st, status, ends, transient, unit, outdir)
    if status == "interrupted":
        raise KeyboardInterrupt(result)
    if status == "failed":
        result["error"] = failure
        atomic_write(outdir / "result.json",
                     json.dumps(result, indent=2, default=_json_default).encode())
        raise RunError(f"{failure} (the finished part is in {outdir}/result.json)")
    return result


def _pos_of(st, ends):
    """Units of the main pass done."""
    k = min(st.chunk_index, getattr(st, "n_main", len(ends)))
    return ends[k - 1] if k else 0


def _angles_pass(st: _RunState):
    """The hyperbolicity test (section 4) from the initial state: forward tangent vectors,
    backward adjoint vectors along the re-integrated trajectory (``charts.hyperbolicity``)."""
    from ..analyses.hyperbolicity import hyperbolicity_angles

    sc, sys_ = st.scene, st.system
    a = sc.effects["angles"]
    dt = sc.integrator["dt"]
    n = sys_.n
    res = hyperbolicity_angles(sys_, st.y0[:n], st.y0[n:], sc.run["t_final"], dt=dt,
                               n_unstable=a["n_vectors"], t_transient=sc.run["t_transient"],
                               sample_every=_ticks(a["sample_every"], dt),
                               checkpoint_every=ANGLES_CHECKPOINT_STEPS,
                               seed=sc.initial["seed"] or 0)
    st.rec["angles"] = [list(r) for r in np.column_stack([res.t, res.phi_full,
                                                          res.phi_restricted])]
    st.rec["angles_exponents"] = [list(res.forward_exponents), list(res.adjoint_exponents)]
    st.rhs += st.plan.angles["rhs_evaluations"]
    st.steps += 2 * st.plan.angles["steps"]


def _read_status(outdir):
    try:
        return json.loads((outdir / "result.json").read_text()).get("status")
    except (OSError, ValueError):
        return None


# ------------------------------------------------------------------------------- results
def _finalize(st: _RunState, status, ends, transient, unit, outdir: Path) -> dict:
    sc, plan, system = st.scene, st.plan, st.system
    n = system.n
    eff = sc.effects
    pos = _pos_of(st, ends)
    t_done = max(0, pos - transient) * unit
    angles_done = bool(st.rec["angles"])
    if not plan.main_pass:
        t_done = sc.run["t_final"] if angles_done else 0.0
    arrays, results, figures = {}, {}, {}
    stored = {}
    if "waveforms" in eff:
        t = np.array(st.rec_t["waveforms"])
        U = np.array(st.rec["waveforms"]).reshape(len(t), len(eff["waveforms"]["rotors"]))
        arrays.update(waveforms_t=t + sc.run["t_transient"], waveforms_u=U)
        stored["waveforms"] = (len(t), int(U.size))
        results["waveforms"] = {"rotors": eff["waveforms"]["rotors"], "samples": len(t),
                                "rms": np.sqrt((U ** 2).mean(axis=0)).tolist() if len(t) else []}
        if len(t):
            figures["waveforms.png"] = _fig_waveforms(sc, arrays["waveforms_t"], U)
    if "spectrum" in eff:
        x = np.array(st.rec["spectrum"])
        stored["spectrum"] = (int(x.size), int(x.size))
        nper = eff["spectrum"]["nperseg"]
        res = {"rotor": eff["spectrum"]["rotor"], "samples": int(x.size)}
        if x.size >= nper:
            from scipy.signal import welch
            f, p = welch(x, fs=1.0 / sc.run["sample_dt"], nperseg=nper)
            arrays.update(spectrum_f=f, spectrum_psd=p)
            res.update(segments=int(2 * x.size // nper - 1), peak_frequency=float(f[np.argmax(p)]),
                       variance=float(x.var()))
            figures["spectrum.png"] = _fig_spectrum(sc, f, p)
        else:
            res["note"] = f"only {x.size} samples so far (< nperseg = {nper}): no spectrum yet"
        results["spectrum"] = res
    if "drift" in eff:
        t = np.array(st.rec_t["drift"])
        D = np.array(st.rec["drift"]).reshape(len(t), 3)
        arrays.update(drift_t=t + sc.run["t_transient"], drift_constraint=D[:, 0],
                      drift_tangency=D[:, 1], drift_energy=D[:, 2])
        stored["drift"] = (len(t), int(D.size))
        if len(t):
            figures["drift.png"] = _fig_drift(sc, arrays["drift_t"], D)
    if "lyapunov" in eff:
        results["lyapunov"] = _lyapunov_result(st, t_done, arrays)
        if "lyapunov_history_t" in arrays:
            figures["lyapunov.png"] = _fig_lyapunov(sc, arrays, results["lyapunov"])
    if "curvature" in eff:
        results["curvature"], curv_arrays = _curvature_result(st)
        arrays.update(curv_arrays)
        stored["curvature"] = (len(st.rec_t["curvature"]),
                                int(sum(v.size for v in curv_arrays.values())))
        if len(st.rec_t["curvature"]):
            figures["curvature.png"] = _fig_curvature(sc, curv_arrays)
    if "angles" in eff:
        results["angles"], ang_arrays = _angles_result(st)
        arrays.update(ang_arrays)
        if angles_done:
            stored["angles"] = (len(ang_arrays["angles_t"]),
                                int(sum(v.size for v in ang_arrays.values())))
            figures["angles.png"] = _fig_angles(sc, ang_arrays)
    if "switches" in eff:
        S = np.array(st.rec["switches"]).reshape(-1, 3)
        arrays["switches"] = S
        results["switches"] = {"count": len(S),
                               "rate": len(S) / t_done if t_done else None}
    theta, u = st.y[:n], st.y[n:]
    inv = _invariants(st)
    drift = {"constraint": inv[0], "tangency": inv[1], "energy_relative": inv[2]}
    if "drift" in eff and stored.get("drift", (0,))[0]:
        D = np.array(st.rec["drift"])
        drift.update(max_abs_constraint=float(np.abs(D[:, 0]).max()),
                     max_abs_tangency=float(np.abs(D[:, 1]).max()),
                     max_abs_energy_relative=float(np.abs(D[:, 2]).max()))
    comp = plan.as_dict()
    comp["stored_samples"] = {k: v[0] for k, v in stored.items()}
    comp["stored_values"] = int(sum(v[1] for v in stored.values()))
    comp["rhs_evaluations"] = st.rhs
    comp["steps"] = st.steps
    comp["frame_rhs_evaluations"] = st.rhs_frame
    comp["tangent_vector_evaluations"] = st.rhs * plan.tangent_vectors
    files = ["result.json", CHECKPOINT] + (["arrays.npz"] if arrays else []) + sorted(figures)
    result = {
        "status": status,
        "scene": scene_to_dict(sc),
        "source": sc.source,
        "versions": _versions(),
        "progress": {"t_done": t_done, "t_final": sc.run["t_final"],
                     "t_transient": sc.run["t_transient"],
                     "chunks_done": st.chunk_index, "chunks": len(ends)},
        "timings": {"integration_wall_s": round(st.elapsed, 4)},
        "computation": comp,
        "initial_state": {"theta": st.y0[:n].tolist(), "u": st.y0[n:].tolist()},
        "final_state": {"theta": theta.tolist(), "u": u.tolist()},
        "drift": drift,
        "results": results,
        "files": files,
    }
    if status == "interrupted":
        result["resume"] = f"charts run {sc.source} -o {outdir} --resume"
    t0 = time.perf_counter()
    for name, png in figures.items():
        atomic_write(outdir / name, png)
    if arrays:
        atomic_write(outdir / "arrays.npz", _npz_bytes(arrays))
    result["timings"]["output_wall_s"] = round(time.perf_counter() - t0, 4)
    atomic_write(outdir / "result.json",
                 json.dumps(result, indent=2, default=_json_default).encode())
    return result


def _lyapunov_result(st, t_done, arrays):
    ly = st.scene.effects["lyapunov"]
    n = st.system.n
    res = {"n_exponents": ly["n_exponents"], "inner_product": ly["inner_product"],
           "t_averaged": t_done}
    marks = st.lyap_marks
    if not marks:
        res["note"] = "no Lyapunov batch finished yet"
        return res
    ticks = np.array([m[0] for m in marks], dtype=float)
    L = np.array([m[1] for m in marks])[:, : ly["n_exponents"]]
    unit = st.scene.integrator["dt"]
    T = ticks * unit
    exps = L[-1] / T[-1]
    res["exponents"] = exps.tolist()
    if len(marks) >= 2:
        prev = np.vstack([np.zeros((1, L.shape[1])), L[:-1]])
        Tp = np.concatenate([[0.0], T[:-1]])
        batches = (L - prev) / (T - Tp)[:, None]
        res["stderr"] = (batches.std(axis=0, ddof=1) / np.sqrt(len(batches))).tolist()
        res["batches"] = len(batches)
    equal = np.allclose(st.system.masses, 1.0)
    if n in PAPER_EXPONENTS and equal:
        paper = np.array(PAPER_EXPONENTS[n]) * st.speed
        res["paper"] = [round(float(p), 12) for p in paper[: ly["n_exponents"]]]
        res["paper_note"] = "section 2, unit speed, equal masses; scaled by the speed"
    arrays.update(lyapunov_history_t=T, lyapunov_history=L / T[:, None])
    return res


def _angles_result(st):
    from ..analyses.hyperbolicity import SMALL_ANGLE, angle_statistics

    a = st.scene.effects["angles"]
    res = {"variant": a["variant"], "n_vectors": a["n_vectors"]}
    if not st.rec["angles"]:
        res["note"] = "the angles pass has not run yet"
        return res, {}
    A = np.array(st.rec["angles"])
    arr = {"angles_t": A[:, 0]}
    for j, variant in ((1, "full"), (2, "restricted")):
        if a["variant"] in (variant, "both"):
            arr[f"angles_{variant}"] = A[:, j]
            res[variant] = angle_statistics(A[:, j], SMALL_ANGLE)
    fwd, adj = st.rec["angles_exponents"]
    res["forward_exponents"] = list(fwd)
    res["adjoint_exponents"] = list(adj)
    return res, arr


def _curvature_result(st):
    c = st.scene.effects["curvature"]
    n = st.system.n
    t = np.array(st.rec_t["curvature"])
    arr = {"curvature_t": t + st.scene.run["t_transient"]}
    res = {"route": c["route"], "samples": len(t)}
    for route, key in (("numerical", "curvature_num"), ("exact", "curvature_exact")):
        if c["route"] in (route, "both"):
            K = np.array(st.rec[key]).reshape(len(t), c["n_directions"])
            arr[f"curvature_{route}"] = K
            if len(t):
                res[route] = {"mean": K.mean(axis=0).tolist(), "min": K.min(axis=0).tolist(),
                              "max": K.max(axis=0).tolist(),
                              "fraction_positive": (K > 0).mean(axis=0).tolist()}
    if c["route"] == "both" and len(t):
        res["max_abs_route_difference"] = float(np.abs(arr["curvature_numerical"]
                                                       - arr["curvature_exact"]).max())
    if n == 3 and np.allclose(st.system.masses, 1.0) and len(t):
        from ..analyses.curvature import gaussian_curvature_eq22
        Y = np.array(st.rec["curvature_y"])
        K22 = gaussian_curvature_eq22(Y[:, :3])
        arr["curvature_eq22"] = K22
        for route in ("numerical", "exact"):
            if f"curvature_{route}" in arr:
                err = np.abs(arr[f"curvature_{route}"][:, 0] - K22)
                # relative errors blow up near the zero-curvature points: report both
                res[route]["max_abs_error_vs_eq22"] = float(err.max())
                res[route]["median_rel_error_vs_eq22"] = float(np.median(err / np.abs(K22)))
    return res, arr


# ------------------------------------------------------------------------------- figures
def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    return buf.getvalue()


def _subplots(nrows=1, ncols=1, **kw):
    """pyplot-free figure (no global state, no GUI backend): matplotlib.figure.Figure."""
    from matplotlib.figure import Figure
    fig = Figure(figsize=kw.pop("figsize", (6, 3.5)))
    axes = fig.subplots(nrows, ncols, **kw)
    return fig, axes


def _fig_waveforms(sc, t, U):
    rotors = sc.effects["waveforms"]["rotors"]
    fig, axes = _subplots(len(rotors), 1, figsize=(8, 1.4 * len(rotors) + 0.6), sharex=True,
                             squeeze=False)
    for ax, r, col in zip(axes[:, 0], rotors, U.T):
        ax.plot(t, col, lw=0.7)
        ax.set_ylabel(f"$u_{{{r}}}$")
    axes[-1, 0].set_xlabel("t")
    axes[0, 0].set_title(f"{sc.name}: angular velocities, N = {sc.system['n']}")
    return _png(fig)


def _fig_spectrum(sc, f, p):
    fig, ax = _subplots(figsize=(6, 3.5))
    ax.semilogy(f[1:], p[1:], lw=0.8)
    ax.set_xlabel("frequency")
    ax.set_ylabel("spectral density")
    ax.set_title(f"{sc.name}: Welch spectrum of u_{sc.effects['spectrum']['rotor']}, "
                 f"N = {sc.system['n']}")
    return _png(fig)


def _fig_drift(sc, t, D):
    fig, ax = _subplots(figsize=(6, 3.5))
    for col, lab in zip(D.T, ("Σ cos θ", "Σ u sin θ", "ΔE/E")):
        ax.semilogy(t, np.abs(col) + 1e-300, lw=0.8, label=lab)
    ax.set_xlabel("t")
    ax.set_ylabel("|invariant drift|")
    ax.legend()
    ax.set_title(f"{sc.name}: invariants")
    return _png(fig)


def _fig_lyapunov(sc, arrays, res):
    fig, ax = _subplots(figsize=(6, 3.5))
    T, H = arrays["lyapunov_history_t"], arrays["lyapunov_history"]
    for i, col in enumerate(H.T):
        ax.plot(T, col, marker="o", ms=3, label=f"λ{i + 1}")
    for p in res.get("paper", []):
        ax.axhline(p, color="k", lw=0.5, ls=":")
    ax.set_xlabel("averaging time")
    ax.set_ylabel("running estimate")
    ax.legend()
    ax.set_title(f"{sc.name}: Lyapunov exponents (dotted: paper)")
    return _png(fig)


def _fig_angles(sc, arr):
    variants = [v for v in ("full", "restricted") if f"angles_{v}" in arr]
    fig, axes = _subplots(1, len(variants), figsize=(4.5 * len(variants), 3.2), squeeze=False)
    for ax, v in zip(axes[0], variants):
        ax.hist(arr[f"angles_{v}"], bins=60, range=(0, np.pi / 2), density=True)
        ax.set_xlabel("φ (rad)")
        ax.set_title(f"{v} tangent space")
    fig.suptitle(f"{sc.name}: angles between E_u and E_cs, N = {sc.system['n']}")
    return _png(fig)


def _fig_curvature(sc, arr):
    routes = [r for r in ("numerical", "exact") if f"curvature_{r}" in arr]
    k = arr[f"curvature_{routes[0]}"].shape[1]
    fig, axes = _subplots(1, k, figsize=(4 * k, 3.2), squeeze=False)
    for i in range(k):
        ax = axes[0, i]
        for r in routes:   # the routes agree closely: dashed over solid keeps both visible
            ax.hist(arr[f"curvature_{r}"][:, i], bins=60, histtype="step", density=True, label=r,
                    ls="--" if r == "numerical" else "-", lw=1.6 if r == "exact" else 1.0)
        ax.set_xlabel(f"$K_{{{i + 1}{i + 1}}}$")
        ax.legend()
    fig.suptitle(f"{sc.name}: sectional curvatures, N = {sc.system['n']}")
    return _png(fig)
