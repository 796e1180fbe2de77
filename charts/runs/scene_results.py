"""The results of a scene run, from its :class:`~charts.runs.run_state.RunState`, complete or
partial: ``result.json`` (status, scene, versions, progress, timings, computation, states,
drift, the per-effect results), ``arrays.npz`` and the figures, each written atomically."""
from __future__ import annotations

import json
import shlex
import time
from pathlib import Path

import numpy as np

from ..analyses.lyapunov import exponents_from_marks
from ..analyses.spectrum_quantities import leading_entropy_with_error

from ..analyses.curvature import gaussian_curvature_eq22
from ..analyses.angle_tally import SMALL_ANGLE
from ..analyses.hyperbolicity import angle_statistics
from ..analyses.spectra import power_spectrum
from ..io.archive import require_xarray
from ..geometry.energy_shares import LOCALISED_SHARE, localised_fraction
from . import scene_figures as figs
from .netcdf_results import SCENE_NETCDF, SceneResult
from .io import atomic_write, json_default, npz_bytes, versions
from .run_state import CHECKPOINT, RunState, units_done
from .scene import positive_exponents, scene_to_dict
from .scene_kind import scene_kind

__all__ = ["finalize", "progress_of", "result_header", "resume_command", "write_result", "waveforms_result", "spectrum_result", "drift_result",
           "lyapunov_result", "curvature_result", "angles_result", "clv_result",
           "switches_result", "FTLE_STATS"]

#: the finite-time exponent statistics of a CLV pass, in the order of its record rows.
FTLE_STATS = ("mean", "std", "p01", "p50", "p99")


class _Outputs:
    """What the result builders collect: arrays (arrays.npz), scalar results
    (result.json), PNG bytes by file name, and the stored (rows, values) per effect."""

    def __init__(self):
        self.arrays, self.results, self.figures, self.stored = {}, {}, {}, {}


def write_result(outdir: Path, result: dict) -> None:
    """``result.json``, atomically."""
    atomic_write(outdir / "result.json", json.dumps(result, indent=2, default=json_default).encode())


def progress_of(st: RunState, ends, transient, unit) -> dict:
    """The run's progress: simulated time done after the transient (``t_done``), its
    ``t_final`` and ``t_transient``, chunks done and in all; with ``resumed_from`` (the
    ``t_done`` and ``chunks_done`` of the checkpoint it continued) where it resumed."""
    sc, plan = st.scene, st.plan
    t_done = max(0, units_done(st, ends) - transient) * unit
    if not plan.main_pass:    # the separate passes only: done when the last one has run
        t_done = sc.run["t_final"] if st.chunk_index == len(plan.passes) else 0.0
    out = {"t_done": t_done, "t_final": sc.run["t_final"], "t_transient": sc.run["t_transient"],
           "chunks_done": st.chunk_index,
           "chunks": (len(ends) if plan.main_pass else 0) + len(plan.passes)}
    if st.resumed_from is not None:
        out["resumed_from"] = st.resumed_from
    return out


def result_header(st: RunState, status, ends, transient, unit) -> dict:
    """The first entries of result.json: status, scene, source, versions, progress and the
    provenance of the start: ``state_seed``, the seed the initial state was drawn from
    (``RotorSystem.random_state``; the tangent vectors' seed too), or "given" where the scene
    gives θ and u; ``transient_rule``, where a rule ("scaled", "auto") gave the transient
    that ``scene.run.t_transient`` holds."""
    sc = st.scene
    out = {"status": status, "scene": scene_to_dict(sc), "source": sc.source,
           "versions": versions(), "progress": progress_of(st, ends, transient, unit),
           "state_seed": "given" if sc.initial.get("theta") is not None
           else sc.initial.get("seed")}
    if sc.transient_rule:
        out["transient_rule"] = sc.transient_rule
    return out


def resume_command(st: RunState, outdir: Path) -> str:
    """The shell command that continues this run (its paths quoted)."""
    return f"charts run {shlex.quote(str(st.scene.source))} -o {shlex.quote(str(outdir))} --resume"


