"""The analyses of a generic Mechanism (charts.analyses.mechanism_angles, ...) against the
rotors' own analyses on ``rotors(3)``, the rotors as a generic Mechanism: the independent
route (eq (8) in closed form, adjoint vectors, the rotors' kernels).

Tolerances (named in TOL, each with its reason).
"""
import numpy as np
import pytest

import charts
from charts.analyses.curvature import gaussian_curvature_eq22
from charts.analyses.mechanism_angles import mechanism_angles
from charts.analyses.mechanism_covariant import mechanism_clvs
from charts.analyses.mechanism_curvature import mechanism_curvature
from charts.mechanism import MechanismError, rotors, triple_linkage

TOL = {
    # the two routes' trajectories separate at rounding level, grown by e^{λt} (λ ≈ 0.5):
    # 1e-16·e^{0.5·30} ≈ 3e-10 at the window's start; each pass's vectors converge like
    # e^{−λ₁ t_transient} = e^{−15} ≈ 3e-7 (the gap to the zero exponents, d = 2):
    # measured 4e-8 rad; 1e-6 leaves a factor 25
    "pointwise": 1e-6,
    # statistics of angles from two trajectories that decorrelate after t ≈ 17 (measured):
    # independent estimates, two-sided, within a few combined standard errors
    "sigmas": 3.0,
    # the same curvature at the same points and frames by two routes of rounding-level
    # error (Riemann tensor of generated/lambdified jets, the Gauss equation, eq (22)):
    # measured 2e-10 between the rotors' and the mechanism's routes (the trajectories
    # agree to ~1e-11 over t ≤ 25), 2e-11 against eq (22)
    "same_curvature": 1e-8,
    # route (a) against route (b): the central difference's O(Δt²) truncation at Δt =
    # 0.01 (measured 3.3e-5 on rotors(3), 7e-6 on rotors(5), for |K| ≤ 0.4)
    "jacobi": 2e-4,
    # CLVs by Ginelli's method on the same trajectory (t ≤ 65, separated by ~1e-9 by its
    # end), both bases converged (forward and backward transients of 30): measured 3e-9
    # (angles), 3e-9 (growth rates) on rotors(3) and rotors(5)
    "clv": 1e-7,
    # the growth along the two neutral CLVs (the flow direction and the energy shift, a
    # Jordan block: the shift grows linearly) is fixed within E_0 only algebraically, as
    # 1/t of the transients, not exponentially: measured 1.2e-6 on rotors(3)
    "clv_neutral": 1e-5,
}


@pytest.fixture(scope="module")
def rot3():
    return rotors(3)


@pytest.fixture(scope="module")
def start(rot3):
    return rot3.random_state(3)


def _refused(analysis, cases, mech, start):
    """Each case (keywords, error, word) replaces the base call's arguments (mech, the
    start, t_final = 1, no transient) and is refused with ``error`` naming ``word``."""
    q, v = start
    for kw, err, word in cases:
        args = dict(mech=mech, q0=q, v0=v, t_final=1.0, t_transient=0.0)
        args.update(kw)
        with pytest.raises(err, match=word):
            analysis(args.pop("mech"), args.pop("q0"), args.pop("v0"), args.pop("t_final"),
                     **args)


def test_angles_meet_the_rotors_restricted_angles_pointwise(rot3, start):
    """Over a window that ends before the two routes' trajectories separate (t ≤ 45), the
    angles of ``rotors(3)`` by the generic test (backward tangent vectors, kinetic product =
    the Euclidean one at unit masses) equal the rotors' ``restricted`` angles (adjoint
    vectors, T_r) sample by sample, at the same times."""
    q, v = start
    mine = mechanism_angles(rot3, q, v, 10.0, t_transient=30.0)
    ref = charts.hyperbolicity_angles(charts.RotorSystem(3), q, v, 10.0, t_transient=30.0)
    np.testing.assert_array_equal(mine.t, ref.t)
    assert np.max(np.abs(mine.phi_restricted - ref.phi_restricted)) < TOL["pointwise"]
    assert mine.phi_restricted.min() > 0.1          # not a vacuous comparison of zeros


