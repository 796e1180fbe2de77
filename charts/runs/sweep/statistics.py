"""The statistics of one point: which columns a scene's effects give, and their values
read from a run's ``result.json`` (and the curvature samples of ``arrays.npz``)."""
from __future__ import annotations

from ..scene import Scene, positive_exponents

__all__ = ["stat_columns", "result_statistics", "KS_ENTROPY"]

#: The angle statistics, per variant (``phi_<variant>_<stat>``; CLV route:
#: ``clv_phi_<variant>_<stat>``): minimum, 0.1 % quantile, median, fraction below 0.05 rad,
#: sample count, and the law of the small angles P(φ < x) = A x^β below 0.05 rad (exponent
#: β and A for β = 2, each with its batch-means standard error, and the count below).
ANGLE_STATS = ("min", "p001", "median", "frac_small", "n", "law_count", "law_exponent",
               "law_exponent_se", "law_coef2", "law_coef2_se")
#: The Kolmogorov–Sinai entropy by Pesin's formula, h_KS = Σ λᵢ over the positive exponents,
#: and its batch-means standard error (the run's result ``h_ks``, ``h_ks_stderr``: the sum of
#: the leading N − 2 exponents positive in the run's estimate, the same exponents summed in
#: every batch; ``charts.analyses.spectrum_quantities.leading_entropy_with_error``); in
#: sweeps that compute every positive exponent (``n_exponents`` ≥ N − 2).
KS_ENTROPY = ("h_ks", "h_ks_se")
#: The linkage's own columns (``charts.runs.mechanism_run.linkage_result``): the smallest
#: Σ sin²θᵢ at the curvature samples (0 at a cone point of Σ cos θ = 0; with curvature
#: only), the smallest KKT health, the distance of M from the four avoided cone points and
#: the number of cone points on M.
LINKAGE_STATS = ("sin2_min", "kkt_health_min", "cone_distance_min", "cone_points_on_manifold")
_LINKAGE_RESULT = dict(zip(LINKAGE_STATS, ("min_sin2", "min_kkt_health", "cone_distance_min",
                                           "cone_points_on_manifold")))


def stat_columns(scene: Scene) -> list[str]:
    """The statistic columns a scene's effects give, in table order."""
    eff, cols = scene.effects, []
    if "lyapunov" in eff:
        k = eff["lyapunov"]["n_exponents"]
        cols += [f"lambda_{i}" for i in range(1, k + 1)]
        cols += [f"lambda_{i}_se" for i in range(1, k + 1)]
        if k >= positive_exponents(scene):    # every positive exponent: Pesin's h_KS
            cols += list(KS_ENTROPY)
    if "curvature" in eff:
        c = eff["curvature"]
        routes = ["numerical", "exact"] if c["route"] == "both" else [c["route"]]
        for r in routes:
            cols += [f"Kpos_{r}_{i}" for i in range(1, c["n_directions"] + 1)]
            cols += [f"Kpos_{r}_any"]
            cols += [f"Kmean_{r}_{i}" for i in range(1, c["n_directions"] + 1)]
    if "angles" in eff:
        v = eff["angles"]["variant"]
        for var in (["full", "restricted"] if v == "both" else [v]):
            cols += [f"phi_{var}_{s}" for s in ANGLE_STATS]
    if scene.system.get("kind") == "linkage":
        cols += LINKAGE_STATS[0 if "curvature" in eff else 1:]
    if "clv" in eff:
        c = eff["clv"]
        for var in (["full", "restricted"] if c["variant"] == "both" else [c["variant"]]):
            cols += [f"clv_phi_{var}_{s}" for s in ANGLE_STATS]
            cols += [f"clv_split_{var}_{w:g}" for w in c["windows"]]
    return cols


def result_statistics(result: dict, arrays) -> dict:
    """Column -> value from a run's result (``result.json`` as a dict) and, for the
    ``Kpos_<route>_any`` fractions, its ``curvature_<route>`` arrays (or None)."""
    res, out = result.get("results", {}), {}
    ly = res.get("lyapunov", {})
    for i, (e, s) in enumerate(zip(ly.get("exponents", []),
                                   ly.get("stderr", [None] * len(ly.get("exponents", [])))), 1):
        out[f"lambda_{i}"], out[f"lambda_{i}_se"] = e, s
    if "h_ks" in ly:
        out[KS_ENTROPY[0]], out[KS_ENTROPY[1]] = ly["h_ks"], ly.get("h_ks_stderr")
    cv = res.get("curvature", {})
    for route in ("numerical", "exact"):
        if route in cv:
            for i, (f, m) in enumerate(zip(cv[route]["fraction_positive"], cv[route]["mean"]), 1):
                out[f"Kpos_{route}_{i}"], out[f"Kmean_{route}_{i}"] = f, m
            K = arrays.get(f"curvature_{route}") if arrays is not None else None
            if K is not None and len(K):
                out[f"Kpos_{route}_any"] = float((K > 0).any(axis=1).mean())
    an = res.get("angles", {})
    for var in ("full", "restricted"):
        if var in an:
            for s in ANGLE_STATS:
                out[f"phi_{var}_{s}"] = _finite_or_none(an[var].get(s))
    lk = res.get("linkage", {})
    for col, key in _LINKAGE_RESULT.items():
        if key in lk:
            out[col] = lk[key]
    cl = res.get("clv", {})
    for var in ("full", "restricted"):
        if var in cl:
            for s in ANGLE_STATS:
                out[f"clv_phi_{var}_{s}"] = _finite_or_none(cl[var]["phi"].get(s))
            for w, d in cl[var]["domination"].items():
                out[f"clv_split_{var}_{w}"] = d["split"]
    return out


def _finite_or_none(v):
    """A statistic as a cell value: None (an empty cell) for a missing or undefined (NaN)
    statistic, e.g. the law's exponent of a trajectory without angles below the threshold;
    an integer stays an integer."""
    if v is None or (isinstance(v, float) and v != v):
        return None
    return v
