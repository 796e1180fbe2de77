"""A certified sign of the Gaussian curvature of the N = 3 surface: K ≤ 0 everywhere with
zeros only at listed isolated points, or K > 0 proven on a region — by exact algebra and
interval arithmetic, from the library's own symbolic curvature.

**Reduction to polynomials.**  In chart k (``charts.codegen.symbolic.ChartGeometry``, the
Gauss route of the generated Riemann tensor), K = R₀₁₀₁ / det g is a rational function of
the weighted sines σ and cosines κ of the chart's two angles, with the masses, weights and
level as exact rationals.  SymPy brings it to one fraction; σ enters only squared, so with
σ² = a² − κ² the numerator and denominator are polynomials in x = κᵢ, y = κⱼ alone, the
numerator carries the factor D = aₖ² − C² = (aₖ sin θₖ)² of the denominator, C = x + y − c,
and on the chart's domain (D > 0)

    sign K = sign P(x, y) · sign Q(x, y),   P = numerator / D,  Q = denominator / D.

Every surface point over (x, y) (eight, by the signs of the sines) has the same K.

**Cover.**  Chart k is used where |C| ≤ r aₖ (the first r of `COVER_RATIOS` that works:
√(2/3) for the paper's surface, so D ≥ aₖ²/3, far from the chart's edge); that these parts
cover the surface is proved first: no sign pattern of κₖ ∈ ±[r aₖ, aₖ] for all k meets
Σ κₖ = c (interval sums that exclude c).

**Branch and bound.**  Over the rectangle |x| ≤ aᵢ, |y| ≤ aⱼ, boxes outside the strip are
dropped; on the others Q > 0 and P < 0 are proved by interval evaluation (mpmath's rigorous
interval arithmetic), first naive, then in the mean-value form P(m) + ∇P(X)·(X − m); a box
where P > 0 proves K > 0 on it; a box holding a candidate zero z (κ = 0 at level 0, where the
second fundamental form vanishes) is closed when P(z) = 0 and ∇P(z) = 0 exactly and the
interval Hessian of P is negative definite on the box, so that by Taylor's theorem P < 0 on
the box but at z; every other box is split in four.  A certificate that ends with no open
box is a proof.
"""
from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from collections import deque
from itertools import product

import numpy as np
import sympy as sp
from mpmath import iv

from ..codegen.symbolic import ChartGeometry, weighted_sincos
from ..geometry.checks import integer
from .arguments import rotor_system

__all__ = ["CurvatureCertificate", "certify_curvature_sign", "sign_polynomials", "COVER_RATIOS",
           "MAX_BOXES"]

#: The ratios r tried, in order, for the charts' parts |C| ≤ r aₖ, i.e. (aₖ sin θₖ)² ≥
#: (1 − r²) aₖ²: the first whose cover is proved is used (√(2/3), D ≥ aₖ²/3, covers the
#: paper's surface; family members may need a part closer to a chart's edge).
COVER_RATIOS = (float(np.sqrt(2.0 / 3.0)), 0.9, 0.95, 0.99, 0.999)
#: Smallest box side (in κ) before a box is left open: the certificate then says "undecided".
MIN_WIDTH = 1e-9
#: Most boxes per chart a certificate may examine (``max_boxes``): about 0.2 ms each
#: (measured, mpmath intervals), so three charts of 10⁶ boxes are some ten minutes; the
#: paper's surface needs 1525 per chart.
MAX_BOXES = 10 ** 6


def _interval(r):
    """The interval enclosing the rational ``r`` (SymPy's, or a float's exact value)."""
    r = r if isinstance(r, sp.Rational) else sp.Rational(float(r))
    return iv.mpf(int(r.p)) / iv.mpf(int(r.q))


def _system3(system):
    if rotor_system(system).n != 3:
        raise ValueError(f"the curvature certificate is for the surface of N = 3 rotors, got "
                         f"N = {system.n}")
    return system


