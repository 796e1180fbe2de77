"""Mechanisms of one's own for ``charts verdict --mechanism`` (tests/test_verdict_mechanism.py),
named ``"verdict_mechanism_factory:<factory>"``: none has closed-form sheets, so the surface's
points come from Newton's method (``charts.mechanism.sheets``)."""
import sympy as sp

import charts


def arm():
    """The arm on a rail of docs/mechanisms.md (a configuration-dependent metric): χ = −4."""
    from test_mechanism_ensembles import arm as the_arm
    return the_arm()


def sphere(level=1.5):
    """Three angles with cos θ₁ + cos θ₂ + cos θ₃ = ``level`` and unit inertias, written by
    hand (not ``charts.mechanism.rotors``): for 1 < level < 3 the surface is a sphere, χ = 2
    by the Morse count (``charts.geometry.topology.euler_characteristic``)."""
    th = sp.symbols("phi1:4")
    c = sp.Symbol("c")
    return charts.Mechanism(th, [sum(sp.cos(t) for t in th) - c], sp.eye(3), periodic=th,
                            parameters={c: level}, name=f"sphere of angles (level {level:g})")


def pendulum(length=1.0):
    """A planar pendulum as a point on a circle: a 1-dimensional configuration space."""
    x, y, a = sp.symbols("x y a")
    return charts.Mechanism([x, y], [x ** 2 + y ** 2 - a ** 2], sp.eye(2),
                            parameters={a: length}, bounds={"x": (-2, 2), "y": (-2, 2)},
                            name="pendulum")
