"""The symbolic derivation of a Mechanism: what SymPy differentiates, once and cached, and
how it becomes NumPy.

SymPy differentiates the constraints F three times and the kinetic metric M twice:
J = ∂F/∂q, ∂²F, ∂³F, ∂M, ∂²M, and writes the ambient equations of motion (the paper's eqs
(4)-(8) generalised: λ is its Λ, from the constraint differentiated twice as in its eq (5)):

    M q̈ − Jᵀλ = −C(q, v),   C_i = Σ_jk (∂_j M_ik − ½ ∂_i M_jk) v^j v^k,
    J q̈        = −Σ_jk ∂²F/∂q_j∂q_k v^j v^k                 (F differentiated twice in time)

Each derivative tensor is lambdified to NumPy (only its non-zero entries, the parameters as
arguments); everything numerical downstream (``dynamics``, ``atlas``, ``geometry``,
``embedding``) is exact linear algebra on these jets at a point, no finite differences.  The
compiled flows read the same jets from generated code (`SymbolicJets.compiled_jets`; the
derivatives and the generator are ``charts.codegen.mechanism``'s).

Index order: J[a, i] = ∂F_a/∂q_i, F2[a, i, j], F3[a, i, j, l]; dM[i, j, l] = ∂_l M_ij,
d2M[i, j, l, m] = ∂_l∂_m M_ij.
"""
from __future__ import annotations

from functools import cached_property

import numpy as np
import sympy as sp

from ..codegen.mechanism import JET_ORDER, derivative, jets_module

__all__ = ["SymbolicJets", "sparse_lambdify", "JET_ORDER"]


def sparse_lambdify(args, array):
    """f(*args) -> np.ndarray of the shape of the SymPy ``array``, only its non-zero entries
    evaluated (one lambdified function for all of them).  Arguments that are arrays of one
    shape B (a batch of points) give shape B + array's shape."""
    arr = sp.Array(array)
    shape = arr.shape
    flat = list(sp.flatten(arr.tolist())) if len(shape) else [arr]
    nz = [(i, e) for i, e in enumerate(flat) if e != 0]
    idx = np.array([i for i, _ in nz], dtype=np.intp)
    size = int(np.prod(shape)) if len(shape) else 1
    fn = sp.lambdify(args, [e for _, e in nz], modules="numpy", cse=True) if nz else None

    def f(*a):
        batch = np.broadcast_shapes(*(np.shape(x) for x in a))
        out = np.zeros(batch + (size,))
        if fn is not None:
            vals = fn(*a)
            out[..., idx] = np.stack([np.broadcast_to(v, batch) for v in vals], axis=-1)
        return out.reshape(batch + shape)
    return f


class SymbolicJets:
    """The derivatives of a mechanism's F and M, symbolic and lambdified.

    The host class supplies: ``q`` (the n coordinate Symbols), ``n``, ``k``, ``F`` (SymPy
    Matrix (k, 1)), ``M`` (SymPy Matrix (n, n)), ``params`` (the parameter Symbols) and
    ``param_values`` (their values, an array in the same order).
    """

    @cached_property
    def J(self):
        """∂F/∂q, SymPy (k, n)."""
        return self.F.jacobian(self.q)

    @cached_property
    def F2(self):
        """∂²F_a/∂q_i∂q_j, SymPy Array (k, n, n)."""
        return derivative(self.J, self.q)

    @cached_property
    def F3(self):
        """∂³F, SymPy Array (k, n, n, n)."""
        return derivative(self.F2, self.q)

    @cached_property
    def dM(self):
        """∂_l M_ij as dM[i, j, l], SymPy Array (n, n, n)."""
        return derivative(self.M, self.q)

    @cached_property
    def d2M(self):
        """∂_l∂_m M_ij as d2M[i, j, l, m], SymPy Array (n, n, n, n)."""
        return derivative(self.dM, self.q)

    @cached_property
    def constant_metric(self) -> bool:
        """True when M does not depend on q."""
        return all(e == 0 for e in sp.flatten(self.dM.tolist()))

    def ambient_equations(self):
        """The ambient constrained equations as SymPy: (velocity symbols v, acceleration symbols
        a, multiplier symbols λ, the n + k equations, each an expression = 0):
        M a + C(q, v) − Jᵀλ and J a + vᵀ ∂²F v (the constraint differentiated twice)."""
        v = sp.symbols(" ".join(f"v_{s.name}" for s in self.q), real=True, seq=True)
        a = sp.symbols(" ".join(f"a_{s.name}" for s in self.q), real=True, seq=True)
        lam = sp.symbols(" ".join(f"lambda{i}" for i in range(self.k)), real=True, seq=True)
        A, L = sp.Matrix(a), sp.Matrix(lam)
        C = sp.Matrix([sum((self.dM[i, kk, j] - sp.Rational(1, 2) * self.dM[j, kk, i]) * v[j] * v[kk]
                           for j in range(self.n) for kk in range(self.n)) for i in range(self.n)])
        eqs = list(self.M * A + C - self.J.T * L)
        eqs += [sum(self.F2[c, i, j] * v[i] * v[j] for i in range(self.n) for j in range(self.n))
                + (self.J[c, :] * A)[0] for c in range(self.k)]
        return v, a, lam, eqs

    @cached_property
    def _num(self):
        """The lambdified jets (arguments: the n coordinates, then the parameters)."""
        args = self.q + self.params
        return {"F": sparse_lambdify(args, list(self.F)),
                "J": sparse_lambdify(args, self.J.tolist()),
                "F2": sparse_lambdify(args, self.F2),
                "F3": sparse_lambdify(args, self.F3),
                "M": sparse_lambdify(args, self.M.tolist()),
                "dM": sparse_lambdify(args, self.dM),
                "d2M": sparse_lambdify(args, self.d2M)}

    def compiled_jets(self):
        """The jets of `JET_ORDER` as one numba-compiled function ``jets(q, p, F, J, F2, F3,
        M, dM, d2M)``: the generated module of this symbolic model (``charts.codegen.mechanism``:
        shipped in ``generated/`` for the named instances, else written on first use into the
        disk cache, found by the model's key), compiled with numba's disk cache, so that a
        second process neither derives nor compiles; shared by the copies of
        ``with_parameters`` (the parameters are the argument p)."""
        num = self._num
        if "compiled" not in num:
            from ..jit import njit
            mod = jets_module(self.q, self.params, self.F, self.M, say=self.name,
                              arrays=lambda: [self._jet_array(key) for key in JET_ORDER])
            num["compiled"] = njit(cache=True)(mod.jets)
        return num["compiled"]

    def _jet_array(self, key):
        """The SymPy array of the jet ``key`` (as ``_num``'s)."""
        return {"F": sp.Array(list(self.F)), "J": self.J, "F2": self.F2, "F3": self.F3,
                "M": self.M, "dM": self.dM, "d2M": self.d2M}[key]

    def derive(self):
        """Derive and lambdify everything now (otherwise done on first use); returns self."""
        self._num
        return self

    def _eval(self, key, q):
        """The jet ``key`` at q, shape (n,) or a batch (..., n): shape (...,) + the jet's."""
        q = np.asarray(q, dtype=float)
        return self._num[key](*np.moveaxis(q, -1, 0), *self.param_values)
