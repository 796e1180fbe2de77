"""A mechanism's jets as generated code (charts.codegen.mechanism): the shipped modules are the
named instances' models (found by key, never by name), a user's model is written once into
the disk cache and a second process neither writes nor compiles it, a changed model gets a
new key, and the generated function gives the lambdified jets.

That ``generated/`` is current (the mechanisms' modules and their index included) is
tests/test_generated.py's freshness test: ``write_all`` writes them with the rotors'.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from charts.codegen import mechanism as gen
from charts.codegen.cache import cache_dir
from charts.codegen.shipped import import_shipped
from charts.mechanism import Mechanism
from charts.mechanism.symbolic import JET_ORDER

#: A user's model (every jet non-zero: a configuration-dependent metric), built the same way
#: here and in the child process.
USER_MODEL = """
import sympy as sp
from charts.mechanism import Mechanism
a, b, s, kk, c = sp.symbols("a b s kk c", real=True)
M = sp.Matrix([[2 + sp.cos(b), sp.sin(a) / 3, 0], [sp.sin(a) / 3, 1.5, 0], [0, 0, 1 + s**2]])
user = Mechanism([a, b, s], [sp.cos(a) + kk * sp.cos(b) + s**3 / 3 - c], M,
                 parameters={kk: 0.7, c: 0.2}, periodic=[a, b], name="user_codegen")
"""

#: The generated source and the lambdified functions evaluate the same expressions with their
#: common subexpressions grouped differently: they agree to rounding (a few ulps of entries of
#: order one, the metric's ∂²M included).
RTOL, ATOL = 1e-12, 1e-12


def _user():
    namespace = {}
    exec(USER_MODEL, namespace)
    return namespace["user"]


def _key(m):
    return gen.model_key(m.q, m.params, m.F, m.M)


def _jets_at(fn, mech, q):
    outs = [np.zeros(mech._eval(key, q).shape) for key in JET_ORDER]
    fn(q, mech.param_values, *outs)
    return outs


def _points(mech, count, seed):
    rng = np.random.default_rng(seed)
    return [mech.random_state(seed=int(s))[0] for s in rng.integers(0, 2**31, count)]


@pytest.mark.parametrize("name", sorted(gen.SHIPPED_MECHANISMS))
def test_shipped_modules_hold_the_instances_models_and_give_their_jets(name):
    """Each shipped module's KEY is its instance's model key and the index maps that key to
    it; its ``jets`` (run by CPython: the same text numba compiles) equals the lambdified
    jets at random points of the instance."""
    mech = gen._shipped_model(name)
    mod = import_shipped(name)
    key = _key(mech)
    assert mod.KEY == key and import_shipped(gen.INDEX).MODULES[key] == name
    assert mod.COORDINATES == tuple(s.name for s in mech.q)
    for q in _points(mech, 3, seed=len(name)):
        for k, got in zip(JET_ORDER, _jets_at(mod.jets, mech, q)):
            np.testing.assert_allclose(got, mech._eval(k, q), rtol=RTOL, atol=ATOL, err_msg=k)


def test_a_changed_model_gets_a_new_key_and_never_the_shipped_module(tmp_path, monkeypatch):
    """The key is the model's: another parameter value keeps it (an argument of the jets), a
    flipped sign, a renamed coordinate or another metric changes it; a model one sign away
    from rotors(3) is written into the cache, not served by the shipped module."""
    monkeypatch.setenv("CHARTS_CACHE_DIR", str(tmp_path))
    from charts.mechanism import rotors
    R = rotors(3)
    assert _key(R.with_parameters(c=0.3, m1=2.0)) == _key(R)
    th = sp.symbols("theta1:4", real=True)
    m = sp.symbols("m1:4", positive=True)
    w = sp.symbols("w1:4", positive=True)
    c = sp.Symbol("c", real=True)
    params = {**{s: 1.0 for s in m + w}, c: 0.0}

    def model(F, masses=m, coords=th):
        return Mechanism(coords, [F], masses=masses, parameters=params, periodic=coords)
    same = model(sum(wi * sp.cos(t) for wi, t in zip(w, th)) - c)
    flipped = model(sum(wi * sp.cos(t) for wi, t in zip(w, th)) + c)
    heavier = model(sum(wi * sp.cos(t) for wi, t in zip(w, th)) - c, masses=(m[0], m[1], 2 * m[2]))
    phi = sp.symbols("phi1:4", real=True)
    renamed = model(sum(wi * sp.cos(t) for wi, t in zip(w, phi)) - c, coords=phi)
    assert _key(same) == _key(R)
    keys = {_key(x) for x in (R, flipped, heavier, renamed)}
    assert len(keys) == 4
    assert same.compiled_jets().py_func.__module__ == "charts.generated.mechanism_rotors_n3"
    mod = flipped.compiled_jets().py_func.__module__
    assert mod.startswith("charts_ondemand_mechanism_"), mod
    assert sys.modules[mod].KEY == _key(flipped)


def _tree(folder):
    """{relative path: (size, mtime_ns)} of every file under ``folder``."""
    out = {}
    for root, _, files in os.walk(folder):
        for f in files:
            st = os.stat(os.path.join(root, f))
            out[os.path.relpath(os.path.join(root, f), folder)] = (st.st_size, st.st_mtime_ns)
    return out


CHILD = USER_MODEL + """
import json, sys
import numpy as np
from charts.mechanism.symbolic import JET_ORDER
jets = user.compiled_jets()
q = np.array(json.loads(sys.argv[1]))
outs = [np.zeros(user._eval(key, q).shape) for key in JET_ORDER]
jets(q, user.param_values, *outs)
print(json.dumps({"module": jets.py_func.__module__, "file": sys.modules[jets.py_func.__module__].__file__,
                  "hits": sum(jets.stats.cache_hits.values()),
                  "misses": sum(jets.stats.cache_misses.values()),
                  "jets": [o.tolist() for o in outs]}))
