"""Geometry for N not shipped in generated/: derived on demand, cached on disk, byte-identical
to the generator's output, and equal to the closed forms (13), (15) generalised to masses
(tests/scenarios.py).  One N = 7 derivation per session is shared by the tests (conftest)."""
import numpy as np
import pytest

from charts.codegen.emit import SHIPPED_N, module_name, module_source

from scenarios import TOL, christoffel_eq15, gauss_sectional_curvature, masses, metric_eq13, rel_err

N = 7
MASSES = masses("n7", N)


def test_n7_is_not_shipped():
    assert N not in SHIPPED_N


def _load():
    from charts.codegen.cache import load_or_generate
    return load_or_generate(N)


def test_derived_once_cached_and_cost_reported(derived_n7, capsys):
    cache, path, stderr = derived_n7
    assert path.startswith(str(cache)) and path.endswith(f"{module_name(N)}.py")
    assert f"deriving geometry for N={N}" in stderr and f"N={N} derived in" in stderr
    mod = _load()                  # second time: from the cache, silently
    assert "deriving" not in capsys.readouterr().err
    assert mod.N == N and mod.DIM == N - 1


def test_byte_identical_to_the_generator(derived_n7):
    """Another process, another hash seed: the same bytes as ``module_source``."""
    _, path, _ = derived_n7
    with open(path) as f:
        assert f.read() == module_source(N)


def _points(count, seed=0):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        theta = rng.uniform(-np.pi, np.pi, N)
        C = np.cos(theta[:-1]).sum()
        if abs(C) < 0.95:                       # the canonical chart's domain, not too close
            theta[-1] = np.sign(rng.normal()) * np.arccos(-C)
            out.append(theta)
    return out


@pytest.mark.parametrize("kind", ["equal", "n7"])
def test_closed_forms_13_15_every_chart(derived_n7, kind):
    """The canonical module serves chart k with the local angles (θ without θₖ) and the
    masses (m without mₖ, then mₖ) — the relabelling RotorSystem uses."""
    mod = _load()
    m = masses(kind, N)
    d = N - 1
    for theta in _points(4):
        for k in (N - 1, 0, 3):
            idx = [i for i in range(N) if i != k]
            if abs(np.cos(theta[idx]).sum()) > 0.99:
                continue
            q = theta[idx]
            mm = np.concatenate([m[idx], m[k:k + 1]])
            g = mod.metric(q, mm, np.ones(N), 0.0, np.empty((d, d)))
            assert rel_err(g, metric_eq13(theta, k, m)) < TOL["closed_form_n7"]
            G = mod.christoffel(q, mm, np.ones(N), 0.0, np.empty((d, d, d)))
            assert rel_err(G, christoffel_eq15(theta, k, m)) < TOL["closed_form_n7"]
            gi = mod.metric_inverse(q, mm, np.ones(N), 0.0, np.empty((d, d)))
            # g⁻¹ g = 1: the inverse's error is the metric's condition number (≲ 1e2 here)
            # times the closed-form rounding
            np.testing.assert_allclose(gi @ g, np.eye(d), rtol=0, atol=1e2 * TOL["closed_form_n7"])
            v = np.random.default_rng(k).normal(size=d)
            acc = mod.geodesic_acceleration(q, v, mm, np.ones(N), 0.0, np.empty(d))
            np.testing.assert_allclose(acc, -np.einsum("abc,b,c->a", G, v, v),
                                       rtol=0, atol=1e-10 * np.abs(acc).max())


def test_riemann_matches_the_gauss_equation(derived_n7):
    """The largest generated function (N = 7 Riemann) against the Gauss equation of the
    hypersurface (scenarios.gauss_sectional_curvature)."""
    mod = _load()
    d, rng = N - 1, np.random.default_rng(1)
    ip = lambda a, b: np.sum(MASSES * a * b)
    for theta in _points(3, seed=2):
        q = theta[:-1]
        R = mod.riemann(q, MASSES, np.ones(N), 0.0, np.empty((d,) * 4))
        s = np.sin(theta)
        for _ in range(3):
            x, y = rng.normal(size=d), rng.normal(size=d)
            # ambient tangent vectors from local components (tangency fixes the last one)
            v = np.append(x, -(x @ s[:-1]) / s[-1])
            w = np.append(y, -(y @ s[:-1]) / s[-1])
            area2 = ip(v, v) * ip(w, w) - ip(v, w) ** 2
            K = np.einsum("abcd,a,b,c,d->", R, x, y, x, y) / area2
            assert K == pytest.approx(gauss_sectional_curvature(theta, v, w, MASSES),
                                      rel=TOL["gauss"], abs=TOL["gauss"])
