"""Ensembles: one analysis on independent random initial states, in parallel processes."""
from __future__ import annotations

import os
import warnings
from contextlib import nullcontext
from dataclasses import dataclass, field

import numpy as np

from ..io.archive import (ENSEMBLE_TITLES, Archivable, attributes, dataset, require_xarray,
                       same_value)
from ..io.file_settings import MEMBER, member_attributes, member_settings
from ..io.renamed_settings import NOTE
from ..io.result_words import RATE, counted, exponent_words, smallest_words
from ..jit.compilation import announce, timed_call
from ..geometry.checks import shown
from ..geometry.energy_shares import LOCALISED_SHARE
from ..solvers.progress import check_progress
from .worker_pool import worker_pool
from ..geometry.checks import integer
from .arguments import (MAX_MEMBERS, MAX_SPEED, MAX_WORKERS, positive_time, progress_reporter,
                        seed_of)
from .cluster import cluster_pool
from .spectrum_quantities import SpectrumQuantities
from .statistics import standard_error

__all__ = ["EnsembleResult", "run_ensemble", "ensemble_arguments", "map_jobs", "stream_jobs",
           "ensemble_result", "system_settings",
           "error_ratio_of", "warn_understated", "member_states_of", "resolved_settings",
           "OWN_SETTINGS", "ErrorBarWarning", "UNDERSTATED_RATIO",
           "MIN_MEMBERS_TO_JUDGE"]


