"""Hostile input at the public analyses on a Mechanism: each bad argument is refused by a
one-line error naming it, before any flow runs (never a NaN-filled result or an error from
deep inside)."""
import numpy as np
import pytest

import charts
from charts.mechanism import MechanismError


@pytest.fixture(scope="module")
def linkage_state():
    mech = charts.triple_linkage(0.1)
    q, v = mech.random_state(seed=1)
    return mech, q, v


@pytest.mark.parametrize("name", ["lyapunov_spectrum", "hyperbolicity_angles",
                                  "curvature_along_trajectory", "covariant_lyapunov_vectors"])
def test_a_state_at_rest_is_refused_naming_v0(linkage_state, name):
    # v0 = 0 is on the manifold and tangent, but has no flow direction: before this check the
    # angles and CLVs came back NaN-filled and the exponents raised ZeroDivisionError
    mech, q, v = linkage_state
    with pytest.raises(MechanismError, match=r"v0 must be a moving state"):
        getattr(charts, name)(mech, q, np.zeros_like(v), 2.0)


def test_lyapunov_refuses_an_off_manifold_start_naming_q0(linkage_state):
    mech, q, v = linkage_state
    with pytest.raises(MechanismError, match=r"^q0: .*off the constraint"):
        charts.lyapunov_spectrum(mech, q + 0.1, v, 2.0)


def test_too_many_exponents_with_the_full_product_gives_no_circular_hint(linkage_state):
    mech, q, v = linkage_state
    with pytest.raises(ValueError, match=r"out of range 1\.\.4 .*inner='full'$"):
        charts.lyapunov_spectrum(mech, q, v, 1.0, n_exponents=5, inner="full")
    with pytest.raises(ValueError, match=r"use inner='full' for up to 4"):
        charts.lyapunov_spectrum(mech, q, v, 1.0, n_exponents=3)


@pytest.mark.parametrize("name", ["lyapunov_spectrum", "lyapunov_ensemble"])
def test_a_system_that_is_no_mechanism_is_named_with_both_kinds(name):
    with pytest.raises(TypeError, match=r"system must be a charts.RotorSystem or another "
                                        r"charts.Mechanism, got 'm'"):
        getattr(charts, name)("m", 2, 1.0)


def circle(radius=1.0):
    """A 1-dimensional mechanism (a point on a circle): the factory of the scene test below."""
    import sympy as sp
    from charts.mechanism import Mechanism
    x, y = sp.symbols("x y")
    return Mechanism([x, y], [x ** 2 + y ** 2 - radius ** 2], masses=[1, 1], name="circle")


def test_a_one_dimensional_mechanism_is_refused_by_the_analysis_and_the_scene():
    # the exponents came back as one positive number (the linear growth along the flow over
    # t_final, not an exponent), and a scene printed an empty list: both now refuse it, as
    # the other analyses and the ensembles do
    from charts.runs.scene import SceneError, parse_scene
    mech = circle()
    q, v = mech.random_state(seed=2)
    with pytest.raises(MechanismError, match=r"^mech: circle has a 1-dimensional"):
        charts.lyapunov_spectrum(mech, q, v, 2.0)
    with pytest.raises(SceneError, match=r"\[mechanism\] name = 'test_mechanism_hostile:circle'"
                                         r": circle has a 1-dimensional configuration space"):
        parse_scene({"mechanism": {"name": "test_mechanism_hostile:circle"},
                     "run": {"t_final": 1.0}, "effects": {"lyapunov": {}}})


def test_a_sweep_setting_a_parameter_twice_is_refused():
    # r and "mechanism.r" both: the rows were labelled with r's value while the scenes ran
    # at the dotted axis's, a silent wrong table
    from charts.runs.sweep.spec import SweepError, parse_sweep
    data = {"scene": {"mechanism": {"name": "triple_linkage", "r": 0.2},
                      "run": {"t_final": 2.0}, "effects": {"lyapunov": {"n_batches": 2}}},
            "sweep": {"mode": "grid", "seeds": 1,
                      "parameters": {"r": [0.1], "mechanism.r": [0.2]}}}
    with pytest.raises(SweepError, match=r"r and \"mechanism.r\" both set the mechanism's r"):
        parse_sweep(data)
    del data["sweep"]["parameters"]["mechanism.r"]
    assert parse_sweep(data).axes == {"r": [0.1]}


def test_the_verdicts_refusal_of_a_linkage_that_does_not_assemble_states_the_condition():
    # the message said "it needs at least r + l >= R" also where r + l >= R held (l = 5); the
    # condition it now states is checked both ways: l = 1.099 (strict triangle inequalities,
    # the joint at the centre) assembles, l = 5 and l = 0.85 (l + r < R) do not
    from charts.runs.verdict_linkage import linkage_plan
    linkage_plan(0.1, l=1.099)
    for l in (5.0, 0.85):
        with pytest.raises(MechanismError, match=r"never where l \+ r < R; always where l, r, R "
                                                 r"satisfy the strict triangle inequalities"):
            linkage_plan(0.1, l=l)