def _block_se(phi, stat, blocks=10):
    """The standard error of ``stat`` of a long series from its values on ``blocks``
    consecutive blocks (batch means: the blocks, each ≫ the angles' correlation time ~1, are
    nearly independent)."""
    vals = np.array([stat(b) for b in np.array_split(phi, blocks)])
    return vals.std(ddof=1) / np.sqrt(blocks)


def test_angle_statistics_and_growth_rates_meet_the_rotors(rot3, start):
    """Over a long window (the trajectories decorrelated) the median and the 1 % quantile of
    the angles agree with the rotors' within TOL["sigmas"] combined batch standard errors,
    and the smallest angles are of one size (N = 3 is uniformly hyperbolic: no small angle in
    either); the forward and backward growth rates agree with λ₁ of
    ``charts.lyapunov_spectrum(RotorSystem(3))`` within TOL["sigmas"] of the finite-time
    spread over the same time (the rotors' standard error of a run as long) and the
    reference's error."""
    q, v = start
    T, tr = 400.0, 40.0
    mine = mechanism_angles(rot3, q, v, T, t_transient=tr)
    ref = charts.hyperbolicity_angles(charts.RotorSystem(3), q, v, T, t_transient=tr)
    a, b = mine.phi_restricted, ref.phi_restricted
    for stat in (np.median, lambda x: np.percentile(x, 1)):
        se = np.hypot(_block_se(a, stat), _block_se(b, stat))
        assert abs(stat(a) - stat(b)) < TOL["sigmas"] * se, (stat(a), stat(b), se)
    sa, sb = mine.statistics(), ref.statistics()
    assert sa["frac_small"] == sb["frac_small"] == 0.0
    assert 0.5 < sa["min"] / sb["min"] < 2.0
    rotor = charts.RotorSystem(3)
    lam = charts.lyapunov_spectrum(rotor, q, v, 2000.0, n_batches=10, t_transient=50.0)
    spread = charts.lyapunov_spectrum(rotor, q, v, T + tr, n_batches=10, t_transient=0.0)
    se = np.hypot(lam.stderr[0], spread.stderr[0])
    for rate in (mine.forward_exponents[0], mine.adjoint_exponents[0]):
        assert abs(rate - lam.exponents[0]) < TOL["sigmas"] * se, (rate, lam.exponents, se)


def test_angles_bad_input_is_refused(rot3, start):
    q, v = start
    cases = [
        (dict(mech="rotors(3)"), MechanismError, "Mechanism"),
        (dict(mech=charts.Mechanism(["x", "y"], ["x**2 + y**2 - 1"], masses=[1, 1])),
         MechanismError, "1-dimensional"),
        (dict(q0=q + 0.1), MechanismError, "off the constraint"),
        (dict(q0=q[:2]), MechanismError, "q0"),
        (dict(v0=np.ones(3)), MechanismError, "not tangent"),
        (dict(t_final=-1.0), ValueError, "t_final"),
        (dict(t_final=1.005), ValueError, "t_final"),
        (dict(dt=0.0), ValueError, "dt"),
        (dict(n_unstable=2), ValueError, "n_unstable"),
        (dict(n_unstable=0), ValueError, "n_unstable"),
        (dict(t_transient=0.15, sample_every=0.1), ValueError, "multiples of sample_every"),
        (dict(project_every=0.0), ValueError, "project_every"),
        (dict(seed=-1), ValueError, "seed"),
    ]
    _refused(mechanism_angles, cases, rot3, start)
    res = mechanism_angles(rot3, q, v, 1.0, t_transient=0.0)
    with pytest.raises(ValueError, match="full"):
        res.statistics("full")


def _same_frames(a, b):
    """Frames equal up to the sign of each row (a Lyapunov vector's sign is arbitrary)."""
    return np.max(np.abs(np.abs(a) - np.abs(b)))


