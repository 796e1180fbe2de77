"""Code generator: SymPy chart geometry → plain-Python kernels in ``generated/``.

Design note.  For each N one module ``rotor_n{N}.py`` is written for the
*canonical* chart, the one that eliminates the last angle.  Any other chart k
is the same formulas with the local angles (θ without θₖ, in order) and the
masses reordered as (m without mₖ, then mₖ): the metric (eq 13) is symmetric
under that relabelling, and ``tests/test_generated.py`` proves it by comparing
against a live SymPy derivation of every chart.  Masses, the weights aᵢ and the level c of
the constraint Σ aᵢ cos θᵢ = c are run-time arguments (weights in the masses' local order),
so ``generated/`` holds one module per N for the whole family.  Each function works on scalars with ``math`` (so numba compiles it
and plain CPython runs it), reads 1-D arrays, and writes into a caller-given
``out`` array (no allocation in hot loops).  ``geodesic_acceleration`` and ``transport_rate``
come in two parts: ``*_sc(ws, wc, ...)`` holds the formulas with σ = a sin q and κ = a cos q
given, and the public function evaluates σ, κ once and calls it: the chart right-hand side
shares one evaluation between them and its health test (``charts.flows.chart``).  Both do the
operations the single function did (the paper's ``_sc`` is its kernel with the sin/cos calls
read from ws, wc), so the numbers keep their bits.

Output is deterministic: ``sympy.cse(order='canonical')`` with numbered
symbols and no dates; the header records the command and SymPy version.  The modules import
``math`` only: nothing hand-written, no numba.  The loader (``charts.geometry.kernels``) makes
the ``_sc`` kernels callable from compiled code, and ``charts.flows.chart`` binds them into
the chart right-hand side.
"""
from __future__ import annotations

import math

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from .names import GENERATED_FUNCTIONS, SHIPPED_N, module_name
from .symbolic import ChartGeometry

__all__ = ["module_source", "module_name", "GENERATED_FUNCTIONS", "SHIPPED_N"]

GENERATOR_COMMAND = "python scripts/generate.py"


class _Printer(PythonCodePrinter):
    def __init__(self, names):
        super().__init__({"fully_qualified_modules": True, "standard": "python3"})
        self._names = names

    def _print_Symbol(self, expr):
        return self._names.get(expr, super()._print_Symbol(expr))


def _shape(nested):
    shape = []
    while isinstance(nested, list):
        shape.append(len(nested))
        nested = nested[0]
    return tuple(shape)


def _flatten(nested, prefix=()):
    if isinstance(nested, list):
        for i, x in enumerate(nested):
            yield from _flatten(x, prefix + (i,))
    else:
        yield prefix, nested


def _function(name, args, doc, outputs, printer, scalar=False, atoms=()):
    """Source of one function; ``outputs`` is a nested list (written to ``out``)
    or a single expression (returned) when ``scalar``.  ``atoms``: (symbol, source) pairs
    computed first, where the expressions use them."""
    flat = [(None, outputs)] if scalar else list(_flatten(outputs))
    exprs = [e for _, e in flat]
    lines = [f"def {name}({', '.join(args)}):", f'    """{doc}"""']
    used = set().union(*(sp.sympify(e).free_symbols for e in exprs))
    lines += [f"    {printer.doprint(sym)} = {code}" for sym, code in atoms if sym in used]
    reps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("x"), order="canonical")
    for sym, e in reps:
        lines.append(f"    {sym} = {printer.doprint(e)}")
    if scalar:
        lines.append(f"    return {printer.doprint(reduced[0])}")
    elif len(_shape(outputs)) == 1:
        for (index, _), e in zip(flat, reduced):
            lines.append(f"    out[{index[0]}] = {printer.doprint(e)}")
        lines.append("    return out")
    else:
        lines += _flat_stores(_shape(outputs), [i for i, _ in flat], reduced, printer)
    return "\n".join(lines) + "\n"


#: The last line of every generated module: a file cut short (which may still import) lacks
#: it, and ``charts.codegen.shipped.import_shipped`` refuses such a file.
COMPLETE_LINE = "\n\n#: The file's last line: a file cut short lacks it.\nCOMPLETE = True\n"