def sign_polynomials(system, k):
    """(P, Q, x, y) of chart k (module doc): SymPy polynomials in x = κᵢ, y = κⱼ (i < j the
    chart's angles) with exact rational coefficients, sign K = sign P · sign Q where D > 0."""
    _system3(system)
    g = ChartGeometry(3, k)
    i, j = g.idx
    x, y = sp.symbols("x y", real=True)
    sx, sy = sp.symbols("s_x s_y", real=True)
    G = g.metric
    K = g.riemann[0][1][0][1] / (G[0][0] * G[1][1] - G[0][1] ** 2)
    names = {weighted_sincos(i)[0](g.theta[i]): sx, weighted_sincos(i)[1](g.theta[i]): x,
             weighted_sincos(j)[0](g.theta[j]): sy, weighted_sincos(j)[1](g.theta[j]): y}
    values = g.exact_values(system.masses, system.weights, system.level)
    num, den = sp.fraction(sp.together(K.xreplace(names)))
    a = [values[g.a[q]] for q in range(3)]
    D = a[k] ** 2 - (x + y - values[g.c]) ** 2
    out = []
    for part in (num, den):
        part = sp.expand(part.xreplace(values))
        for s_, aa, v in ((sx, a[i], x), (sy, a[j], y)):
            poly = sp.Poly(part, s_)
            if any(deg % 2 for (deg,), cf in poly.terms() if cf != 0):
                raise AssertionError("the curvature is not even in the sines")  # pragma: no cover
            part = sp.expand(part.subs(s_, sp.sqrt(aa ** 2 - v ** 2)))
        quotient, remainder = sp.div(sp.Poly(part, x, y), sp.Poly(D, x, y))
        if not remainder.is_zero:
            raise AssertionError("the curvature's fraction lost its factor D")  # pragma: no cover
        out.append(quotient)
    return out[0], out[1], x, y


class _IntervalPolynomial:
    """A polynomial in (x, y) with rational coefficients, evaluated rigorously on intervals."""

    def __init__(self, poly: sp.Poly):
        self.terms = [(ex, ey, _interval(c)) for (ex, ey), c in poly.terms()]

    def __call__(self, X, Y):
        acc = iv.mpf(0)
        for ex, ey, c in self.terms:
            acc += c * X ** ex * Y ** ey
        return acc


@dataclass
class CurvatureCertificate:
    """The outcome of `certify_curvature_sign`.

    verdict : ``"nonpositive"`` (K ≤ 0 on the whole surface, zero exactly at ``zeros``),
    ``"positive somewhere"`` (K > 0 proved on ``positive_box``), or ``"undecided"``
    (``open_boxes`` boxes left, none proved either way);  zeros : the surface points where
    K = 0, exact (each κ = 0: θᵢ = ±π/2);  charts : per chart, the polynomials and the box
    counts;  cover : how the charts' parts were proved to cover the surface.
    """
    verdict: str
    zeros: list
    charts: list
    cover: str
    positive_box: dict | None
    open_boxes: int
    seconds: float
    params: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        return asdict(self)


def _cover_proof(a, c, r):
    """The charts' parts |κₖ| ≤ r aₖ cover the level set Σ κₖ = c: for every sign pattern the
    interval Σ ±[r aₖ, aₖ] excludes c (exact rationals in intervals)."""
    for signs in product((1, -1), repeat=3):
        total = iv.mpf(0)
        for s_, ak in zip(signs, a):
            lo, hi = iv.mpf(r) * ak, iv.mpf(ak)
            total += iv.mpf([lo.a, hi.b]) if s_ > 0 else -iv.mpf([lo.a, hi.b])
        if not (total.b < c.a or total.a > c.b):      # the sum may reach the level
            return None
    return (f"every point has |a_k cos theta_k| <= {r:.6g} a_k for some k: for each of the 8 sign "
            f"patterns the interval sum of ±[{r:.6g} a_k, a_k] excludes the level {float(c)!r}")


def _hessian_negative(Hxx, Hxy, Hyy, X, Y):
    hxx, hxy, hyy = Hxx(X, Y), Hxy(X, Y), Hyy(X, Y)
    return hxx.b < 0 and (hxx * hyy - hxy * hxy).a > 0