@pytest.mark.parametrize("dt", [-1.0, 0.0, float("nan"), "0.01"])
def test_the_cross_check_integrators_refuse_a_bad_step_naming_dt(linkage_state, dt):
    # integrate_chart took dt <= 0 as one step per sample (a silent h = t_final / samples), and
    # a NaN failed in np.ceil
    from charts.mechanism import integrate_ambient, integrate_chart
    mech, q, v = linkage_state
    with pytest.raises(MechanismError, match=r"^dt must be"):
        integrate_chart(mech, q, v, 1.0, samples=2, dt=dt)
    with pytest.raises(MechanismError, match=r"^dt must be"):
        integrate_ambient(mech, q, v, 1.0, samples=2, method="rk4", dt=dt)


def test_lift_refuses_chart_coordinates_of_the_wrong_length(linkage_state):
    # three numbers for a 2-coordinate chart: numpy's broadcast error from inside lift
    mech, q, _ = linkage_state
    with pytest.raises(MechanismError, match=r"s must have shape \(2,\), got \(3,\): s is the "
                                             r"chart's coordinates \('theta1', 'theta2'\)"):
        mech.lift([0.1, 0.2, 0.3], (0, 1), q)
    p = mech.lift(q[[0, 1]], (0, 1), q)            # the right length lifts back to q itself
    np.testing.assert_allclose(p, q, atol=1e-10)  # q is on F = 0 to ~1e-15; Newton's tol 1e-13


def test_random_state_says_why_a_negative_metric_has_no_state():
    # a sphere with M = -I: the points exist, the velocities have no positive energy; the
    # message said only "no random point found"
    import sympy as sp
    from charts.mechanism import Mechanism
    x, y, z = sp.symbols("x y z")
    box = {c: (-2, 2) for c in "xyz"}
    neg = Mechanism([x, y, z], [x ** 2 + y ** 2 + z ** 2 - 1], -sp.eye(3), name="neg", bounds=box)
    with pytest.raises(MechanismError, match=r"200 points had a tangent velocity of kinetic "
                                             r"energy vᵀMv <= 0 \(the metric must be positive"):
        neg.random_state(seed=0)
    pos = Mechanism([x, y, z], [x ** 2 + y ** 2 + z ** 2 - 1], sp.eye(3), name="pos", bounds=box)
    q, v = pos.random_state(seed=0, speed=2.0)
    assert np.isclose(v @ v, 4.0, rtol=1e-12)        # M = I: vᵀMv = speed², to rounding


def test_verdict_refuses_a_rim_radius_given_twice():
    # 0.1,0.10 ran the same case twice (minutes of work, a repeated row)
    import argparse
    from charts.cli.verdict import radii_arg
    with pytest.raises(argparse.ArgumentTypeError, match=r"the rim radius 0.10 is given twice"):
        radii_arg("0.1,0.2,0.10")
    assert radii_arg("0.1,0.2") == [0.1, 0.2]


def test_second_fundamental_form_checks_its_point_and_vectors_and_is_the_spheres():
    # it took a point off the manifold and a normal vector as u without a word, and returned
    # a vector; on the unit sphere (M = I) h(u, w) is ±⟨u, w⟩ q, an independent closed form
    import sympy as sp
    from charts.mechanism import Mechanism
    x, y, z = sp.symbols("x y z")
    sphere = Mechanism([x, y, z], [x ** 2 + y ** 2 + z ** 2 - 1], sp.eye(3), name="sphere",
                       bounds={c: (-2, 2) for c in "xyz"})
    q, v = sphere.random_state(seed=0)
    w = np.cross(q, v)                                   # tangent, orthogonal to v
    with pytest.raises(MechanismError, match=r"off the constraint"):
        sphere.second_fundamental_form(3 * q, v, v)
    with pytest.raises(MechanismError, match=r"^u is not tangent"):
        sphere.second_fundamental_form(q, q, v)
    h = sphere.second_fundamental_form(q, v, v)
    assert abs(abs(h @ q) - v @ v) < 1e-12            # |h(v, v)| = |v|², along the normal q
    assert np.linalg.norm(h - (h @ q) * q) < 1e-12      # (rounding of unit-size vectors)
    assert np.linalg.norm(sphere.second_fundamental_form(q, v, w)) < 1e-12   # ⟨v, w⟩ = 0


@pytest.mark.parametrize("order", [0, 4, 1.5, "x"])
def test_embedding_jets_refuses_an_order_other_than_1_2_3(linkage_state, order):
    # any order but 1 and 2 returned all three jets (RotorSystem's twin refused them already)
    mech, q, _ = linkage_state
    with pytest.raises(MechanismError, match=r"^order must be an integer in 1\.\.3"):
        mech.embedding_jets(q, (0, 1), order)
    assert len(mech.embedding_jets(q, (0, 1), 2)) == 2


