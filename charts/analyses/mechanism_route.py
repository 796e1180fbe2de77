"""The route of the public analyses to a Mechanism: ``charts.lyapunov_spectrum``,
``hyperbolicity_angles``, ``curvature_along_trajectory`` and ``covariant_lyapunov_vectors``,
and the ensembles ``lyapunov_ensemble``, ``hyperbolicity_ensemble``, ``hyperbolicity_tally``
and ``covariant_ensemble``, take a ``charts.Mechanism`` that is not a ``RotorSystem`` (the
rotors keep their own route, bit for bit) and hand it to the generic analysis of
``charts.analyses`` named by `mechanism_route`, with the caller's arguments: positional
(system, state, velocity, t_final) as for the rotors, keywords by the generic analysis's names
(q0, v0, …) or the rotors' spelling of the state (theta0, u0).  A rotors' setting the generic
analysis does not take is refused naming it (TypeError), never dropped: here, or for an
ensemble (whose ``**kwargs`` are its members' settings) by the ensemble
(``charts.analyses.mechanism_ensemble.member_settings``).

Nothing here imports the mechanism layer (SymPy): a process that never made a Mechanism
cannot hold one, so the test is `generic_mechanism`'s look into ``sys.modules``.
"""
from __future__ import annotations

import functools
import importlib
import inspect
import sys

__all__ = ["generic_mechanism", "mechanism_route", "STATE_NAMES"]

#: The rotors' keywords of the state and the generic analyses' names for them.
STATE_NAMES = {"theta0": "q0", "u0": "v0"}

_MODEL = __package__.rsplit(".", 1)[0] + ".mechanism.model"


def generic_mechanism(system) -> bool:
    """True where ``system`` is a ``charts.Mechanism`` that is not a ``charts.RotorSystem``
    (a subclass or not: the rotors keep their own route)."""
    model = sys.modules.get(_MODEL)
    if model is None:                  # no Mechanism was ever made in this process
        return False
    from ..geometry.system import RotorSystem
    return isinstance(system, model.Mechanism) and not isinstance(system, RotorSystem)


def _generic_arguments(target, args, kw):
    """(args, kw) for ``target`` from a call of the rotors' entry point: ``system`` moved to
    the first place, theta0/u0 renamed, every keyword checked against ``target``."""
    kw = dict(kw)
    if not args:
        args = (kw.pop("system"),)
    for rotor, generic in STATE_NAMES.items():
        if rotor in kw:
            if generic in kw:
                raise TypeError(f"give {generic} or {rotor} (the same argument), not both")
            kw[generic] = kw.pop(rotor)
    takes = inspect.signature(target).parameters
    if any(p.kind is p.VAR_KEYWORD for p in takes.values()):
        return args, kw                 # an ensemble: it checks its members' settings itself
    for key in kw:
        if key not in takes:
            raise TypeError(f"{key} is a setting of the rotors' route: {target.__name__} of a "
                            f"Mechanism takes {', '.join(list(takes)[1:])}")
    return args, kw


def _known_system(system):
    """TypeError naming ``system`` where it is neither a ``charts.RotorSystem`` nor another
    ``charts.Mechanism`` (the rotors' own check would name only the first)."""
    from ..geometry.system import RotorSystem
    if not isinstance(system, RotorSystem):
        from ..geometry.checks import shown
        raise TypeError(f"system must be a charts.RotorSystem or another charts.Mechanism, "
                        f"got {shown(system)}")


def mechanism_route(module, name):
    """Decorator of a rotors' public analysis: a call whose system (first argument or
    ``system=``) is a `generic_mechanism` goes to ``charts.analyses.<module>.<name>``
    (imported at that call) with the caller's arguments (module docstring); every other call
    to the decorated function, unchanged."""
    def wrap(fn):
        @functools.wraps(fn)
        def call(*args, **kw):
            system = args[0] if args else kw.get("system")
            if not generic_mechanism(system):
                _known_system(system)
                return fn(*args, **kw)
            target = getattr(importlib.import_module(f"{__package__}.{module}"), name)
            args, kw = _generic_arguments(target, args, kw)
            return target(*args, **kw)
        return call
    return wrap
