"""A holonomic mechanism: coordinates q (angles and lengths), constraints F(q) = 0 of any
codimension k, a kinetic metric M(q) and parameters, all given as SymPy expressions
(docs/mechanisms.md).

``Mechanism`` validates and holds the description; what it derives lives in one module per
concept, each a base class whose docstring says what it needs from this one:

* ``charts.mechanism.symbolic``: the SymPy derivatives of F and M, the ambient equations
  (the paper's eqs (4)-(8) generalised), lambdified to NumPy;
* ``charts.mechanism.dynamics``: the ambient flow as a saddle-point (KKT) system, its exact
  linearisation, the projections onto F = 0 and its tangent spaces, random states;
* ``charts.mechanism.atlas``: charts by the implicit function theorem, the switching rule,
  the embedding's jets;
* ``charts.mechanism.geometry``: the induced metric, Christoffel symbols, Riemann tensor,
  Gaussian and sectional curvature in a chart (the intrinsic route);
* ``charts.mechanism.embedding``: the second fundamental form and the Gauss equation (the
  independent, chart-free route).
"""
from __future__ import annotations

import keyword
from abc import ABCMeta

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from .atlas import Atlas
from .dynamics import RANK_TOL, AmbientDynamics
from .embedding import EmbeddingGeometry
from ..geometry.checks import number, shown
from ..geometry.system import RotorSystem
from .errors import MechanismError
from .geometry import ChartGeometry
from .symbolic import SymbolicJets

__all__ = ["Mechanism", "MechanismError", "RANK_TOL"]

#: Functions that are not smooth everywhere: refused in F and M, whose jets differentiate them
#: (SymPy's derivatives of these are DiracDelta and sign, which the generated code cannot use).
_NOT_SMOOTH = (sp.Abs, sp.sign, sp.Piecewise, sp.Heaviside, sp.DiracDelta, sp.Max, sp.Min,
               sp.floor, sp.ceiling)


def _symbol(name, what):
    if isinstance(name, sp.Symbol):
        name = name.name
    if not isinstance(name, str) or not name.isidentifier() or keyword.iskeyword(name):
        raise MechanismError(f"{what} must be Python identifiers (str or sympy.Symbol), "
                             f"got {shown(name)}")
    return sp.Symbol(name, real=True)


def _check_containers(coordinates, constraints, masses, parameters, periodic, bounds, name):
    """`MechanismError` naming the argument of `Mechanism` that is not the kind of container
    its docstring says (before any entry is read)."""
    seq = (list, tuple)
    for arg, value, ok, kind in (
            ("coordinates", coordinates, isinstance(coordinates, seq), "a list of names"),
            ("constraints", constraints, isinstance(constraints, seq + (sp.Basic,)),
             "a SymPy expression or a list of them"),
            ("masses", masses, masses is None or isinstance(masses, seq + (np.ndarray,))
             and np.ndim(masses) == 1, "None or a list of n entries"),
            ("parameters", parameters, parameters is None or isinstance(parameters, dict),
             "None or a dict {name: value}"),
            ("periodic", periodic, isinstance(periodic, seq + (set, frozenset)),
             "a list of coordinate names"),
            ("bounds", bounds, bounds is None or isinstance(bounds, dict),
             "None or a dict {name: (lo, hi)}"),
            ("name", name, isinstance(name, str), "a str")):
        if not ok:
            raise MechanismError(f"{arg} must be {kind}, got {shown(value)}")


