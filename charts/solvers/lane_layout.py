"""The layout of the lane kernel (``charts.solvers.lanes``) and its compilation.

Layout: L trajectories as flat arrays, element i of lane l at ``i·Lp + l``, the lane count
rounded up to a multiple Lp of `LANE_WIDTH` (padding lanes: copies of a running lane), each
array starting on a cache line (`aligned`), allocated once with the work arrays of the loop
(`lane_arrays`); `lanes_in` / `lanes_out` convert from / to the (R·d, L) and (2, N, L)
arrays of `LaneFlows`, `gather` / `scatter` copy one lane to / from the one-trajectory
layout.

Compilation: ``charts.jit.vector_lowering`` (the kernel's arrays ``noalias``, LLVM's SLP
vectoriser packing the blocks of `LANE_WIDTH` lanes; the same bits as the one-trajectory
kernel).
"""
from __future__ import annotations

import numpy as np

from ..jit import njit

from ..geometry.primitives import LANE_WIDTH

__all__ = ["aligned", "lane_arrays", "lanes_in", "lanes_out", "gather", "scatter"]


@njit(cache=True)
def aligned(size):
    """An empty float array of ``size`` whose data starts on a 64-byte boundary (a cache
    line: a block of `LANE_WIDTH` doubles then never straddles two lines; Numba aligns its
    arrays to 32 bytes: 147 against 123 ns per lane-step for the lane step in a stand-alone
    harness, N = 5, 16 lanes)."""
    b = np.empty(size + 8)
    off = (64 - b.ctypes.data % 64) % 64 // 8
    return b[off:off + size]


@njit(cache=True)
def lane_arrays(D, L, wts):
    """The arrays of ``charts.solvers.lanes.lanes_kernel`` for L lanes of D-element stacked
    states: flat, padded, aligned Zp, s0, c0 (filled by `lanes_in`) and the work arrays of
    its time loop (every one an argument of the loop, hence ``noalias``: a work array the
    loop allocated itself may, for LLVM, overlap the others, and its blocks stay scalar
    code), the last of them the weights per lane."""
    n = wts.size
    W = int(LANE_WIDTH)
    Lp = (L + W - 1) // W * W
    M = D * Lp
    nl = n * Lp
    kL = max(D // (2 * n) - 1, 1) * Lp
    wl = aligned(nl)
    for j in range(n):
        for l in range(Lp):
            wl[j * Lp + l] = wts[j]
    work = (aligned(M), aligned(4 * M), aligned(nl), aligned(nl), aligned(nl), aligned(nl),
            aligned(nl), aligned(nl), aligned(nl), aligned(nl), aligned(Lp), aligned(Lp),
            aligned(kL), wl, aligned(Lp), aligned(Lp), aligned(Lp), aligned(Lp), aligned(Lp),
            aligned(Lp), aligned(kL))
    return aligned(M), aligned(nl), aligned(nl), work


@njit(cache=True)
def lanes_in(Z, sc, Zp, s0, c0):
    """Z and sc into the flat, padded lanes Zp, s0, c0 of `lane_arrays` (padding lanes:
    copies of lane 0)."""
    D, L = Z.shape
    n = sc.shape[1]
    Lp = Zp.size // D
    for l in range(Lp):
        src = l if l < L else 0
        for i in range(D):
            Zp[i * Lp + l] = Z[i, src]
        for j in range(n):
            s0[j * Lp + l] = sc[0, j, src]
            c0[j * Lp + l] = sc[1, j, src]


@njit(cache=True)
def lanes_out(Zp, s0, c0, Z, sc):
    """The inverse of `lanes_in` for the L lanes of Z and sc."""
    D, L = Z.shape
    n = sc.shape[1]
    Lp = Zp.size // D
    for l in range(L):
        for i in range(D):
            Z[i, l] = Zp[i * Lp + l]
        for j in range(n):
            sc[0, j, l] = s0[j * Lp + l]
            sc[1, j, l] = c0[j * Lp + l]


@njit(cache=True, inline="always")
def gather(Zf, s0, c0, Lp, l, z, zs, zc):
    """Lane l of the flat lanes Zf, s0, c0 (element i of lane l at i·Lp + l) into z (R·d,),
    zs, zc (N,)."""
    for i in range(z.size):
        z[i] = Zf[i * Lp + l]
    for j in range(zs.size):
        zs[j] = s0[j * Lp + l]
        zc[j] = c0[j * Lp + l]


@njit(cache=True, inline="always")
def scatter(z, zs, zc, Zf, s0, c0, Lp, l):
    """The inverse of `gather`."""
    for i in range(z.size):
        Zf[i * Lp + l] = z[i]
    for j in range(zs.size):
        s0[j * Lp + l] = zs[j]
        c0[j * Lp + l] = zc[j]
