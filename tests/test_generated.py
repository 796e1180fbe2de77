"""Generated chart geometry against independent routes.

Routes: the paper's closed forms (13), (15), (22) and the Gauss equation of the hypersurface,
written independently in tests/scenarios.py; a live ``sympy.lambdify`` of the derivation of
*every* chart (which also proves that the canonical-chart module with relabelled inputs is
each chart's geometry); the textbook ∂Γ definition of Riemann; Riemann's algebraic identities.
"""
import shutil
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import charts
import charts.codegen.emit
from charts.geometry.kernels import chart_module
from charts.codegen.symbolic import ChartGeometry

from scenarios import (FLAT_N3, TOL, christoffel_eq15, gauss_sectional_curvature,
                       gaussian_curvature_eq22, masses, metric_eq13, rel_err)

ROOT = Path(__file__).resolve().parent.parent
NS = (3, 4, 5, 6)
# Closed forms and generated code evaluate the same rational functions of sin/cos in a
# different order: agreement to ~1e2 ulp is expected at well-conditioned points.
REL = TOL["closed_form"]
# Chart-to-chart agreement passes through the metric of each chart, whose condition
# number grows like 1/sin²θ_k; charts with |sin θ_k| >= WELL_CONDITIONED keep it < ~1e3.
WELL_CONDITIONED = 0.05
CHART_REL = 1e-10


def masses_for(n, kind):
    return masses("equal" if kind == "equal" else "ramp", n)


def points(system, count, seed=0):
    return [system.random_state(seed=seed * 1000 + i) for i in range(count)]


def charts_with_domain(system, theta, threshold=WELL_CONDITIONED):
    return [k for k in range(system.n) if abs(np.sin(theta[k])) >= threshold]


# -- closed forms (13), (15), (22) --------------------------------------------------------
@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("kind", ["equal", "unequal"])
def test_metric_and_christoffel_match_closed_forms(n, kind):
    S = charts.RotorSystem(n, masses_for(n, kind))
    for theta, _ in points(S, 20, seed=n):
        for k in charts_with_domain(S, theta):
            assert rel_err(S.metric(theta, chart=k), metric_eq13(theta, k, S.masses)) < REL
            assert rel_err(S.christoffel(theta, chart=k), christoffel_eq15(theta, k, S.masses)) < REL


def test_n3_sectional_curvature_is_eq22():
    S = charts.RotorSystem(3)
    rng = np.random.default_rng(22)
    for theta, u in points(S, 50, seed=3):
        w = S.project_tangent(theta, rng.normal(size=3))
        K22 = gaussian_curvature_eq22(theta)
        assert abs(S.sectional_curvature(theta, u, w) - K22) <= REL * abs(K22)


def test_n3_curvature_vanishes_at_the_eight_points():
    S = charts.RotorSystem(3)
    theta = np.array(FLAT_N3)
    v = S.project_tangent(theta, [1.0, 0.0, 0.0])
    w = S.project_tangent(theta, [0.0, 1.0, 0.0])
    assert abs(S.sectional_curvature(theta, v, w)) < 1e-14


# -- live SymPy derivation of every chart -------------------------------------------------
def _lambdified(n, k, what):
    G = ChartGeometry(n, k)
    return sp.lambdify([G.q, G.m, G.a, G.c], G.explicit(getattr(G, what)), modules="math", cse=True)


@pytest.mark.parametrize("n", NS)
def test_every_chart_matches_live_sympy_unequal_masses(n):
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    whats = ["metric", "christoffel"]
    for k in range(n):
        fns = {w: _lambdified(n, k, w) for w in whats}
        for theta, _ in points(S, 20, seed=10 + k):
            if abs(np.sin(theta[k])) < WELL_CONDITIONED:
                continue
            q = [theta[i] for i in range(n) if i != k]
            for w, f in fns.items():
                assert rel_err(getattr(S, w)(theta, chart=k), np.array(f(q, list(S.masses), [1.0] * n, 0.0))) < REL, (w, k)


