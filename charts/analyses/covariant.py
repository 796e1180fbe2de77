"""Covariant Lyapunov vectors (Ginelli et al., PRL 99, 130601 (2007)) and, from them, the
hyperbolicity test of section 4 by a route independent of the backward adjoint one.

Along one reference trajectory of eq (8), with D tangent vectors (eq 17):

1. forward: the tangent kernel (``charts.solvers.tangent.TangentFlow``) advances the state and
   D vectors sample by sample; at every sample point the vectors are projected onto T_r (the
   restricted variant) and re-orthonormalised by the kernel's Gram–Schmidt (eq 18) in the
   Euclidean product of R^{2N} (the angle test's).  The Gram–Schmidt vectors Q_j and the
   upper-triangular R_j with M(t_{j−1} → t_j) Q_{j−1} = Q_j R_j are stored at every sample;
2. backward: from a random upper-triangular C at the last sample, C_{j−1} = R_j⁻¹ C_j with
   unit columns; after a backward transient the columns give the CLVs v_j^i = Σ_q C_j[q, i] Q_j[q]
   (unit, largest exponent first), and the norm lost in each step the growth rate along v^i;
3. at each sample: sin φ = the smallest singular value of the part of E_u = span(Q_j[:m])
   orthogonal to E_cs = span(v_j^{m+1} … v_j^D) — the angle of `hyperbolicity_angles`.

Variants (as the angle test's): ``restricted`` keeps the D = 2N−2 vectors in the invariant
constraint-preserving subspace T_r (``charts.geometry.projection``); ``full`` uses D = 2N
vectors in all of R^{2N}, so E_cs contains the two non-physical directions.  Masses enter
through eq (8); the product is Euclidean in both variants.

Layout of the trajectory: the same as `hyperbolicity_angles` (transient, window of S samples
from t_transient, then at least one more sample interval and t_transient for the backward
iteration), from the same start, dt and projection steps, hence the same trajectory.

Memory: the stored factors take 8·(D·2N + D² + 2N) bytes per sample (Q, R and the state;
`sample_bytes`): N = 3 restricted 368 B, N = 5 full 1.68 kB, i.e. 420 MB for the 2.5·10⁵
samples of t = 2.5·10⁴ at sample_every = 0.1.  Above ``max_memory`` they are streamed to
``.npy`` memory maps in a temporary folder (``scratch``), removed at the end, and the
backward pass reads them in chunks of `CHUNK` samples.  In memory in any case: the rates,
8·3D bytes per sample, and the results (the CLVs themselves only with ``keep_vectors``).
"""
from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass
from math import isfinite
from typing import NamedTuple

import numpy as np
from ..jit import njit

from ..io.archive import Archivable, attributes, dataset, index_coordinate
from ..io.result_words import ANGULAR_VELOCITY, RATE, exponent_words, smallest_words
from ..jit.compilation import announces_compilation
from ..geometry.checks import integer, option, shown
from ..geometry.projection import project_tangent_sc
from ..geometry.system import MAX_N
from ..solvers.status import NONFINITE, RUNNING, status_error
from ..solvers.driver import Phases
from ..solvers.device import load_member, store_member
from ..solvers.tangent import (Records, Rotors, Stack, Stepping, TangentFlow, check_memory,
                               orthonormalize, stacked_work, tangent_loop)
from .arguments import (positive_int, positive_time, progress_reporter, project_steps,
                        samples_of, start_state, steps_of, unstable_dimension, Documented)
from .finite_time import domination, finite_time_statistics
from .hyperbolicity import angle_statistics
from .singular_values import smallest_singular_values
from .arguments import flag, rotor_system
from .mechanism_route import mechanism_route

__all__ = ["CovariantResult", "covariant_lyapunov_vectors", "clv_dimension", "sample_bytes",
           "MAX_MEMORY", "CLVSettings", "clv_settings", "clv_flow", "ginelli_start",
           "clv_samples", "covariant_result", "factor_sample", "backward_coefficients",
           "clv_forward_member", "forward_members", "result_bytes"]

#: default limit (bytes) of the stored factors kept in memory; beyond it they go to disk.
MAX_MEMORY = 256 << 20
#: samples per chunk of the forward buffers and of the backward pass.
CHUNK = 2048