def _flat_stores(shape, indices, reduced, printer):
    """The stores of a multi-index output ``out`` (C-contiguous, ``shape``) through its flat
    view, zeros by one fill: numba lowers every store to an N-d array with a copy of the
    array's descriptor that LLVM must then take apart (its SROA pass), and the N = 6 Riemann
    tensor's 625 stores compiled for 7 s this way against 1.6 s through the flat view with
    the 345 zeros filled (the values are the same, bit for bit).  An ``out`` that is not
    C-contiguous is refused with a ValueError (NumPy's reshape would write into a copy);
    compiled by numba, a strided one is refused earlier, by its typing of the reshape."""
    strides = [math.prod(shape[i + 1:]) for i in range(len(shape))]
    lines = ["    if not out.flags.c_contiguous:  # (reshape would copy it: written, then lost)",
             "        raise ValueError(\"out must be a C-contiguous array\")",
             "    o = out.reshape(-1)"]
    if any(e == 0 for e in reduced):
        lines.append("    o[:] = 0.0")
    for index, e in zip(indices, reduced):
        if e != 0:
            flat = sum(i * s for i, s in zip(index, strides))
            lines.append(f"    o[{flat}] = {printer.doprint(e)}  # {', '.join(map(str, index))}")
    lines.append("    return out")
    return lines


