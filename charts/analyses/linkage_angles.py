"""Hyperbolicity test of section 4 for the linkage of the Appendix: the angle φ between the
expanding subspace E_u and the centre-stable subspace E_cs = E_0 ⊕ E_s, in the tangent space
of its phase space, T_r = {J δq = 0, J δv + ∂²F(v, δq) = 0}.

The linkage is a `charts.Mechanism`, so this is the generic test
(``charts.analyses.mechanism_angles.mechanism_angles``: forward vectors converge to E_u,
backward ones, on the stored forward states, to E_s; E_0 = span{(v, a), (0, v)}; sin φ the
smallest singular value of E_u's part orthogonal to E_cs) with two vectors each (the
linkage's two positive exponents) and the linkage's settings: its default transient, its
grid of times (`angle_steps`) and its result, `LinkageAngles`.

Inner product: the kinetic metric on both parts, Σ Mⱼⱼ (δqⱼ² + δvⱼ²) for the linkage's
diagonal M — for a massless disk Σ δθ² + Σ δθ̇², the Euclidean product of the rotors' (θ, u)
of the restricted variant of ``charts.analyses.hyperbolicity`` (the disk's parts are
determined by the rotors' in T_r).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .arguments import (Documented, inner_steps, linkage_system, positive_time, project_steps,
                        seed_of, steps_of)
from .hyperbolicity import angle_statistics
from .mechanism_angles import mechanism_angles

__all__ = ["LinkageAngles", "linkage_angles", "angle_steps"]


@dataclass
class LinkageAngles:
    """t (S,) sample times from the window's start; phi (S,) angles between E_u and E_cs
    (rad); forward_exponents, backward_exponents (2,) growth rates of the two passes (both
    ≈ λ₁, λ₂ when converged)."""
    t: np.ndarray
    phi: np.ndarray
    forward_exponents: np.ndarray
    backward_exponents: np.ndarray
    params: dict = field(default_factory=dict)

    def statistics(self, small=0.05):
        return angle_statistics(self.phi, small)


def angle_steps(dt, t_final, t_transient, sample_every):
    """(t_final, t_transient, sample_every) of `linkage_angles` in steps dt: a written time
    a whole number of steps or ValueError; a `Documented` default placed as the signature's
    docstring says (as ``lyapunov_spectrum`` places reorth_every and record_every)."""
    total = steps_of("t_final", t_final, dt)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    sample = inner_steps("sample_every", sample_every, dt, total, t_transient, transient)
    if isinstance(t_transient, Documented) and transient:
        transient = sample * steps_of("t_transient", t_transient, sample * dt)
    return total, transient, sample


def linkage_angles(system, q0, v0, t_final, *, dt=0.01, t_transient=Documented(50.0),
                   sample_every=Documented(0.1), project_every=Documented(1.0),
                   seed=0) -> LinkageAngles:
    """Angles φ between E_u and E_cs along the linkage's trajectory from (q0, v0) at every
    ``sample_every`` (default 0.1) over ``t_final`` (module doc; ``mechanism_angles``); the
    trajectory runs t_transient + t_final + t_transient (default 50) so that both passes
    converge; the state is projected onto the invariants every ``project_every`` (default
    1.0, None: never).  t_final and t_transient are multiples of sample_every.  A time
    written must be a whole number of steps dt; a default left is the nearest whole number
    of steps at other dt (README, "Conventions"): a default ``sample_every`` the largest
    count at most that which divides t_final (and a written t_transient), a default
    ``t_transient`` the nearest multiple of ``sample_every``."""
    linkage_system(system)
    q0, v0 = system.check_state(q0, v0, ("q0", "v0"))
    dt = positive_time("dt", dt)
    total, transient, sample = angle_steps(dt, t_final, t_transient, sample_every)
    if total % sample or transient % sample:
        raise ValueError(f"t_final={t_final:g} and t_transient={t_transient:g} must be "
                         f"multiples of sample_every={sample_every:g}")
    project = project_steps(project_every, dt)
    seed = seed_of(seed)
    res = mechanism_angles(system, q0, v0, total * dt, dt=dt, n_unstable=2,
                           t_transient=transient * dt, sample_every=sample * dt,
                           project_every=project * dt or None, seed=seed)
    params = dict(eps=system.eps, rho=system.rho, dt=dt, t_final=total * dt,
                  t_transient=transient * dt, sample_every=sample * dt, vectors_seed=seed,
                  state_seed="given")
    return LinkageAngles(np.arange(len(res.t)) * sample * dt, res.phi_restricted,
                         res.forward_exponents, res.adjoint_exponents, params)