@dataclass(eq=False, repr=False)
class EnsembleResult(SpectrumQuantities, Archivable):
    """Results of one analysis on independent trajectories (seeds seed, seed+1, …).

    members : list of the analysis' results, in seed order.

    exponents, stderr : (k,) for Lyapunov members: mean over the members and its two-sided
        standard error (their spread); None for other analyses.

    error_ratio : (k,) for Lyapunov members: the members' own batch-mean errors (root mean
        square) over the spread of their exponents (standard deviation) — about 1 when the
        error bars of single runs are honest, below 1 when they understate the spread between
        trajectories (`error_ratio_of`; `ErrorBarWarning`).
    """
    members: list
    exponents: np.ndarray | None = None
    stderr: np.ndarray | None = None
    params: dict = field(default_factory=dict)
    error_ratio: np.ndarray | None = None

    def __len__(self):
        return len(self.members)

    def __iter__(self):
        return iter(self.members)

    def __getitem__(self, i):
        return self.members[i]

    def localised_fractions(self, share=LOCALISED_SHARE):
        """(members,): for each Lyapunov member, the fraction of its averaging time in which
        one rotor held at least ``share`` of the kinetic energy
        (`LyapunovResult.localised_fraction`)."""
        return np.array([m.localised_fraction(share) for m in self.members])

    def concatenate(self, attribute):
        """The members' array ``attribute`` joined along its first axis (ValueError naming
        ``attribute`` unless every member holds an array of that name)."""
        if not isinstance(attribute, str) or not self.members or not all(
                isinstance(getattr(m, attribute, None), np.ndarray) for m in self.members):
            raise ValueError(f"attribute must name an array of the members (e.g. "
                             f"'exponents'), got {shown(attribute)}")
        return np.concatenate([getattr(m, attribute) for m in self.members])

    KIND = "ensemble"

    def to_xarray(self):
        """The members' datasets stacked along a ``member`` dimension (members of one
        analysis share their shapes); their settings as ``member.*`` attributes where they
        share them and ``member.*`` variables along ``member`` where they differ (the seed,
        the speed: ``charts.io.file_settings.member_settings``)."""
        xr = require_xarray()
        if not self.members:
            raise ValueError("an empty ensemble has nothing to save")
        parts = [m.to_xarray() for m in self.members]
        kinds = {p.attrs["charts_kind"] for p in parts}
        if len(kinds) != 1:
            raise ValueError(f"members of different kinds cannot be saved together: {sorted(kinds)}")
        stacked = xr.concat(parts, dim="member", combine_attrs="drop")

        def spec(name, v):          # the members' units and description, kept
            a = parts[0][name].attrs if name in parts[0].variables else {}
            out = (v.dims, v.values, a.get("units", "1"))
            return out + (a["long_name"],) if "long_name" in a else out

        data = {k: spec(k, v) for k, v in stacked.data_vars.items()}
        coords = {k: spec(k, v) for k, v in stacked.coords.items()}
        if self.exponents is not None:
            data["ensemble_exponents"] = (("exponent",), self.exponents, RATE, "mean")
            data["ensemble_stderr"] = (("exponent",), self.stderr, RATE,
                                       "two-sided standard error of the mean")
        if self.error_ratio is not None:
            data["batch_error_ratio"] = (("exponent",), self.error_ratio, "1",
                                         "members' batch-mean errors (rms) / spread of their "
                                         "exponents (std)")
        shared, varying = member_settings([attributes(p) for p in parts])
        data.update(varying)
        member_kind = kinds.pop()
        return dataset(self.KIND, data, coords=coords, title=ENSEMBLE_TITLES.get(member_kind),
                       attrs={"params": self.params, "member_kind": member_kind, **shared})

    @classmethod
    def from_xarray(cls, ds):
        import importlib

        from ..io.archive import KINDS
        a = attributes(ds)
        module, name = KINDS[a["member_kind"]].split(":")
        member_cls = getattr(importlib.import_module(module), name)
        body = ds.drop_vars([v for v in ds.data_vars if v.startswith(MEMBER) or v in (
            "ensemble_exponents", "ensemble_stderr", "batch_error_ratio")])
        old = a.get("member_attrs")              # files written before the members' settings
        members = []                             # had their own attributes and variables
        for i in range(ds.sizes["member"]):
            m = body.isel(member=i)
            m.attrs = old[i] if old is not None else member_attributes(ds, i)
            members.append(member_cls.from_xarray(m))
        ex = ds["ensemble_exponents"].values if "ensemble_exponents" in ds else None
        se = ds["ensemble_stderr"].values if "ensemble_stderr" in ds else None
        ratio = ds["batch_error_ratio"].values if "batch_error_ratio" in ds else None
        if NOTE in a["params"]:                  # a file from before the seeds' names: member
            for m in members:                    # i had seed + i for its state and vectors
                m.params.setdefault("state_seed", m.params.get("vectors_seed"))
        return cls(members=members, exponents=ex, stderr=se, params=a["params"],
                   error_ratio=ratio)

    def _spectra(self):
        """(mean spectrum, the members' spectra) of a Lyapunov ensemble."""
        spectra = [getattr(m, "spectrum", None) for m in self.members]
        if self.exponents is None or any(x is None for x in spectra):
            raise ValueError("the entropy and the dimension need a Lyapunov ensemble whose "
                             "members hold the whole relevant spectrum (n_exponents=None)")
        rows = np.array(spectra)
        return rows.mean(axis=0), rows

    def plot_spectrum(self, ax=None, **kw):
        """The mean exponents ± their standard error (the members' spread) against i/(N − 2)
        (``charts.plotting.plot_lyapunov_spectrum``); ``(fig, ax)``."""
        if self.exponents is None:
            raise ValueError("plot_spectrum needs a Lyapunov ensemble")
        from ..plotting import plot_lyapunov_spectrum, system_label
        kw.setdefault("label", f"{system_label(self.params)} ({len(self)} members)")
        return plot_lyapunov_spectrum(self.exponents, self.stderr, self.params["n"], ax=ax, **kw)

    def plot(self, ax=None, kind=None, **kw):
        """The ensemble's picture; ``kind`` None picks the natural one.  Exponent ensembles
        (Lyapunov, linkage): ``"members"`` (default) each member's exponents beside the mean
        ± its standard error (``charts.plotting.plot_ensemble_exponents``), ``"spectrum"``
        as `plot_spectrum`; angle ensembles: ``"histogram"`` (default), the members' angles
        pooled (``charts.plotting.plot_angles``).  ``(fig, ax)`` or ``(fig, axes)``."""
        if self.exponents is not None:
            kind = kind or "members"
            if kind == "spectrum":
                return self.plot_spectrum(ax=ax, **kw)
            if kind == "members":
                from ..plotting import plot_ensemble_exponents, system_label
                rows = np.array([m.exponents for m in self.members])
                kw.setdefault("title", f"Lyapunov exponents, {system_label(self.params)}\n"
                                       f"{len(self)} members")
                return plot_ensemble_exponents(rows, self.exponents, self.stderr, ax=ax, **kw)
            raise ValueError(f"kind must be 'members' or 'spectrum' for an ensemble of "
                             f"exponents, got {kind!r}")
        if self.members and hasattr(self.members[0], "phi_restricted"):
            kind = kind or "histogram"
            if kind != "histogram":
                raise ValueError(f"kind must be 'histogram' for an ensemble of angles, got {kind!r}")
            from ..plotting import plot_angles, system_label
            phis = {v: self.concatenate(f"phi_{v}") for v in ("full", "restricted")
                    if hasattr(self.members[0], f"phi_{v}")}   # a mechanism's: restricted
            kw.setdefault("title", f"angles between $E_u$ and $E_{{cs}}$, "
                                   f"{system_label(self.params)}: {len(self)} members pooled")
            return plot_angles(phis, axes=ax, **kw)
        raise ValueError("this ensemble's members have no common picture; plot one member "
                         "(ensemble[i].plot())")

    def summary_parts(self):
        """The members (their kind), the time of each, and the mean exponents ± their
        standard error, or for angle members the smallest restricted angle of all."""
        kind = type(self.members[0]).__name__ if self.members else "no"
        T = self.params.get("t_final")
        parts = [counted(len(self), f"{kind} member"), f"T = {T:g} each" if T is not None else ""]
        if self.exponents is not None:
            parts.append(exponent_words(self.exponents, self.stderr))
        elif self.members and hasattr(self.members[0], "phi_restricted"):
            parts.append(f"min φ restricted {smallest_words(self.concatenate('phi_restricted'))}")
        return parts