class Mechanism(SymbolicJets, AmbientDynamics,
                Atlas, ChartGeometry, EmbeddingGeometry, metaclass=ABCMeta):
    """A holonomic mechanism.

    Parameters
    ----------
    coordinates : sequence of str or sympy.Symbol
        The n ambient coordinates q.
    constraints : sequence of SymPy expressions
        F(q) = 0, k of them (1 ≤ k < n), in the coordinates and parameters.
    metric : SymPy matrix (n, n), optional
        The kinetic metric, T = ½ q̇ᵀ M(q) q̇ (constant or configuration-dependent).
    masses : sequence of n numbers or expressions, optional
        Instead of ``metric``: M = diag(masses) (masses and moments of inertia).
    parameters : dict, optional
        {name or Symbol: value} for every other symbol in the expressions.
    periodic : sequence of str, optional
        The coordinates that are angles (period 2π); default none.
    bounds : dict, optional
        {name: (lo, hi)} where ``random_state`` draws the non-periodic coordinates
        (default (−1, 1)) before projecting onto F = 0.
    name : str, optional
    """

    def __init__(self, coordinates, constraints, metric=None, *, masses=None, parameters=None,
                 periodic=(), bounds=None, name="mechanism"):
        _check_containers(coordinates, constraints, masses, parameters, periodic, bounds, name)
        self.name = str(name)
        if isinstance(coordinates, (str, sp.Symbol)):
            raise MechanismError("coordinates must be a sequence of names, not one name")
        self.q = tuple(_symbol(c, "coordinates") for c in coordinates)
        names = [s.name for s in self.q]
        if len(set(names)) != len(names):
            raise MechanismError(f"coordinate names must be distinct, got {names}")
        self.n = len(self.q)
        if self.n < 2:
            raise MechanismError(f"need at least 2 coordinates, got {names}")
        parameters = dict(parameters or {})
        self.params = tuple(_symbol(p, "parameters") for p in parameters)
        clash = set(names) & {p.name for p in self.params}
        if clash:
            raise MechanismError(f"{sorted(clash)} are both coordinates and parameters")
        values = []
        for p, v in parameters.items():
            try:
                v = number(f"parameters[{p!r}]", v)
            except ValueError as exc:
                raise MechanismError(str(exc)) from None
            values.append(v)
        self.param_values = np.array(values, dtype=float)
        # every symbol is made real: map the user's symbols (by name) onto ours
        self._names = {s.name: s for s in self.q + self.params}

        if isinstance(constraints, sp.Basic) and not isinstance(constraints, sp.MatrixBase):
            constraints = [constraints]
        F = [self._expr(c, f"constraints[{i}]") for i, c in enumerate(constraints)]
        self.k = len(F)
        if not 1 <= self.k < self.n:
            raise MechanismError(f"need 1 <= (number of constraints) < (number of coordinates) "
                                 f"= {self.n}, got {self.k} constraints")
        self.F = sp.Matrix(F)

        if (metric is None) == (masses is None):
            raise MechanismError("give exactly one of metric (an n x n SymPy matrix) or masses "
                                 "(n entries)")
        if masses is not None:
            masses = list(masses)
            if len(masses) != self.n:
                raise MechanismError(f"masses must have one entry per coordinate ({self.n}), "
                                     f"got {len(masses)}")
            metric = sp.diag(*[self._expr(m, f"masses[{i}]") for i, m in enumerate(masses)])
        else:
            metric = sp.Matrix(metric)
            if metric.shape != (self.n, self.n):
                raise MechanismError(f"metric must be {self.n} x {self.n}, got {metric.shape}")
            metric = metric.applyfunc(lambda e: self._expr(e, "metric entry"))
            if not (metric - metric.T).applyfunc(sp.expand).is_zero_matrix:
                raise MechanismError("metric must be symmetric")
        self.M = metric
        self.periodic = tuple(_symbol(p, "periodic").name for p in periodic)
        unknown = set(self.periodic) - set(names)
        if unknown:
            raise MechanismError(f"periodic names {sorted(unknown)} are not coordinates {names}")
        self._periodic_mask = np.array([s.name in self.periodic for s in self.q])
        self.bounds = {s.name: (-1.0, 1.0) for s in self.q}
        for c, b in (bounds or {}).items():
            if c not in self.bounds:
                raise MechanismError(f"bounds for {c!r}: not a coordinate of {names}")
            try:
                lo, hi = (number(f"bounds[{c!r}]", x) for x in b)
            except (TypeError, ValueError):
                raise MechanismError(f"bounds for {c!r} must be (lo, hi), two finite numbers, "
                                     f"got {shown(b)}") from None
            if not lo < hi:
                raise MechanismError(f"bounds for {c!r} must be (lo, hi) with lo < hi, got {b}")
            self.bounds[c] = (lo, hi)
        self.dim = self.n - self.k

    def with_parameters(self, *, name=None, bounds=None, **values):
        """A copy with other parameter values (by name) that shares this one's symbolic
        derivations and lambdified functions (the parameters are their arguments): no
        re-derivation.  ``bounds`` updates ``random_state``'s boxes."""
        import copy
        self.derive()                               # derive once, share with every copy
        out = copy.copy(self)
        out.param_values = self.param_values.copy()
        index = {p.name: i for i, p in enumerate(self.params)}
        for k, v in values.items():
            if k not in index:
                raise MechanismError(f"{k!r} is not a parameter of {self.name} "
                                     f"({sorted(index)})")
            try:
                v = float(v)
            except (TypeError, ValueError):
                raise MechanismError(f"parameter {k} must be a real number, got {v!r}") from None
            if not np.isfinite(v):
                raise MechanismError(f"parameter {k} must be finite, got {v}")
            out.param_values[index[k]] = v
        out.bounds = dict(self.bounds)
        for c, b in (bounds or {}).items():
            if c not in out.bounds:
                raise MechanismError(f"bounds for {c!r}: not a coordinate")
            lo, hi = map(float, b)
            if not lo < hi:
                raise MechanismError(f"bounds for {c!r} must be (lo, hi) with lo < hi, got {b}")
            out.bounds[c] = (lo, hi)
        if name is not None:
            out.name = str(name)
        return out

    @property
    def parameter_values(self) -> dict:
        """{name: value} of the parameters."""
        return {p.name: float(v) for p, v in zip(self.params, self.param_values)}

    def _expr(self, e, what):
        try:
            e = sp.sympify(e)
        except (sp.SympifyError, TypeError) as err:
            raise MechanismError(f"{what} is not a SymPy expression: {e!r}") from err
        subs = {}
        for s in e.free_symbols:
            if s.name not in self._names:
                raise MechanismError(
                    f"{what} = {e} contains {s.name!r}, which is neither a coordinate "
                    f"{[c.name for c in self.q]} nor a parameter {[p.name for p in self.params]}")
            subs[s] = self._names[s.name]
        e = e.xreplace(subs)
        if e.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise MechanismError(f"{what} = {e} is not finite")
        undefined = e.atoms(AppliedUndef)
        if undefined:
            raise MechanismError(f"{what} = {e} contains the undefined function(s) "
                                 f"{sorted(map(str, undefined))}: write them out (the jets "
                                 "differentiate F three times and M twice)")
        rough = e.atoms(*_NOT_SMOOTH)
        if rough:
            raise MechanismError(f"{what} = {e} uses {sorted(map(str, rough))}, which is not "
                                 "smooth: F and M must be smooth (differentiated three and two "
                                 "times)")
        return e

    def __repr__(self):
        return (f"Mechanism({self.name!r}: q = ({', '.join(s.name for s in self.q)}), "
                f"{self.k} constraint(s), dim {self.dim})")

    def __copy__(self):
        """A shallow copy that shares the lambdified and compiled functions (``_num``), as
        `with_parameters` needs (a pickle leaves them out: `__getstate__`)."""
        out = object.__new__(type(self))
        out.__dict__.update(self.__dict__)
        return out

    def __getstate__(self):
        """Pickled as its SymPy description, parameter values and what SymPy derived (SymPy
        expressions pickle), without the lambdified and compiled functions (``_num``): an
        ensemble sends a mechanism to its worker processes."""
        state = dict(self.__dict__)
        state.pop("_num", None)
        return state

    def __setstate__(self, state):
        """The pickled state; the functions of ``_num`` are those of the first copy of this
        symbolic model loaded in this process (found by its ``model_key``), so that the many
        copies a worker receives lambdify it once."""
        from ..codegen.mechanism import model_key
        self.__dict__.update(state)
        key = model_key(self.q, self.params, self.F, self.M)
        if key not in _LOADED:
            _LOADED[key] = SymbolicJets._num.func(self)
        self.__dict__["_num"] = _LOADED[key]


#: model_key → the lambdified functions (``_num``) of the symbolic models loaded from pickles
#: in this process.
_LOADED = {}


# The rotors' RotorSystem (a layer below) is a Mechanism: its structured methods, and the
# others of its generic twin ``RotorSystem.mechanism`` (``charts.geometry.system``).
Mechanism.register(RotorSystem)
