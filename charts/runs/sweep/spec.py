"""Sweep files: the :class:`Sweep` read from TOML and validated, and the bundled sweeps.

Every error is a :class:`SweepError` whose message names the key, the value and what is
allowed.  The layout of a sweep file is described in :mod:`charts.runs.sweep` and
docs/sweeps.md.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

from ..bundled import bundled_files, path_or_bundled
from ..input_files import read_toml
from ...geometry.checks import path as file_path
from ...geometry.checks import shown
from ..scene_checks import is_finite_number, source_names, unknown_key
from .expressions import ExpressionError, expression_symbols

__all__ = ["Sweep", "SweepError", "load_sweep", "parse_sweep", "bundled_sweeps",
           "resolve_sweep", "MODES", "SYSTEM_AXES", "PATTERNS", "mechanism_keys"]

MODES = ("grid", "random")
#: Parameter names with a fixed meaning; any other plain name is a symbol of the patterns,
#: or, where the base scene has a [mechanism] table holding it, that mechanism's parameter
#: (``r`` of the triple linkage; `mechanism_keys`).  (``eps``: the linkage's crank length,
#: [system] kind = "linkage" or [mechanism] name = "linkage".)
SYSTEM_AXES = {"n": "n", "speed": "speed", "level": "level", "eps": "eps"}
#: Tables of named patterns, ``[sweep.<name>]``: each is one more axis (the pattern name) and
#: fills the [system] key of the same name with the evaluated vector.
PATTERNS = ("masses", "weights")


#: Most points a sweep may have (parameter combinations × seeds): validating a point takes
#: about 1.6 ms and 6.3 kB before any runs (``large-n`` × 100 seeds, 2400 points: 3.9 s),
#: so the bound keeps the plan under three minutes and 1 GB; larger studies are split.
MAX_POINTS = 100_000


class SweepError(ValueError):
    """A sweep that cannot run.  The message names the key, the value and what is allowed."""


@dataclass(frozen=True)
class Sweep:
    """A validated sweep file: the base scene and the parameters to vary."""
    name: str
    description: str
    base: dict
    mode: str
    seeds: tuple
    axes: dict                      # name -> list (grid) or list / {min, max, log} (random)
    masses: dict = field(default_factory=dict)   # pattern name -> list of numbers/exprs
    weights: dict = field(default_factory=dict)  # pattern name -> list of numbers/exprs
    n_points: int = 0
    sample_seed: int = 0
    source: str = "<sweep>"
    data: dict = field(default_factory=dict)     # the file as read


def mechanism_keys(base: dict) -> set:
    """The parameters written in the base scene's [mechanism] table (without its ``name``):
    a plain axis of that name sets it there (``r = [0.1, 0.2]``), as ``mechanism.r`` does."""
    mech = base.get("mechanism") if isinstance(base, dict) else None
    return set(mech) - {"name"} if isinstance(mech, dict) else set()


def bundled_sweeps() -> dict[str, Path]:
    """Name -> path of every sweep shipped in ``charts/data/sweeps``."""
    return bundled_files("charts.data.sweeps")


def resolve_sweep(arg: str) -> Path:
    """A sweep argument is a path to a .toml file or the name of a bundled sweep."""
    path = path_or_bundled(arg, bundled_sweeps())
    if path is None:
        raise SweepError(f"{shown(arg)} is neither a sweep file nor a bundled sweep (list them with "
                         "`charts sweep --list`)")
    return path


def load_sweep(path) -> Sweep:
    """Read and validate a sweep file (TOML).  Raises :class:`SweepError` (ValueError for a
    ``path`` that is not a path)."""
    path = file_path("path", path)
    data = read_toml(path, "sweep", SweepError, " (bundled sweeps: `charts sweep --list`)")
    return parse_sweep(data, source=str(path), default_name=path.stem)


def parse_sweep(data: dict, *, source="<sweep>", default_name="sweep") -> Sweep:
    """Validate a sweep given as a dict (as read from TOML); every point's scene is
    validated by :func:`charts.runs.sweep.sweep_points` too."""
    source_names(source, default_name, SweepError)
    if not isinstance(data, dict):
        raise SweepError(f"{source}: a sweep is a TOML table, got {type(data).__name__}")
    top = {"name", "description", "scene", "sweep"}
    for key in data:
        if key not in top:
            raise unknown_key(source, "", key, top, SweepError)
    base = data.get("scene", {})
    if not isinstance(base, dict):
        raise SweepError(f"{source}: [scene] must be a table (the base scene)")
    if any(k in base.get("initial", {}) for k in ("theta", "u")):
        raise SweepError(f"{source}: [scene.initial] theta/u are not allowed in a sweep: "
                         "points are seeded (use [sweep] seeds)")
    if "name" in base:
        raise SweepError(f"{source}: [scene] name is not allowed: points are named "
                         "<sweep name>-<index>")
    sw = data.get("sweep")
    if not isinstance(sw, dict):
        raise SweepError(f"{source}: [sweep] is required: the parameters to vary")
    allowed = {"mode", "seeds", "n_points", "sample_seed", "parameters", *PATTERNS}
    for key in sw:
        if key not in allowed:
            raise unknown_key(source, "sweep", key, allowed, SweepError)
    mode, seeds, n_points, sample_seed = _sampling(source, sw)
    axes = sw.get("parameters", {})
    patterns = {k: sw.get(k, {}) for k in PATTERNS}
    if not isinstance(axes, dict) or not all(isinstance(v, dict) for v in patterns.values()):
        raise SweepError(f"{source}: [sweep.parameters], [sweep.masses] and [sweep.weights] "
                         "must be tables")
    if "seed" in axes or any(k in axes for k in PATTERNS):
        raise SweepError(f"{source}: [sweep.parameters] seed/masses/weights are reserved: use "
                         "[sweep] seeds and the [sweep.masses] / [sweep.weights] patterns")
    if patterns["weights"] and "system.weights" in axes:
        raise SweepError(f"{source}: [sweep.weights] and the axis \"system.weights\" both set the "
                         "weights; keep one")
    for key in sorted(k for k in axes if "." not in k and f"mechanism.{k}" in axes):
        raise SweepError(f"{source}: [sweep.parameters] {key} and \"mechanism.{key}\" both set "
                         f"the mechanism's {key}; keep one")
    for name, vals in axes.items():
        _check_axis(f"{source}: [sweep.parameters] {name}", name, vals, mode)
    for v in axes.get("speed", []) if isinstance(axes.get("speed"), list) else []:
        if isinstance(v, str) and not _speed_expression(v):
            raise SweepError(f"{source}: [sweep.parameters] speed = {shown(v)}: a speed given as a "
                             "string must be an arithmetic expression in n (e.g. \"n ** 0.5\": "
                             "kinetic energy ½ per rotor of unit mass)")
    symbols = {k for k in axes if "." not in k and k not in SYSTEM_AXES
               and k not in mechanism_keys(base)}
    used = set()
    for kind, table in patterns.items():
        used |= _pattern_symbols(source, kind, table, symbols)
    _plan_points(source, mode, seeds, n_points, patterns, axes)
    unused = symbols - used
    if unused:
        mech = isinstance(base, dict) and isinstance(base.get("mechanism"), dict)
        hint = (f" (for a parameter of the factory that [scene.mechanism] does not write: "
                f"\"mechanism.{min(unused)}\")") if mech else ""
        raise SweepError(f"{source}: [sweep.parameters] {', '.join(sorted(unused))} is not used: "
                         "reference it in a [sweep.masses] or [sweep.weights] pattern, or use n, "
                         "speed, level, a parameter of the [scene.mechanism] table or a dotted "
                         f"scene key such as \"run.t_final\" or \"mechanism.r\"{hint}")
    return Sweep(name=data.get("name", default_name), description=data.get("description", ""),
                 base=base, mode=mode, seeds=tuple(seeds), axes=dict(axes),
                 masses=dict(patterns["masses"]), weights=dict(patterns["weights"]),
                 n_points=n_points or 0, sample_seed=sample_seed, source=source, data=data)


def _plan_points(source, mode, seeds, n_points, patterns, axes) -> int:
    """The number of points (combinations × seeds), counted before any is built;
    :class:`SweepError` with the factors above `MAX_POINTS`."""
    factors = [(f"[sweep.{k}]", len(t)) for k, t in patterns.items() if t]
    if mode == "grid":
        factors += [(name, len(vals)) for name, vals in axes.items()]
    else:
        factors.append(("n_points", n_points))
    factors.append(("seeds", len(seeds)))
    total = math.prod(n for _, n in factors)
    if total > MAX_POINTS:
        factors_text = " × ".join(f"{_count(n)} ({name})" for name, n in factors)
        cost = (f" (planning them alone would take {total * 1.6e-3:.3g} s and "
                f"{total * 6.3e3 / 2**30:.3g} GiB)" if total < 10**300 else "")
        raise SweepError(f"{source}: the sweep has {_count(total)} points = {factors_text}, more "
                         f"than the {MAX_POINTS} a sweep may have{cost}; split the study into "
                         "several sweeps or use mode = \"random\" with n_points")
    return total


def _count(n: int) -> str:
    """An integer count for a message: exact up to 10¹², else its leading digits and the
    exponent (also beyond a float's range)."""
    n = int(n)
    if n <= 10**12:
        return str(n)
    digits = str(n)
    return f"{digits[0]}.{digits[1:3]}e+{len(digits) - 1:02d}"


def _speed_expression(v: str) -> bool:
    try:
        return expression_symbols(v) <= {"n"}
    except ExpressionError:
        return False


def _is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def _sampling(source, sw: dict):
    """``mode, seeds, n_points, sample_seed`` of the [sweep] table, validated."""
    mode = sw.get("mode", "grid")
    if mode not in MODES:
        raise SweepError(f"{source}: [sweep] mode = {shown(mode)} is not allowed "
                         f"(allowed: {', '.join(map(repr, MODES))})")
    seeds = sw.get("seeds", [0])
    if _is_int(seeds) and seeds > MAX_POINTS:
        raise SweepError(f"{source}: [sweep] seeds = {seeds} is more than the {MAX_POINTS} "
                         "points a sweep may have; split the study into several sweeps")
    if _is_int(seeds) and seeds >= 1:
        seeds = list(range(seeds))
    if not (isinstance(seeds, list) and seeds and all(_is_int(s) and s >= 0 for s in seeds)):
        raise SweepError(f"{source}: [sweep] seeds = {shown(seeds)} is not allowed: expected a "
                         "non-empty list of integers >= 0, or a count >= 1")
    if len(set(seeds)) != len(seeds):
        raise SweepError(f"{source}: [sweep] seeds = {shown(seeds)} repeats a seed")
    n_points, sample_seed = sw.get("n_points"), sw.get("sample_seed", 0)
    if mode == "random":
        if not (_is_int(n_points) and n_points >= 1):
            raise SweepError(f"{source}: [sweep] n_points = {shown(n_points)}: random mode needs "
                             "an integer >= 1 (the number of parameter draws)")
        if not _is_int(sample_seed):
            raise SweepError(f"{source}: [sweep] sample_seed = {shown(sample_seed)}: expected an integer")
    elif n_points is not None or "sample_seed" in sw:
        raise SweepError(f"{source}: [sweep] n_points/sample_seed are for mode = \"random\" "
                         "only")
    return mode, seeds, n_points, sample_seed


def _check_axis(where: str, name: str, vals, mode: str) -> None:
    """One entry of [sweep.parameters]: a list of values, or a range in random mode."""
    if isinstance(vals, dict):
        if mode != "random":
            raise SweepError(f"{where} = {shown(vals)}: a range {{min, max, log}} needs mode = "
                             "\"random\"; a grid takes a list of values")
        extra = set(vals) - {"min", "max", "log"}
        if extra or not (is_finite_number(vals.get("min")) and is_finite_number(vals.get("max"))
                         and vals["min"] < vals["max"]):
            raise SweepError(f"{where} = {shown(vals)} is not allowed: expected {{min = a, "
                             "max = b, log = true|false}} with a < b")
        if vals.get("log", False) and vals["min"] <= 0:
            raise SweepError(f"{where}: log = true needs min > 0")
    elif not (isinstance(vals, list) and vals):
        raise SweepError(f"{where} = {shown(vals)} is not allowed: expected a non-empty list "
                         "of values" + (" or {min, max, log}" if mode == "random" else ""))
    elif len({json.dumps(v) for v in vals}) != len(vals):
        raise SweepError(f"{where} = {shown(vals)} repeats a value")
    if "." in name:
        section = name.split(".")[0]
        if section not in ("system", "mechanism", "initial", "integrator", "run", "effects"):
            raise SweepError(f"{where}: a dotted key must start with system., mechanism., "
                             "integrator., run. or effects. (e.g. \"run.t_final\", "
                             "\"mechanism.r\")")
        if name in ("system.masses", "system.n", "system.speed", "initial.seed"):
            raise SweepError(f"{where}: use the parameter name "
                             f"{shown(name.split('.')[-1])} (or seeds / [sweep.masses])")


def _pattern_symbols(source, kind: str, patterns: dict, symbols: set) -> set:
    """Validate the [sweep.<kind>] patterns (kind: masses or weights); return the parameter
    symbols they use."""
    used = set()
    for pname, pat in patterns.items():
        where = f"{source}: [sweep.{kind}] {shown(pname)}"
        if not (isinstance(pat, list) and pat):
            raise SweepError(f"{where} = {shown(pat)}: expected a list of numbers or expressions")
        for x in pat:
            if isinstance(x, str):
                try:
                    names = expression_symbols(x)
                except ExpressionError as exc:
                    raise SweepError(f"{where}: {exc}") from None
                missing = names - symbols
                if missing:
                    raise SweepError(f"{where}: {shown(x)} uses {', '.join(sorted(missing))}, which is "
                                     "not a parameter; add it to [sweep.parameters]")
                used |= names
            elif not (is_finite_number(x) and x > 0):
                raise SweepError(f"{where}: {shown(x)} is not allowed: entries are numbers > 0 or "
                                 "expressions in the parameters")
    return used