def clv_dimension(n, variant):
    """D, the number of CLVs: 2N−2 (``restricted``) or 2N (``full``)."""
    return 2 * n - 2 if option("variant", variant, ("restricted", "full")) == "restricted" \
        else 2 * n


def sample_bytes(n, variant):
    """Bytes of the factors stored per sample point by the forward pass: Q (D, 2N),
    R (D, D) and the state (2N,)."""
    n = integer("n", n, 3, MAX_N)
    D = clv_dimension(n, variant)
    return 8 * (D * 2 * n + D * D + 2 * n)


@njit(cache=True)
def factor_sample(y, X, minv, s, c, w, restricted, logs, Xraw, Rout):
    """Project X (D, 2N) onto T_r at y (if ``restricted``), keep a copy in Xraw, Gram–Schmidt
    it in place (eq 18, `orthonormalize`, logs added to ``logs``) and store the upper-
    triangular factor Rout[q, r] = ⟨Q_q, X_r⟩ (q ≤ r) of X = Rᵀ Q (rows)."""
    if restricted:
        project_tangent_sc(y, X, minv, s, c)
    D, d = X.shape
    for r in range(D):
        for i in range(d):
            Xraw[r, i] = X[r, i]
    orthonormalize(X, w, logs)
    for q in range(D):
        for r in range(D):
            a = 0.0
            if r >= q:
                for i in range(d):
                    a += w[i] * X[q, i] * Xraw[r, i]
            Rout[q, r] = a


def _forward_samples(flow, system, n_tr, sample, a, b, tau, Xraw, bq, br, by, gs, logs):
    """The forward pass of ``flow`` for samples a … b − 1 (the transient of n_tr steps first
    if a = 0): Q, R, y of sample j into row j − a of bq, br, by, its Gram–Schmidt rates into
    gs[j], by `forward_members` with the flow as its one member (its arrays, not copies).
    Returns the loop's status (NONFINITE for a norm that is not finite)."""
    stack, rotors, stepping = flow.stack(), flow.rotors(), flow.stepping()
    status = np.full(1, RUNNING, dtype=np.int64)
    forward_members(stack.Z[None], stack.sc[None], stack.counter, stack.logsum[None], status,
                    np.zeros(1, dtype=np.int64), bq[None], br[None], by[None], gs[a:][None],
                    (rotors.minv, rotors.m, rotors.wts, stepping.w, stepping.restricted),
                    float(rotors.level), np.array([stepping.speed]), stepping.dt,
                    (n_tr, sample, flow.project_every, flow.reorth_every, a, a, b), tau,
                    _NO_EVENTS, _NONE)
    return int(status[0])


_NO_EVENTS = np.empty(0, dtype=np.int64)
_NONE = np.empty((0, 0))


@njit(cache=True, inline="always")
def clv_forward_member(l, Zs, scs, counters, logsums, status, stopped, Qs, Rs, Ys, GS, arrays,
                       level, speeds, dt, steps, tau, no_events, none, Z, sc, counter, logsum,
                       work, Xraw, logs):
    """What one thread does in a forward launch: member l's flow (Zs (L, 1 + D, 2N), scs,
    counters, logsums) into the local Z, sc, counter, logsum; the forward pass of
    `covariant_lyapunov_vectors` (`_forward_samples`) for samples ja … jb − 1 (``steps`` =
    (n_tr, sample, project, reorth, first, ja, jb): the transient of n_tr steps first when
    ja = 0), sample j's Q, R, state and Gram–Schmidt rates into row j − first of Qs[l], Rs[l],
    Ys[l], GS[l]; back into the member arrays; a stop is flagged (status, global step)."""
    if status[l] != RUNNING:
        return
    minv, m, wts, w, restricted = arrays
    n_tr, sample, project, reorth, first, ja, jb = steps
    D = Z.shape[0] - 1
    d = Z.shape[1]
    load_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum)
    stack = Stack(Z, sc, counter, logsum, no_events)
    rotors = Rotors(minv, m, wts, level)
    stepping = Stepping(speeds[l], dt, w, restricted)
    phases = Phases(project, reorth, 0, 0)
    records = Records(none, no_events, none)
    code = RUNNING
    done = 0
    j = ja
    while j < jb:
        transient = ja == 0 and done < n_tr
        left = n_tr - done                  # (no min(): the GPU target cannot type it)
        k = (sample if sample < left else left) if transient else (sample if j > 0 else 0)
        if k > 0:
            code, _ = tangent_loop(stack, rotors, stepping, phases, records, k, work)
            if code != RUNNING:
                break
        if transient:
            factor_sample(Z[0], Z[1:], minv, sc[0], sc[1], w, restricted, logs, Xraw, Rs[l, 0])
            done += k
            continue
        for r in range(D):
            logs[r] = 0.0
        row = j - first
        factor_sample(Z[0], Z[1:], minv, sc[0], sc[1], w, restricted, logs, Xraw, Rs[l, row])
        for r in range(D):
            if not isfinite(logs[r]):
                code = NONFINITE
            GS[l, row, r] = logs[r] / tau
            for i in range(d):
                Qs[l, row, r, i] = Z[1 + r, i]
        if code != RUNNING:
            break
        for i in range(d):
            Ys[l, row, i] = Z[0, i]
        j += 1
    store_member(l, Zs, scs, counters, logsums, Z, sc, counter, logsum, code, status, stopped)


