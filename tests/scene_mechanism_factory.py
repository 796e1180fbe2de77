"""A user's own mechanism factory for the scene tests (``[mechanism] name =
"scene_mechanism_factory:sphere"``, tests/test_mechanism_scene.py): a point of mass ``mass``
on a sphere of radius ``radius``, q = (x, y, z), one constraint."""
import sympy

import charts


def sphere(radius=1.0, mass=1.0):
    """The sphere x² + y² + z² = radius² as a charts.Mechanism with parameters a, m."""
    x, y, z, a, m = sympy.symbols("x y z a m")
    return charts.Mechanism(["x", "y", "z"], [x ** 2 + y ** 2 + z ** 2 - a ** 2],
                            masses=[m, m, m], parameters={a: radius, m: mass},
                            bounds={"x": (-radius, radius), "y": (-radius, radius),
                                    "z": (-radius, radius)},
                            name=f"sphere(radius={radius:g})")


def not_a_mechanism(size=1.0):
    """A factory that returns something else (refused by the scene)."""
    return {"size": size}


def broken(size=1.0):
    """A factory that fails (refused by the scene, naming it)."""
    return 1.0 / (size - size)
