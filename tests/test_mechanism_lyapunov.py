"""Lyapunov exponents on a Mechanism (charts.analyses.mechanism_lyapunov, the compiled
tangent flow of charts.mechanism.tangent_flow) against the rotors' own analysis, the
structure of a geodesic flow's spectrum, the compiled jets against the lambdified ones and
the tangent flow against finite differences of the flow.

Tolerances (named in TOL, each with its reason).
"""
import numpy as np
import pytest

import charts
from charts.analyses.mechanism_lyapunov import lyapunov_spectrum
from charts.mechanism import MechanismError, rotors, triple_linkage
from charts.mechanism.symbolic import JET_ORDER
from charts.mechanism.tangent_flow import MechanismTangentFlow

TOL = {
    # two estimates of one exponent from different trajectories (the two routes' rounding
    # separates them within t ≈ 70): statistically independent, so they agree within a few
    # of their combined standard errors, two-sided
    "sigmas": 3.0,
    # the compiled jets (math, one CSE over all jets) and the lambdified ones (NumPy, CSE per
    # jet) are the same expressions rounded differently: a few ulps of entries of order ≤ 10
    "jets": 1e-13,
    # the RK4 map of the variational equations is the derivative of the RK4 map, so the
    # tangent flow equals central differences of the flow up to O(ε²) = 1e-12 and rounding
    # ~1e-16/ε = 1e-10, grown by e^{λt} ≈ 3 over t = 2: 1e-8 relative
    "finite_difference": 1e-8,
    # RK4's energy drift is ~ t · dt⁴ times the flow's scale: measured 7e-9 over t = 2050 at
    # dt = 0.01 on rotors(3), 1.3e-9 on the linkage; 1e-7 leaves a factor ~14
    "energy": 1e-7,
}


@pytest.fixture(scope="module")
def rot3():
    return rotors(3)


def test_rotors3_exponent_meets_the_rotor_analysis(rot3):
    """λ₁ of ``RotorSystem(3)`` by the generic route of a Mechanism (a RotorSystem is one: the
    compiled tangent flow of its symbolic jets, projected by its own `project_point`) equals
    λ₁ of ``charts.lyapunov_spectrum(RotorSystem(3))`` (eqs 17-18 by the rotors' own kernels)
    from the same state, within TOL["sigmas"] combined standard errors.  Not bit for bit: the
    two routes evaluate eq (8) by different formulas (a KKT solve against its closed form), so
    their trajectories separate at rounding level and decorrelate within the transient."""
    q, v = rot3.random_state(3)
    system = charts.RotorSystem(3)
    mine = lyapunov_spectrum(system, q, v, 2000.0, n_batches=10)
    ref = charts.lyapunov_spectrum(system, q, v, 2000.0, n_batches=10, t_transient=50.0)
    se = np.hypot(mine.stderr[0], ref.stderr[0])
    assert abs(mine.exponents[0] - ref.exponents[0]) < TOL["sigmas"] * se, (mine.summary(), ref)
    assert 0 < se < 0.02                             # a real error bar, not a vacuous one
    assert mine.energy_error < TOL["energy"]


def test_spectrum_of_a_geodesic_flow_pairs_and_zeros(rot3):
    """All 2d = 4 exponents of the surface Σ cos θ = 0 (inner="full"): (λ, 0, 0, −λ).  The pair
    sums λᵢ + λ_{2d+1−i} vanish within TOL["sigmas"] of their standard errors; the two zeros
    (flow direction, energy shift) converge only like ln t / t (the energy-shift vector grows
    linearly in time), so they are bounded by 2 ln T / T rather than by their error bars."""
    q, v = rot3.random_state(1)
    T = 500.0
    res = lyapunov_spectrum(rot3, q, v, T, inner="full", n_exponents=4, n_batches=10)
    lam, se = res.exponents, res.stderr
    assert lam[0] > 0.4                                       # chaotic: λ₁ ≈ 0.5
    assert abs(lam[0] + lam[3]) < TOL["sigmas"] * (se[0] + se[3]), res.summary()
    assert np.all(np.abs(lam[1:3]) < 2 * np.log(T) / T), res.summary()