@pytest.mark.parametrize("n", [3, 4])
def test_riemann_matches_textbook_derivation_in_high_precision(n):
    """The generated Riemann tensor (Gauss-equation route) against SymPy's textbook
    derivation from second metric derivatives, evaluated with 40-digit
    mpmath (that route cancels badly in floating point where sin θ_k is small, ~1e-16/sin⁸θ_k,
    so it is a reference only in high precision).  Every chart for N = 3; for N = 4 the
    first and the canonical chart, to bound the run time (every chart is covered in double
    precision by the chart-agreement and finite-difference tests)."""
    import mpmath

    mpmath.mp.dps = 40
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    for k in range(n) if n == 3 else (0, n - 1):
        G = ChartGeometry(n, k)
        f = sp.lambdify([G.q, G.m, G.a, G.c], G.explicit(G.riemann_from_metric), modules="mpmath", cse=True)
        for theta, _ in points(S, 2, seed=40 + n + k):
            if abs(np.sin(theta[k])) < WELL_CONDITIONED:
                continue
            q = [mpmath.mpf(float(theta[i])) for i in range(n) if i != k]
            ref = np.array(f(q, [mpmath.mpf(float(x)) for x in S.masses], [mpmath.mpf(1)] * n, mpmath.mpf(0)),
                           dtype=float)
            assert rel_err(S.riemann(theta, chart=k), ref) < REL, (n, k)


# Fourth-order central differences of Γ with step FD_STEP.  Near chart edges ∂ⁿΓ grows like
# 1/(1−C²)ⁿ, so the step is small: measured errors at a point with |sin θ_k| = 0.36 are
# 8e-6 (h=1e-3), 8e-10 (h=1e-4), 1.2e-10 (h=1e-5, rounding-limited).
FD_STEP = 2e-5
FD_REL = 1e-8


@pytest.mark.parametrize("n", NS)
def test_riemann_matches_textbook_definition_with_numerical_derivatives(n):
    """Generated Riemann (Gauss-equation route) against the textbook definition
    R^a_bcd = ∂_cΓ^a_db − ∂_dΓ^a_cb + Γ^a_ceΓ^e_db − Γ^a_deΓ^e_cb, lowered with g, where ∂Γ
    are fourth-order central differences of the generated Christoffel symbols (the metric
    route)."""
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    mod, d = chart_module(n), n - 1
    m, a1 = S.masses, np.ones(n)  # the family module at the paper's a = 1, c = 0
    gam = lambda q: mod.christoffel(q, m, a1, 0.0, np.empty((d,) * 3))
    for theta, _ in points(S, 4, seed=90 + n):
        if abs(np.sin(theta[-1])) < 0.3:
            continue
        q = theta[:-1]
        G = gam(q)
        dG = np.empty((d,) * 4)  # dG[e, a, b, c] = ∂_e Γ^a_bc
        for e in range(d):
            h = np.zeros(d)
            h[e] = FD_STEP
            dG[e] = (8 * (gam(q + h) - gam(q - h)) - (gam(q + 2 * h) - gam(q - 2 * h))) / (12 * FD_STEP)
        up = (np.einsum("cadb->abcd", dG) - np.einsum("dacb->abcd", dG)
              + np.einsum("ace,edb->abcd", G, G) - np.einsum("ade,ecb->abcd", G, G))
        textbook = np.einsum("fa,abcd->fbcd", mod.metric(q, m, a1, 0.0, np.empty((d, d))), up)
        assert rel_err(mod.riemann(q, m, a1, 0.0, np.empty((d,) * 4)), textbook) < FD_REL


