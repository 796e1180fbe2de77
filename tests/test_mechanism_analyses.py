"""The analyses of a generic Mechanism (charts.analyses.mechanism_angles, ...) against the
rotors' own analyses on ``rotors(3)``, the rotors as a generic Mechanism: the independent
route (eq (8) in closed form, adjoint vectors, the rotors' kernels).

Tolerances (named in TOL, each with its reason).
"""
import numpy as np
import pytest

import charts
from charts.analyses.mechanism_angles import mechanism_angles
from charts.mechanism import MechanismError, rotors

TOL = {
    # the two routes' trajectories separate at rounding level, grown by e^{λt} (λ ≈ 0.5):
    # 1e-16·e^{0.5·30} ≈ 3e-10 at the window's start; each pass's vectors converge like
    # e^{−λ₁ t_transient} = e^{−15} ≈ 3e-7 (the gap to the zero exponents, d = 2):
    # measured 4e-8 rad; 1e-6 leaves a factor 25
    "pointwise": 1e-6,
    # statistics of angles from two trajectories that decorrelate after t ≈ 17 (measured):
    # independent estimates, two-sided, within a few combined standard errors
    "sigmas": 3.0,
}


@pytest.fixture(scope="module")
def rot3():
    return rotors(3)


@pytest.fixture(scope="module")
def start(rot3):
    return rot3.random_state(3)


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
    for kw, err, word in cases:
        args = dict(mech=rot3, q0=q, v0=v, t_final=1.0, t_transient=0.0)
        args.update(kw)
        with pytest.raises(err, match=word):
            mechanism_angles(args.pop("mech"), args.pop("q0"), args.pop("v0"),
                             args.pop("t_final"), **args)
    res = mechanism_angles(rot3, q, v, 1.0, t_transient=0.0)
    with pytest.raises(ValueError, match="full"):
        res.statistics("full")
