"""Code generator for mechanisms: a symbolic model (coordinates q, parameters p, constraints
F(q) = 0, kinetic metric M(q)) → one plain-Python module with its jets.

Design note.  What the ambient flow of any holonomic mechanism, its linearisation and its
projections read at a point are seven jets (`JET_ORDER`): F, J = ∂F/∂q, ∂²F, ∂³F, M, ∂M, ∂²M,
each derivative taken here by `derivative` (one more index, the last; index order of
``charts.mechanism.symbolic``).  `module_source` writes a module holding one function
``jets(q, p, F, J, F2, F3, M, dM, d2M)`` that stores their non-zero entries (`jets_source`:
``math`` only, so numba compiles it and CPython runs it; the common subexpressions of all six
shared, ``sympy.cse(order='canonical')``, so the text is deterministic).

A module is known by the key of the model it was written from (`model_key`: a hash of the
coordinate and parameter names, the expressions of F and M, the SymPy version and this
generator's own source): the parameters' values are arguments, so one module serves every
value.  The named instances are shipped in ``generated/`` (`SHIPPED_MECHANISMS`, written by
``python scripts/generate.py``, indexed by key in ``generated/mechanism_index.py``); any other
model is written on first use into the disk cache (``charts.codegen.cache``, the rotors'
cache: atomic writes, a hash beside each file, a file lock).  `jets_module` finds a model's
module by its key, never by a name: a model that differs from the shipped one by one sign
gets its own module.  The caller compiles ``jets`` with numba's disk cache
(``Mechanism.compiled_jets``), so that a second process neither derives nor compiles.
"""
from __future__ import annotations

import hashlib
import importlib
import time
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

__all__ = ["JET_ORDER", "SHIPPED_MECHANISMS", "INDEX", "derivative", "jet_arrays", "jets_source",
           "model_key", "module_source", "index_source", "jets_module", "write_shipped"]

#: The jets the generated function writes, in its argument order (after q and p).
JET_ORDER = ("F", "J", "F2", "F3", "M", "dM", "d2M")

#: The shipped mechanism modules of ``generated/``: module name → ("module:function", keyword
#: arguments) of the instance whose symbolic model it holds (imported by name when
#: ``generated/`` is written: the instances live in a layer above this one).
SHIPPED_MECHANISMS = {
    **{f"mechanism_rotors_n{n}": ("charts.mechanism.instances:rotors", {"n": n})
       for n in (3, 4, 5, 6)},
    "mechanism_triple_linkage": ("charts.mechanism.instances:triple_linkage", {"r": 0.1}),
    "mechanism_triple_linkage_rods": ("charts.mechanism.instances:triple_linkage",
                                      {"r": 0.1, "rod_mass": 1.0}),
    "mechanism_appendix_linkage": ("charts.mechanism.instances:appendix_linkage_model", {}),
}
#: The shipped module that maps each shipped model's key to its module's name.
INDEX = "mechanism_index"

_COMMAND = "python scripts/generate.py"
_DOC = ("the jets of a mechanism's constraints F(q) = 0 and kinetic metric M(q) (see\n"
        "charts/codegen/mechanism.py).  jets(q, p, F, J, F2, F3, M, dM, d2M): q = the\n"
        "coordinates, p = the parameters (values), in the orders below; the outputs, of shapes\n"
        "(k,), (k, n), (k, n, n), (k, n, n, n), (n, n), (n, n, n), (n, n, n, n), get their non-zero\n"
        "entries written (the caller zeroes them once).  J[a, i] = dF_a/dq_i, F2[a, i, j], F3[a, i, j, l];\n"
        "dM[i, j, l] = d_l M_ij, d2M[i, j, l, m] = d_l d_m M_ij.\n")


def derivative(array, q):
    """∂ of every entry of the SymPy ``array`` along the coordinates ``q``, appended as the
    last index: shape (..., len(q))."""
    arr = sp.Array(array)
    flat = list(sp.flatten(arr.tolist())) if arr.shape else [arr]
    return sp.Array([sp.diff(e, x) for e in flat for x in q], arr.shape + (len(q),))


def jet_arrays(q, F, M) -> list:
    """The SymPy arrays of `JET_ORDER` for constraints F (k entries) and metric M (n × n)."""
    J = sp.Matrix(F).jacobian(q)
    F2 = derivative(J, q)
    dM = derivative(M, q)
    return [sp.Array(list(F)), J, F2, derivative(F2, q), M, dM, derivative(dM, q)]


def _generator_digest() -> str:
    """Hash of this generator's source: a changed derivation or emission changes every key."""
    return hashlib.sha256(Path(__file__).read_bytes()).hexdigest()[:16]


def model_key(q, params, F, M) -> str:
    """SHA-256 (hex) of a symbolic model: the coordinate and parameter Symbols (names and
    assumptions), the expressions of F and M (``srepr``: SymPy's canonical argument order),
    the SymPy version and the generator's source.  Cheap: nothing is differentiated."""
    h = hashlib.sha256()
    for part in (f"sympy {sp.__version__}", f"generator {_generator_digest()}",
                 sp.srepr(tuple(q)), sp.srepr(tuple(params)), sp.srepr(sp.Matrix(F)),
                 sp.srepr(sp.Matrix(M))):
        h.update(part.encode("utf-8") + b"\n")
    return h.hexdigest()