def _member(job):
    fn, system, seed, speed, t_final, kwargs = job
    theta0, u0 = system.random_state(seed=seed, speed=speed)
    return [fn(system, theta0, u0, t_final, seed=seed, **kwargs)]


def run_ensemble(fn, system, n_trajectories, t_final, *, speed=1.0, seed=0, workers=None,
                 progress=False, desc="ensemble", prime=None, pool=None, client=None,
                 notice=None, **kwargs) -> EnsembleResult:
    """``fn(system, theta0, u0, t_final, seed=s, **kwargs)`` on ``n_trajectories`` random
    states of speed ``speed`` (seeds seed, seed+1, …), in ``workers`` processes (default:
    all cores; 1: in this process), in the process pool ``pool`` (a caller's, kept across
    its ensembles) or on the Dask cluster ``client`` (``charts.analyses.cluster``: a Client,
    a scheduler's address or "local", a LocalCluster of ``workers`` processes).  Members
    whose results have ``exponents`` give the ensemble's mean and standard error.
    ``prime``: (t_final, settings overriding kwargs) of a short call that compiles the
    kernels in this process before the workers start (`map_jobs`); ``notice``: (name, n) of
    its compile notices (default: ``fn``'s name and ``system.n``, the rotors' N)."""
    n_trajectories, seed, workers = ensemble_arguments(n_trajectories, t_final, speed, seed,
                                                       workers, progress)
    if pool is not None and client is not None:
        raise ValueError("give pool= or client=, not both")
    jobs = [(fn, system, seed + i, speed, t_final, kwargs)
            for i in range(n_trajectories)]
    first = None
    if prime is not None:
        first = (_member, (fn, system, seed, speed, prime[0], {**kwargs, **prime[1]}))
    name, n = notice or (fn.__name__, system.n)
    with cluster_pool(client, workers) as (cluster, slots):
        members = map_jobs(_member, jobs, [1] * len(jobs), slots, t_final, progress, desc,
                           prime=first, name=name, n=n,
                           pool=pool if pool is not None else cluster)
    return ensemble_result(members, system, seed, speed, t_final, kwargs)


def ensemble_arguments(n_trajectories, t_final, speed, seed, workers, progress):
    """Checked (n_trajectories, seed, workers) of an ensemble (ValueError naming the bad one)."""
    n_trajectories = integer("n_trajectories", n_trajectories, 2, MAX_MEMBERS)
    seed = seed_of(seed)
    if workers is not None:
        workers = integer("workers", workers, 1, MAX_WORKERS)
    positive_time("t_final", t_final)
    if positive_time("speed", speed) > MAX_SPEED:
        raise ValueError(f"speed={float(speed):g} is beyond {MAX_SPEED:g}: the kinetic energy "
                         "½|u|² of such a state overflows a float")
    check_progress(progress)
    return n_trajectories, seed, workers


