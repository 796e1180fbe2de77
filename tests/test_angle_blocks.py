"""The angle test's GPU route without a GPU (``charts.analyses.angle_blocks``): its member
functions on the CPU (the twin) and its kernels' Python bodies with a stand-in for
``numba.cuda``, against `hyperbolicity_angles`."""
import types

import numpy as np
import pytest

import charts.analyses.angle_blocks as blocks
from charts.analyses.angle_blocks import block_bytes, block_plan
from charts.analyses.forward_pass import angle_settings
from charts.analyses.hyperbolicity import angle_members, hyperbolicity_angles, hyperbolicity_ensemble
from charts.geometry.system import RotorSystem
from charts.solvers.device import DeviceUnavailable, cuda_available

SYSTEM = RotorSystem(4)


def test_one_block_equals_hyperbolicity_angles_bit_for_bit():
    """The window in one block: each member is `hyperbolicity_angles` with its seed — both
    angle variants, both passes' exponents, times and settings, to the bit."""
    kw = dict(t_transient=3.0, checkpoint_every=1.0)
    cfg = angle_settings(SYSTEM, 6.0, **kw)
    got = angle_members(SYSTEM, cfg, [3, 4], 1.0, backend="cpu")
    for g, s in zip(got, [3, 4]):
        r = hyperbolicity_angles(SYSTEM, *SYSTEM.random_state(seed=s), 6.0, seed=s, **kw)
        for a in ("t", "phi_full", "phi_restricted", "forward_exponents", "adjoint_exponents"):
            assert np.array_equal(getattr(g, a), getattr(r, a)), a
        assert g.params == r.params


def test_blocks_keep_the_forward_pass_and_converge_to_the_same_angles():
    """Five blocks of 2 time units: the forward pass is one continuous run (its exponents
    identical), and each block's fresh adjoint vectors converge over the 40-unit backward
    transient: the restricted angles agree with one block to 2e-3 rad.  (The error falls as
    e^(−λ₂ t_transient), λ₂ ≈ 0.22 at N = 4: 1.5e-4 at 40; measured 2.6e-4.)"""
    cfg = angle_settings(SYSTEM, 10.0, t_transient=40.0)
    one = angle_members(SYSTEM, cfg, [3], 1.0, backend="cpu")[0]
    five = angle_members(SYSTEM, cfg, [3], 1.0, backend="cpu", block=200)[0]
    assert np.array_equal(one.forward_exponents, five.forward_exponents)
    assert np.array_equal(one.t, five.t)
    assert np.max(np.abs(one.phi_restricted - five.phi_restricted)) < 2e-3


def test_the_kernel_bodies_with_a_stand_in_for_cuda(monkeypatch):
    """The CUDA kernels' Python functions, thread by thread with numpy local arrays, give the
    twin's numbers (their argument order, local array shapes and grid guard)."""
    state = {"l": 0}

    def grid(dim):
        return state["l"]

    fake = types.SimpleNamespace(grid=grid, local=types.SimpleNamespace(
        array=lambda shape, dtype: np.empty(shape, dtype=np.dtype(str(dtype)))))
    fwd, bwd = blocks.kernel_functions(4, 2, 11)

    def launch(kernel, L):
        def run(*a):
            for l in range(L + 1):      # one past the members: the guard
                state["l"] = l
                kernel(*a)
        return run

    monkeypatch.setattr(blocks, "cuda", fake)
    cfg = angle_settings(SYSTEM, 4.0, t_transient=2.0)
    twin = angle_members(SYSTEM, cfg, [5, 6], 1.0, backend="cpu")
    monkeypatch.setattr(blocks, "_forward_cpu", lambda *a: launch(fwd, 2)(*a[:8], *a[8], *a[9:]))
    monkeypatch.setattr(blocks, "_backward_cpu", lambda *a: launch(bwd, 2)(*a[:9], *a[9], *a[10:]))
    body = angle_members(SYSTEM, cfg, [5, 6], 1.0, backend="cpu")
    for a, b in zip(twin, body):
        assert np.array_equal(a.phi_full, b.phi_full)
        assert np.array_equal(a.phi_restricted, b.phi_restricted)


def test_the_block_plan_fits_the_budget_or_refuses_with_numbers():
    cfg = angle_settings(SYSTEM, 100.0, t_transient=10.0)
    plan = block_plan(cfg, 1000, 1000 * block_bytes(cfg, 2500))
    assert plan.largest <= 2500 and sum(plan.lengths) == cfg.n_win
    assert all(b % cfg.ce == 0 for b in plan.lengths)
    with pytest.raises(ValueError, match=r"1000 members need .* GiB .* budget"):
        block_plan(cfg, 1000, 1000)
    with pytest.raises(ValueError, match="t_transient .* multiple of checkpoint_every"):
        block_plan(angle_settings(SYSTEM, 100.0, t_transient=10.5), 10, 1 << 30)


@pytest.mark.skipif(cuda_available(), reason="this machine has a GPU")
def test_the_ensemble_asks_for_a_gpu_by_name():
    with pytest.raises(DeviceUnavailable, match="needs an NVIDIA GPU"):
        hyperbolicity_ensemble(SYSTEM, 2, 2.0, device="cuda")


def test_a_stopped_member_is_named_with_its_pass_and_seed():
    """The device routes' stops (``solvers.device.member_stops``): each the error the CPU
    route raises, naming the pass and the member's seed, at its time."""
    from charts.analyses.angle_blocks import BACKWARD, _stops
    from charts.solvers.device import DeviceArrays
    from charts.solvers.status import RUNNING, SINGULAR, SingularPointError
    dev = {"status": np.array([RUNNING, SINGULAR]), "stopped": np.array([0, 1234]),
           "phase": np.array([0, BACKWARD])}
    (l, seed, t, err), = _stops(DeviceArrays("cpu"), dev, [7, 8], 0.01)
    assert (l, seed, t) == (1, 8, 12.34)
    assert isinstance(err, SingularPointError) and "backward RK4, member seed=8" in str(err)