def jets_source(args, jets, name="jets"):
    """Python source (``math`` only, numba-compilable) of ``name(q, p, *outs)`` that writes the
    non-zero entries of each SymPy array of ``jets`` into its output array (same order and
    shapes; the zero entries are not written: the caller zeroes the arrays once).  ``args``:
    the coordinate Symbols, then the parameter Symbols, read as q[i] and p[j].  Common
    subexpressions of all the jets are shared (``sympy.cse``, canonical order, so the source
    is deterministic)."""
    names = {s: f"q[{i}]" for i, s in enumerate(args[0])}
    names.update({s: f"p[{j}]" for j, s in enumerate(args[1])})
    entries = []
    for a, arr in enumerate(jets):
        arr = sp.Array(arr)
        shape = arr.shape
        for flat, e in enumerate(sp.flatten(arr.tolist())):
            if e != 0:
                entries.append((a, np.unravel_index(flat, shape), e))
    subs, reduced = sp.cse([e for *_, e in entries], symbols=sp.numbered_symbols("x"),
                           order="canonical")
    printer = PythonCodePrinter({"standard": "python3"})
    pr = lambda e: printer.doprint(e.xreplace({s: sp.Symbol(v) for s, v in names.items()}))
    outs = [f"o{a}" for a in range(len(jets))]
    lines = [f"def {name}(q, p, {', '.join(outs)}):"]
    lines += [f"    {s} = {pr(e)}" for s, e in subs]
    lines += [f"    o{a}[{', '.join(map(str, ix))}] = {pr(e)}"
              for (a, ix, _), e in zip(entries, reduced)]
    return "\n".join(lines + ["    return 0"]) + "\n"


def module_source(q, params, F, M, key=None, arrays=None, command=None) -> str:
    """Full text of a mechanism's jets module: a header, the docstring, ``KEY`` (`model_key`),
    ``COORDINATES``, ``PARAMETERS``, ``jets`` and the last line ``COMPLETE = True``.
    ``arrays``: the jets already derived (`jet_arrays`' list), else derived here; ``command``:
    the command named in the header (shipped modules: ``python scripts/generate.py``)."""
    from .emit import COMPLETE_LINE

    key = model_key(q, params, F, M) if key is None else key
    arrays = jet_arrays(q, F, M) if arrays is None else arrays
    made = (f"# Generated by `{command}` (SymPy {sp.__version__}) from charts/codegen/mechanism.py.\n"
            "# Do not edit by hand: regenerate, and `python scripts/generate.py --check` must pass.\n"
            if command else
            f"# Generated on first use by charts/codegen/mechanism.py (SymPy {sp.__version__}) into\n"
            "# the disk cache (charts/codegen/cache.py); do not edit: delete it to have it written again.\n")
    body = (f'"""Mechanism jets: {_DOC}"""\nimport math\n\n'
            f"KEY = {key!r}\nCOORDINATES = {tuple(s.name for s in q)!r}\n"
            f"PARAMETERS = {tuple(s.name for s in params)!r}\n\n\n")
    return made + body + jets_source((q, params), arrays) + COMPLETE_LINE


def index_source(keys: dict) -> str:
    """Text of ``generated/mechanism_index.py``: ``MODULES`` = {model key: module name}."""
    from .emit import COMPLETE_LINE

    rows = "".join(f"    {k!r}: {v!r},\n" for k, v in sorted(keys.items(), key=lambda kv: kv[1]))
    return (f"# Generated by `{_COMMAND}`. Do not edit by hand.\n"
            '"""The shipped mechanism jets modules by the key of their symbolic model\n'
            '(charts.codegen.mechanism.model_key)."""\n'
            f"MODULES = {{\n{rows}}}\n" + COMPLETE_LINE)


def _shipped_model(name):
    """The instance named by `SHIPPED_MECHANISMS` for module ``name``."""
    target, kwargs = SHIPPED_MECHANISMS[name]
    module, function = target.split(":")
    return getattr(importlib.import_module(module), function)(**kwargs)


def write_shipped(outdir: Path, verbose=True) -> dict:
    """Write every module of `SHIPPED_MECHANISMS` and the index `INDEX` into ``outdir``;
    returns the seconds each took."""
    from ..io.atomic import atomic_write

    timings, keys = {}, {}
    for name in SHIPPED_MECHANISMS:
        t0 = time.perf_counter()
        m = _shipped_model(name)
        key = model_key(m.q, m.params, m.F, m.M)
        keys[key] = name
        atomic_write(Path(outdir) / f"{name}.py",
                     module_source(m.q, m.params, m.F, m.M, key, command=_COMMAND).encode("utf-8"))
        timings[name] = time.perf_counter() - t0
        if verbose:
            print(f"  {name}: {timings[name]:.1f} s", flush=True)
    atomic_write(Path(outdir) / f"{INDEX}.py", index_source(keys).encode("utf-8"))
    return timings


def jets_module(q, params, F, M, arrays=None, say=None):
    """The jets module of a model: the shipped one whose ``KEY`` is the model's key, else the
    disk cache's (written on first use: `module_source` with ``arrays()``, the jets already
    derived, when given).  ``say``: a label for the cache's messages."""
    from .shipped import import_shipped

    key = model_key(q, params, F, M)
    name = import_shipped(INDEX).MODULES.get(key)
    if name is not None:
        mod = import_shipped(name)
        if mod.KEY == key:
            return mod
    from .cache import load_or_write

    source = lambda: module_source(q, params, F, M, key, None if arrays is None else arrays())
    return load_or_write(f"mechanism_{key[:20]}", f"jets of {say or 'a mechanism'} "
                         f"(key {key[:12]})", source)