@pytest.mark.parametrize("n", [3, 5])
def test_curvature_meets_the_rotors_curvature(n):
    """On ``rotors(n)`` (a surface for n = 3, a 4-dimensional manifold for n = 5) the
    generic curvature along a trajectory (frames from the mechanism's Lyapunov vectors,
    route (a) by the ambient flow and parallel transport, route (b) by the Riemann tensor in
    a chart) equals ``charts.curvature_along_trajectory(RotorSystem(n))`` at the same
    times, states (angles modulo 2π: the mechanism wraps them) and frames; for n = 3 also
    eq (22)'s closed form."""
    mech = rotors(n)
    q, v = mech.random_state(3)
    T = 5.0 if n == 3 else 1.0
    mine = mechanism_curvature(mech, q, v, T, t_transient=20.0)
    ref = charts.curvature_along_trajectory(charts.RotorSystem(n), q, v, T, t_transient=20.0)
    np.testing.assert_allclose(mine.t, ref.t, rtol=0, atol=1e-12)
    wrapped = np.angle(np.exp(1j * (mine.theta - ref.theta)))
    assert np.max(np.abs(wrapped)) < TOL["same_curvature"]
    assert _same_frames(mine.frames, ref.frames) < TOL["same_curvature"]
    assert np.max(np.abs(mine.K_exact - ref.K_exact)) < TOL["same_curvature"]
    assert np.max(np.abs(mine.K_numeric - ref.K_numeric)) < TOL["jacobi"]
    assert np.max(np.abs(mine.K_numeric - mine.K_exact)) < TOL["jacobi"]
    assert np.max(np.abs(mine.K_exact)) > 0.01               # not a comparison of zeros
    if n == 3:
        assert np.max(np.abs(mine.K_exact[:, 0, 0] - gaussian_curvature_eq22(mine.theta))) \
            < TOL["same_curvature"]


def test_curvature_by_the_gauss_equation_in_four_dimensions():
    """The intrinsic K_ij of ``rotors(5)`` equals the Gauss equation of the embedding (no
    chart, no Christoffel symbols): the diagonal as K(p_i, p_0), the off-diagonal by
    polarisation, K_ij = K(p_i + p_j, p_0) − (K_ii + K_jj)/2 for an orthonormal frame."""
    mech = rotors(5)
    q, v = mech.random_state(4)
    res = mechanism_curvature(mech, q, v, 0.3, t_transient=0.0)
    for q, P, K in zip(res.theta, res.frames, res.K_exact):
        g = lambda a, b: mech.gauss_equation_curvature(q, a, b)
        for i in range(1, 4):
            assert abs(K[i - 1, i - 1] - g(P[i], P[0])) < TOL["same_curvature"]
            for j in range(i + 1, 4):
                off = g(P[i] + P[j], P[0]) - (K[i - 1, i - 1] + K[j - 1, j - 1]) / 2
                assert abs(K[i - 1, j - 1] - off) < TOL["same_curvature"]
        np.testing.assert_allclose(K, K.T, atol=TOL["same_curvature"])


def test_curvature_of_a_surface_is_its_gaussian_curvature():
    """On the triple linkage (a surface, the metric semi-definite: a massless joint) the one
    sectional curvature at every sample is the Gaussian curvature, by the intrinsic route and
    by the Gauss equation, and route (a) meets it within its O(Δt²)."""
    mech = triple_linkage(0.3)
    q, v = mech.random_state(2)
    res = mechanism_curvature(mech, q, v, 0.5, t_transient=1.0)
    K = res.K_exact[:, 0, 0]
    gauss = mech.gauss_equation_curvatures(res.theta)
    intrinsic = [mech.gaussian_curvature(x) for x in res.theta]
    assert np.max(np.abs(K - gauss)) < TOL["same_curvature"] * max(1.0, np.max(np.abs(K)))
    assert np.max(np.abs(K - intrinsic)) < TOL["same_curvature"] * max(1.0, np.max(np.abs(K)))
    assert np.max(np.abs(res.K_numeric[:, 0, 0] - K)) < TOL["jacobi"] * max(1.0, np.max(np.abs(K)))


