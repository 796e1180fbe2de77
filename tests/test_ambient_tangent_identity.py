"""Same question, same bits: an ambient RK4 trajectory from ``charts.integrate`` and the
tangent kernel without vectors (``TangentFlow(k=0)``, what ``waveform`` advances) take the
same step (the stage sin/cos shifted from the step's start, the start's carried from step to
step and recomputed after a projection), so they agree bit for bit, with projection at the
same phases: ``project=True`` after every step is ``project_every = 1``, ``False`` is 0.
Where the step cap binds (near a singular point) the two part: the loop caps each step from
its own start, the tangent kernel cuts dt into equal sub-steps."""
import numpy as np
import pytest

from charts import RotorSystem, integrate, waveform
from charts.solvers.tangent import TangentFlow

SYSTEMS = {
    "N3": dict(n=3),
    "N3-masses": dict(n=3, masses=[1.0, 1.7, 0.6]),
    "N5-masses": dict(n=5, masses=[1.0, 2.0, 0.5, 1.5, 1.1]),
    "N4-family": dict(n=4, masses=[1.2, 0.8, 1.0, 1.5], weights=[1.0, 1.5, 0.8, 1.2], level=0.3),
    "N5-family": dict(n=5, weights=[0.7, 1.0, 1.3, 0.9, 1.1], level=0.05),
}


@pytest.mark.parametrize("project", [False, True], ids=["free", "projected"])
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_integrate_rk4_equals_the_tangent_kernel(name, project):
    system = RotorSystem(**SYSTEMS[name])
    for seed in (1, 7):
        theta, u = system.random_state(seed=seed)
        steps, dt = 1000, 0.01
        r = integrate(system, theta, u, steps * dt, formulation="ambient", method="rk4", dt=dt,
                      project=project, t_eval=np.arange(0, steps + 1, 100) * dt)
        f = TangentFlow(system, theta, u, 0, dt=dt, project_every=1 if project else 0)
        for i in range(1, 11):                      # every 100 steps, including the last
            f.advance(100)
            assert np.array_equal(r.theta[i], f.y[:system.n]), (name, seed, i)
            assert np.array_equal(r.u[i], f.y[system.n:]), (name, seed, i)


def test_every_step_output_and_chunks_keep_the_bits():
    """Output after every step (landing on t_final) and short chunks change nothing."""
    system = RotorSystem(4, masses=[1.0, 2.0, 1.0, 0.5])
    theta, u = system.random_state(seed=3)
    r = integrate(system, theta, u, 5.0, formulation="ambient", method="rk4", dt=0.01,
                  chunk_steps=37)
    f = TangentFlow(system, theta, u, 0, dt=0.01, project_every=0)
    for i in (1, 2, 250, 500):
        f.advance(i - f.steps)
        assert np.array_equal(r.theta[i], f.y[:4]) and np.array_equal(r.u[i], f.y[4:])


def test_waveform_is_the_integrate_route():
    """``waveform`` (the tangent kernel, project_every = 1.0 → every 100 steps) sampled at
    the same times as an ambient RK4 run without projection, before the first projection."""
    system = RotorSystem(3, masses=[1.0, 1.5, 0.8])
    theta, u = system.random_state(seed=4)
    w = waveform(system, theta, u, 0.9, sample_every=0.05, project_every=None)
    r = integrate(system, theta, u, w.t[-1], formulation="ambient", method="rk4", dt=0.01,
                  t_eval=w.t)
    assert w.u.shape == (18, 3) and np.array_equal(w.u, r.u) and np.array_equal(w.theta, r.theta)



def test_records_hold_the_state_the_vectors_and_the_kept_sines():
    """The stacked loop's records: Z's first entries, then (where the record is wider than Z)
    the weighted sin and cos of the state's angles as the loop keeps them — what the
    backward pass of the angle test reads at its samples; bit for bit what the flow holds
    after the recorded step, whatever the chunks."""
    system = RotorSystem(4, masses=[1.0, 1.3, 0.8, 1.1])
    theta, u = system.random_state(seed=2)
    n, k = 4, 2
    L = (1 + k) * 2 * n
    f = TangentFlow(system, theta, u, k, dt=0.01, reorth_every=3, project_every=7)
    states = np.full((5, L + 2 * n), np.nan)
    short = np.full((5, 2 * n), np.nan)          # narrower than Z: the state alone
    for row in range(5):
        for chunk in (2, 3):                       # records every 5 steps, from step 5
            f.advance(chunk, rec_start=5, rec_every=5, states=states)
        assert np.array_equal(states[row, :L], f.Z.ravel())
        assert np.array_equal(states[row, L:], f.sc.ravel())
    g = TangentFlow(system, theta, u, k, dt=0.01, reorth_every=3, project_every=7)
    g.advance(25, rec_start=5, rec_every=5, states=short)
    assert np.array_equal(short, states[:, :2 * n])
