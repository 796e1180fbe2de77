"""The angle test at scale as a verdict (``charts verdict --statistics``;
docs/hyperbolicity.md): members tallied by ``charts.analyses.angle_tally``, their report and
its verdict (`charts.runs.verdict.case_verdict`: statistics decide nothing), and the systems
of a bundled sweep to run it on."""
from __future__ import annotations

import json
import time
import warnings

import numpy as np

from .verdict import case_verdict, verdict_line

__all__ = ["statistics_verdict", "tally_report", "family_systems", "format_statistics",
           "members_window"]


def members_window(samples, members, sample_every=0.1, unit=1.0) -> float:
    """The window T per member for at least ``samples`` angles over ``members`` members
    sampled every ``sample_every``: a whole number of ``unit`` (the checkpoint segment)."""
    return float(unit * np.ceil(samples / members * sample_every / unit))


def statistics_verdict(system, samples, *, members, device="auto", t_transient=100.0,
                       sample_every=0.1, workers=None, out=None, label="",
                       progress=False, checkpoint=None, client=None) -> dict:
    """The angle test at scale: ``members`` trajectories (seeds 0, 1, …) with at least
    ``samples`` angles together, tallied (``charts.analyses.angle_tally``), as one JSON-ready
    dict: the run (members, window, device, seconds) and `AngleTally.statistics` of both
    variants; the tally saved as ``out`` (a path) when given; ``checkpoint``: the path of
    the partial tally of a run on the CPU (`hyperbolicity_tally`); ``client``: its chunks on
    a Dask cluster (`hyperbolicity_tally`'s; the device is then the workers' CPUs)."""
    from ..analyses.tally_run import hyperbolicity_tally
    t_final = members_window(samples, members, sample_every)
    t0 = time.perf_counter()
    tally = hyperbolicity_tally(system, members, t_final, device=device, workers=workers,
                                t_transient=t_transient, sample_every=sample_every,
                                progress=progress, checkpoint=checkpoint, client=client)
    rep = tally_report(tally, label, time.perf_counter() - t0)
    if out is not None:
        rep["file"] = str(tally.save(out))
    return rep


def tally_report(tally, label="", seconds=None) -> dict:
    """The report of an `AngleTally` as `statistics_verdict` writes it: the run (system,
    members, window, transient, sample step, device, ``seconds`` or None for a tally read
    from a file) and `AngleTally.statistics` of both variants."""
    from ..analyses.angle_tally import VARIANTS
    p = tally.params
    system = {k: p[k] for k in ("n", "masses", "weights", "level") if k in p}
    rep = dict(label=label, system=system, members=tally.n_members, t_final=p["t_final"],
               t_transient=p["t_transient"], sample_every=p["sample_every"],
               device=p["device"], seconds=seconds,
               statistics={v: tally.statistics(v) for v in VARIANTS})
    return dict(rep, **case_verdict(rep))


def family_systems(name) -> list:
    """[(label, RotorSystem)] of the distinct systems (N, masses, weights, level) of the
    bundled sweep ``name``, in the sweep's order; the test runs them at unit speed.
    ValueError for a sweep of the linkage."""
    from ..geometry.system import RotorSystem
    from .sweep.points import sweep_points
    from .sweep.spec import bundled_sweeps, load_sweep
    sweeps = bundled_sweeps()
    if name not in sweeps:
        raise ValueError(f"unknown sweep {name!r}; bundled: {', '.join(sorted(sweeps))}")
    out, seen = [], set()
    for point in sweep_points(load_sweep(sweeps[name])):
        sysd = point.scene.system
        if sysd.get("kind", "rotors") != "rotors":
            raise ValueError(f"the sweep {name!r} runs the {sysd['kind']}: the angle test at "
                             "scale is the rotors' (charts.linkage_angles for the linkage)")
        key = json.dumps([sysd["n"], sysd.get("masses"), sysd.get("weights"),
                          sysd.get("level", 0.0)])
        if key in seen:                     # points that differ only in seed, speed, …
            continue
        seen.add(key)
        params = {k: v for k, v in point.params.items() if k not in ("seed", "speed")}
        with warnings.catch_warnings():       # critical levels: a stopped member is reported
            warnings.simplefilter("ignore")
            system = RotorSystem(sysd["n"], masses=sysd.get("masses"),
                                 weights=sysd.get("weights"), level=sysd.get("level", 0.0))
        out.append((", ".join(f"{k} {v}" for k, v in params.items()), system))
    return out


def format_statistics(rep: dict) -> str:
    """A report of `statistics_verdict` as text: the restricted angles first ("?" for a
    number the report leaves undefined)."""
    def f(x, fmt):
        return "?" if x is None else format(x, fmt)
    s = rep["system"]
    took = "read from its saved tally" if rep.get("seconds") is None else f"{rep['seconds']:.0f} s"
    head = (f"{rep['label'] or 'N = ' + str(s['n'])}: masses {s['masses']}, weights "
            f"{s['weights']}, level {s['level']:g}; {rep['members']} members x T = "
            f"{rep['t_final']:g} (transient {rep['t_transient']:g}) on the {rep['device']}, "
            f"{took}")
    lines = [head]
    for variant in ("restricted", "full"):
        st = rep["statistics"][variant]
        lines.append(f"  {variant}: {st['n']:.3g} angles, min {st['min']:.3g} rad (seed "
                     f"{st['min_seed']}, t = {f(st['min_t'], 'g')}); {st['episodes']} episodes "
                     f"below {st['small']:g} rad ({f(st['episode_rate'], '.3g')} per time unit)")
        laws = [f"x0 {d['x0']:g}: beta {f(d['exponent'], '.3f')} ± "
                f"{f(d['exponent_se'], '.3f')} (n {d['count']})" for d in st["law"] if d["count"]]
        if laws:
            lines.append("    law P(phi < x) = A x^beta: " + "; ".join(laws))
        lines.append("    mean block minima: " + ", ".join(
            f"{size:g}: {f(m, '.3g')} ± {f(se, '.1g')}" for size, m, se in st["block_minima"]))
        lines.append("    slopes d ln min / d ln size: " + ", ".join(
            f"{a:g}-{b:g}: {f(x, '.3f')} ± {f(se, '.3f')}" for a, b, x, se in st["slopes"]))
    lines.append(verdict_line(rep))
    return "\n".join(lines)
