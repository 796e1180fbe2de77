"""The scene schema: every key of a scene file, its type, default, allowed values and the
help text that ``docs/scenes.md`` documents (the tests check the page against it).

A key that a scene forwards to an API call takes that call's default (:class:`FromAPI`: read
from the function's signature, never copied here), so a scene that leaves it out and the API
call that leaves it out compute the same numbers.  :data:`API` names the call each effect
mirrors; where a linkage scene's call has another default (curvature's ``sample_every`` is
``linkage_run``'s), the key names it too (``Key.linkage``)."""
from __future__ import annotations

import importlib
import inspect
from dataclasses import dataclass
from functools import cache
from typing import Any, Callable

from ..analyses.arguments import GRID_RTOL
from ..mechanism.linkage import LENGTH_MAX, LENGTH_MIN
from ..geometry.system import MAX_N

__all__ = ["Key", "SceneError", "SCHEMA", "EFFECTS", "TOP_KEYS", "TANGENT_EFFECTS", "GRID_RTOL",
           "API", "FromAPI", "api_default"]

#: The API call each effect mirrors (``module:function``); ``linkage`` and
#: ``linkage_angles``: the main pass and the angles pass of a linkage scene; ``mechanism``:
#: the main pass of a scene with a [mechanism] table on the generic route, and
#: ``mechanism_angles`` its angles pass.
API = {
    "lyapunov": "charts.analyses.lyapunov:lyapunov_spectrum",
    "curvature": "charts.analyses.curvature:curvature_along_trajectory",
    "angles": "charts.analyses.hyperbolicity:hyperbolicity_angles",
    "clv": "charts.analyses.covariant:covariant_lyapunov_vectors",
    "waveforms": "charts.analyses.spectra:waveform",
    "linkage": "charts.analyses.linkage:linkage_run",
    "mechanism": "charts.analyses.mechanism_lyapunov:lyapunov_spectrum",
    "mechanism_angles": "charts.analyses.mechanism_angles:mechanism_angles",
    "linkage_angles": "charts.analyses.linkage_angles:linkage_angles",
}


@cache
def api_default(function: str, parameter: str):
    """The default of ``parameter`` in the signature of ``function`` (``module:name``, or a
    key of :data:`API`)."""
    module, name = API.get(function, function).split(":")
    sig = inspect.signature(getattr(importlib.import_module(module), name))
    return sig.parameters[parameter].default


@dataclass(frozen=True)
class FromAPI:
    """A scene default that is the API's own: ``parameter``'s default in the signature of
    the call that :data:`API` names for ``effect``."""
    effect: str
    parameter: str

    @property
    def value(self):
        return api_default(self.effect, self.parameter)

    def __str__(self):
        return f"{API[self.effect].split(':')[1]}'s {self.parameter} ({self.value!r})"



class SceneError(ValueError):
    """A scene that cannot run.  The message names the key, the value and what is allowed."""


# ---------------------------------------------------------------------------------------
# Schema: one Key per leaf.  ``check`` returns None when fine, else "what is allowed".
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Key:
    kind: str                      # "int", "float", "str", "bool", "floats", "ints",
                                   # "duration" (a float or a transient rule's name)
    default: Any = None            # None: no default (optional, or required if required=True)
    doc: str = ""
    choices: tuple = ()
    check: Callable[[Any], str | None] | None = None
    required: bool = False
    linkage: FromAPI | None = None  # a linkage scene's default where its call's differs

    @property
    def value(self):
        """The default a scene gets (a :class:`FromAPI` read from the API's signature)."""
        return self.default.value if isinstance(self.default, FromAPI) else self.default


def _gt(lo):
    return lambda v: None if v > lo else f"a number > {lo:g}"


def _ge(lo):
    return lambda v: None if v >= lo else f"a number >= {lo:g}"


def _int_between(lo, hi):
    return lambda v: None if lo <= v <= hi else f"an integer in {lo}..{hi}"


def _half_open(lo, hi):
    return lambda v: None if lo <= v < hi else f"a number in [{lo:g}, {hi:g})"


def _between(lo, hi):
    return lambda v: None if lo <= v <= hi else f"a number in [{lo:g}, {hi:g}]"


#: Keys at the top level of a scene file.
TOP_KEYS = {
    "name": Key("str", None, "Run name used in outputs (default: the file name without .toml)."),
    "description": Key("str", "", "Free text copied into result.json."),
}