def test_riemann_formula_matches_textbook_definition():
    """Both Riemann routes of the derivation (Gauss equation, second metric derivatives)
    against R^a_bcd = ∂_cΓ^a_db − ∂_dΓ^a_cb
    + Γ^a_ceΓ^e_db − Γ^a_deΓ^e_cb, lowered with g (N=3, unequal masses), for the paper's
    a = 1, c = 0 and for weights a = (1.2, 0.8, 1.5) at the level c = 0.3."""
    G = ChartGeometry(3, 0)
    d, q, Gm = G.dim, G.q, G.explicit(G.christoffel)
    for a_, c_ in [((1, 1, 1), 0), ((1.2, 0.8, 1.5), 0.3)]:
        vals = {G.theta[1]: 0.7, G.theta[2]: 2.1, G.m[0]: 1.3, G.m[1]: 0.7, G.m[2]: 2.0, G.c: c_}
        vals.update(zip(G.a, a_))
        num = lambda e: float(G.explicit(e).subs(vals))
        g = np.array([[num(G.metric[a][b]) for b in range(d)] for a in range(d)])
        for a, b, c, e in [(0, 1, 0, 1), (1, 0, 0, 1), (0, 0, 0, 1), (1, 1, 0, 1)]:
            up = [sp.diff(Gm[f][e][b], q[c]) - sp.diff(Gm[f][c][b], q[e])
                  + sum(Gm[f][c][h] * Gm[h][e][b] - Gm[f][e][h] * Gm[h][c][b] for h in range(d))
                  for f in range(d)]
            textbook = sum(g[a, f] * float(up[f].subs(vals)) for f in range(d))
            assert abs(textbook - num(G.riemann_from_metric[a][b][c][e])) < 1e-12
            assert abs(textbook - num(G.riemann[a][b][c][e])) < 1e-12


# -- Riemann identities, every chart ---------------------------------------------------
@pytest.mark.parametrize("n", NS)
def test_riemann_symmetries_and_bianchi_every_chart(n):
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    for theta, _ in points(S, 5, seed=50 + n):
        for k in charts_with_domain(S, theta):
            R = S.riemann(theta, chart=k)
            scale = np.max(np.abs(R))
            assert scale > 0
            tol = 1e-12 * scale
            assert np.max(np.abs(R + R.transpose(1, 0, 2, 3))) < tol  # R_abcd = −R_bacd
            assert np.max(np.abs(R + R.transpose(0, 1, 3, 2))) < tol  # R_abcd = −R_abdc
            assert np.max(np.abs(R - R.transpose(2, 3, 0, 1))) < tol  # pair symmetry
            bianchi = R + R.transpose(0, 2, 3, 1) + R.transpose(0, 3, 1, 2)  # R_abcd+R_acdb+R_adbc
            assert np.max(np.abs(bianchi)) < tol


# -- one ambient plane, every chart; Gauss equation -----------------------------------------
@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("kind", ["equal", "unequal"])
def test_sectional_curvature_agrees_across_charts_and_with_gauss(n, kind):
    S = charts.RotorSystem(n, masses_for(n, kind))
    rng = np.random.default_rng(n)
    checked = 0
    for theta, u in points(S, 10, seed=60 + n):
        w = S.project_tangent(theta, rng.normal(size=n))
        ref = gauss_sectional_curvature(theta, u, w, S.masses)
        # the package's own Gauss-equation route, against the Riemann route (best chart)
        assert S.sectional_curvature_gauss(theta, u, w) == pytest.approx(
            S.sectional_curvature(theta, u, w), rel=CHART_REL, abs=CHART_REL * 1e-3)
        for k in range(n):
            sk = abs(np.sin(theta[k]))
            if sk < 1e-6:
                continue
            K = S.sectional_curvature(theta, u, w, chart=k)
            # Outside the well-conditioned part of a chart's domain the rounding error grows
            # (measured: ~1e-6 relative at |sin θ_k| = 5e-3); the integrators never use a
            # chart there (they switch at |sin θ_k| < τ·max|sin θ|).
            tol = CHART_REL if sk >= WELL_CONDITIONED else 1e-13 / sk**4
            assert abs(K - ref) <= tol * max(abs(ref), 1e-3), (k, sk, K, ref)
            checked += 1
    assert checked >= 10 * (n - 1)