"""


def test_a_users_mechanism_is_written_once_and_read_by_a_second_process(tmp_path, monkeypatch):
    """First use writes the jets module (and its hash) into the cache folder and numba's
    compiled code beside it; a fresh process with the same cache folder loads both: no
    derivation message, no file written or touched, numba's cache hit and no compilation,
    and the same jets bit for bit.  The compiled jets equal the lambdified ones."""
    monkeypatch.setenv("CHARTS_CACHE_DIR", str(tmp_path))
    user = _user()
    jets = user.compiled_jets()
    path = sys.modules[jets.py_func.__module__].__file__
    assert Path(path) == cache_dir() / f"mechanism_{_key(user)[:20]}.py"
    assert str(cache_dir()).startswith(str(tmp_path))
    q = _points(user, 1, seed=5)[0]
    mine = _jets_at(jets, user, q)                          # compiled here: numba writes its cache
    for k, got in zip(JET_ORDER, mine):
        np.testing.assert_allclose(got, user._eval(k, q), rtol=RTOL, atol=ATOL, err_msg=k)
    before = _tree(tmp_path)
    env = dict(os.environ, CHARTS_CACHE_DIR=str(tmp_path))
    done = subprocess.run([sys.executable, "-c", CHILD, json.dumps(q.tolist())], env=env,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    child = json.loads(done.stdout.strip().splitlines()[-1])
    assert "deriving" not in done.stderr, done.stderr
    assert child["file"] == path
    assert (child["hits"], child["misses"]) == (1, 0), child
    assert _tree(tmp_path) == before
    for got, theirs in zip(mine, child["jets"]):
        assert np.array_equal(got, np.array(theirs))


def test_the_compiled_projection_is_project_now():
    """The tangent flow's compiled projection (``project=1``: after every step) equals the
    NumPy route (``project=0``, then ``project_now``) from a state, velocity and vectors put
    1e-4 off the manifold, on the linkage with massive rods (k = 3 constraints, M(q)): Newton
    to |F| ≤ 1e-13 and the same KKT solves by LAPACK and by the flow's own LU agree to
    rounding (1e-12 on entries of order one)."""
    from charts.mechanism import triple_linkage
    from charts.mechanism.tangent_flow import MechanismTangentFlow

    L = triple_linkage(0.3, joint_mass=0.2, rod_mass=0.5)
    q0, v0 = L.random_state(seed=2)
    kick = np.random.default_rng(3).normal(scale=1e-4, size=(3, 2 * L.n))
    flows = [MechanismTangentFlow(L, q0, v0, 2, dt=1e-3, reorth=10**6, project=p, seed=1)
             for p in (1, 0)]
    for f in flows:
        f.Z += kick
        f.advance(1)
    flows[1].project_now()
    np.testing.assert_allclose(flows[0].Z, flows[1].Z, rtol=0, atol=1e-12)
    assert np.max(np.abs(L.constraint(flows[0].Z[0, :L.n]))) <= 1e-13


def test_a_refused_projection_stops_the_compiled_run_at_that_step():
    """The compiled projection refuses a state that is not finite (a NaN in a tangent vector):
    the run stops after that step, and the flow's check names it (a MechanismError after
    1 step, not 3)."""
    from charts.mechanism import MechanismError, triple_linkage
    from charts.mechanism.tangent_flow import MechanismTangentFlow

    L = triple_linkage(0.3, joint_mass=0.2)
    q0, v0 = L.random_state(seed=2)
    flow = MechanismTangentFlow(L, q0, v0, 1, dt=1e-3, reorth=10, project=1)
    flow.Z[1, 0] = np.nan
    with pytest.raises(MechanismError, match="left the finite numbers after 1 steps"):
        flow.advance(3)
    assert flow.steps == 1
