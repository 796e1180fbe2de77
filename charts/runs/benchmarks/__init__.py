"""Benchmarks of the package, run by ``charts bench NAME`` (no source checkout needed).

* ``integrators`` (`integrators`): cost per unit time of ``charts.integrate`` against
  ``scipy.integrate.solve_ivp``;
* ``performance`` (`performance`): the Lyapunov task against JiTCODE and SciPy, cold start,
  both cores, code generation (peers in `peers`);
* ``compare`` (`compare`): the Lyapunov throughput of several installations of charts (e.g.
  two checkouts, each with its own interpreter), interleaved in one run;
* ``coldstart`` (`coldstart`): where a new process's seconds go before its first exponents,
  on an empty and on a filled numba cache (every compilation timed);
* ``accuracy``: work–precision diagrams (``charts.runs.accuracy``).

`environment` describes the machine and its load for every report.
"""