# -- contracted kernels -------------------------------------------------------------------
@pytest.mark.parametrize("n", NS)
def test_contracted_kernels_match_full_tensors(n):
    mod = chart_module(n)
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    rng = np.random.default_rng(7)
    d = n - 1
    for theta, _ in points(S, 5, seed=70 + n):
        k = n - 1
        if abs(np.sin(theta[k])) < WELL_CONDITIONED:
            continue
        q, m, a1 = theta[:-1], S.masses, np.ones(n)  # the family module at a = 1, c = 0
        v, p, x = rng.normal(size=(3, d))
        G = mod.christoffel(q, m, a1, 0.0, np.empty((d,) * 3))
        g = mod.metric(q, m, a1, 0.0, np.empty((d, d)))
        gi = mod.metric_inverse(q, m, a1, 0.0, np.empty((d, d)))
        R = mod.riemann(q, m, a1, 0.0, np.empty((d,) * 4))
        assert rel_err(g @ gi, np.eye(d)) < REL
        assert rel_err(mod.geodesic_acceleration(q, v, m, a1, 0.0, np.empty(d)), -np.einsum("abc,b,c->a", G, v, v)) < REL
        assert rel_err(mod.transport_rate(q, v, p, m, a1, 0.0, np.empty(d)), -np.einsum("abc,b,c->a", G, v, p)) < REL
        Rop = gi @ np.einsum("ebcd,b,c,d->e", R, v, x, v)
        assert rel_err(mod.curvature_operator(q, x, v, m, a1, 0.0, np.empty(d)), Rop) < REL


@pytest.mark.parametrize("n", NS)
def test_chart_round_trip_and_tangency(n):
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    for theta, u in points(S, 10, seed=80 + n):
        for k in charts_with_domain(S, theta):
            q, v = S.to_chart(theta, u, k)
            th2, u2 = S.from_chart(q, v, k, np.sign(np.sin(theta[k])))
            np.testing.assert_allclose(np.angle(np.exp(1j * (th2 - theta))), 0, rtol=0, atol=1e-12)
            np.testing.assert_allclose(u2, u, rtol=0, atol=1e-12)


@pytest.mark.parametrize("n", NS)
def test_random_state_is_on_the_manifold(n):
    S = charts.RotorSystem(n, masses_for(n, "unequal"))
    for seed in range(5):
        theta, u = S.random_state(seed=seed, speed=2.5)
        assert theta.shape == u.shape == (n,)
        assert abs(np.cos(theta).sum()) < 1e-13
        assert abs(u @ np.sin(theta)) < 1e-13
        assert abs(np.sum(S.masses * u * u) - 2.5**2) < 1e-12


# -- bad input ---------------------------------------------------------------------------
@pytest.mark.parametrize("args, match", [
    ((2,), "n must be >= 3"),
    ((3.5,), "integer"),
    ((3, [1, 1]), r"masses must have shape \(3,\)"),
    ((3, [1, 0, 1]), "positive"),
    ((3, [1, -2, 1]), "positive"),
    ((3, [1, np.nan, 1]), "masses has non-finite entries"),
])
def test_bad_system_arguments(args, match):
    with pytest.raises(ValueError, match=match):
        charts.RotorSystem(*args)


def test_bad_points_vectors_and_charts():
    S = charts.RotorSystem(4)
    theta, u = S.random_state(1)
    with pytest.raises(ValueError, match="off the manifold"):
        S.metric(theta + 0.1)
    with pytest.raises(ValueError, match="shape"):
        S.metric(theta[:3])
    with pytest.raises(ValueError, match="non-finite"):
        S.metric(np.array([np.nan, 0, 0, 0]))
    with pytest.raises(ValueError, match="not tangent"):
        S.sectional_curvature(theta, u + 0.3, u)
    with pytest.raises(ValueError, match="parallel"):
        S.sectional_curvature(theta, u, 2 * u)
    on_axis = np.array([0.0, np.pi, np.pi / 2, -np.pi / 2])  # sin θ_0 = 0: outside chart 0
    with pytest.raises(ValueError, match="outside the domain of chart 0"):
        S.christoffel(on_axis, chart=0)
    with pytest.raises(ValueError, match="chart must be an integer"):
        S.metric(theta, chart=7)
    assert S.christoffel(on_axis).shape == (3, 3, 3)  # default: best-conditioned chart


