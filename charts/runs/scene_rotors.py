"""The rotors' [system] and [initial] tables of a scene (charts.runs.scene): N, masses,
weights and level as ``RotorSystem`` takes them, and an explicit state on its manifold; a
[mechanism] table's are ``charts.runs.scene_mechanism``'s."""
from __future__ import annotations

import math
import warnings

from ..geometry.checks import shown
from .scene_checks import where
from .scene_mechanism import LINKAGE_KEYS
from .scene_schema import SceneError

__all__ = ["check_rotors", "check_family", "check_state"]


def check_rotors(source, system, raw_sys, initial, raw_init):
    """The joined rules of a rotor scene's [system] and [initial] (kind = "rotors")."""
    n = system["n"]
    for key in ("kind",) + LINKAGE_KEYS:    # no trace of the linkage's keys: ids unchanged
        del system[key]
    if system["masses"] is not None and len(system["masses"]) != n:
        raise SceneError(f"{where(source, 'system', 'masses')} = {shown(system['masses'])} is not "
                         f"allowed: expected a list of n = {n} positive numbers")
    masses = system["masses"] if system["masses"] is not None else [1.0] * n
    system["masses"] = masses
    if system["weights"] is not None and len(system["weights"]) != n:
        raise SceneError(f"{where(source, 'system', 'weights')} = {shown(system['weights'])} is not "
                         f"allowed: expected a list of n = {n} positive numbers")
    check_family(source, system)
    # the paper's constraint leaves no trace: scenes (and sweep point ids) stay as they were
    if system["weights"] is None:
        del system["weights"]
    if system["level"] == 0.0 and "level" not in raw_sys:
        del system["level"]

    # -- initial state ---------------------------------------------------------------------
    explicit = ("theta" in raw_init) or ("u" in raw_init)
    if explicit:
        if "seed" in raw_init:
            raise SceneError(f"{where(source, 'initial', 'seed')} = {shown(raw_init['seed'])} is not "
                             "allowed together with an explicit theta/u: give one or the other")
        for key in ("theta", "u"):
            if key not in raw_init:
                other = "u" if key == "theta" else "theta"
                raise SceneError(f"{where(source, 'initial', key)} is required when "
                                 f"[initial] {other} is given (an explicit state needs both)")
            if len(initial[key]) != n:
                raise SceneError(f"{where(source, 'initial', key)} = {shown(initial[key])} is not "
                                 f"allowed: expected a list of n = {n} numbers")
        if "speed" in raw_sys:
            raise SceneError(f"{where(source, 'system', 'speed')} = {shown(raw_sys['speed'])} is not "
                             "allowed with an explicit [initial] u (the speed is that of u)")
        check_state(source, n, masses, initial["theta"], initial["u"], system.get("weights"),
                     system.get("level", 0.0))
        initial["seed"] = None
        system["speed"] = float(math.sqrt(sum(m * x * x for m, x in zip(masses, initial["u"]))))
        if not system["speed"] > 0:
            raise SceneError(f"{where(source, 'initial', 'u')} = {shown(initial['u'])} is not "
                             "allowed: the velocity must be nonzero (a geodesic needs a speed)")


def check_family(source, system):
    """Weights and level as RotorSystem takes them (an empty level set is refused here)."""
    from ..geometry.system import RotorSystem       # the kernels load when a scene is read

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the critical-level warning comes with the run
        try:
            RotorSystem(system["n"], system["masses"], system["weights"], system["level"])
        except ValueError as exc:
            key = "weights" if str(exc).startswith("weights") else "level"
            raise SceneError(f"{where(source, 'system', key)} = {shown(system[key])} is not "
                             f"allowed: {exc}") from None


def check_state(source, n, masses, theta, u, weights=None, level=0.0):
    """The explicit [initial] theta on the rotors' manifold and u tangent there (SceneError
    naming the key otherwise)."""
    import numpy as np

    from ..geometry.system import RotorSystem

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sys_ = RotorSystem(n, masses, weights, level)
    try:
        sys_.check_point(np.array(theta))
    except ValueError as exc:
        raise SceneError(f"{where(source, 'initial', 'theta')} = {shown(theta)} is not allowed: "
                         f"{exc}") from None
    try:
        sys_.check_tangent(np.array(theta), np.array(u))
    except ValueError as exc:
        raise SceneError(f"{where(source, 'initial', 'u')} = {shown(u)} is not allowed: "
                         f"{exc}") from None
