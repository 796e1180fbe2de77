"""No input reaches a compiled kernel that could make it read or write outside its arrays.

The linkage's compiled LU factorisation once left its pivot rows uninitialised past a zero
pivot, and the solve then swapped entries at those garbage indices: a singular Gram matrix
J Jᵀ (``LinkageSystem(0.1).project(np.zeros(7), np.zeros(7))``) ended the interpreter with a
segmentation fault.  Every case here runs in a child process, so a crash is a failed test
(the child's exit status and stderr), never a dead pytest.  (The linkage is now a
``charts.Mechanism``: its projections and flow are the mechanism's, on LAPACK's
factorisations, and its compiled LU and projections are gone with their test.)"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

import pytest

#: The public calls tried in the child: name -> expression, each expected to raise a
#: ValueError whose message contains the given words (the argument it names).
PUBLIC = {
    "project at q = 0 (singular J Jᵀ)": ("L.project(np.zeros(7), np.zeros(7))",
                                         ["q =", "singular configuration", "random_state"]),
    "project with NaN": ("L.project(np.full(7, np.nan), np.zeros(7))", ["q", "non-finite"]),
    "project with NaN v": ("L.project(q0, np.full(7, np.nan))", ["v", "non-finite"]),
    "project with q too short": ("L.project(np.zeros(3), np.zeros(7))", ["q", "shape (7,)"]),
    "project with q too long": ("L.project(np.zeros(9), np.zeros(7))", ["q", "shape (7,)"]),
    "project with v too short": ("L.project(q0, np.zeros(2))", ["v", "shape (7,)"]),
    "project with a 2-D q": ("L.project(np.zeros((2, 7)), np.zeros(7))", ["q", "shape (7,)"]),
    "project with a string": ("L.project('abcdefg', np.zeros(7))", ["q", "real numbers"]),
    "project with complex q": ("L.project(q0 + 1j, v0)", ["q", "real numbers"]),
    "project with a NaN speed": ("L.project(q0, v0, speed=float('nan'))", ["speed"]),
    "project with a negative speed": ("L.project(q0, v0, speed=-1.0)", ["speed"]),
    "a speed for a zero velocity": ("L.project(q0, np.zeros(7), speed=1.0)",
                                    ["v has no component tangent", "speed=None"]),
    "check_state at zeros": ("L.check_state(np.zeros(7), np.zeros(7))", ["q is off"]),
    "check_state with short v": ("L.check_state(q0, np.zeros(6))", ["v", "shape (7,)"]),
    "constraints of a short q": ("L.constraints(np.zeros(2))", ["q", "shape (7,)"]),
    "jacobian of an empty q": ("L.jacobian(np.zeros(0))", ["q", "shape (7,)"]),
    "disk_margin of NaN": ("L.disk_margin(np.full(7, np.nan))", ["q", "non-finite"]),
    "from_rotor_state with 3 angles": ("L.from_rotor_state(np.zeros(3), np.zeros(4))",
                                       ["theta", "shape (4,)"]),
    "from_rotor_state with short u": ("L.from_rotor_state(th, np.zeros(2))", ["u", "shape (4,)"]),
    "gauss_curvature of a short q": ("gauss_curvature(L, np.zeros(3), v0, v0)", ["q", "shape (7,)"]),
    "gauss_curvature of a short X": ("gauss_curvature(L, q0, np.zeros(3), v0)", ["X", "shape (7,)"]),
    "linkage_run from q = 0": ("linkage_run(L, np.zeros(7), np.zeros(7), 1.0)", ["q0 is off"]),
}

CHILD = """
import json, sys
import numpy as np
import charts
from charts.analyses.linkage import gauss_curvature, linkage_run
L = charts.LinkageSystem(0.1)
q0, v0 = L.random_state(seed=3)
th, u = charts.RotorSystem(4).random_state(seed=3)
out = {}
for name, expr in json.loads(sys.argv[1]).items():
    try:
        eval(expr)
        out[name] = ["returned", ""]
    except Exception as exc:
        out[name] = [type(exc).__name__, str(exc)]
    print(name, flush=True)        # the last case printed is the one running if it crashes
print("RESULT " + json.dumps(out))
"""

def _child(code, *args):
    env = dict(os.environ, PYTHONFAULTHANDLER="1")
    p = subprocess.run([sys.executable, "-c", textwrap.dedent(code), *args], env=env,
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, (f"the child process died with status {p.returncode} "
                               f"(a negative status is a signal: -11 = segmentation fault) "
                               f"after:\n{p.stdout[-2000:]}\n{p.stderr[-3000:]}")
    line = [ln for ln in p.stdout.splitlines() if ln.startswith("RESULT ")]
    assert line, p.stdout + p.stderr
    return json.loads(line[-1][len("RESULT "):])


def test_degenerate_linkage_input_is_a_value_error_naming_the_argument():
    exprs = {name: expr for name, (expr, _) in PUBLIC.items()}
    out = _child(CHILD, json.dumps(exprs))
    bad = []
    for name, (expr, words) in PUBLIC.items():
        kind, msg = out[name]
        if kind != "ValueError" or not all(w in msg for w in words):
            bad.append(f"{name}: {expr} gave {kind}: {msg!r}, expected a ValueError with {words}")
    assert not bad, "\n".join(bad)


def test_valid_states_still_project_and_keep_their_numbers():
    """The guards change no result: a state projected twice is a fixed point, and a speed is
    set exactly (as before the guards)."""
    import numpy as np

    import charts

    L = charts.LinkageSystem(0.1)
    q, v = L.random_state(seed=5, speed=2.0)
    assert L.speed(v) == pytest.approx(2.0, rel=1e-14)
    q2, v2 = L.project(q, v)
    assert np.max(np.abs(q2 - q)) < 1e-13 and np.max(np.abs(v2 - v)) < 1e-12
    L.check_state(q, v)
    assert L.constraint_rank_margin(q) > 1e-6
    assert L.constraint_rank_margin(np.zeros(7)) == 0.0


def test_rotor_to_chart_checks_the_velocity():
    import numpy as np

    import charts

    S = charts.RotorSystem(4)
    th, u = S.random_state(seed=1)
    for bad in (np.zeros(2), np.zeros(7), np.full(4, np.nan)):
        with pytest.raises(ValueError, match="u"):
            S.to_chart(th, bad, 0)