def test_a_factory_that_fails_with_a_type_error_is_named_as_failing():
    # math.cos called with no arguments: the scene said "[mechanism] is not allowed: ...",
    # naming no key; a value the factory refuses is still named by its key
    from charts.runs.scene import SceneError, parse_scene
    base = {"run": {"t_final": 1.0}, "effects": {"lyapunov": {}}}
    with pytest.raises(SceneError, match=r"\[mechanism\] name = 'math:cos': the factory failed "
                                         r"\(TypeError: "):
        parse_scene(dict(base, mechanism={"name": "math:cos"}))
    with pytest.raises(SceneError, match=r"\[mechanism\] r = -0.3 is not allowed: r must be "
                                         r"positive"):
        parse_scene(dict(base, mechanism={"name": "triple_linkage", "r": -0.3}))


def test_a_sweep_axis_over_a_factory_default_points_to_the_dotted_key():
    # joint_mass is triple_linkage's parameter, but the base table does not write it: the
    # message listed the ways to use an axis without the one that works here
    from charts.runs.sweep.spec import SweepError, parse_sweep
    data = {"scene": {"mechanism": {"name": "triple_linkage", "r": 0.2},
                      "run": {"t_final": 2.0}, "effects": {"lyapunov": {"n_batches": 2}}},
            "sweep": {"mode": "grid", "seeds": 1, "parameters": {"joint_mass": [0.0, 0.1]}}}
    with pytest.raises(SweepError, match=r"joint_mass is not used: .*\(for a parameter of the "
                                         r"factory that \[scene.mechanism\] does not write: "
                                         r"\"mechanism.joint_mass\"\)$"):
        parse_sweep(data)
    data["sweep"]["parameters"] = {"mechanism.joint_mass": [0.0, 0.1]}
    assert parse_sweep(data).axes == {"mechanism.joint_mass": [0.0, 0.1]}


def test_a_model_with_a_kink_or_an_undefined_function_is_refused_when_made():
    # |x| failed in the generated code (NameError: DiracDelta), f(x) in SymPy's printer: both
    # deep inside derive(); now the constructor names the expression and the function
    import sympy as sp
    from charts.mechanism import Mechanism
    x, y, z = sp.symbols("x y z")
    rest = y ** 2 + z ** 2 - 1
    with pytest.raises(MechanismError, match=r"constraints\[0\] = .*uses \['Abs\(x\)'\], which "
                                             r"is not smooth"):
        Mechanism([x, y, z], [sp.Abs(x) + rest], sp.eye(3))
    with pytest.raises(MechanismError, match=r"undefined function\(s\) \['f\(x\)'\]"):
        Mechanism([x, y, z], [sp.Function("f")(x) + rest], sp.eye(3))
    with pytest.raises(MechanismError, match=r"metric entry = Max\(1, x\) uses"):
        Mechanism([x, y, z], [x ** 2 + rest], sp.diag(sp.Max(1, x), 1, 1))
    smooth = Mechanism([x, y, z], [sp.sqrt(1 + x ** 2) + rest], sp.eye(3))   # smooth: accepted
    assert smooth.dim == 2


def test_n_unstable_out_of_range_on_a_surface_reads_one_dimension(linkage_state):
    mech, q, v = linkage_state
    with pytest.raises(ValueError, match=r"^n_unstable must be an integer in 1\.\.1, got 2 \(E_u "
                                         r"of a 2-dimensional configuration space has at most 1 "
                                         r"dimension\)$"):
        charts.hyperbolicity_angles(mech, q, v, 2.0, n_unstable=2)


def test_a_mechanism_projects_a_tangent_by_the_rotors_name():
    """``project_tangent`` (the rotors' name) is the M-orthogonal projection onto ker J, the
    same numbers as ``project_velocity``, and agrees with ``RotorSystem.project_tangent`` on
    the generic rotors of unequal masses (1e-12: two solves of the same projection)."""
    import charts
    from charts.mechanism.instances import rotors
    m = charts.triple_linkage(0.2)
    q, _ = m.random_state(seed=3)
    u = np.arange(1.0, 6.0)
    w = m.project_tangent(q, u)
    assert np.array_equal(w, m.project_velocity(q, u))
    assert np.max(np.abs(m.jacobian(q) @ w)) < 1e-12
    generic, rotor = rotors(3, masses=[1.0, 2.0, 3.0]), charts.RotorSystem(3, masses=[1.0, 2.0, 3.0])
    theta, _ = rotor.random_state(seed=2)
    x = np.array([0.3, -1.0, 0.7])
    assert np.allclose(generic.project_tangent(theta, x), rotor.project_tangent(theta, x),
                       rtol=0, atol=1e-12)
    with pytest.raises(charts.MechanismError, match="u"):
        m.project_tangent(q, np.ones(4))
