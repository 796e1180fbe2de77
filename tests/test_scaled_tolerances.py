"""The manifold checks are relative to the size of the constraint's terms
(``RotorSystem.constraint_scale``): with weights of 1e-10 a far point is still refused, with
weights of 1e9 the system's own random states are accepted, and the paper's tolerance is
unchanged."""
import numpy as np
import pytest

import charts


def test_tiny_weights_do_not_make_every_point_lie_on_the_manifold():
    s = charts.RotorSystem(4, weights=[1e-10] * 4)
    with pytest.raises(ValueError, match="off the manifold"):
        s.check_point(np.zeros(4))                       # Σ a cos θ = 4e-10, far from 0
    th, u = s.random_state(seed=1)
    s.check_state(th, u)
    with pytest.raises(ValueError, match="not tangent"):
        s.check_tangent(th, np.ones(4))


def test_huge_weights_accept_their_own_random_states():
    s = charts.RotorSystem(4, weights=[1e9, 2e9, 1.5e9, 1e9], level=3e8)
    for seed in range(5):
        s.check_state(*s.random_state(seed=seed))
    th, _ = s.random_state(seed=0)
    with pytest.raises(ValueError, match="off the manifold"):
        s.check_point(th + 1e-6)                         # 1e-6 rad off: ~1e3 against 1e9


def test_the_paper_tolerance_is_unchanged():
    s = charts.RotorSystem(3)
    assert s.constraint_scale == 1.0
    th = np.array([np.pi / 2, np.pi / 2, np.pi / 2])
    s.check_point(th + np.array([0.0, 0.0, 5e-9]))       # |F| = 5e-9 < 1e-8
    with pytest.raises(ValueError, match=r"tolerance 1e-08"):
        s.check_point(th + np.array([0.0, 0.0, 2e-8]))