def _chart_run(system, k, r, max_boxes):
    """Branch and bound of chart k; returns the chart's record, a positive box or None, and
    the number of open boxes."""
    P, Q, x, y = sign_polynomials(system, k)
    i, j = [q for q in range(3) if q != k]
    a = system.weights
    ak = _interval(a[k])
    c = _interval(system.level)
    Pi, Qi = _IntervalPolynomial(P), _IntervalPolynomial(Q)
    dPx, dPy = _IntervalPolynomial(P.diff(x)), _IntervalPolynomial(P.diff(y))
    Hxx = _IntervalPolynomial(P.diff(x).diff(x))
    Hxy = _IntervalPolynomial(P.diff(x).diff(y))
    Hyy = _IntervalPolynomial(P.diff(y).diff(y))
    # candidate zeros: where the second fundamental form vanishes (every κ = 0), on the surface
    # only at level 0; closed only if P and ∇P vanish there exactly
    zeros = []
    if system.level == 0.0:
        z = {x: 0, y: 0}
        if P.as_expr().subs(z) == 0 and P.diff(x).as_expr().subs(z) == 0 \
                and P.diff(y).as_expr().subs(z) == 0:
            zeros.append((0.0, 0.0))
    # breadth first: a region where K > 0 is found at the coarsest level that proves it
    boxes = deque([(iv.mpf([-float(a[i]), float(a[i])]), iv.mpf([-float(a[j]), float(a[j])]))])
    counts = dict(boxes=0, outside=0, negative=0, mean_value=0, zero=0)
    positive, open_ = None, 0
    strip = iv.mpf(r) * ak
    while boxes:
        X, Y = boxes.popleft()
        counts["boxes"] += 1
        if counts["boxes"] > max_boxes:
            open_ += 1 + len(boxes)
            break
        C = X + Y - c
        if C.a > strip.b or C.b < -strip.b:
            counts["outside"] += 1
            continue
        inside_domain = C.b < ak.a and C.a > -ak.b      # D > 0 on the whole box
        if inside_domain and Qi(X, Y).a > 0:
            Pv = Pi(X, Y)
            if Pv.b < 0:
                counts["negative"] += 1
                continue
            mx, my = iv.mpf(X.mid.a), iv.mpf(Y.mid.a)
            if (Pi(mx, my) + dPx(X, Y) * (X - mx) + dPy(X, Y) * (Y - my)).b < 0:
                counts["mean_value"] += 1
                continue
            if Pv.a > 0:
                positive = dict(chart=k, x=[float(X.a), float(X.b)], y=[float(Y.a), float(Y.b)],
                                K_sign="+", note=f"x = a_{i} cos theta_{i}, y = a_{j} cos theta_{j}")
                break
            if any(zx in X and zy in Y for zx, zy in zeros) and _hessian_negative(Hxx, Hxy, Hyy,
                                                                                  X, Y):
                counts["zero"] += 1
                continue
        wx, wy = float(X.delta.b), float(Y.delta.b)
        if max(wx, wy) < MIN_WIDTH:
            open_ += 1
            continue
        xs = (iv.mpf([X.a, X.mid.a]), iv.mpf([X.mid.a, X.b]))
        ys = (iv.mpf([Y.a, Y.mid.a]), iv.mpf([Y.mid.a, Y.b]))
        boxes.extend((xx, yy) for xx in xs for yy in ys)
    record = dict(chart=k, variables=[f"x = a_{i} cos theta_{i}", f"y = a_{j} cos theta_{j}"],
                  P=str(P.as_expr()), Q=str(Q.as_expr()),
                  P_approx=str(P.as_expr().evalf(6)), zero_candidates=len(zeros), **counts)
    return record, positive, open_


def certify_curvature_sign(system, *, max_boxes=200_000):
    """Prove the sign of the Gaussian curvature of the surface of ``system`` (N = 3: any
    masses, weights and smooth level) by the reduction, cover and branch and bound of the
    module doc; returns a `CurvatureCertificate`.  ``max_boxes``: the boxes examined per
    chart before the rest is left open ("undecided"), an integer in 1..`MAX_BOXES`."""
    _system3(system)
    max_boxes = integer("max_boxes", max_boxes, 1, MAX_BOXES)
    t0 = time.process_time()
    a = [_interval(w) for w in system.weights]
    c = _interval(system.level)
    ratio, cover = None, None
    for ratio in COVER_RATIOS:
        cover = _cover_proof(a, c, ratio)
        if cover is not None:
            break
    params = dict(**system.describe(), cover_ratio=ratio, max_boxes=max_boxes)
    if cover is None:
        return CurvatureCertificate("undecided", [], [], "no part of the charts' domains |C| <= "
                                    f"r a_k with r in {COVER_RATIOS} was proved to cover this "
                                    "level set", None, 0, time.process_time() - t0, params)
    charts_, positive, open_ = [], None, 0
    for k in range(3):
        record, positive, left = _chart_run(system, k, ratio, max_boxes)
        charts_.append(record)
        open_ += left
        if positive is not None:
            break
    zeros = []
    if positive is None and open_ == 0 and any(r["zero"] for r in charts_):
        zeros = [dict(theta=[f"{'+' if s_ > 0 else '-'}pi/2" for s_ in signs],
                      value=[s_ * np.pi / 2 for s_ in signs])
                 for signs in product((1, -1), repeat=3)]
    verdict = ("positive somewhere" if positive is not None else
               "nonpositive" if open_ == 0 else "undecided")
    return CurvatureCertificate(verdict, zeros, charts_, cover, positive, open_,
                                time.process_time() - t0, params)