def finalize(st: RunState, status, ends, transient, unit, outdir: Path) -> dict:
    """Build the result of the run so far and write every output file; return the result."""
    sc, plan = st.scene, st.plan
    eff = sc.effects
    result = result_header(st, status, ends, transient, unit)
    t_done = result["progress"]["t_done"]
    out = _Outputs()
    for name, build in (("waveforms", waveforms_result), ("spectrum", spectrum_result),
                        ("drift", drift_result), ("lyapunov", lyapunov_result),
                        ("curvature", curvature_result), ("angles", angles_result),
                        ("clv", clv_result),
                        ("switches", switches_result)):
        if name in eff:
            build(st, out, t_done=t_done, status=status)
    scene_kind(sc).results(st, out)
    comp = plan.as_dict()
    comp["stored_samples"] = {k: v[0] for k, v in out.stored.items()}
    comp["stored_values"] = int(sum(v[1] for v in out.stored.values()))
    comp["rhs_evaluations"] = st.rhs
    comp["steps"] = st.steps
    comp["frame_rhs_evaluations"] = st.rhs_frame
    comp["tangent_vector_evaluations"] = st.rhs * plan.tangent_vectors
    files = ["result.json", CHECKPOINT] + (["arrays.npz"] if out.arrays else []) + sorted(out.figures)
    result.update({
        "timings": {"integration_wall_s": round(max(st.elapsed - st.compile_s, 0.0), 4),
                    "compile_wall_s": round(st.compile_s, 4)},
        "computation": comp,
        "initial_state": _state(st, st.y0),
        "final_state": _state(st, st.y),
        "drift": _drift_summary(st, out),
        "results": out.results,
        "files": files,
    })
    if status == "interrupted":
        result["resume"] = resume_command(st, outdir)
    t0 = time.perf_counter()
    for name, png in out.figures.items():
        atomic_write(outdir / name, png)
    if out.arrays:
        atomic_write(outdir / "arrays.npz", npz_bytes(out.arrays))
        _write_netcdf(outdir, result, out.arrays)
    result["timings"]["output_wall_s"] = round(time.perf_counter() - t0, 4)
    write_result(outdir, result)
    return result


def _write_netcdf(outdir, result, arrays):
    """``results.nc`` beside result.json (arrays with named dimensions and units, the result
    and the scene text as attributes), when the extra ``charts[io]`` is installed."""
    try:
        require_xarray()
    except ImportError as err:
        result["netcdf"] = f"not written: {err}"
        return
    result["files"].insert(result["files"].index("arrays.npz") + 1, SCENE_NETCDF)
    SceneResult.from_run(result, arrays, result["source"]).save(outdir / SCENE_NETCDF)


def _state(st, y):
    """A state as result.json holds it: θ and u, or the linkage's q = (θ₀…θ₃, x, y, α), v."""
    keys = scene_kind(st.scene).state_keys
    return {keys[0]: y[:st.nq].tolist(), keys[1]: y[st.nq:].tolist()}


def _drift_summary(st, out):
    """The invariants at the final state, and their largest recorded drift."""
    inv = scene_kind(st.scene).invariants(st)
    drift = {"constraint": inv[0], "tangency": inv[1], "energy_relative": inv[2]}
    if out.stored.get("drift", (0,))[0]:
        D = np.array(st.rec["drift"])
        drift.update(max_abs_constraint=float(np.abs(D[:, 0]).max()),
                     max_abs_tangency=float(np.abs(D[:, 1]).max()),
                     max_abs_energy_relative=float(np.abs(D[:, 2]).max()))
    return drift


# ------------------------------------------------------------------------ per-effect results
def waveforms_result(st, out, **_):
    sc = st.scene
    w = sc.effects["waveforms"]
    t = np.array(st.rec_t["waveforms"])
    U = np.array(st.rec["waveforms"]).reshape(len(t), len(w["rotors"]))
    out.arrays.update(waveforms_t=t + sc.run["t_transient"], waveforms_u=U)
    out.stored["waveforms"] = (len(t), int(U.size))
    out.results["waveforms"] = {"rotors": w["rotors"], "samples": len(t),
                                "rms": np.sqrt((U ** 2).mean(axis=0)).tolist() if len(t) else []}
    if len(t):
        out.figures["waveforms.png"] = figs.waveforms_png(sc, out.arrays["waveforms_t"], U)