def test_jacobi_route_converges_at_second_order_with_a_varying_metric():
    """Route (a) on the triple linkage with massive rods and joint (a configuration-dependent
    metric, so parallel transport's polarised acceleration carries ∂M): its distance to
    route (b) falls by 2² = 4 when Δt halves (the central difference's O(Δt²); measured
    4.0), and route (b) is the Gaussian curvature."""
    mech = triple_linkage(0.3, rod_mass=0.3, joint_mass=0.1)
    q, v = mech.random_state(2)
    err = []
    for dt in (0.02, 0.01):
        res = mechanism_curvature(mech, q, v, 0.4, t_transient=0.0, dt=dt, sample_every=0.2)
        err.append(np.max(np.abs(res.K_numeric - res.K_exact)))
        K = [mech.gaussian_curvature(x) for x in res.theta]
        assert np.max(np.abs(res.K_exact[:, 0, 0] - K)) < TOL["same_curvature"]
    assert 3.0 < err[0] / err[1] < 5.0, err


def test_curvature_bad_input_is_refused(rot3, start):
    q, v = start
    cases = [
        (dict(mech=None), MechanismError, "mech"),
        (dict(q0=q + 0.1), MechanismError, "q0"),
        (dict(v0=np.ones(3)), MechanismError, "v0"),
        (dict(t_final=0.0), ValueError, "t_final"),
        (dict(sample_every=0.3), ValueError, "sample_every"),
        (dict(exact="yes"), ValueError, "exact"),
        (dict(t_transient=-1.0), ValueError, "t_transient"),
        (dict(seed=1.5), ValueError, "seed"),
    ]
    _refused(mechanism_curvature, cases, rot3, start)


def test_public_analyses_route_a_mechanism_to_the_generic_ones(rot3, start):
    """``charts.lyapunov_spectrum``, ``hyperbolicity_angles`` and
    ``curvature_along_trajectory`` hand a Mechanism to the generic analyses: the same
    numbers bit for bit, positional or by keyword in either spelling of the state."""
    from charts.analyses import mechanism_lyapunov
    q, v = start
    ref = mechanism_lyapunov.lyapunov_spectrum(rot3, q, v, 2.0, n_batches=2, t_transient=1.0)
    for call in (lambda: charts.lyapunov_spectrum(rot3, q, v, 2.0, n_batches=2, t_transient=1.0),
                 lambda: charts.lyapunov_spectrum(rot3, q0=q, v0=v, t_final=2.0, n_batches=2,
                                                  t_transient=1.0),
                 lambda: charts.lyapunov_spectrum(system=rot3, theta0=q, u0=v, t_final=2.0,
                                                  n_batches=2, t_transient=1.0)):
        np.testing.assert_array_equal(call().batches, ref.batches)
    angles = charts.hyperbolicity_angles(rot3, q, v, 0.5, t_transient=0.5)
    np.testing.assert_array_equal(
        angles.phi_restricted, mechanism_angles(rot3, q, v, 0.5, t_transient=0.5).phi_restricted)
    clv = charts.covariant_lyapunov_vectors(rot3, q, v, 0.5, t_transient=0.5)
    np.testing.assert_array_equal(clv.phi, mechanism_clvs(rot3, q, v, 0.5, t_transient=0.5).phi)
    curv = charts.curvature_along_trajectory(rot3, q, v, 0.3, t_transient=0.0)
    np.testing.assert_array_equal(
        curv.K_exact, mechanism_curvature(rot3, q, v, 0.3, t_transient=0.0).K_exact)


def test_the_route_refuses_what_the_generic_analysis_does_not_take(rot3, start):
    q, v = start
    with pytest.raises(TypeError, match="space"):
        charts.lyapunov_spectrum(rot3, q, v, 2.0, space="full")
    with pytest.raises(TypeError, match="checkpoint_every"):
        charts.hyperbolicity_angles(rot3, q, v, 2.0, checkpoint_every=1.0)
    with pytest.raises(TypeError, match="q0 or theta0"):
        charts.curvature_along_trajectory(rot3, q0=q, theta0=q, v0=v, t_final=1.0)


