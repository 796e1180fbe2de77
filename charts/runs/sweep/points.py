"""A sweep expanded into points: parameter combinations (a grid or a seeded random sample)
times seeds, each an ordinary validated scene with a content hash ``point_id``."""
from __future__ import annotations

import hashlib
import itertools
import json
import math
from dataclasses import dataclass

import numpy as np

from ..scene import Scene, SceneError, parse_scene, scene_to_dict
from .expressions import ExpressionError, evaluate_expression
from .spec import PATTERNS, SYSTEM_AXES, Sweep, SweepError, mechanism_keys

__all__ = ["SweepPoint", "sweep_points", "point_scene", "digest"]


@dataclass(frozen=True)
class SweepPoint:
    """One point: its parameters (axis name -> value, ``seed`` last), the raw scene dict
    sent to the worker, the validated :class:`Scene` and a content hash ``point_id``."""
    index: int
    params: dict
    raw: dict
    scene: Scene
    point_id: str


def sweep_points(sweep: Sweep) -> list[SweepPoint]:
    """Every point of the sweep, in a deterministic order (parameter combinations, then
    seeds), each with its validated scene.  Raises :class:`SweepError` naming the point."""
    points = []
    for combo in _combinations(sweep):
        for seed in sweep.seeds:
            params = dict(combo, seed=seed)
            index = len(points)
            desc = ", ".join(f"{k}={v}" for k, v in params.items())
            try:
                raw = point_scene(sweep, params)
            except ExpressionError as exc:
                raise SweepError(f"{sweep.source} point {index} ({desc}): pattern "
                                 f"{exc.args[0]}") from None
            raw["name"] = f"{sweep.name}-{index:04d}"
            if sweep.description:
                raw.setdefault("description", sweep.description)
            try:
                scene = parse_scene(raw, source=f"{sweep.source} point {index} ({desc})")
            except SceneError as exc:
                raise SweepError(str(exc)) from None
            d = scene_to_dict(scene)
            # the parameters are part of the identity: two families that meet (e.g. equal
            # masses in both) are two points, each with its own row
            pid = digest([params, {k: v for k, v in d.items()
                                   if k not in ("name", "description")}])
            points.append(SweepPoint(index, params, raw, scene, pid))
    if not points:
        raise SweepError(f"{sweep.source}: the sweep has no points")
    return points


def point_scene(sweep: Sweep, params: dict) -> dict:
    """The base scene (a deep copy) with the parameters of one point applied: a parameter
    of the base's [mechanism] table to that table (``r``), ``n``, ``speed`` and ``level`` to
    [system] (a string speed is an expression in n), dotted keys to their table, the mass
    and weight patterns evaluated, the seed to [initial]."""
    raw = json.loads(json.dumps(sweep.base))          # deep copy, TOML types only
    system = raw.setdefault("system", {})
    own = mechanism_keys(raw)
    for key, val in params.items():
        if key == "speed" and isinstance(val, str):  # a normalisation in n, e.g. "n ** 0.5"
            val = float(evaluate_expression(val, {"n": params.get("n", system.get("n"))}))
        if key in own:
            raw["mechanism"][key] = val
        elif key in SYSTEM_AXES:
            system[SYSTEM_AXES[key]] = val
        elif "." in key:
            *path, leaf = key.split(".")
            node = raw
            for p in path:
                node = node.setdefault(p, {})
            node[leaf] = val
    env = {k: v for k, v in params.items() if k not in (*PATTERNS, "seed") and "." not in k}
    for kind in PATTERNS:
        if kind in params:
            name = params[kind]
            try:
                system[kind] = [float(evaluate_expression(x, env)) if isinstance(x, str)
                                else float(x) for x in getattr(sweep, kind)[name]]
            except ExpressionError as exc:
                raise ExpressionError(f"[sweep.{kind}] {name!r}: {exc}") from None
    raw.setdefault("initial", {})["seed"] = params["seed"]
    return raw


def digest(obj) -> str:
    """A short content hash of a JSON-able object (keys sorted)."""
    return hashlib.sha256(json.dumps(obj, sort_keys=True).encode()).hexdigest()[:12]


def _draw(rng, spec):
    if isinstance(spec, dict):
        lo, hi = spec["min"], spec["max"]
        if spec.get("log", False):
            return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))
        return float(rng.uniform(lo, hi))
    return spec[int(rng.integers(len(spec)))]


def _combinations(sweep: Sweep) -> list[dict]:
    kinds = [k for k in PATTERNS if getattr(sweep, k)]
    names = kinds + list(sweep.axes)
    values = [list(getattr(sweep, k)) for k in kinds] + list(sweep.axes.values())
    if sweep.mode == "grid":
        return [dict(zip(names, combo)) for combo in itertools.product(*values)]
    rng = np.random.default_rng(sweep.sample_seed)
    return [{k: _draw(rng, v) for k, v in zip(names, values)} for _ in range(sweep.n_points)]
