"""Each shared kernel compiles once per process: no call passes a literal (``True``, ``-1``)
where the others pass a typed value, which would compile the whole kernel again for the
literal's type (seconds of every first use: docs/performance.md, First use)."""
import json
import os
import subprocess
import sys

PROBE = r"""
import json, charts
from charts.solvers.chart_formulation import enter_chart
from charts.solvers.tangent import tangent_kernel
s = charts.RotorSystem(3)
th, u = s.random_state(0)
charts.integrate(s, th, u, 30.0)                                   # chart switches
charts.integrate(s, th, u, 5.0, formulation="ambient", method="rk4")
charts.lyapunov_spectrum(s, th, u, 4.0, t_transient=1.0)
charts.curvature_along_trajectory(s, th, u, 2.0, t_transient=1.0)
charts.hyperbolicity_angles(s, th, u, 2.0, t_transient=1.0)
charts.covariant_lyapunov_vectors(s, th, u, 2.0, t_transient=1.0)
print(json.dumps({f.__name__: [str(sig) for sig in f.signatures]
                  for f in (enter_chart, tangent_kernel)}))
"""


def test_shared_kernels_have_one_signature_each():
    env = dict(os.environ)
    out = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True,
                         env=env, check=True, cwd=os.path.dirname(__file__) + "/..")
    signatures = json.loads(out.stdout.strip().splitlines()[-1])
    for name, sigs in signatures.items():
        assert len(sigs) == 1, (name, sigs)