@njit(cache=True)
def forward_members(Zs, scs, counters, logsums, status, stopped, Qs, Rs, Ys, GS, arrays, level,
                 speeds, dt, steps, tau, no_events, none):
    """`clv_forward_member` for every member in turn: the forward pass of
    `covariant_lyapunov_vectors` (one member) and the CPU twin of the ensembles' CUDA
    forward kernel (``charts.analyses.clv_ensemble``)."""
    L, R, d = Zs.shape
    n = d // 2
    D = R - 1
    for l in range(L):
        clv_forward_member(l, Zs, scs, counters, logsums, status, stopped, Qs, Rs, Ys, GS,
                           arrays, level, speeds, dt, steps, tau, no_events, none,
                           np.empty((R, d)), np.empty((2, n)), np.empty(1, dtype=np.int64),
                           np.empty(D), stacked_work(R, d), np.empty((D, d)), np.empty(D))



@njit(cache=True, nogil=True)
def backward_coefficients(R, C, Cs, lost):
    """Ginelli's backward step over one chunk, last sample first: Cs[b] = C (unit columns,
    the coefficients at sample b), then C ← R[b]⁻¹ C (back substitution), lost[b, i] = log of
    the norm of column i (minus the log growth along CLV i from sample b−1 to b), normalised."""
    B, D, _ = R.shape
    x = np.empty(D)
    for b in range(B - 1, -1, -1):
        for r in range(D):              # (a loop, not an array assignment: numba compiles
            # the shape-mismatch message of one, 3 s of a first call)
            for i in range(D):
                Cs[b, r, i] = C[r, i]
        for i in range(D):
            for r in range(D - 1, -1, -1):
                a = C[r, i]
                for q in range(r + 1, D):
                    a -= R[b, r, q] * x[q]
                x[r] = a / R[b, r, r]
            nrm = 0.0
            for r in range(D):
                nrm += x[r] * x[r]
            nrm = np.sqrt(nrm)
            lost[b, i] = np.log(nrm)
            for r in range(D):
                C[r, i] = x[r] / nrm


def _angle(A, B):
    """Smallest angle (rad) between span(rows of A) and span(rows of B), stacked over the
    first axis; A has orthonormal rows.  From the sine (the part of A orthogonal to B)."""
    Bq, _ = np.linalg.qr(np.swapaxes(B, 1, 2))                       # (S, d, kB)
    P = np.ascontiguousarray(A - (A @ Bq) @ np.swapaxes(Bq, 1, 2))
    sv = np.empty(P.shape[0])
    smallest_singular_values(P, sv)
    return np.arcsin(np.clip(sv, 0.0, 1.0))


def result_bytes(cfg, n, keep_vectors=False) -> int:
    """Bytes of one `CovariantResult` of the settings ``cfg`` for N = n: its growth rates
    over every sample and its angles, rates and states over the window (and the CLVs
    themselves with ``keep_vectors``)."""
    results = 8 * (cfg.total * cfg.D + cfg.S * (2 + 2 * cfg.D + 2 * n))
    return results + (8 * cfg.S * cfg.D * 2 * n if keep_vectors else 0)


