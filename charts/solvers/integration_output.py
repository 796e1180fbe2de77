"""The :class:`IntegrationResult` of a finished, stopped or failed ``integrate`` run: the
samples in user time up to where the run ended, chart switches, drift of the invariants
(eqs 9, 10 and the energy) and the counters."""
from __future__ import annotations

import numpy as np

from ..geometry.projection import invariants
from .integration_arguments import IntegrationArguments
from .loop_run import LoopRun
from .trajectory import IntegrationResult

__all__ = ["collect_result"]


def collect_result(args: IntegrationArguments, run: LoopRun, status: str, s_end: float,
                   tracker=None) -> IntegrationResult:
    """The result of ``run`` up to integration time ``s_end`` (the end, a failure or a
    terminal event of ``tracker``), with ``status`` (``IntegrationResult.status``)."""
    n = args.system.n
    s, Y = run.samples.close(run.state)
    switches = [(args.user_time(w[0]),) + tuple(w[1:]) for w in run.switches if w[0] <= s_end]
    keep = slice(0, int(np.searchsorted(s, s_end, side="right")))  # s <= s_end (s increases)
    t = args.t_eval[:s.size][keep] if args.use_eval else args.user_time(s[keep])
    Y = Y[keep]
    if run.sol is not None:
        run.sol.close(s_end)
    if args.sign < 0:
        Y[:, n:2 * n] *= -1.0            # back from the forward run from (θ₀, −u₀)
    # rows whose invariants the loop's monitor has not seen (in ``mon`` already): the input
    # row and, with t_eval, every sample (not every sample is a step's end)
    check = np.ones(Y.shape[0], bool) if args.use_eval else np.arange(Y.shape[0]) == 0
    if tracker is not None and tracker.stop is not None and not args.use_eval \
            and not (s.size and s[keep][-1] == s_end):
        t = np.append(t, args.user_time(s_end))  # the terminal event closes the output (SciPy)
        Y = np.concatenate([Y, run.sol.sample([s_end])])   # (sol's rows are in user time)
        check = np.append(check, True)
    res = IntegrationResult(t=t, **_split_rows(Y, n, args.P.shape[0]), switches=switches,
                            drift=_drift(args.system, Y, check, args.P.shape[0], run.mon),
                            **run.counters(), status=status, formulation=args.formulation,
                            method=args.method, options=args.options(), params=args.params())
    res.sol = run.sol if args.dense_output else None
    if tracker is not None:
        res.t_events, res.y_events = tracker.results()
    return res


def _split_rows(Y, n, k):
    """θ, u (m, n) and the transported vectors (m, k, n) or None of the ambient rows Y."""
    return dict(theta=Y[:, :n], u=Y[:, n:2 * n],
                transported=Y[:, 2 * n:].reshape(-1, k, n) if k else None)


def _drift(system, Y, check, k, mon):
    """The drift of the invariants: the max of the loop's monitor ``mon`` and of the rows
    ``Y[check]`` that it has not seen (the same formula: ``invariants``); with transported
    vectors, the largest relative change of the Gram matrix of (u, p¹…pᵏ)."""
    n = system.n
    theta, u = Y[:, :n], Y[:, n:2 * n]
    F, G, E = invariants(theta[check], u[check], system.masses, system.weights, system.level)
    e0 = float(system.energy(u[0])) if len(u) else 1.0
    drift = {
        "constraint": float(max(mon[0], np.max(np.abs(F), initial=0.0))),
        "tangency": float(max(mon[1], np.max(np.abs(G), initial=0.0))),
        "energy": float(max(mon[2], np.max(np.abs(E - e0) / e0, initial=0.0))),
    }
    if k:
        V = np.concatenate([u[:, None, :], Y[:, 2 * n:].reshape(-1, k, n)], axis=1)  # (m, k+1, n)
        Gm = np.einsum("tin,tjn,n->tij", V, V, system.masses)
        norms = np.maximum(np.sqrt(np.diagonal(Gm[0])), 1e-300)
        drift["transport"] = float(np.max(np.abs(Gm - Gm[0]) / np.outer(norms, norms)))
    return drift