def map_jobs(fn, jobs, sizes, workers, t_final, progress, desc, prime=None, name=None, n=None,
             pool=None):
    """The members of ``fn(job)`` for the jobs, in order (each returns a list of ``sizes[i]``
    members), in ``workers`` processes (default all cores; 1: in this process) or in the
    executor ``pool`` (a caller's, not shut down here: a process pool, or a Dask cluster's,
    ``charts.analyses.cluster.cluster_pool``); progress in simulated time (members done ×
    t_final).  `stream_jobs` runs them.

    With workers, the kernels are compiled once: ``prime`` = (function, job), a short call
    that compiles them, runs here first, so that the workers load them from numba's disk
    cache instead of each compiling them at once; what it or a worker compiled for longer
    than ``charts.jit.compilation.NOTE_SECONDS`` is announced here, on this process's stderr
    (``name``, ``n``: the analysis and N the notice names).  Never more processes than jobs
    (``workers=10**6`` for two jobs starts two)."""
    return _collect(stream_jobs(fn, jobs, workers, prime, name, n, pool), sizes, t_final,
                    progress, desc)


def stream_jobs(fn, jobs, workers, prime=None, name=None, n=None, pool=None):
    """``fn(job)`` of each job, yielded in the jobs' order as they come in: as `map_jobs`
    (``workers``, ``pool``, ``prime`` and the compile notices there), for a caller that
    consumes each result as it arrives (``charts.analyses.hyperbolicity.hyperbolicity_tally``
    merges each chunk's tally and saves its checkpoint)."""
    workers = min(workers or os.cpu_count() or 1, max(1, len(jobs)))
    if workers == 1 and pool is None:
        yield from map(fn, jobs)
        return
    name = name or getattr(fn, "__name__", "ensemble")
    if prime is not None:
        announce(name, timed_call(*prime)[1], n)
    with nullcontext(pool) if pool is not None else worker_pool(workers) as executor:
        timed = executor.map(_timed_job, [(fn, job) for job in jobs])
        try:
            yield from _announced(timed, name, n)
        finally:                # left early (an error, a Ctrl-C): the jobs not started
            close = getattr(timed, "close", None)   # are cancelled by the executor's own
            if close is not None:                   # iterator
                close()