def test_rotors_keep_their_route_and_other_systems_are_routed_by_type():
    """A RotorSystem (a Mechanism or not) keeps its own analyses, bit for bit with the
    undecorated function; the Appendix linkage goes to the generic route exactly when it
    is a Mechanism."""
    from charts.analyses import lyapunov
    from charts.analyses.mechanism_route import generic_mechanism
    S = charts.RotorSystem(3)
    th, u = S.random_state(seed=1)
    assert not generic_mechanism(S)
    assert generic_mechanism(rotors(3))
    L = charts.LinkageSystem(0.1)
    assert generic_mechanism(L) == isinstance(L, charts.Mechanism)
    if isinstance(L, charts.Mechanism):         # the Appendix linkage runs the generic test
        res = charts.hyperbolicity_angles(L, *L.random_state(seed=1), 1.0, t_transient=1.0)
        assert type(res).__name__ == "MechanismAngles" and res.forward_exponents.shape == (2,)
    assert not generic_mechanism("rotors") and not generic_mechanism(None)
    a = charts.lyapunov_spectrum(S, th, u, 2.0, n_batches=2, t_transient=1.0)
    b = lyapunov.lyapunov_spectrum.__wrapped__(S, th, u, 2.0, n_batches=2, t_transient=1.0)
    np.testing.assert_array_equal(a.exponents, b.exponents)
    with pytest.raises(TypeError, match="system"):
        charts.lyapunov_spectrum("rotors", th, u, 2.0)


@pytest.mark.parametrize("n", [3, 5])
def test_clvs_meet_the_rotors_clvs(n):
    """Ginelli's CLVs of ``rotors(n)`` by the generic route (the mechanism's tangent flow,
    Gram–Schmidt in the kinetic product) equal ``charts.covariant_lyapunov_vectors`` of
    ``RotorSystem(n)`` (restricted variant) sample by sample: the angle between E_u and E_cs,
    the angle between the leading unstable and stable CLVs, the growth rates along the CLVs
    and of the Gram–Schmidt vectors; the growth rates pair as (λ, …, 0, 0, …, −λ)."""
    mech = rotors(n)
    q, v = mech.random_state(3)
    mine = mechanism_clvs(mech, q, v, 5.0, t_transient=30.0)
    ref = charts.covariant_lyapunov_vectors(charts.RotorSystem(n), q, v, 5.0, t_transient=30.0)
    np.testing.assert_array_equal(mine.t, ref.t)
    for field in ("phi", "phi_vectors", "growth", "gs_rates"):
        diff = np.max(np.abs(getattr(mine, field) - getattr(ref, field)), axis=0)
        if field == "growth":                       # the neutral pair: columns n − 2, n − 1
            assert np.all(diff[n - 2:n] < TOL["clv_neutral"]), diff
            diff = np.delete(diff, [n - 2, n - 1])
        assert np.all(diff < TOL["clv"]), (field, diff)
    assert mine.phi.min() > 0.01 and mine.growth.shape == (50, 2 * (n - 1))


def test_clvs_bad_input_is_refused(rot3, start):
    q, v = start
    cases = [
        (dict(mech=0), MechanismError, "mech"),
        (dict(q0=q + 0.1), MechanismError, "q0"),
        (dict(variant="full"), ValueError, "variant"),
        (dict(variant="x"), ValueError, "variant"),
        (dict(keep_vectors=2), ValueError, "keep_vectors"),
        (dict(n_unstable=2), ValueError, "n_unstable"),
        (dict(t_final=0.05, sample_every=0.1), ValueError, "t_final"),
    ]
    _refused(mechanism_clvs, cases, rot3, start)
    res = mechanism_clvs(rot3, q, v, 0.5, t_transient=0.0, keep_vectors=True)
    assert res.vectors.shape == (5, 4, 6)