SCHEMA: dict[str, dict[str, Key]] = {
    "system": {
        "kind": Key("str", "rotors", "\"rotors\": N rotors on Σ aᵢ cos θᵢ = level (the "
                    "paper's); \"linkage\": the exact four-rotor linkage of the Appendix "
                    "(docs/linkage.md), with eps, rho, disk_mass, disk_inertia.",
                    choices=("rotors", "linkage")),
        "n": Key("int", None, "Number of rotors N (3 <= N <= 1048576; the manifold has "
                 "dimension N−1). Required for kind = \"rotors\"; 4 for the linkage (may be "
                 "omitted).", check=_int_between(3, MAX_N)),
        "masses": Key("floats", None, "Moments of inertia m₁..m_N, all > 0 (default: all 1, "
                      "the paper's case).", check=lambda v: None if all(x > 0 for x in v)
                      else "a list of numbers, each > 0"),
        "weights": Key("floats", None, "Weights a₁..a_N of the constraint Σ aᵢ cos θᵢ = level, "
                       "all > 0 (default: all 1, the paper's case; docs/families.md).",
                       check=lambda v: None if all(x > 0 for x in v)
                       else "a list of numbers, each > 0"),
        "level": Key("float", 0.0, "Level c of the constraint Σ aᵢ cos θᵢ = c (default 0, the "
                     "paper's case); |c| < Σ aᵢ, and a critical value Σ ±aᵢ warns "
                     "(docs/families.md)."),
        "eps": Key("float", None, "Linkage only (required there): crank length ε of the "
                   "rotors' hinges, 1e-6 <= ε < 0.5 (rods R = 1; below, the projections lose "
                   "their digits); ε → 0 gives Σ cos θᵢ = 0.",
                   check=_half_open(LENGTH_MIN, LENGTH_MAX)),
        "rho": Key("float", None, "Linkage only: radius ρ of the disk's hinges, in [1e-6, 0.5) "
                   "(default 2ε, as LinkageSystem: unset in a sweep over eps, ρ/ε stays 2).",
                   check=_half_open(LENGTH_MIN, LENGTH_MAX)),
        "disk_mass": Key("float", 0.0, "Linkage only: the disk's mass m_d (default 0, the "
                         "Appendix's massless disk).", check=_ge(0)),
        "disk_inertia": Key("float", 0.0, "Linkage only: the disk's moment of inertia I_d "
                            "(default 0).", check=_ge(0)),
        "speed": Key("float", 1.0, "Speed along the geodesic ‖u‖_g = √(Σ mᵢuᵢ²) of a seeded "
                     "initial state (the paper uses 1). Not allowed with an explicit u.",
                     check=_gt(0)),
    },
    "initial": {
        "seed": Key("int", 0, "Seed of RotorSystem.random_state (used when theta/u are not "
                    "given).", check=_ge(0)),
        "theta": Key("floats", None, "Explicit initial angles, length N, on Σ cos θᵢ = 0 "
                     "(to 1e-8). Requires u; excludes seed."),
        "u": Key("floats", None, "Explicit initial angular velocities, length N, tangent: "
                 "Σ uᵢ sin θᵢ = 0 (to 1e-8). Requires theta."),
    },
    "integrator": {
        "formulation": Key("str", "ambient", "\"ambient\": the Lagrange equations (8) in N "
                           "angles; \"chart\": the intrinsic geodesic equation (14) in N−1 "
                           "chart coordinates with chart switching.", choices=("ambient", "chart")),
        "method": Key("str", "rk4", "\"rk4\": classical fixed-step Runge–Kutta (the paper's); "
                      "\"dop853\": adaptive embedded 8(5,3) with rtol/atol.",
                      choices=("rk4", "dop853")),
        "dt": Key("float", None, "RK4 step (default: the analyses' dt, 0.01, the paper's). "
                  "rk4 only.", check=_gt(0)),
        "rtol": Key("float", None, "Relative tolerance (default 1e-10). dop853 only.",
                    check=_between(1e-15, 1e-1)),
        "atol": Key("float", None, "Absolute tolerance (default rtol·min(1, speed), as "
                    "charts.integrate). dop853 only.",
                    check=_between(1e-18, 1e-1)),
        "project": Key("bool", False, "Project back onto the invariants after every step "
                       "(overrides project_every)."),
        "project_every": Key("float", FromAPI("lyapunov", "project_every"), "Time between projections of the state onto the "
                             "invariants (constraint, tangency, energy) for ambient RK4, as "
                             "project_every of the analyses; 0 = never. A multiple of dt where written; left "
                             "out, the API's default on the grid of dt (README, \"Conventions\").",
                             check=_ge(0)),
    },
    "run": {
        "t_final": Key("float", None, "Simulated time after the transient.", check=_gt(0),
                       required=True),
        "t_transient": Key("duration", None, "Time integrated first and discarded (also "
                           "settles the Lyapunov vectors), or a rule of the rotors: \"scaled\" "
                           "(5 N^2 / speed, at least 50) or \"auto\" (from a pilot run of "
                           "the scene's state; a [mechanism] scene's only rule, its pilot "
                           "the mechanism's), resolved when the scene is read. Default: the "
                           "API's default of the call the main pass mirrors: "
                           "lyapunov_spectrum's (\"scaled\") with lyapunov, else "
                           "curvature_along_trajectory's with curvature (linkage: "
                           "linkage_run's), else waveform's; with only angles or clv, "
                           "that pass's. Written, it is every pass's transient.", check=_ge(0)),
        "sample_dt": Key("float", None, "Interval between stored samples (default: dt for "
                         "rk4, 0.01 for dop853); a multiple of dt for rk4.", check=_gt(0)),
        "checkpoint_every": Key("float", None, "Simulated time between checkpoints / progress "
                                "updates (default: t_final/20, rounded to samples); a "
                                "multiple of sample_dt.", check=_gt(0)),
    },
}