def plan_storage(cfg, n, variant, keep_vectors, scratch) -> bool:
    """Whether the stored factors go to disk; ValueError with the numbers, before anything is
    allocated, when the results (and the factors kept in memory, or the CLVs with
    ``keep_vectors``) exceed the memory budget (``charts.solvers.tangent.check_memory``), or
    the factors on disk exceed 90 % of the free space of the scratch folder."""
    factors = cfg.total * sample_bytes(n, variant)
    on_disk = factors > cfg.max_memory
    check_memory(result_bytes(cfg, n, keep_vectors) + (0 if on_disk else factors),
                 f"covariant_lyapunov_vectors' {cfg.S} samples" + (" with their CLVs"
                                                                     if keep_vectors else ""),
                 "shorten t_final, raise sample_every" + (" or drop keep_vectors"
                                                          if keep_vectors else ""))
    if on_disk:
        folder = scratch if scratch is not None else tempfile.gettempdir()
        free = shutil.disk_usage(folder).free
        if factors > 0.9 * free:
            raise ValueError(
                f"covariant_lyapunov_vectors' stored factors need {factors / 2**30:.1f} GiB on "
                f"disk in {folder}, which has {free / 2**30:.1f} GiB free; shorten t_final, "
                "raise sample_every, or give scratch= a folder with room")
    return on_disk


class _Store:
    """Q (S, D, 2N), R (S, D, D) and states (S, 2N) in memory or as .npy memory maps (the
    folder removed again if they cannot be made)."""

    def __init__(self, shape_q, shape_r, shape_y, on_disk, scratch):
        self.folder = None
        if on_disk:
            self.folder = tempfile.mkdtemp(prefix="charts-clv-", dir=scratch)
            mk = lambda name, shp: np.lib.format.open_memmap(    # noqa: E731
                f"{self.folder}/{name}.npy", mode="w+", dtype=float, shape=shp)
        else:
            mk = lambda name, shp: np.empty(shp)                   # noqa: E731
        try:
            self.Q, self.R, self.y = mk("Q", shape_q), mk("R", shape_r), mk("y", shape_y)
        except BaseException:
            self.close()
            raise

    def close(self):
        if self.folder is not None:
            for name in ("Q", "R", "y"):
                self.__dict__.pop(name, None)
            shutil.rmtree(self.folder, ignore_errors=True)


