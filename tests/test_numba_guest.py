"""charts as a guest in numba's house (charts.jit.adaptations): nothing of it runs in a
process that does not import it; each adaptation steps aside, with one notice and the same
numbers, when numba's internals are not what it expects; ``CHARTS_NUMBA_PLAIN=1`` turns all
of them off and leaves numba's functions as numba defines them, with the same bits."""
import importlib.metadata
import json
import os
import subprocess
import sys

import pytest

#: A user's three-line numba script, and what it then finds in its process.
_USERS_SCRIPT = """
from numba import njit
@njit(cache=False)
def f(x): return x + 1
f(1)
import sys
from numba.core.caching import Cache
from numba.core.inline_closurecall import InlineWorker
from numba.core.types.functions import BaseFunction
print(sorted(m for m in sys.modules if m.split('.')[0] == 'charts'))
print(sorted({BaseFunction.get_call_type.__module__, InlineWorker.inline_ir.__module__,
              Cache.load_overload.__module__, Cache.save_overload.__module__}))
"""


def test_a_numba_script_that_never_imports_charts_loads_none_of_it():
    r = subprocess.run([sys.executable, "-c", _USERS_SCRIPT], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    modules, homes = r.stdout.splitlines()
    assert modules == "[]"
    assert homes == str(sorted({"numba.core.caching", "numba.core.inline_closurecall",
                                "numba.core.types.functions"}))
    groups = importlib.metadata.entry_points(group="numba_extensions")
    assert not [e for e in groups if e.value.startswith("charts")]


#: What a process computes: short hashes of a trajectory in each formulation, exponents,
#: angles, CLVs and an ensemble by lanes, N = 3, and what the adaptations' checks said.
_COMPUTE = """
import hashlib, json, sys
import numpy as np
import charts
import charts.jit

def digest(*arrays):
    h = hashlib.sha1()
    for a in arrays:
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()[:12]

what = sys.argv[1].split(",")
s = charts.RotorSystem(3)
th, u = s.random_state(seed=4)
out = {"state": charts.jit.report()}
if "chart" in what:
    r = charts.integrate(s, th, u, 10.0, formulation="chart")
    out["chart"] = digest(r.theta, r.u)
if "ambient" in what:
    r = charts.integrate(s, th, u, 10.0, formulation="ambient")
    out["ambient"] = digest(r.theta, r.u)
if "lyap" in what:
    out["lyap"] = digest(charts.lyapunov_spectrum(s, th, u, 20.0, t_transient=2.0).exponents)
if "angles" in what:
    a = charts.hyperbolicity_angles(s, th, u, 20.0, t_transient=2.0)
    out["angles"] = digest(a.phi_restricted, a.phi_full)
if "clv" in what:
    v = charts.covariant_lyapunov_vectors(s, th, u, 10.0, t_transient=2.0)
    out["clv"] = digest(v.phi, v.exponents)
if "lanes" in what:
    e = charts.lyapunov_ensemble(s, 3, 10.0, t_transient=1.0, workers=1, lanes=True)
    out["lanes"] = digest(*[m.exponents for m in e.members])
from numba.core.caching import Cache
from numba.core.inline_closurecall import InlineWorker
from numba.core.types.functions import BaseFunction
out["numba_own"] = (BaseFunction.get_call_type.__module__ == "numba.core.types.functions"
                    and InlineWorker.inline_ir.__module__ == "numba.core.inline_closurecall"
                    and Cache.load_overload.__module__ == "numba.core.caching")
print(json.dumps(out))
"""


def _compute(what, prelude="", cache=None, plain=False):
    env = dict(os.environ, CHARTS_NUMBA_PLAIN="1" if plain else "0")
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = str(cache)
    r = subprocess.run([sys.executable, "-c", prelude + _COMPUTE, ",".join(what)],
                       capture_output=True, text=True, env=env, timeout=900)
    assert r.returncode == 0, r.stderr
    notes = [line for line in r.stderr.splitlines()
             if line.startswith("charts:") and "compiled its kernels" not in line]
    return json.loads(r.stdout.splitlines()[-1]), notes


@pytest.fixture(scope="module")
def reference():
    """Every number with every adaptation on (the suite's shared cache)."""
    out, notes = _compute(["chart", "ambient", "lyap", "angles", "clv", "lanes"])
    assert notes == []
    assert set(out.pop("state").values()) == {"on"}
    assert out.pop("numba_own")
    return out


@pytest.mark.slow
def test_plain_numba_gives_the_same_bits_and_leaves_numba_alone(reference, tmp_path):
    """``CHARTS_NUMBA_PLAIN=1``, compiling everything afresh on stock numba (a cache of its
    own): the same trajectories in both formulations, exponents, angles, CLVs and lanes, bit
    for bit, and numba's functions are numba's throughout."""
    out, notes = _compute(list(reference), cache=tmp_path / "cache", plain=True)
    assert notes == []
    assert set(out.pop("state").values()) == {"plain"}
    assert out.pop("numba_own")
    assert out == reference


#: numba changed under each adaptation (before charts is imported): a signature with other
#: parameters, an attribute gone — numba itself keeps working.
_MISMATCHES = {
    "cache_lock": """
from numba.core.caching import FunctionCache
_load = FunctionCache.load_overload
def load_overload(self, signature, target_context):
    return _load(self, signature, target_context)
FunctionCache.load_overload = load_overload
""",
    "inliner": """
from numba.core.inline_closurecall import InlineWorker
_inline_ir = InlineWorker.inline_ir
def inline_ir(self, *args, **kws):
    return _inline_ir(self, *args, **kws)
InlineWorker.inline_ir = inline_ir
""",
    "typing_memo": """
from numba.core.types.functions import BaseFunction
_get = BaseFunction.get_call_type
def get_call_type(self, ctx, args, kws):
    return _get(self, ctx, args, kws)
BaseFunction.get_call_type = get_call_type
""",
    "kernel_address": """
from numba.core.dispatcher import Dispatcher
_cfa = Dispatcher._compile_for_args
def _compile_for_args(self, *args):
    return _cfa(self, *args)
Dispatcher._compile_for_args = _compile_for_args
""",
    "vector_lowering": """
from numba.core.compiler import Flags
Flags.options = {k: v for k, v in Flags.options.items() if k != "noalias"}
""",
    "borrowed_views": """
from numba.core.datamodel import models
models.ArrayModel.__module__ = "numba.core.datamodel.elsewhere"     # its source not found
""",
}

#: What each mismatch is shown on (the analyses whose code takes the adaptation), and
#: whether it needs a cache of its own (an adaptation that changes the machine code, not only
#: how fast it compiles: numba's cache key does not hold the choice).
_SHOWN_ON = {"cache_lock": (["chart", "lyap"], False), "inliner": (["lyap"], False),
             "typing_memo": (["lyap"], False), "kernel_address": (["angles"], False),
             "vector_lowering": (["lanes"], True), "borrowed_views": (["lyap"], True)}


@pytest.mark.parametrize("name", sorted(_MISMATCHES))
def test_an_adaptation_steps_aside_on_a_mismatch(name, reference, tmp_path):
    """The adaptation whose internals changed is off, with one notice that names it; the
    others stay on; the numbers are the same bits."""
    what, own_cache = _SHOWN_ON[name]
    out, notes = _compute(what, prelude=_MISMATCHES[name],
                          cache=tmp_path / "cache" if own_cache else None)
    state = out.pop("state")
    assert state[name].startswith("off: ")
    assert all(v == "on" for k, v in state.items() if k != name)
    assert len(notes) == 1 and f"'{name}' adaptation" in notes[0], notes
    out.pop("numba_own")
    assert out == {k: reference[k] for k in what}


def test_the_switch_is_read_as_documented():
    code = "from charts.jit import adaptations; print(adaptations.PLAIN)"
    for value, plain in (("1", True), ("yes", True), ("0", False), ("", False)):
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           env=dict(os.environ, CHARTS_NUMBA_PLAIN=value), timeout=120)
        assert r.stdout.strip() == str(plain), r.stderr