def module_source(n: int, paper: bool = False, geometry: ChartGeometry | None = None) -> str:
    """Full text of ``generated/rotor_n{n}.py`` (the family, canonical chart k = n−1), or with
    ``paper`` of ``rotor_n{n}_paper.py`` (the same derivation at a = 1, c = 0, specialised
    before CSE: the paper's kernels keep their operations, and so their bits).  Both take
    the same arguments.  ``geometry``: the derivation to reuse (``ChartGeometry(n, n − 1)``)."""
    G = ChartGeometry(n, n - 1) if geometry is None else geometry
    d = G.dim
    names = {G.theta[a]: f"q[{a}]" for a in range(d)}
    names.update({G.m[i]: f"m[{i}]" for i in range(n)})
    names.update({G.a[i]: f"a[{i}]" for i in range(n)})
    names[G.c] = "c"
    x = list(sp.symbols(f"x_0:{d}", real=True))
    y = list(sp.symbols(f"y_0:{d}", real=True))
    names.update({G.v[a]: f"v[{a}]" for a in range(d)})
    names.update({G.w[a]: f"p[{a}]" for a in range(d)})
    names.update({x[a]: f"x[{a}]" for a in range(d)})
    names.update({y[a]: f"y[{a}]" for a in range(d)})
    sin_k = sp.Symbol("sin_k", real=True)
    # σ_α = a_α sin q_α and κ_α = a_α cos q_α become symbols computed once at the top (``atoms``)
    # (the _sc variants read them from the arrays ws, wc: their callers share one evaluation)
    atoms, calls, sc_names = [], {}, {}
    for kind, fns in (("cos", G.wcos), ("sin", G.wsin)):
        for a, f in enumerate(fns):
            sym = sp.Symbol(f"z{kind}{a}", real=True)
            calls[f] = sym
            names[sym] = f"w{kind[0]}{a}"
            sc_names[sym] = f"w{kind[0]}[{a}]"
            atoms.append((sym, f"a[{a}]*math.{kind}(q[{a}])"))
    P = _Printer(names)
    P_sc = _Printer({**names, **sc_names})

    def coded(nested):
        if isinstance(nested, list):
            return [coded(x) for x in nested]
        return sp.sympify(nested).xreplace(calls)

    def function(fname, args, doc, outputs, scalar=False):
        if paper:
            return _function(fname, args, doc, G.paper(outputs), P, scalar=scalar)
        return _function(fname, args, doc, coded(outputs), P, scalar=scalar, atoms=atoms)

    def sc_pair(fname, args, doc, outputs):
        """``fname_sc(ws, wc, *args[1:])`` with the formulas, σ = ws = a sin q and κ = wc =
        a cos q given, and ``fname(*args)``, which evaluates them once and calls it."""
        doc_sc = doc + f" ws, wc = a*sin(q), a*cos(q), shape ({d},)."
        if paper:  # the paper's kernel with its sin/cos read from ws, wc: the same operations
            sc = _function(f"{fname}_sc", ["ws", "wc"] + args[1:], doc_sc, G.paper(outputs), P)
            for a in range(d):
                sc = sc.replace(f"math.sin(q[{a}])", f"ws[{a}]").replace(f"math.cos(q[{a}])", f"wc[{a}]")
            assert "q[" not in sc
        else:
            sc = _function(f"{fname}_sc", ["ws", "wc"] + args[1:], doc_sc, coded(outputs), P_sc)
        w = "" if paper else "a[{a}]*"
        ws = ", ".join((w + "math.sin(q[{a}])").format(a=a) for a in range(d))
        wc = ", ".join((w + "math.cos(q[{a}])").format(a=a) for a in range(d))
        wrapper = (f"def {fname}({', '.join(args)}):\n    \"\"\"{doc}\"\"\"\n"
                   f"    return {fname}_sc(({ws}), ({wc}), {', '.join(args[1:])})\n")
        return sc + "\n\n" + wrapper

    what = (f"the paper's constraint sum(cos(theta_i)) = 0 (a = 1, c = 0 substituted before code\n"
            f"generation; a and c are accepted and ignored).  Arguments: q = local angles, shape ({d},);\n"
            if paper else
            f"the constraint sum(a_i cos(theta_i)) = c.  Arguments: q = local angles, shape ({d},);\n")

    shape = lambda t: "x".join(map(str, _shape(t)))
    parts = [
        f'"""Rotor manifold, N = {n}: geometry of the canonical chart (eliminates θ_{n - 1}) on\n'
        + what +
        f"m = masses and a = weights, shape ({n},) each, local order with the eliminated rotor's\n"
        f"last; c = level (float); v, p, x, y = local vector components, shape ({d},);\n"
        f"out = a C-contiguous array of the shape each function names, written whole.\n"
        f'Index conventions: see charts/codegen/symbolic.py.\n"""\n'
        "import math\n\nN = {n}\nDIM = {d}\n".format(n=n, d=d),
        function("metric", ["q", "m", "a", "c", "out"],
                  f"g_ab, eq (13); out shape ({shape(G.metric)}).", G.metric),
        function("metric_inverse", ["q", "m", "a", "c", "out"],
                  f"g^ab (Sherman-Morrison); out shape ({shape(G.metric)}).", G.metric_inverse),
        function("christoffel", ["q", "m", "a", "c", "out"],
                  f"Gamma^a_bc, upper index first, eq (15); out shape ({shape(G.christoffel)}).",
                  G.christoffel),
        function("riemann", ["q", "m", "a", "c", "out"],
                  f"R_abcd = <R(d_c, d_d) d_b, d_a>; out shape ({shape(G.riemann)}).", G.riemann),
        sc_pair("geodesic_acceleration", ["q", "v", "m", "a", "c", "out"],
                "dv^a/dt = -Gamma^a_bc v^b v^c, eq (14).",
                [-e for e in G.connection_contract(G.v, G.v)]),
        sc_pair("transport_rate", ["q", "v", "p", "m", "a", "c", "out"],
                "dp^a/dt = -Gamma^a_bc v^b p^c, eq (16).",
                [-e for e in G.connection_contract(G.v, G.w)]),
        function("curvature_operator", ["q", "x", "y", "m", "a", "c", "out"],
                  "(R(x, y) y)^a; the Jacobi equation is J'' + R(J, v) v = 0.",
                  G.curvature_operator(x, y)),
        function("eliminated_component", ["q", "x", "a", "sin_k"],
                  "Ambient component of the eliminated angle of tangent vector x (tangency).",
                  G.eliminated_velocity(x, sin_k), scalar=True),
    ]
    header = (f"# Generated by `{GENERATOR_COMMAND}` (SymPy {sp.__version__}) from charts/codegen/symbolic.py.\n"
              "# Do not edit by hand: regenerate, and `python scripts/generate.py --check` must pass.\n")
    return header + "\n\n".join(parts) + COMPLETE_LINE


def init_source() -> str:
    return (f"# Generated by `{GENERATOR_COMMAND}`. Do not edit by hand.\n"
            '"""Generated chart kernels, one module per N (see charts/codegen/emit.py)."""\n'
            f"SHIPPED_N = {tuple(SHIPPED_N)}\n")