#: Effects and their options.  Each is requested by its table (or ``name = true``).
EFFECTS: dict[str, dict[str, Key]] = {
    "waveforms": {
        "rotors": Key("ints", None, "Rotors whose velocity uᵢ(t) is stored and plotted "
                      "(0-based; default: all)."),
        "t_window": Key("float", 100.0, "Length of the stored window, from the end of the "
                        "transient (capped at t_final).", check=_gt(0)),
    },
    "spectrum": {
        "rotor": Key("int", 0, "Rotor whose velocity is analysed (0-based).", check=_ge(0)),
        "nperseg": Key("int", 4096, "Welch segment length in samples (scipy.signal.welch).",
                       check=_ge(16)),
    },
    "lyapunov": {
        "n_exponents": Key("int", None, "Number of exponents (default N−2, the positive "
                           "ones; at most N−1 with the θ product, 2N−2 with the full one).",
                           check=_ge(1)),
        "inner_product": Key("str", FromAPI("lyapunov", "inner"), "\"theta\": the paper's θ-only product (sec. 2); "
                             "\"full\": all 2N components.", choices=("theta", "full")),
        "n_batches": Key("int", FromAPI("lyapunov", "n_batches"), "Batches for the batch-means standard error.",
                         check=_ge(2)),
        "reorth_every": Key("float", FromAPI("lyapunov", "reorth_every"), "Time between re-orthonormalisations (eq 18); a "
                            "multiple of dt that divides t_final (left out: the API's default "
                            "on the grid of dt).", check=_gt(0)),
    },
    "curvature": {
        "route": Key("str", "both", "\"numerical\": eqs (19)–(21); \"exact\": from the "
                     "generated Riemann tensor; \"both\" at the same points.",
                     choices=("numerical", "exact", "both")),
        "n_directions": Key("int", None, "Diagonal elements K_ii (planes velocity × i-th "
                            "Lyapunov vector) to record (default N−2, at most N−2).",
                            check=_ge(1)),
        "sample_every": Key("float", FromAPI("curvature", "sample_every"), "Simulated time between curvature samples; a "
                            "multiple of dt.", check=_gt(0),
                            linkage=FromAPI("linkage", "sample_every")),
    },
    "angles": {
        "variant": Key("str", "both", "\"full\": the paper's 2N-dimensional tangent space; "
                       "\"restricted\": the constraint-preserving subspace; or \"both\".",
                       choices=("full", "restricted", "both")),
        "n_vectors": Key("int", None, "Dimension m of the expanding subspace (default N−2, at "
                         "most N−2).",
                         check=_ge(1)),
        "sample_every": Key("float", FromAPI("angles", "sample_every"), "Simulated time "
                            "between angle samples; a multiple of dt.", check=_gt(0)),
        "t_transient": Key("duration", None, "Transient of the angles pass (default: [run] "
                           "t_transient where written, else hyperbolicity_angles's; "
                           "linkage: linkage_angles's); a multiple of dt, or \"scaled\" or "
                           "\"auto\" as [run] t_transient.", check=_ge(0)),
    },
    "clv": {
        "variant": Key("str", "both", "Covariant Lyapunov vectors (Ginelli's method) in "
                       "\"full\": the 2N-dimensional tangent space; \"restricted\": the "
                       "constraint-preserving subspace; or \"both\".",
                       choices=("full", "restricted", "both")),
        "n_vectors": Key("int", None, "Dimension m of the expanding subspace (default N−2, at "
                         "most N−2).", check=_ge(1)),
        "sample_every": Key("float", FromAPI("clv", "sample_every"), "Simulated time between samples, which are also the "
                            "re-orthonormalisations giving the R factors; a multiple of dt.",
                            check=_gt(0)),
        "windows": Key("floats", None, "Window lengths of the finite-time exponents and of the "
                       "domination test (default [1.0, 10.0]); multiples of sample_every.",
                       check=lambda v: None if v and all(x > 0 for x in v)
                       else "a non-empty list of numbers, each > 0"),
        "t_transient": Key("duration", None, "Transient of the CLV pass (default: [run] "
                           "t_transient where written, else covariant_lyapunov_vectors's); "
                           "a multiple of dt, or \"scaled\" or \"auto\" as [run] "
                           "t_transient.", check=_ge(0)),
    },
    "switches": {},
    "drift": {
        "sample_every": Key("float", 1.0, "Simulated time between recorded invariant values; "
                            "a multiple of sample_dt.", check=_gt(0)),
    },
}

#: Effects that need tangent vectors (variational eq 17), integrated with ambient RK4.
TANGENT_EFFECTS = ("lyapunov", "curvature", "angles", "clv")
