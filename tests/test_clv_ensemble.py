"""Covariant Lyapunov vectors of ensembles (``charts.analyses.clv_ensemble``): the GPU route's
member function on the CPU (the twin) and its kernel's Python body with a stand-in for
``numba.cuda``, against `covariant_lyapunov_vectors`; the CPU route."""
import types

import numpy as np
import pytest

import charts.analyses.clv_ensemble as clv
from charts.analyses.clv_ensemble import (clv_ensemble_settings, clv_block_bytes, clv_block_plan,
                                          clvs_on_device, covariant_ensemble)
from charts.analyses.covariant import covariant_lyapunov_vectors
from charts.geometry.system import RotorSystem
from charts.solvers.device import DeviceUnavailable, cuda_available

SYSTEM = RotorSystem(4)
FIELDS = ("t", "phi", "phi_vectors", "growth", "gs_rates", "states")


@pytest.mark.parametrize("variant", ["restricted", "full"])
def test_one_block_equals_covariant_lyapunov_vectors_bit_for_bit(variant):
    """The window in one block: each member is `covariant_lyapunov_vectors` with its seed —
    angles, growth rates, Gram–Schmidt rates, states and settings, to the bit."""
    kw = dict(t_transient=2.0)
    cfg = clv_ensemble_settings(SYSTEM, 6.0, variant, 0, kw)
    got = clvs_on_device(SYSTEM, cfg, variant, [3, 4], 1.0, backend="cpu")
    for g, s in zip(got, [3, 4]):
        r = covariant_lyapunov_vectors(SYSTEM, *SYSTEM.random_state(seed=s), 6.0, seed=s,
                                       variant=variant, **kw)
        for a in FIELDS:
            assert np.array_equal(getattr(g, a), getattr(r, a)), a
        assert g.params == r.params


def test_blocks_keep_the_forward_pass_and_converge_to_the_same_clvs():
    """Three blocks of 20 samples: the forward pass is one continuous run (its Gram–Schmidt
    rates and states identical), and each block's backward iteration converges over the
    30-unit transient: the angles agree with one block to 1e-3 rad (the error falls as
    e^(−(λ₂ − λ₃) t_transient) ≈ 2e-3 at N = 4; measured 2.8e-4).  The host's backward
    iterations on two threads: each member as alone."""
    cfg = clv_ensemble_settings(SYSTEM, 6.0, "restricted", 0, dict(t_transient=30.0))
    one = clvs_on_device(SYSTEM, cfg, "restricted", [3], 1.0, backend="cpu")[0]
    three, again = clvs_on_device(SYSTEM, cfg, "restricted", [3, 3], 1.0, backend="cpu",
                                  block=20, workers=2)      # the host's members on threads
    assert np.array_equal(one.gs_rates, three.gs_rates)
    assert np.array_equal(one.states, three.states)
    assert np.max(np.abs(one.phi - three.phi)) < 1e-3
    assert np.max(np.abs(one.phi_vectors - three.phi_vectors)) < 3e-3
    for f in FIELDS:
        assert np.array_equal(getattr(three, f), getattr(again, f)), f


def test_the_kernel_body_with_a_stand_in_for_cuda(monkeypatch):
    """The CUDA kernel's Python function, thread by thread with numpy local arrays, gives the
    twin's numbers (its argument order, local array shapes and grid guard)."""
    state = {"l": 0}
    fake = types.SimpleNamespace(grid=lambda dim: state["l"], local=types.SimpleNamespace(
        array=lambda shape, dtype: np.empty(shape, dtype=np.dtype(str(dtype)))))
    fwd = clv.kernel_function(4, 6)

    def launch(*a):
        for l in range(3):              # one past the two members: the guard
            state["l"] = l
            fwd(*a[:10], *a[10][:4], a[10][4], *a[11:])

    cfg = clv_ensemble_settings(SYSTEM, 3.0, "restricted", 0, dict(t_transient=1.0))
    twin = clvs_on_device(SYSTEM, cfg, "restricted", [5, 6], 1.0, backend="cpu")
    monkeypatch.setattr(clv, "cuda", fake)
    monkeypatch.setattr(clv, "_forward_cpu", launch)
    body = clvs_on_device(SYSTEM, cfg, "restricted", [5, 6], 1.0, backend="cpu")
    for a, b in zip(twin, body):
        for f in FIELDS:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f


def test_the_block_plan_fits_the_budget_or_refuses_with_numbers():
    cfg = clv_ensemble_settings(SYSTEM, 100.0, "restricted", 0, dict(t_transient=10.0))
    plan = clv_block_plan(cfg, 4, 1000, 1000 * clv_block_bytes(cfg, 4, 250))
    assert max(plan) == 250 and sum(plan) == cfg.S                 # as many as fit
    assert clv_block_plan(cfg, 4, 1000, 1000 * clv_block_bytes(cfg, 4, 250) - 1)[0] == 249
    with pytest.raises(ValueError, match=r"1000 members need .* GiB .* budget"):
        clv_block_plan(cfg, 4, 1000, 1000)


def test_the_cpu_route_is_the_members_own_call():
    """`covariant_ensemble` on the CPU: each member is `covariant_lyapunov_vectors` with its
    seed; a setting the call does not take is refused."""
    S = RotorSystem(3)
    ens = covariant_ensemble(S, 2, 2.0, t_transient=1.0, seed=7, workers=1)
    for m, s in zip(ens.members, (7, 8)):
        r = covariant_lyapunov_vectors(S, *S.random_state(seed=s), 2.0, t_transient=1.0, seed=s)
        for a in FIELDS:
            assert np.array_equal(getattr(m, a), getattr(r, a)), a
    with pytest.raises(TypeError, match="unexpected settings"):
        clv_ensemble_settings(S, 2.0, "restricted", 0, dict(inner="theta"))


@pytest.mark.skipif(cuda_available(), reason="this machine has a GPU")
def test_the_ensemble_asks_for_a_gpu_by_name():
    with pytest.raises(DeviceUnavailable, match="needs an NVIDIA GPU"):
        covariant_ensemble(SYSTEM, 2, 2.0, device="cuda")