def spectrum_result(st, out, *, status, **_):
    """Welch spectrum of the recorded rotor (``charts.power_spectrum``: angular frequency ω,
    density per unit ω), segments of ``nperseg`` samples."""
    sc = st.scene
    x = np.array(st.rec["spectrum"])
    out.stored["spectrum"] = (int(x.size), int(x.size))
    nper = sc.effects["spectrum"]["nperseg"]
    segment_time = nper * sc.run["sample_dt"]
    res = {"rotor": sc.effects["spectrum"]["rotor"], "samples": int(x.size)}
    try:
        omega, density = power_spectrum(x, sc.run["sample_dt"], segment_time=segment_time)
    except ValueError:     # fewer than 4 segments fit in the samples recorded
        need = f"at least 4 × nperseg = {4 * nper}"
        res["note"] = (f"only {x.size} samples so far ({need}): no spectrum yet"
                       if status != "complete" else
                       f"{x.size} samples are too few for segments of nperseg = {nper} ({need}): "
                       "no spectrum; lengthen [run] t_final or lower nperseg")
    else:
        out.arrays.update(spectrum_omega=omega, spectrum_psd=density)
        res.update(segments=int(2 * x.size // nper - 1),
                   peak_frequency=float(omega[np.argmax(density)]), variance=float(x.var()))
        out.figures["spectrum.png"] = figs.spectrum_png(sc, omega, density, segment_time)
    out.results["spectrum"] = res


def drift_result(st, out, **_):
    sc = st.scene
    t = np.array(st.rec_t["drift"])
    D = np.array(st.rec["drift"]).reshape(len(t), 3)
    out.arrays.update(drift_t=t + sc.run["t_transient"], drift_constraint=D[:, 0],
                      drift_tangency=D[:, 1], drift_energy=D[:, 2])
    out.stored["drift"] = (len(t), int(D.size))
    if len(t):
        out.figures["drift.png"] = figs.drift_png(sc, out.arrays["drift_t"], D)


def lyapunov_result(st, out, *, t_done, **_):
    ly = st.scene.effects["lyapunov"]
    res = {"n_exponents": ly["n_exponents"], "inner_product": ly["inner_product"],
           "t_averaged": t_done}
    out.results["lyapunov"] = res
    marks = st.lyap_marks
    if not marks:
        res["note"] = "no Lyapunov batch finished yet"
        return
    steps = np.array([m[0] for m in marks])
    L = np.array([m[1] for m in marks])[:, : ly["n_exponents"]]
    T = steps * st.scene.integrator["dt"]
    exps, batches, stderr = exponents_from_marks(L, steps, st.scene.integrator["dt"])
    res["exponents"] = exps.tolist()
    if len(marks) >= 2:
        res["stderr"] = stderr.tolist()
        res["batches"] = len(batches)
    positive = positive_exponents(st.scene)
    if ly["n_exponents"] >= positive:   # every positive exponent of the pairs ±λ computed
        # Pesin's h_KS: the leading N − 2 (d − 1) positive in the run's estimate, summed in
        # each batch alike for the batch-means error (charts.analyses.spectrum_quantities)
        h, h_se = leading_entropy_with_error(exps, batches, positive)
        res["h_ks"] = h
        if len(marks) >= 2:
            res["h_ks_stderr"] = h_se
    paper = scene_kind(st.scene).paper_exponents(st, ly["n_exponents"])
    if paper is not None:
        res["paper"], res["paper_note"] = paper
    out.arrays.update(lyapunov_history_t=T, lyapunov_history=L / T[:, None])
    shares = st.flow.shares
    if st.shares_partial:
        res["energy_localisation"] = {"note": "not given: the run resumed from a checkpoint "
                                              "written before the energy shares were recorded"}
    elif shares.sum():
        res["energy_localisation"] = {
            "share": LOCALISED_SHARE, "fraction": float(localised_fraction(shares)),
            "samples": int(shares.sum()),
            "note": ("fraction of the samples (every re-orthonormalisation after the transient) "
                     "in which one rotor held at least this share of the kinetic energy; the "
                     "histogram: energy_share_counts")}
        out.arrays["energy_share_counts"] = shares.copy()
    out.figures["lyapunov.png"] = figs.lyapunov_png(st.scene, T, L / T[:, None], res)


def _pass_rows(st, out, name, keys):
    """(result dict of the separate pass ``name`` holding its settings ``keys``, its recorded
    rows as an array, or None with a note when the pass has not run yet)."""
    e = st.scene.effects[name]
    res = {k: e[k] for k in keys}
    out.results[name] = res
    if not st.rec[name]:
        res["note"] = f"the {name} pass has not run yet"
        return res, None
    return res, np.array(st.rec[name])


def angles_result(st, out, **_):
    sc = st.scene
    a = sc.effects["angles"]
    res, A = _pass_rows(st, out, "angles", ("variant", "n_vectors"))
    if A is None:
        return
    arr = {"angles_t": A[:, 0]}
    for j, variant in ((1, "full"), (2, "restricted")):
        if a["variant"] in (variant, "both"):
            arr[f"angles_{variant}"] = A[:, j]
            res[variant] = angle_statistics(A[:, j], SMALL_ANGLE)
    fwd, adj = st.rec["angles_exponents"]
    res["forward_exponents"] = list(fwd)
    res["adjoint_exponents"] = list(adj)
    out.arrays.update(arr)
    out.stored["angles"] = (len(arr["angles_t"]), int(sum(v.size for v in arr.values())))
    out.figures["angles.png"] = figs.angles_png(sc, arr)


def clv_result(st, out, **_):
    """Per variant: angle statistics of φ (CLV route) and of the angle between the leading
    unstable and stable CLVs, the mean growth rates along the CLVs, the domination
    fractions and the finite-time exponents per window (``charts.analyses.covariant``)."""
    sc = st.scene
    c = sc.effects["clv"]
    res, A = _pass_rows(st, out, "clv", ("variant", "n_vectors", "windows"))
    if A is None:
        return
    arr = {"clv_t": A[:, 0]}
    variants = [v for v in ("full", "restricted") if c["variant"] in (v, "both")]
    E, Dm, F = (np.array(st.rec[k]) for k in ("clv_exponents", "clv_domination", "clv_ftle"))
    d2 = 2 * st.system.n
    for j, v in enumerate(variants):
        iv = ("full", "restricted").index(v)
        arr[f"clv_phi_{v}"], arr[f"clv_phi_vectors_{v}"] = A[:, 1 + 2 * j], A[:, 2 + 2 * j]
        ex = E[E[:, 0] == iv][0, 1:]
        r = {"phi": angle_statistics(arr[f"clv_phi_{v}"], SMALL_ANGLE),
             "phi_vectors": angle_statistics(arr[f"clv_phi_vectors_{v}"], SMALL_ANGLE),
             "exponents": ex[np.isfinite(ex)].tolist(),
             "domination": {f"{w:g}": {"split": s, "windows": int(k)}
                            for _, w, s, k in Dm[Dm[:, 0] == iv]}, "finite_time": {}}
        for row in F[F[:, 0] == iv]:
            st_ = row[4:].reshape(len(FTLE_STATS), d2)
            r["finite_time"][f"{row[1]:g}"] = dict(
                windows=int(row[2]), frac_nonpositive_leading=float(row[3]),
                **{k: x[np.isfinite(x)].tolist() for k, x in zip(FTLE_STATS, st_)})
        res[v] = r
    out.arrays.update(arr)
    out.stored["clv"] = (len(arr["clv_t"]), int(sum(x.size for x in arr.values())))
    out.figures["clv.png"] = figs.clv_png(sc, arr, res)


def curvature_result(st, out, **_):
    sc = st.scene
    c = sc.effects["curvature"]
    n = st.system.n
    t = np.array(st.rec_t["curvature"])
    arr = {"curvature_t": t + sc.run["t_transient"]}
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
    if n == 3 and np.allclose(st.system.masses, 1.0) and st.system.is_paper_family and len(t):
        Y = np.array(st.rec["curvature_y"])
        K22 = gaussian_curvature_eq22(Y[:, :3])
        arr["curvature_eq22"] = K22
        for route in ("numerical", "exact"):
            if f"curvature_{route}" in arr:
                err = np.abs(arr[f"curvature_{route}"][:, 0] - K22)
                # relative errors blow up near the zero-curvature points: report both
                res[route]["max_abs_error_vs_eq22"] = float(err.max())
                res[route]["median_rel_error_vs_eq22"] = float(np.median(err / np.abs(K22)))
    out.results["curvature"] = res
    out.arrays.update(arr)
    out.stored["curvature"] = (len(t), int(sum(v.size for v in arr.values())))
    if len(t):
        out.figures["curvature.png"] = figs.curvature_png(sc, arr)


def switches_result(st, out, *, t_done, **_):
    S = np.array(st.rec["switches"]).reshape(-1, 3)
    out.arrays["switches"] = S
    out.results["switches"] = {"count": len(S), "rate": len(S) / t_done if t_done else None}