def member_states_of(states_of, system, cfg, seeds, speed, workers):
    """The members' initial states [Zs, scs, speeds] (``charts.solvers.device.flow_states``)
    of the seeds, built by ``states_of((system, cfg, seeds, speed))`` (which returns them in
    a list of one) in about four chunks per process of ``workers`` (`map_jobs`; the first
    seed's state built here first, so that the workers load its kernels from the disk cache
    instead of each compiling them)."""
    size = max(1, -(-len(seeds) // (4 * workers)))
    jobs = [(system, cfg, seeds[i:i + size], speed) for i in range(0, len(seeds), size)]
    parts = map_jobs(states_of, jobs, [1] * len(jobs), workers, 0.0, False, "states",
                     prime=(states_of, (system, cfg, seeds[:1], speed)),
                     name=getattr(states_of, "__name__", "states"), n=system.n)
    return [np.concatenate(a) for a in zip(*parts)]


def _timed_job(fn_job):
    """In a worker: (``fn(job)``, seconds numba spent compiling in it)."""
    fn, job = fn_job
    return timed_call(fn, job)


def _announced(timed, name, n):
    """The results of (result, compile seconds) pairs, announcing a worker's long compilation."""
    for result, seconds in timed:
        announce(name, seconds, n, where=" in a worker process")
        yield result


#: Members' settings that are each member's own (its initial state and the seeds of that
#: state and of its tangent vectors, its measured speed), never the ensemble's even where the
#: members happen to share them.
OWN_SETTINGS = ("vectors_seed", "state_seed", "speed", "theta0", "u0")


def resolved_settings(members, kwargs) -> dict:
    """The settings of the call as the members resolved them: every setting the members
    share (defaults filled in, durations on the step grid: ``dt=0.01`` written or left out
    gives the same), over ``kwargs`` (the keywords written; those the members do not record,
    such as ``device``, kept as written); `OWN_SETTINGS` excluded."""
    shared = {}
    params = [getattr(m, "params", None) or {} for m in members]
    if params:
        for key, value in params[0].items():
            if key not in OWN_SETTINGS and all(
                    key in p and same_value(p[key], value) for p in params[1:]):
                shared[key] = value
    return {**kwargs, **shared}


def ensemble_result(members, system, seed, speed, t_final, kwargs) -> EnsembleResult:
    """The `EnsembleResult` of ``members`` (seeds seed, seed+1, …); its ``params``: the
    system, the ensemble's own arguments (``members_seed``: the first member's seed) and the
    members' resolved settings (`resolved_settings`), so that equal calls typed differently
    give equal results and a file's top level names every setting.  Member i records the seed
    of its initial state, ``state_seed`` = seed + i (``system.random_state(seed=seed + i,
    speed=speed)``), beside ``vectors_seed``, the seed of its tangent vectors."""
    for i, m in enumerate(members):
        if getattr(m, "params", None) is not None:
            m.params["state_seed"] = seed + i
    res = EnsembleResult(members, params={**resolved_settings(members, kwargs),
                                          **system_settings(system),
                                          "n_trajectories": len(members),
                                          "members_seed": seed, "speed": float(speed),
                                          "t_final": float(t_final)})
    if all(hasattr(m, "exponents") for m in members):
        E = np.array([m.exponents for m in members])
        res.exponents, res.stderr = E.mean(axis=0), standard_error(E)
        if all(getattr(m, "stderr", None) is not None for m in members):
            res.error_ratio = error_ratio_of(E, np.array([m.stderr for m in members]))
            warn_understated(res.error_ratio, len(members))
    return res


def system_settings(system) -> dict:
    """The system as an ensemble's settings: ``system.describe()`` (the rotors, the
    Appendix's linkage), else a Mechanism's name and parameter values (as its members'
    results record them, ``charts.analyses.mechanism_lyapunov``)."""
    describe = getattr(system, "describe", None)
    if describe is not None:
        return describe()
    return dict(mechanism=system.name, parameters=system.parameter_values)


class ErrorBarWarning(UserWarning):
    """The error bars of single runs understate the spread between trajectories."""


#: Fewest members for `warn_understated` to judge (the spread's own relative error is
#: 1/√(2(M − 1)): 27 % at 8 members).
MIN_MEMBERS_TO_JUDGE = 8
#: `error_ratio_of` below which the members' error bars count as understated: with 8 members
#: an honest ratio falls below 0.5 by chance with probability ≈ 2·10⁻⁴ (χ² with 7 degrees of
#: freedom above 28).
UNDERSTATED_RATIO = 0.5


def error_ratio_of(exponents, stderrs):
    """(k,) the members' batch-mean errors, root mean square over the members, divided by
    the standard deviation of their exponents (members × k both): each member's error bar
    claims the error of its own estimate, the spread measures it; NaN for fewer than two
    members or no spread."""
    E = np.asarray(exponents, dtype=float)
    if E.shape[0] < 2:
        return np.full(E.shape[1:], np.nan)
    spread = E.std(axis=0, ddof=1)
    claimed = np.sqrt(np.mean(np.asarray(stderrs, dtype=float) ** 2, axis=0))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(spread > 0, claimed / spread, np.nan)


def warn_understated(ratio, members) -> None:
    """`ErrorBarWarning` when an ensemble of at least `MIN_MEMBERS_TO_JUDGE` members shows
    error bars of single runs below `UNDERSTATED_RATIO` of the spread between them."""
    r = np.asarray(ratio, dtype=float)
    bad = np.flatnonzero(r < UNDERSTATED_RATIO)
    if members >= MIN_MEMBERS_TO_JUDGE and bad.size:
        i = int(bad[np.argmin(r[bad])])
        warnings.warn(f"the members' own error bars understate the spread between trajectories: "
                      f"for exponent {i} they are {r[i]:.2f} of the members' standard deviation "
                      f"({members} members); quote the ensemble's stderr (across trajectories), "
                      "not a single run's batch error, and run longer transients or longer runs",
                      ErrorBarWarning, stacklevel=3)


def _collect(it, sizes, t_final, progress, desc):
    """The members in order; progress in simulated time (members done × t_final)."""
    rep = progress_reporter(progress, sum(sizes) * t_final, desc)
    out = []
    for r, size in zip(it, sizes):
        out.extend(r)
        rep.update(size * t_final)
    rep.close()
    return out