# -- generated/ is fresh ----------------------------------------------------------------
def test_generated_folder_is_fresh_and_edits_are_caught(tmp_path):
    from charts.codegen.regenerate import compare, write_all
    fresh = tmp_path / "fresh"
    write_all(fresh, verbose=False)
    assert compare(fresh, ROOT / "generated") == [], \
        "generated/ is stale: run python scripts/generate.py"
    edited = tmp_path / "edited"
    shutil.copytree(ROOT / "generated", edited)
    path = edited / "rotor_n4.py"
    path.write_text(path.read_text().replace("math.sin(q[0])", "math.sin(q[0] + 1e-9)", 1))
    (edited / "mechanism_appendix_linkage.py").write_bytes(b"\xff\xfe not python")
    diff = compare(fresh, edited)
    assert any(line.startswith("-") and "1e-9" in line for line in diff)
    assert any(line.startswith("-<unreadable") for line in diff)


def test_a_damaged_shipped_module_names_itself_and_the_repair(tmp_path, monkeypatch):
    import sys

    import charts.generated
    from charts.codegen.shipped import REPAIR, DamagedModuleError, import_shipped
    source = (ROOT / "generated" / "rotor_n3.py").read_text()
    (tmp_path / "rotor_n97.py").write_text(source[: len(source) // 2])      # truncated
    (tmp_path / "rotor_n98.py").write_bytes(b"\x00\x89PNG garbage")
    # cut short between two functions: still valid Python, but without its last line
    (tmp_path / "rotor_n96.py").write_text(source[: source.index("\ndef riemann")])
    monkeypatch.setattr(charts.generated, "__path__", [str(tmp_path), *charts.generated.__path__])
    for name in ("rotor_n96", "rotor_n97", "rotor_n98"):
        with pytest.raises(DamagedModuleError) as info:
            import_shipped(name)
        message = str(info.value)
        assert message.startswith(f"{tmp_path / name}.py: the shipped generated module is "
                                  "damaged") and REPAIR in message and "\n" not in message
        sys.modules.pop(f"charts.generated.{name}", None)
    with pytest.raises(DamagedModuleError, match="missing from this installation"):
        import_shipped("rotor_n99")
    assert import_shipped("rotor_n3").__name__ == "charts.generated.rotor_n3"


def test_generated_headers_name_the_command():
    for path in sorted((ROOT / "generated").glob("*.py")):
        assert path.read_text().startswith("# Generated by `python scripts/generate.py`"), path


@pytest.mark.parametrize("compiled", [False, True])
def test_an_out_that_is_not_c_contiguous_is_refused(compiled):
    """The multi-index outputs are written through ``out.reshape(-1)``: for a Fortran-ordered
    or strided ``out`` NumPy's reshape is a copy, written and then lost, so the generated
    functions refuse it, as Python functions and compiled (where numba's typing has not
    already refused a strided array's reshape)."""
    from numba import njit
    from numba.core.errors import TypingError
    import charts.generated.rotor_n4 as module
    fn = njit(module.christoffel) if compiled else module.christoffel
    q, m, a = np.array([0.3, 1.1, 2.0]), np.ones(4), np.ones(4)
    good = np.empty((3, 3, 3))
    fn(q, m, a, 0.0, good)
    with pytest.raises(ValueError, match="C-contiguous"):
        fn(q, m, a, 0.0, np.empty((3, 3, 3), order="F"))
    strided = np.empty((3, 3, 6))[:, :, ::2]
    with pytest.raises(TypingError if compiled else ValueError,
                       match="contiguous array only" if compiled else "C-contiguous"):
        fn(q, m, a, 0.0, strided)
