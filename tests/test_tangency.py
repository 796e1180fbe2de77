"""The oriented volume of the splitting E_u ⊕ E_cs (``charts.analyses.tangency``).

|V| = |det[Q_u, Q_cs, a, b]|/|a ∧ b| is the product of the sines of the principal angles
between E_u and E_cs: checked against SciPy's `subspace_angles` (an independent route), and
so |V| ≤ sin φ, φ the CLV route's angle, along an orbit of a smooth family member that
passes within 4·10⁻⁴ rad of a tangency.  V's sign is fixed along an orbit (by the
invariance of E_u and E_cs, and by the construction of Ginelli's CLVs): a consistency check
of the implementation, which could fail only where |V| ≈ 10⁻¹⁶."""
import numpy as np
import pytest
from scipy.linalg import subspace_angles

from charts import RotorSystem, covariant_lyapunov_vectors
from charts.analyses.tangency import closest_passage, oriented_volume, sign_changes

SYSTEM = RotorSystem(4, level=0.5)          # a smooth member of the N = 4 family
SEED = 2                                    # its orbit passes within 3.7e-4 rad at t ≈ 1646


@pytest.fixture(scope="module")
def scan():
    theta, u = SYSTEM.random_state(seed=SEED)
    return covariant_lyapunov_vectors(SYSTEM, theta, u, 1660.0, keep_vectors=True)


def test_v_is_bounded_by_the_angle_and_keeps_its_sign(scan):
    V = oriented_volume(scan.vectors, scan.params["n_unstable"], scan.states, SYSTEM.weights)
    assert np.unique(np.sign(V)).size == 1
    assert np.nanmin(scan.phi) < 1e-3                 # the orbit does come close
    assert np.abs(V).min() < 1e-3
    assert np.all(np.abs(V) <= np.sin(scan.phi) + 1e-12)


def test_v_is_the_product_of_the_principal_sines(scan):
    m = scan.params["n_unstable"]
    V = oriented_volume(scan.vectors[::500], m, scan.states[::500], SYSTEM.weights)
    for j, v in zip(range(0, len(scan.t), 500), V):
        E = scan.vectors[j]
        angles = subspace_angles(E[:m].T, E[m:].T)
        assert abs(abs(v) - np.prod(np.sin(angles))) < 1e-10


def test_sign_changes_interpolate():
    t = np.linspace(0.0, 1.0, 11)
    times, margins = sign_changes(t, t - 0.55)
    assert np.allclose(times, [0.55]) and np.allclose(margins, [0.05])
    assert sign_changes(t, t + 1.0)[0].size == 0


def test_closest_passage_is_resolved_on_the_same_orbit():
    theta, u = SYSTEM.random_state(seed=SEED)
    cp = closest_passage(SYSTEM, theta, u, 1610.0, window=2.0)
    ref, short, fine = cp.runs
    assert abs(cp.t_scan_min - 1645.8) < 0.05
    assert len(ref.t) == len(short.t) == len(fine.t) == 200
    assert abs(ref.t_min - cp.t_scan_min) <= 0.1 and ref.phi_min <= 2 * cp.phi_scan_min
    assert cp.differences["scan_difference"] < 1e-6       # the same passage
    assert cp.differences["state_difference"] < 1e-3      # dt/2 follows it
    assert cp.sign_kept and ref.crossings.size == 0
    assert "invariance" in cp.summary()


def test_bad_arguments_are_refused(scan):
    with pytest.raises(ValueError, match="restricted variant"):
        oriented_volume(np.zeros((1, 8, 8)), 2, scan.states[:1], SYSTEM.weights)
    theta, u = SYSTEM.random_state(seed=SEED)
    with pytest.raises(ValueError, match="at least 2"):
        closest_passage(SYSTEM, theta, u, 10.0, window=1.0)