def test_energy_is_conserved_along_the_linkage_flow():
    """The triple linkage's tangent flow (r = 0.2) keeps the kinetic energy to TOL["energy"],
    and its λ₁ is positive and of the rotor limit's size."""
    L = triple_linkage(0.2)
    q, v = L.random_state(2)
    res = lyapunov_spectrum(L, q, v, 200.0, n_batches=4, t_transient=20.0)
    assert res.energy_error < TOL["energy"]
    assert 0.3 < res.exponents[0] < 0.7, res.summary()


def test_compiled_jets_equal_the_lambdified_ones():
    """On the linkage with massive rods (a configuration-dependent metric: every jet is
    non-zero) at random points."""
    L = triple_linkage(0.2, rod_mass=0.3, joint_mass=0.1)
    jets = L.compiled_jets()
    for seed in range(3):
        q, _ = L.random_state(seed)
        outs = [np.zeros(L._eval(key, q).shape) for key in JET_ORDER]
        jets(q, L.param_values, *outs)
        for key, out in zip(JET_ORDER, outs):
            ref = L._eval(key, q)
            assert np.max(np.abs(out - ref)) < TOL["jets"] * max(1.0, np.max(np.abs(ref))), key


def test_tangent_flow_is_the_derivative_of_the_flow():
    """A tangent vector advanced by the compiled tangent flow (no re-orthonormalisation, no
    projection) equals the central difference of two advanced states, on the linkage with
    massive rods (so ∂M and ∂²M enter)."""
    L = triple_linkage(0.2, rod_mass=0.3, joint_mass=0.1)
    q, v = L.random_state(4)
    n, steps, eps = L.n, 200, 1e-6
    flow = MechanismTangentFlow(L, q, v, 1, dt=0.01, reorth=10 ** 9, project=0)
    x0 = flow.X[0].copy()
    flow.advance(steps)
    ends = []
    for s in (1.0, -1.0):
        y = np.concatenate([q, v]) + s * eps * x0
        f = MechanismTangentFlow(L, q, v, 0, dt=0.01, reorth=10 ** 9, project=0)
        f.Z[0] = y                  # the perturbed state itself (off TC by O(ε²))
        f.advance(steps)
        ends.append(f.y.copy())
    fd = (ends[0] - ends[1]) / (2 * eps)
    assert np.max(np.abs(fd - flow.X[0])) < TOL["finite_difference"] * np.max(np.abs(fd)) + 1e-9


def test_bad_input_is_refused(rot3):
    q, v = rot3.random_state(0)
    cases = [
        (dict(mech="rotors(3)"), MechanismError, "Mechanism"),
        (dict(q0=q + 0.1), MechanismError, "off the constraint"),
        (dict(q0=q[:2]), MechanismError, "q0"),
        (dict(v0=np.ones(3)), MechanismError, "not tangent"),
        (dict(t_final=-1.0), ValueError, "t_final"),
        (dict(t_final=10.005), ValueError, "t_final"),
        (dict(dt=0.0), ValueError, "dt"),
        (dict(n_exponents=3), ValueError, "n_exponents"),
        (dict(n_exponents=0), ValueError, "n_exponents"),
        (dict(inner="euclid"), ValueError, "inner"),
        (dict(n_batches=1), ValueError, "n_batches"),
        (dict(t_transient=np.nan), ValueError, "t_transient"),
        (dict(project_every=0.0), ValueError, "project_every"),
        (dict(seed=-1), ValueError, "seed"),
    ]
    for kw, err, word in cases:
        args = dict(mech=rot3, q0=q, v0=v, t_final=10.0)
        args.update(kw)
        with pytest.raises(err, match=word):
            lyapunov_spectrum(args.pop("mech"), args.pop("q0"), args.pop("v0"),
                              args.pop("t_final"), n_batches=args.pop("n_batches", 2), **args)