@dataclass(eq=False, repr=False)
class CovariantResult(Archivable):
    """CLV analysis along one trajectory, one variant; S samples, D = `clv_dimension` CLVs
    (index 0 the largest exponent).

    t : (S,) sample times.   phi : (S,) angle (rad) between E_u and E_cs (section 4).

    phi_vectors : (S,) angle (rad, in [0, π/2]) between the leading unstable CLV (index 0)
        and the leading stable one (index D − (N−2), the first negative exponent).

    growth : (S, D) growth rates along the CLVs over [t_j, t_j + sample_every] (1/time).

    gs_rates : (S, D) the same for the Gram–Schmidt vectors, log R_ii / sample_every.

    exponents, gs_exponents : (D,) their means over the window (the Lyapunov spectrum).

    states : (S, 2N) the trajectory (θ, u) at the samples.

    vectors : (S, D, 2N) or None  the CLVs (unit, Euclidean), if ``keep_vectors``.
    """
    t: np.ndarray
    variant: str
    phi: np.ndarray
    phi_vectors: np.ndarray
    growth: np.ndarray
    gs_rates: np.ndarray
    states: np.ndarray
    vectors: np.ndarray | None
    params: dict

    @property
    def exponents(self):
        return self.growth.mean(axis=0)

    @property
    def gs_exponents(self):
        return self.gs_rates.mean(axis=0)

    def statistics(self, **kw):
        """`angle_statistics` of ``phi``."""
        return angle_statistics(self.phi, **kw)

    def finite_time(self, windows):
        """`finite_time_statistics` of the Gram–Schmidt rates for the window lengths
        ``windows`` (time units, multiples of sample_every)."""
        return finite_time_statistics(self.gs_rates, self.params["sample_every"], windows)

    def domination(self, windows):
        """`domination` test of the growth rates along the CLVs."""
        return domination(self.growth, self.params["n_unstable"], self.params["sample_every"],
                          windows)

    def summary_parts(self):
        """The variant, the smallest angles and the growth rates along the CLVs."""
        return [f"{self.variant} variant", f"min φ {smallest_words(self.phi)}",
                f"between CLVs {smallest_words(self.phi_vectors)}",
                exponent_words(self.exponents) if len(self.t) else ""]

    KIND = "covariant"

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``)."""
        data = {
            "phi": (("t",), self.phi, "rad", "angle between E_u and E_cs"),
            "phi_vectors": (("t",), self.phi_vectors, "rad",
                            "angle between the leading unstable and the leading stable CLV"),
            "growth": (("t", "clv"), self.growth, RATE, "growth rate along each CLV"),
            "gs_rates": (("t", "clv"), self.gs_rates, RATE,
                         "growth rate of each Gram-Schmidt vector"),
            "states": (("t", "component"), self.states, "see component_units",
                       "state (theta, u) at the samples")}
        n = self.states.shape[1] // 2
        coords = {"t": (("t",), self.t, "time"),
                  "clv": index_coordinate("clv", self.growth.shape[1],
                                          "i of the i-th covariant vector, from 1"),
                  "component": (("component",),
                                np.array([f"theta_{i}" for i in range(n)]
                                         + [f"u_{i}" for i in range(n)]), "1",
                                "θ₀…θ_{N−1}, then u₀…u_{N−1}"),
                  "component_units": (("component",),
                                      np.array(["rad"] * n + [ANGULAR_VELOCITY] * n), "1",
                                      "the unit of each component of states")}
        if self.vectors is not None:
            data["vectors"] = (("t", "clv", "component"), self.vectors, "1", "unit CLVs")
        return dataset(self.KIND, data, coords=coords,
                       attrs={"variant": self.variant, "params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        return cls(t=ds["t"].values, variant=a["variant"], phi=ds["phi"].values,
                   phi_vectors=ds["phi_vectors"].values, growth=ds["growth"].values,
                   gs_rates=ds["gs_rates"].values, states=ds["states"].values,
                   vectors=ds["vectors"].values if "vectors" in ds else None,
                   params=a["params"])

    def plot(self, axes=None, **kw):
        """Histogram of φ(E_u, E_cs) by the CLV route; ``(fig, axes)``
        (``charts.plotting.plot_angles``)."""
        from ..plotting import plot_angles
        kw.setdefault("title", "angles between $E_u$ and $E_{cs}$ (covariant Lyapunov vectors)")
        return plot_angles({self.variant: self.phi}, axes=axes, **kw)


@mechanism_route("mechanism_covariant", "mechanism_clvs")
@announces_compilation
def covariant_lyapunov_vectors(system, theta0, u0, t_final, *, variant="restricted", dt=0.01,
                               n_unstable=None, t_transient=Documented(100.0),
                               sample_every=Documented(0.1), project_every=Documented(1.0),
                               seed=0, keep_vectors=False,
                               max_memory=MAX_MEMORY, scratch=None,
                               progress=False) -> CovariantResult:
    """CLVs by Ginelli's method along the trajectory from (theta0, u0), and the angles,
    growth rates and finite-time exponents built on them (module docstring).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
    t_final : float
        Length of the analysed window (a multiple of ``sample_every``).
    variant : {'restricted', 'full'}
        CLVs in T_r (D = 2N−2) or in R^{2N} (D = 2N).
    dt : float
        RK4 step.  A time written below must be a whole number of steps;
        a default left is the nearest whole number of steps at other dt (README,
        "Conventions").
    n_unstable : int, optional
        m, the dimension of E_u (default N−2).
    t_transient : float
        Convergence time of the forward Gram–Schmidt vectors and of the backward iteration.
    sample_every : float
        Time between samples, i.e. between re-orthonormalisations (10 steps at the default:
        the vectors grow by at most e^{(λ₁−λ_D)·0.1} ≈ 1.1 in between).
    project_every : float or None
        Time between projections of the state onto the invariants (None: never).
    seed : int
        Seed of the random initial vectors and of the random initial C.
    keep_vectors : bool
        Return the CLVs (S·D·2N·8 bytes).
    max_memory : int
        Bytes of stored factors kept in memory; more goes to a temporary folder on disk.
    scratch : str, optional
        Parent folder of that temporary folder (default: the system's temporary folder).
    progress : bool or callable(t_done, t_total)
    """
    rotor_system(system)
    keep_vectors = flag("keep_vectors", keep_vectors)
    if scratch is not None and (isinstance(scratch, bytes) or str(scratch) == "" or
                                not isinstance(scratch, (str, os.PathLike))):
        raise ValueError(f"scratch must be a folder path (a str or os.PathLike) or None, got "
                         f"{shown(scratch)}")
    cfg = clv_settings(system, t_final, variant, dt, n_unstable, t_transient, sample_every,
                        project_every, seed, max_memory)
    theta0, u0 = start_state(system, theta0, u0, cfg.dt)
    flow = clv_flow(system, theta0, u0, cfg, variant)
    rep = progress_reporter(progress, cfg.n_steps * cfg.dt, f"CLV N={system.n} {variant}")
    on_disk = plan_storage(cfg, system.n, variant, keep_vectors, scratch)
    store = _Store((cfg.total, cfg.D, 2 * system.n), (cfg.total, cfg.D, cfg.D),
                   (cfg.total, 2 * system.n), on_disk, scratch)
    try:
        gs = _forward_pass(flow, system, cfg, store, rep,
                           f"covariant_lyapunov_vectors (RK4, {variant})")
        lost, phi, phi_v, states, vectors = _backward_pass(store, system.n, cfg, keep_vectors)
    finally:
        store.close()
    rep.close()
    return covariant_result(system, cfg, variant, phi, phi_v, lost[1:cfg.S + 1],
                            gs[1:cfg.S + 1], states, vectors, flow.speed, (theta0, u0))


def covariant_result(system, cfg, variant, phi, phi_v, lost, gs, states, vectors, speed,
                     start) -> CovariantResult:
    """The `CovariantResult` of a run with settings ``cfg`` (`clv_settings`) from its
    angles, the logs lost per sample by Ginelli's iteration and the Gram–Schmidt rates of
    the S samples' intervals (S, D), its states, its CLVs (or None), its measured speed
    and its initial state ``start`` = (theta0, u0)."""
    t = (cfg.n_tr + np.arange(cfg.S) * cfg.sample) * cfg.dt
    params = dict(**system.describe(), variant=variant, dt=cfg.dt, D=cfg.D,
                  t_final=cfg.n_win * cfg.dt, t_transient=cfg.n_tr * cfg.dt,
                  sample_every=cfg.tau, speed=speed, project_every=cfg.project * cfg.dt or None,
                  vectors_seed=cfg.seed, state_seed="given",
                  bytes_per_sample=sample_bytes(system.n, variant),
                  stored_samples=cfg.total, n_unstable=cfg.m, keep_vectors=vectors is not None,
                  theta0=np.asarray(start[0], dtype=float).tolist(),
                  u0=np.asarray(start[1], dtype=float).tolist())
    return CovariantResult(t, variant, phi, phi_v, -lost / cfg.tau, gs, states, vectors, params)


def clv_flow(system, theta0, u0, cfg, variant) -> TangentFlow:
    """The forward pass's `TangentFlow`: D vectors in the Euclidean product, in T_r for the
    restricted variant.  The kernel never re-orthonormalises (reorth_every beyond the run):
    `factor_sample` does, at the samples, with the kernel's Gram–Schmidt, keeping R."""
    return TangentFlow(system, theta0, u0, cfg.D, dt=cfg.dt, inner="euclidean",
                       restricted=variant == "restricted", reorth_every=cfg.n_steps + 1,
                       project_every=cfg.project, seed=cfg.seed)


def ginelli_start(seed, D, block=None):
    """Ginelli's random upper-triangular C (D, D) with unit columns, from the stream
    [seed, 2] (the backward pass of `covariant_lyapunov_vectors`), or [seed, 2, block] for
    a later block of the GPU route."""
    rng = np.random.default_rng([seed, 2] if block is None else [seed, 2, block])
    C = np.triu(rng.uniform(0.5, 1.5, size=(D, D)))
    C /= np.linalg.norm(C, axis=0)
    return C


def clv_samples(Q, Cs, m, n):
    """At each sample of a chunk, from the Gram–Schmidt vectors Q (B, D, 2N) and Ginelli's
    coefficients Cs (B, D, D): (the CLVs V (B, D, 2N), the angle between E_u and E_cs, the
    angle between the leading unstable CLV and the leading stable one)."""
    D = Q.shape[1]
    ist = D - (n - 2)                                  # the leading stable CLV
    V = np.einsum("kqi,kqx->kix", Cs, Q)                # rows: the CLVs
    return V, _angle(Q[:, :m], V[:, m:]), _angle(V[:, :1], V[:, ist:ist + 1])


class CLVSettings(NamedTuple):
    """The checked settings of a CLV run, in steps: the transient ``n_tr``, the window
    ``n_win``, steps per sample ``sample`` (τ = ``tau`` in time), projection ``project``;
    ``S`` samples analysed, ``total`` stored (the backward transient's too), ``n_steps``
    forward steps; D and m the dimensions of the tangent space and of E_u."""
    D: int
    m: int
    dt: float
    n_tr: int
    n_win: int
    sample: int
    project: int
    seed: int
    max_memory: int
    S: int
    total: int
    n_steps: int
    tau: float


def clv_settings(system, t_final, variant, dt, n_unstable, t_transient, sample_every,
                  project_every, seed, max_memory) -> CLVSettings:
    """`covariant_lyapunov_vectors`' arguments checked (ValueError naming the bad one), as
    its settings in steps."""
    D = clv_dimension(system.n, variant)
    m = unstable_dimension(system.n, n_unstable)
    dt = positive_time("dt", dt)
    n_tr = steps_of("t_transient", t_transient, dt, allow_zero=True)
    n_win = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=n_win)
    project = project_steps(project_every, dt)
    seed = positive_int("seed", seed, 0)
    max_memory = positive_int("max_memory", max_memory, 0)
    S = samples_of(n_win, sample, t_final, sample_every)
    total = S + max(1, -(-n_tr // sample))              # stored samples
    n_steps = n_tr + (total - 1) * sample               # the first one at the transient's end
    return CLVSettings(D, m, dt, n_tr, n_win, sample, project, seed, max_memory, S, total,
                        n_steps, sample * dt)


def _forward_pass(flow, system, cfg, store, rep, where):
    """The forward pass: the Gram–Schmidt factors Q_j, R_j and states y_j at every stored
    sample into ``store``; returns the growth of each vector per sample, shape (total, D)."""
    D, d, total, sample = cfg.D, 2 * system.n, cfg.total, cfg.sample
    Xraw = np.empty((D, d))
    logs = np.zeros(D)
    gs = np.empty((total, D))
    bq, br, by = np.empty((CHUNK, D, d)), np.empty((CHUNK, D, D)), np.empty((CHUNK, d))
    for a in range(0, total, CHUNK):
        b = min(total, a + CHUNK)
        status = _forward_samples(flow, system, cfg.n_tr, sample, a, b, cfg.tau, Xraw, bq, br,
                                  by, gs, logs)
        if status != RUNNING:
            raise status_error(status, flow.steps * cfg.dt, where)
        rep.update(((cfg.n_tr if a == 0 else 0) + (b - a - (a == 0)) * sample) * cfg.dt)
        store.Q[a:b], store.R[a:b], store.y[a:b] = bq[:b - a], br[:b - a], by[:b - a]
    return gs


def _backward_pass(store, n, cfg, keep_vectors):
    """Ginelli's backward iteration over the stored R_j, last chunk first, from a random
    upper-triangular C: (the log growth lost per sample (total, D), the angle between E_u and
    E_s, the angle between the leading unstable and stable CLVs (S,), the states (S, 2N),
    the CLVs (S, D, 2N) or None)."""
    D, S, m, total = cfg.D, cfg.S, cfg.m, cfg.total
    C = ginelli_start(cfg.seed, D)
    lost = np.zeros((total, D))
    phi, phi_v = np.empty(S), np.empty(S)
    states = np.empty((S, 2 * n))
    vectors = np.empty((S, D, 2 * n)) if keep_vectors else None
    for b in range(total, 0, -CHUNK):
        a = max(0, b - CHUNK)
        Cs = np.empty((b - a, D, D))
        backward_coefficients(np.ascontiguousarray(store.R[a:b]), C, Cs, lost[a:b])
        hi = min(b, S)
        if a < hi:
            V, phi[a:hi], phi_v[a:hi] = clv_samples(np.asarray(store.Q[a:hi]), Cs[:hi - a], m, n)
            states[a:hi] = store.y[a:hi]
            if keep_vectors:
                vectors[a:hi] = V
    return lost, phi, phi_v, states, vectors
