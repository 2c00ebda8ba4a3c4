#!/usr/bin/python3
"""Black-box tests of the query extensions of issue 8 (docs/cli.md, "Beyond
the contract"): `bounds` over a parameter range, `eval`'s `frame` (unit tangent,
normal, binormal, curvature, torsion), inflections and cusps at the breaks of piecewise
curves in `features`, and high-degree `length` and `features`. Expected values come from
closed forms and from oracles at test time: the curve evaluator of test_queries.py in
30-digit mpmath (extrema refined by mpmath.findroot), scipy.interpolate.CubicSpline, and an
arc length integrated in numpy long double on Chebyshev-graded Gauss-Legendre panels.

Usage: test_queries_ext.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import random
import sys
import unittest

import mpmath
import numpy as np
from mpmath import mpf
from scipy.interpolate import CubicSpline

import test_cli
import test_queries as tq
from test_cli import CliTest, bezier


def sub_box(oracle, lo, hi, dim):
    """The tight box over [lo, hi] from the oracle: both ends and every sign change of
    each coordinate's derivative inside, refined in mpf, evaluated in mpf."""
    pts = [oracle.at(lo), oracle.at(hi)]
    for g, a, b in oracle.pieces:
        a2, b2 = max(a, lo), min(b, hi)
        if a2 >= b2:
            continue
        pts += [g.f(mpf(a2)), g.f(mpf(b2))]
        for k in range(dim):
            for r in tq.roots_by_sampling(lambda u: g.df(u)[k], a2, b2, 400):
                pts.append(g.f(r))
    return [min(float(p[k]) for p in pts) for k in range(dim)], [max(float(p[k]) for p in pts) for k in range(dim)]


def samples(oracle, lo, hi, count=2000):
    out = []
    for i in range(count + 1):
        u = lo + (hi - lo) * i / count
        out.append(oracle.piece_at(u).f(u))
    return out


class BoundsRangeTest(CliTest):
    def test_closed_forms(self):
        c = bezier([[0, 0], [1, 2], [2, 0]])
        self.assertEqual(self.ok("bounds", {"curve": c, "from": 0.25, "to": 0.75}), {"min": [0.5, 0.75], "max": [1.5, 1.0]})
        self.assertEqual(self.ok("bounds", {"curve": c, "from": 0.5}), {"min": [1.0, 0.0], "max": [2.0, 1.0]})
        self.assertEqual(self.ok("bounds", {"curve": c, "from": 0.5, "to": 0.5}), {"min": [1.0, 1.0], "max": [1.0, 1.0]})
        # Circle of radius 2 about (1, -1) from 45 to 135 degrees, across the break at 1.
        got = self.ok("bounds", {"curve": tq.circle(2, 1, -1), "from": 0.5, "to": 1.5})
        s = math.sqrt(2)
        self.assert_close(got["min"], [1 - s, -1 + s], 1e-15)
        self.assert_close(got["max"], [1 + s, 1.0], 1e-15)

    def test_against_the_oracle(self):
        """Random curves and ranges: the box holds 2001 samples and equals the oracle's
        tight box (touching the curve) to 1e-12 of the curve's size."""
        rng = random.Random(81)
        curves = tq.random_curves(rng, 16) + [tq.circle(1.5, 0.5, 0.25)]
        for c in curves:
            o = tq.Oracle.of(c)
            lo_dom, hi_dom = o.pieces[0][1], o.pieces[-1][2]
            a = lo_dom + (hi_dom - lo_dom) * rng.uniform(0, 0.6)
            b = a + (hi_dom - a) * rng.uniform(0.1, 1)
            got = self.ok("bounds", {"curve": c, "from": a, "to": b})
            want_lo, want_hi = sub_box(o, a, b, 2)
            size = max(1.0, max(abs(x) for x in want_lo + want_hi))
            for k in range(2):
                self.assertAlmostEqual(got["min"][k], want_lo[k], delta=1e-12 * size, msg=(c, a, b))
                self.assertAlmostEqual(got["max"][k], want_hi[k], delta=1e-12 * size, msg=(c, a, b))
            for p in samples(o, a, b):
                for k in range(2):
                    self.assertGreaterEqual(p[k], got["min"][k] - 1e-13 * size)
                    self.assertLessEqual(p[k], got["max"][k] + 1e-13 * size)

    def test_bad_ranges(self):
        c = bezier([[0, 0], [1, 2], [2, 0]])
        self.bad("bounds", {"curve": c, "from": 0.5, "to": 0.25}, "to", contains=">= from")
        self.bad("bounds", {"curve": c, "from": -0.5}, "from", contains="domain [0, 1]")
        self.bad("bounds", {"curve": tq.circle(), "to": 4.5}, "to", contains="domain [0, 4]")
        self.bad("bounds", {"curve": c, "from": "0"}, "from")
        self.bad("bounds", {"curve": c, "form": 0}, "form")


def frame_oracle(g, u):
    """T, N, B, curvature, torsion of the B-spline piece g at u from its mpf derivatives,
    by the textbook formulas (kappa = |d1 x d2| / |d1|^3, tau = det(d1, d2, d3) /
    |d1 x d2|^2, B = d1 x d2 / |d1 x d2|, N = B x T with dk the k-th derivative)."""
    u = mpf(u)
    d1, d2, d3 = g.df(u, 1), g.df(u, 2), g.df(u, 3)
    cr = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]]
    s = tq.norm(d1)
    kappa = tq.norm(cr) / s ** 3
    B = [x / tq.norm(cr) for x in cr]
    T = [x / s for x in d1]
    N = [B[1] * T[2] - B[2] * T[1], B[2] * T[0] - B[0] * T[2], B[0] * T[1] - B[1] * T[0]]
    tau = sum(x * y for x, y in zip(cr, d3)) / tq.norm(cr) ** 2
    return [float(x) for x in T], [float(x) for x in N], [float(x) for x in B], float(kappa), float(tau)


class FrameTest(CliTest):
    def test_twisted_cubic_closed_forms(self):
        # (t, t^2, t^3): kappa = 2 sqrt(1 + 9t^2 + 9t^4) / (1 + 4t^2 + 9t^4)^(3/2), tau = 3 / (1 + 9t^2 + 9t^4).
        c = bezier([[0, 0, 0], [1 / 3, 0, 0], [2 / 3, 1 / 3, 0], [1, 1, 1]])
        ts = [0, 0.2, 0.5, 0.9, 1]
        got = self.ok("eval", {"curve": c, "t": ts, "frame": True})["frame"]
        for j, t in enumerate(ts):
            q, s = 1 + 9 * t * t + 9 * t ** 4, 1 + 4 * t * t + 9 * t ** 4
            self.assert_close([got["curvature"][j]], [2 * math.sqrt(q) / s ** 1.5], 1e-14)
            self.assert_close([got["torsion"][j]], [3 / q], 1e-14)
            self.assert_close(got["tangent"][j], [x / math.sqrt(s) for x in (1, 2 * t, 3 * t * t)], 1e-15)
            b = [6 * t * t, -6 * t, 2]
            self.assert_close(got["binormal"][j], [x / tq.norm(b) for x in b], 1e-15)

    def test_helix_like_bspline_against_mpmath(self):
        """A cubic B-spline whose control points lie on a helix: frame, curvature and
        torsion against the oracle's de Boor derivatives in 30-digit mpf (parameters inside
        knot spans: the third derivative jumps at the knots)."""
        P = [[2 * math.cos(0.7 * i), 2 * math.sin(0.7 * i), 0.5 * 0.7 * i] for i in range(8)]
        U = [0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1]
        c = {"type": "bspline", "degree": 3, "knots": U, "points": P}
        o = tq.Oracle.of(c)
        ts = [0.05, 0.27, 0.33, 0.5, 0.71, 0.95]
        got = self.ok("eval", {"curve": c, "t": ts, "frame": True})["frame"]
        for j, t in enumerate(ts):
            T, N, B, kappa, tau = frame_oracle(o.piece_at(t), t)
            self.assert_close(got["tangent"][j], T, 1e-14)
            self.assert_close(got["normal"][j], N, 1e-13)
            self.assert_close(got["binormal"][j], B, 1e-13)
            self.assert_close([got["curvature"][j]], [kappa], 1e-13)
            self.assert_close([got["torsion"][j]], [tau], 1e-13)

    def test_circles(self):
        # 2-D: the left normal points to the centre of a counter-clockwise circle, kappa 1/r.
        got = self.ok("eval", {"curve": tq.circle(3, 1, -2), "t": [0, 0.5, 1, 3.25, 4], "frame": True})
        for j, p in enumerate(got["points"]):
            radial = [(p[0] - 1) / 3, (p[1] + 2) / 3]
            self.assert_close(got["frame"]["tangent"][j], [-radial[1], radial[0]], 1e-15)
            self.assert_close(got["frame"]["normal"][j], [-radial[0], -radial[1]], 1e-15)
            self.assert_close([got["frame"]["curvature"][j]], [1 / 3], 1e-15)
        self.assertNotIn("binormal", got["frame"])
        self.assertNotIn("torsion", got["frame"])
        # The nine-point NURBS circle of radius 2 about (-1, 0.5) [PT97, Ex. 7.2]: at every
        # parameter (the knots included, where the right-hand span answers) kappa = 1/2.
        s = math.sqrt(0.5)
        corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
        nurbs = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                 "points": [[-1 + 2 * x, 0.5 + 2 * y] for x, y in corners], "weights": [1, s, 1, s, 1, s, 1, s, 1]}
        ts = [0, 0.1, 0.25, 0.5, 0.6, 0.75, 0.99, 1]
        got = self.ok("eval", {"curve": nurbs, "t": ts, "frame": True})
        for j, p in enumerate(got["points"]):
            radial = [(p[0] + 1) / 2, (p[1] - 0.5) / 2]
            self.assert_close(got["frame"]["tangent"][j], [-radial[1], radial[0]], 1e-15)
            self.assert_close(got["frame"]["normal"][j], [-radial[0], -radial[1]], 1e-15)
            self.assert_close([got["frame"]["curvature"][j]], [0.5], 1e-15)
        # 3-D: a NURBS quarter circle of radius 3 in the plane spanned by (1,0,0), (0,1,1)/sqrt 2:
        # torsion 0, binormal the plane's normal (0,-1,1)/sqrt 2, normal to the centre.
        s = math.sqrt(0.5)
        arc = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[3, 0, 0], [3, 3 * s, 3 * s], [0, 3 * s, 3 * s]],
               "weights": [1, s, 1]}
        got = self.ok("eval", {"curve": arc, "t": [0, 0.4, 1], "frame": True})
        for j, p in enumerate(got["points"]):
            self.assert_close([got["frame"]["torsion"][j]], [0.0], 1e-15)
            self.assert_close([got["frame"]["curvature"][j]], [1 / 3], 1e-15)
            self.assert_close(got["frame"]["binormal"][j], [0, -s, s], 1e-15)
            self.assert_close(got["frame"]["normal"][j], [-x / 3 for x in p], 1e-15)

    def test_dimensions_and_breaks(self):
        got = self.ok("eval", {"curve": bezier([[0], [1], [3]]), "t": [0.5], "frame": True})
        self.assertEqual(got["frame"], {"tangent": [[1.0]], "curvature": [0.0]})
        # At a polyline's vertex the right-hand segment answers; at the end the last one.
        poly = {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1], [0, 1]]}
        got = self.ok("eval", {"curve": poly, "t": [0, 1, 2, 3], "frame": True})["frame"]
        self.assertEqual(got["tangent"], [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [-1.0, 0.0]])
        got = self.ok("eval", {"curve": bezier([[0, 0, 0, 0], [1, 0, 0, 0], [1, 1, 0, 0]]), "t": [0], "frame": True})["frame"]
        self.assertEqual(got["normal"], [[0.0, 1.0, 0.0, 0.0]])
        self.assertNotIn("torsion", got)

    def test_undefined_frames_are_errors(self):
        # A + s D for s = 0, 1, -1/2, 2: straight (up to the rounding of the decimals).
        line = bezier([[0.1, 0.2, 0.3], [0.4, 0.7, 1.0], [-0.05, -0.05, -0.05], [0.7, 1.2, 1.7]])
        self.bad("eval", {"curve": line, "t": [0.3], "frame": True}, "t[0]", contains="curvature is zero")
        cusp = bezier([[0, 0], [1, 1], [0, 1], [1, 0]])
        self.bad("eval", {"curve": cusp, "t": [0.25, 0.5], "frame": True}, "t[1]", contains="velocity is zero")
        self.bad("eval", {"curve": cusp, "t": [0.25], "frame": 1}, "frame")
        # Without frame the same requests answer.
        self.ok("eval", {"curve": line, "t": [0.3]})


def zigzag_spline_oracle(params, points, bc="natural"):
    cs = CubicSpline(params, np.array(points, dtype=float), bc_type=bc)
    d1, d2 = cs.derivative(1), cs.derivative(2)

    def cross(u):
        a, b = d1(float(u)), d2(float(u))
        return a[0] * b[1] - a[1] * b[0]

    out = []
    for lo, hi in zip(params, params[1:]):
        us = np.linspace(lo, hi, 401)
        v = [cross(u) for u in us]
        for i in range(400):
            if v[i] == 0 and i > 0:
                out.append(us[i])
            elif v[i] * v[i + 1] < 0:
                a, b = us[i], us[i + 1]
                for _ in range(200):  # bisection to the last bit
                    m = (a + b) / 2
                    if m in (a, b):
                        break
                    if cross(m) * v[i] > 0:
                        a = m
                    else:
                        b = m
                out.append((a + b) / 2)
    # A natural spline's curvature is zero at its ends: not a feature (the domain's ends
    # are not reported), though rounding may show a sign change there.
    span = params[-1] - params[0]
    return [u for u in out if params[0] + 1e-9 * span < u < params[-1] - 1e-9 * span]


class FeaturesAtBreaksTest(CliTest):
    def test_opposite_arcs(self):
        s = math.sqrt(0.5)
        path = {"type": "path", "segments": [
            {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, s, 1]},
            {"type": "rational_bezier", "points": [[0, 1], [-1, 1], [-1, 2]], "weights": [1, s, 1]}]}
        got = self.ok("features", {"curve": path})
        self.assertEqual(got["inflections"], [1.0])
        self.assertEqual(got["cusps"], [])
        # The S cubic split at its inflection (halves by hand): once, at the break.
        halves = {"type": "path", "segments": [bezier([[0, 0], [0.5, 0.5], [1, 0.25], [1.5, 0]]),
                                               bezier([[1.5, 0], [2, -0.25], [2.5, -0.5], [3, 0]])], "breaks": [0, 0.5, 1]}
        self.assertEqual(self.ok("features", {"curve": halves})["inflections"], [0.5])

    def test_polylines(self):
        got = self.ok("features", {"curve": {"type": "polyline", "points": [[0, 0], [1, 1], [2, 0], [3, 1]]}})
        self.assertEqual((got["inflections"], got["cusps"]), ([], []))
        got = self.ok("features", {"curve": {"type": "polyline", "points": [[0, 0], [2, 1], [1, 0.5], [3, 0]]}})
        self.assertEqual((got["inflections"], got["cusps"]), ([], [1.0]))

    def test_cubic_spline_zigzag_against_scipy(self):
        # Natural spline through (i, 0 or 1): x(t) = t, y'' = 0 at the ends, M1 = -4, M2 = 4
        # for four points (by hand), so one inflection at 1.5 inside the middle piece.
        pts = [[0, 0], [1, 1], [2, 0], [3, 1]]
        got = self.ok("features", {"curve": {"type": "cubic_spline", "params": [0, 1, 2, 3], "points": pts}})
        self.assert_close(got["inflections"], [1.5], 1e-15)
        rng = random.Random(5)
        for bc in ("natural", "not-a-knot"):
            params = [0.0]
            for _ in range(9):
                params.append(params[-1] + rng.uniform(0.5, 2))
            pts = [[p + rng.uniform(-0.2, 0.2), (i % 2) * 2 - 1 + rng.uniform(-0.3, 0.3)] for i, p in enumerate(params)]
            got = self.ok("features", {"curve": {"type": "cubic_spline", "params": params, "points": pts, "boundary": bc}})
            self.assert_close(got["inflections"], zigzag_spline_oracle(params, pts, bc), 1e-12, bc)
            self.assertEqual(got["cusps"], [])


def long_double_length(c, K):
    """Arc length in numpy long double: the hodograph by the Bernstein-Horner scheme,
    30-point Gauss-Legendre on K panels graded like Chebyshev points towards the ends
    (where a high-degree Bernstein polynomial varies on a scale of 1 / n)."""
    ld = np.longdouble
    P = np.array(c["points"], dtype=ld)
    n = len(P) - 1
    H = n * (P[1:] - P[:-1])

    def value(cf, ts):
        out = np.empty(len(ts), dtype=ld)
        for mask, rev in ((ts <= 0.5, False), (ts > 0.5, True)):
            t = ts[mask]
            a = cf[::-1] if rev else cf
            x = (1 - t) if rev else t
            u = 1 - x
            N = len(a) - 1
            term, acc = np.ones_like(x), a[0] * u
            for i in range(1, N):
                term = term * x * ld(N - i + 1) / ld(i)
                acc = (acc + term * a[i]) * u
            out[mask] = acc + term * x / ld(N) * a[N]
        return out

    xg, wg = np.polynomial.legendre.leggauss(30)
    edges = (1 - np.cos(np.pi * np.arange(K + 1) / K)) / 2
    ts = ((edges[:-1, None] + edges[1:, None]) / 2 + (edges[1:, None] - edges[:-1, None]) / 2 * xg[None, :]).ravel().astype(ld)
    wts = ((edges[1:, None] - edges[:-1, None]) / 2 * wg[None, :]).ravel().astype(ld)
    speed = np.sqrt(sum(value(H[:, k], ts) ** 2 for k in range(H.shape[1])))
    return float((speed * wts).sum())


class HighDegreeTest(CliTest):
    def test_length_degree_300_against_long_double(self):
        rng = random.Random(300)
        c = bezier([[rng.uniform(-1, 1), rng.uniform(-1, 1)] for _ in range(301)])
        want, check = long_double_length(c, 800), long_double_length(c, 1600)
        self.assertLess(abs(want - check), 1e-14 * check, "the oracle has converged")
        got = self.ok("length", {"curve": c})["length"]
        self.assertLess(abs(got - check), 1e-12 * check)

    def test_degree_1000_answers(self):
        """Degree 1000 (issue 8: 31 s for length before): length, features, bounds and
        project answer (each well under the suite's timeout; timings in docs/accuracy.md),
        and the length of its first half plus its second half is the whole."""
        rng = random.Random(1000)
        c = bezier([[rng.uniform(-1, 1), rng.uniform(-1, 1)] for _ in range(1001)])
        whole = self.ok("length", {"curve": c})["length"]
        a = self.ok("length", {"curve": c, "to": 0.5})["length"]
        b = self.ok("length", {"curve": c, "from": 0.5})["length"]
        self.assertLess(abs(a + b - whole), 1e-12 * whole)
        f = self.ok("features", {"curve": c})
        self.assertGreater(len(f["inflections"]), 0)
        box = self.ok("bounds", {"curve": c})
        p = self.ok("project", {"curve": c, "point": [0.1, 0.2]})
        for k in range(2):
            self.assertLessEqual(box["min"][k], p["point"][k])
            self.assertGreaterEqual(box["max"][k], p["point"][k])


# ---------------------------------------------------------------------------------------
# Rational curves with extreme weights (section 6 of the renovation issue). The rational
# quadratic with points (1, 0), (1, 1), (0, 1) and weights [1, w, 1] is a conic; with a
# huge w it runs within about 1 / w of its control polygon (legs x = 1 and y = 1), with a
# tiny one within about w of the chord. Reference values: closed forms of this conic,
# written here, in mpmath at 60 digits (enough for w up to 1e300: the forms below have no
# cancellation).

CONIC_P = [[1, 0], [1, 1], [0, 1]]


def conic(w):
    return {"type": "rational_bezier", "points": CONIC_P, "weights": [1, w, 1]}


def conic_point(w, t):
    """The conic at t (mpmath)."""
    w, t = mpf(w), mpf(t)
    b = [(1 - t) ** 2, 2 * t * (1 - t) * w, t ** 2]
    W = sum(b)
    return [sum(b[i] * CONIC_P[i][k] for i in range(3)) / W for k in range(2)]


def conic_t_at_y_half(w):
    """The t where y(t) = 1/2: 2 w t (1 - t) + 2 t - 1 = 0, the root in (0, 1/2) written
    without cancellation: t = 1 / ((w + 1) + sqrt(w^2 + 1))."""
    w = mpf(w)
    return 1 / ((w + 1) + mpmath.sqrt(w * w + 1))


class ExtremeWeightsTest(CliTest):
    HUGE = (1e100, 1e200, 1e300)
    TINY = (1e-100, 1e-200, 1e-300)

    def test_flatten_every_method(self):
        # The polyline runs within the tolerance of the curve: from (1, 0) to (0, 1) and
        # within the tolerance of the corner (1, 1), which the curve passes within 1e-100;
        # every vertex lies on the curve, so within 1e-12 of a leg (the curve is within
        # 1e-100 of them; 1e-12 allows the rounding of the vertices). Weights 1e200 and
        # 1e300 refused the default (optimal) method before: a second derivative of 1e400.
        tol = 1e-3
        for w in self.HUGE:
            for method in ("optimal", "uniform", "subdivision"):
                pts = self.ok("flatten", {"curve": conic(w), "tolerance": tol, "method": method})["points"]
                self.assertEqual(pts[0], [1.0, 0.0])
                self.assertEqual(pts[-1], [0.0, 1.0])
                for x, y in pts:
                    self.assertLessEqual(min(abs(x - 1), abs(y - 1)), 1e-12, (w, method, pts))
                near = min(math.dist(v, (1, 1)) for v in pts)
                self.assertLessEqual(near, tol, (w, method, pts))

    def test_area_of_the_closed_conic(self):
        # The conic closed by the chord from (0, 1) back to (1, 0): the triangle's area
        # 1/2 less the sliver of width about 1 / w along the legs (below 1e-99: the double
        # nearest is 0.5). Quadrature in t failed on it before (its ends take 1e-100 of
        # the parameter).
        for w in self.HUGE:
            c = {"type": "path", "segments": [conic(w), bezier([[0, 1], [1, 0]])]}
            # 1e-13 relative: the quadrature's tolerance (docs/accuracy.md), summed over parts.
            self.assertLessEqual(abs(self.ok("area", {"curve": c})["area"] - 0.5), 1e-13, w)
        for w in self.TINY:
            # Within about w of the chord: an area below 1e-99, against the quadrature's
            # absolute accuracy of 1e-13 of the integrand's size (about 1).
            c = {"type": "path", "segments": [conic(w), bezier([[0, 1], [1, 0]])]}
            self.assertLessEqual(abs(self.ok("area", {"curve": c})["area"]), 1e-13, w)
        # Not closed: the closure is named, not a failed quadrature.
        self.bad("area", {"curve": conic(1e200)}, "curve", contains="closed")

    def test_intersect_with_lines(self):
        # Weights tiny: within w of the chord x + y = 1, which the diagonal meets at
        # (1/2, 1/2), t = 1/2 on both. (Huge weights: ExtremeWeightsIntersectTest.)
        for w in self.TINY:
            r = self.ok("intersect", {"curves": [conic(w), bezier([[0, 0], [2, 2]])]})
            self.assertEqual(len(r["intersections"]), 1, (w, r))
            self.assert_close(r["intersections"][0]["t"], [0.5, 0.25], 1e-15)
            self.assert_close(r["intersections"][0]["point"], [0.5, 0.5], 1e-15)
        for w in self.HUGE + self.TINY:
            self.assertEqual(self.ok("intersect", {"curves": [conic(w)]}), {"intersections": [], "overlaps": []})

    def test_queries_that_were_right(self):
        # Regression guard for the queries that answered correctly already: eval, bounds,
        # length, project, distance, features, split, elevate, to_bezier. Each command's
        # requests through one --jsonl process (a process per request cost 1.5 s of CPU).
        ws = self.HUGE + self.TINY
        curves = [conic(w) for w in ws]
        each = lambda cmd, extra: self.ok_jsonl(cmd, [dict({"curve": c}, **extra) for c in curves])
        halves = [r["curves"] for r in each("split", {"t": 0.5})]
        elevated = [r["curve"] for r in each("elevate", {"times": 1})]
        # eval: the curve at 0, 1/2, 1/4, 1; each half at 1/2; the elevated curve at 1/4.
        evals = iter(self.ok_jsonl("eval", [{"curve": c, "t": [0, 0.5, 0.25, 1]} for c in curves] +
                                   [{"curve": h, "t": [0.5]} for hs in halves for h in hs] +
                                   [{"curve": e, "t": [0.25]} for e in elevated]))
        bounds, lengths, features = each("bounds", {}), each("length", {}), each("features", {})
        for w in ws:
            for t, p in zip([0, 0.5, 0.25, 1], next(evals)["points"]):
                self.assert_close(p, [float(v) for v in conic_point(w, t)], 1e-15)
        for k, w in enumerate(ws):
            self.assertEqual(bounds[k], {"min": [0.0, 0.0], "max": [1.0, 1.0]})
            # Length: within 1/w of 2 (the legs) or of sqrt(2) (the chord), relative 1e-12.
            want = 2.0 if w > 1 else math.sqrt(2)
            self.assertLessEqual(abs(lengths[k]["length"] - want), 1e-12 * want, w)
            self.assertEqual(features[k], {"inflections": [], "cusps": [], "extrema": [[], []]})
        for w in ws:
            for lo, hi in [(0, 0.5), (0.5, 1)]:
                q = next(evals)["points"][0]
                self.assert_close(q, [float(v) for v in conic_point(w, (lo + hi) / 2)], 1e-15)
        for w in ws:
            q = next(evals)["points"][0]
            self.assert_close(q, [float(v) for v in conic_point(w, 0.25)], 1e-15)
        projections = self.ok_jsonl("project", [{"curve": conic(w), "point": [2, 0.5]} for w in self.HUGE])
        distances = self.ok_jsonl("distance", [{"curves": [conic(w), bezier([[2, 0.5], [3, 0.5]])]} for w in self.HUGE])
        for w, p, d in zip(self.HUGE, projections, distances):
            # The point (2, 1/2) is nearest to the leg x = 1 at y = 1/2: distance 1.
            self.assertLessEqual(abs(p["distance"] - 1), 1e-15)
            t = conic_t_at_y_half(w)
            self.assertLessEqual(abs(p["t"] - float(t)), 1e-12 * float(t))
            self.assertLessEqual(abs(d["distance"] - 1), 1e-15)


class ConstantLagrangeTest(CliTest):
    """A one-point lagrange is the constant polynomial: its domain is the single param.
    Every command answers as for a curve standing still at the point (docs/cli.md,
    "lagrange and catmull_rom"), with parameters the param itself."""

    P, U = [1.0, 2.0], 2.5

    def curve(self):
        return {"type": "lagrange", "params": [self.U], "points": [self.P]}

    def test_answers(self):
        c = self.curve()
        self.assertEqual(self.ok("bounds", {"curve": c}), {"min": self.P, "max": self.P})
        self.assertEqual(self.ok("bounds", {"curve": c, "from": self.U, "to": self.U}), {"min": self.P, "max": self.P})
        self.assertEqual(self.ok("length", {"curve": c}), {"length": 0.0})
        self.assertEqual(self.ok("param_at_length", {"curve": c, "lengths": [0]}), {"t": [self.U]})
        self.assertEqual(self.ok("features", {"curve": c}), {"inflections": [], "cusps": [], "extrema": [[], []]})
        for method in ("optimal", "uniform", "subdivision"):
            self.assertEqual(self.ok("flatten", {"curve": c, "tolerance": 0.1, "method": method}), {"points": [self.P, self.P]})
        # The distance is constant over the (one-parameter) domain: the interval is the
        # domain itself, [2.5, 2.5] (it ran to the next double, 2.5000000000000004, before).
        d = math.dist(self.P, [0, 0])
        for farthest in (False, True):
            r = self.ok("project", {"curve": c, "point": [0, 0], "farthest": farthest})
            self.assertEqual(r["t"], self.U)
            self.assertEqual(r["point"], self.P)
            self.assertLessEqual(abs(r["distance"] - d), 1e-15 * d)
            self.assertEqual(r["intervals"], [[self.U, self.U]])
        r = self.ok("distance", {"curves": [c, bezier([[0, 0], [2, 4]])]})
        self.assertEqual(r["t"], [self.U, 0.5])
        self.assertEqual(r["distance"], 0.0)
        # Two copies coincide: one overlap, on the param in both.
        self.assertEqual(self.ok("intersect", {"curves": [c, c]}),
                         {"intersections": [], "overlaps": [{"a": [self.U, self.U], "b": [self.U, self.U]}]})
        self.assertEqual(self.ok("intersect", {"curves": [c]}), {"intersections": [], "overlaps": []})
        r = self.ok("intersect", {"curves": [c, bezier([[0, 0], [2, 4]])]})
        self.assertEqual([x["t"] for x in r["intersections"]], [[self.U, 0.5]])
        # Its Bézier form: the one-point bezier on [param, the next double].
        self.assertEqual(self.ok("to_bezier", {"curve": c}),
                         {"curve": {"type": "path", "segments": [bezier([self.P])], "breaks": [self.U, math.nextafter(self.U, math.inf)]}})
        self.assertEqual(self.ok("eval", {"curve": c, "t": [self.U, -7], "derivatives": 1}),
                         {"points": [self.P, self.P], "derivatives": [[[0.0, 0.0], [0.0, 0.0]]]})

    def test_refusals(self):
        c = self.curve()
        self.bad("eval", {"curve": c, "t": [self.U], "curvature": True}, "t[0]", contains="velocity is zero")
        self.bad("length", {"curve": c, "from": 2, "to": self.U}, "from", contains="domain")
        self.bad("param_at_length", {"curve": c, "lengths": [1]}, "lengths[0]")
        self.bad("split", {"curve": c, "t": self.U}, "curve.type")
        self.bad("elevate", {"curve": c, "times": 1}, "curve.type")


class CurveParameterInErrorsTest(CliTest):
    """Errors of piecewise curves quote the parameter the request sent, not a segment's
    own parameter (a path on [10, 30] evaluated at 1e5 is its second segment at 9998)."""

    def path(self, segment):
        return {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), segment], "breaks": [10, 20, 30]}

    def test_eval_far_outside(self):
        bs = {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1e300, 1e300], [2, 0]]}
        lag = {"type": "lagrange", "params": [0, 1, 2], "points": [[0, 0], [1, 1e300], [2, 0]]}
        high = bezier([[i, (i * 7) % 5] for i in range(21)])
        # (segment, t, how the message writes t, the segment's own parameter there)
        for seg, t, sent, local in [(bs, 1e5, "1e+05", "9998"), (lag, 1e5, "1e+05", "19996"),
                                    (high, 1e200, "1e+200", "9.999999999999999e+198"), (bs, 1e200, "1e+200", "9.999999999999999e+198")]:
            for extra in ({}, {"derivatives": 2}, {"curvature": True}):
                err = self.bad("eval", dict({"curve": self.path(seg), "t": [10, t]}, **extra), "t[1]")
                self.assertIn(f"at t = {sent} ", err)
                self.assertNotIn(local, err)

    def test_ranges_and_lengths(self):
        # The fields named, with the user's values, for a path on [10, 30].
        p = self.path({"type": "polyline", "points": [[1, 0], [2, 1], [3, 0]]})
        self.bad("bounds", {"curve": p, "from": 25, "to": 40}, "to", contains="got 40")
        self.bad("length", {"curve": p, "from": 5, "to": 25}, "from", contains="got 5")
        self.bad("length", {"curve": p, "from": 25, "to": 22}, "to", contains="got 22")
        self.bad("param_at_length", {"curve": p, "lengths": [100]}, "lengths[0]", contains="got 100")


# ---------------------------------------------------------------------------------------
# The same conic, queries that needed forms without cancellation (issue 15, section 6):
# its derivative, curvature, arc length over a part of its domain and the parameter at an
# arc length. Closed forms written here: with u = t / (1 - t) and Q = 1 + 2 w u + u^2,
# the conic's offsets from the corner (1, 1) are (u^2, 1) / Q, so that
#   R'(t) = v / W^2, v = (-2 t ((1 - t) + w t), 2 (1 - t) (t + w (1 - t))), W the weight
#   function (1 - t)^2 + 2 w t (1 - t) + t^2 (from the derivatives of t^2 / W and
#   (1 - t)^2 / W, which are 1 - x and 1 - y), and the curvature 4 w W^3 / |v|^3 (the cross
#   product v x v' simplifies to 4 w W);
#   the speed in z = ln u is u |(2 u (1 + w u), -2 (w + u))| / Q^2,
# every term positive: no cancellation at any weight, so 40 digits suffice.

def conic_derivative(w, t):
    w, t = mpf(w), mpf(t)
    W = (1 - t) ** 2 + 2 * w * t * (1 - t) + t ** 2
    return [-2 * t * ((1 - t) + w * t) / W ** 2, 2 * (1 - t) * (t + w * (1 - t)) / W ** 2], W


def conic_curvature(w, t):
    v, W = conic_derivative(w, t)
    v = [x * W ** 2 for x in v]
    return 4 * mpf(w) * W ** 3 / mpmath.norm(v) ** 3


def conic_length(w, t0, t1):
    """The arc length over [t0, t1], integrated in z = ln(t / (1 - t)) with breakpoints at
    the two scales where the speed concentrates (z = -+ln(2w)); an end at 0 or 1 is
    replaced by 60 units beyond them (the tail there is below e^-60)."""
    w = mpf(w)
    def speed(z):
        u = mpmath.exp(z)
        Q = 1 + 2 * w * u + u * u
        return u * mpmath.sqrt((2 * u * (1 + w * u)) ** 2 + (2 * (w + u)) ** 2) / Q ** 2
    edge = abs(mpmath.log(2 * w)) + 60
    z0 = -edge if t0 == 0 else mpmath.log(mpf(t0) / (1 - mpf(t0)))
    z1 = edge if t1 == 1 else mpmath.log(mpf(t1) / (1 - mpf(t1)))
    pts = sorted({z0, z1} | {z for z in (-mpmath.log(2 * w), mpf(0), mpmath.log(2 * w)) if z0 < z < z1})
    # mpmath's target is absolute (about 10^-dps): a length of 1e-100 near the corner is
    # integrated times w, of size 1.
    k = max(w, mpf(1))
    return mpmath.quad(lambda z: k * speed(z), pts) / k


def conic_point_u(w, u):
    """The conic at u = t / (1 - t) (None: t = 1): offsets u^2 / Q and 1 / Q from the corner."""
    if u is None:
        return [mpf(0), mpf(1)]
    Q = 1 + 2 * mpf(w) * u + u * u
    return [1 - u * u / Q, 1 - 1 / Q]


def conic_extremum(w, q, farthest=False):
    """(t, 1 - t, distance) of the point of the conic closest to q (farthest), in mpmath at
    40 digits, in u = t / (1 - t) = e^z: the ends, and the sign changes of the distance's
    slope, (x - qx) x' + (y - qy) y' with x' = -2 u (1 + w u) / Q^2, y' = 2 (w + u) / Q^2
    (every term positive: no cancellation, so 40 digits give 30), found on a grid in z of
    step 2 over the whole scale of the curve (|z| <= ln w + 80; the slope's roots for the
    points asked are ln w or more apart) and bisected 100 times (to 1e-30 in z)."""
    with mpmath.workdps(40):
        w, qx, qy = mpf(w), mpf(q[0]), mpf(q[1])

        def slope(z):
            u = mpmath.exp(z)
            Q = 1 + 2 * w * u + u * u
            return ((1 - qx) - u * u / Q) * (-u * (1 + w * u)) + ((1 - qy) - 1 / Q) * (w + u)

        def dist(u):
            return mpmath.norm([a - b for a, b in zip(conic_point_u(w, u), (qx, qy))])

        L = int(abs(mpmath.log(w))) + 80
        zs = [mpf(k) for k in range(-L, L + 1, 2)]
        gs = [slope(z) for z in zs]
        found = [(dist(mpf(0)), mpf(0)), (dist(None), None)]
        for z0, z1, g0, g1 in zip(zs, zs[1:], gs, gs[1:]):
            if (g0 < 0) != (g1 < 0):
                for _ in range(100):
                    zm = (z0 + z1) / 2
                    if (slope(zm) < 0) == (g0 < 0):
                        z0 = zm
                    else:
                        z1 = zm
                u = mpmath.exp((z0 + z1) / 2)
                found.append((dist(u), u))
        d, u = (max if farthest else min)(found, key=lambda x: x[0])
        if u is None:
            return mpf(1), mpf(0), d
        return u / (1 + u), 1 / (1 + u), d


class ExtremeWeightsFormsTest(CliTest):
    WS = (1e16, 1e30, 1e100, 1e200, 1e300, 1e-16, 1e-100, 1e-200)

    @staticmethod
    def forms(w):
        c = conic(w)
        return [c, {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": c["points"], "weights": c["weights"]}]

    def assert_rel(self, got, want, tol, msg):
        self.assertLessEqual(abs(got - float(want)), tol * abs(float(want)), (got, float(want), msg))

    def test_derivative(self):
        # R' is a sum of positive multiples of the legs: each coordinate to a few eps of
        # itself (1e-14: 16 eps of rounding in the weights' products and the sum). It was
        # lost where the curve hugs its polygon: 0 for 2e-30 at t = 1/2, w = 1e30.
        ts = [0, 0.25, 0.5, 0.75, 1]
        answers = iter(self.ok_jsonl("eval", [{"curve": c, "t": ts, "derivatives": 1} for w in self.WS for c in self.forms(w)]))
        with mpmath.workdps(40):
            for w in self.WS:
                wants = [conic_derivative(w, t)[0] for t in ts]
                for c in self.forms(w):
                    got = next(answers)["derivatives"][0]
                    for t, g, want in zip(ts, got, wants):
                        for k in range(2):
                            if want[k] == 0:
                                self.assertEqual(g[k], 0.0, (w, t, c["type"]))
                            else:
                                self.assert_rel(g[k], want[k], 1e-14, (w, t, k, c["type"]))

    def test_second_derivative(self):
        # R'' over pairs of control points (differences only): (-8, -8) / w at t = 1/2 for
        # w = 1e30 (0 before: the quotient rule subtracts terms of size 1) and -8 w for w =
        # 1e-100 (0 before). Oracle: the quotient rule itself in mpmath with 3 |log10 w| +
        # 60 digits, where its cancellation costs nothing. 1e-13 of the largest coordinate:
        # a few eps of the pairs' terms. At the ends for w = 1e200 and 1e300 R'' ~ w^2
        # is beyond double (refused, naming t).
        def want(w, t):
            with mpmath.workdps(int(3 * abs(math.log10(w))) + 60):
                w, t = mpf(w), mpf(t)
                s = 1 - t
                B, B1, B2 = [s * s, 2 * w * t * s, t * t], [-2 * s, 2 * w * (1 - 2 * t), 2 * t], [mpf(2), -4 * w, mpf(2)]
                W, W1, W2 = sum(B), sum(B1), sum(B2)
                A, A1, A2 = ([sum(b[i] * CONIC_P[i][k] for i in range(3)) for k in range(2)] for b in (B, B1, B2))
                return [(A2[k] * W - A[k] * W2) / W ** 2 - 2 * W1 * (A1[k] * W - A[k] * W1) / W ** 3 for k in range(2)]
        ts = lambda w: [0.25, 0.5, 0.75] if w > 1e100 else [0, 0.25, 0.5, 0.75, 1]
        answers = iter(self.ok_jsonl("eval", [{"curve": c, "t": ts(w), "derivatives": 2} for w in self.WS for c in self.forms(w)]))
        for w in self.WS:
            for c in self.forms(w):
                got = next(answers)["derivatives"][1]
                for t, g in zip(ts(w), got):
                    v = want(w, t)
                    scale = max(abs(x) for x in v)
                    for k in range(2):
                        self.assertLessEqual(abs(g[k] - v[k]), 1e-13 * scale, (w, t, k, c["type"], g, v))
        for w in (1e200, 1e300):
            for c in self.forms(w):
                self.bad("eval", {"curve": c, "t": [0.5, 0], "derivatives": 2}, "t[1]", contains="not representable")

    def test_higher_derivatives(self):
        # R''' .. R^(6) over pairs of control points (detail::pair_derivative's recursion on
        # the pairs' coefficients); the quotient rule gave 0 for R'''(1/2) = O(1/w) at w =
        # 1e30 and for every order >= 3 at w = 1e-100, and lost the cubic's first two
        # coordinates at weights 1, 1e20, 1e-5, 3. Oracle: R = A / W as power series in h
        # at t in mpmath (the polynomials' Taylor coefficients, one division), at k |log10
        # spread| + 60 digits. Tolerance: 1e-13 of the largest coordinate plus the change
        # that a relative perturbation of 2^-50 in each weight makes (mpmath again): where
        # R^(k) is ill-conditioned in the weights (R^(5) at the ends of the conic [1, w, 1]
        # for w <= 1e-16: its chord component vanishes at w = 0 by an accident of the
        # weights 1, 1), no double computation from the weights does better.
        # At w = 1e100 R^(k) ~ w^k at the ends is beyond double (refused, as R'' at 1e200).
        ends, inside = [0, 0.25, 0.5, 0.75, 1], [0.25, 0.5, 0.75]
        cases = [(CONIC_P, [1, w, 1], ends) for w in (1e8, 1e16, 1e30, 1e-16, 1e-100)] + [(CONIC_P, [1, 1e100, 1], inside)]
        cases += [([[0, 0, 0], [1, 2, 0], [3, 1, 1], [4, 0, -1]], [1, 1e20, 1e-5, 3], ends),
                  ([[0, 0], [1, 2], [3, 1], [4, 0]], [2, 1e-12, 1e-12, 1], ends)]
        K = 6

        def series_derivatives(P, w, t):
            n, t = len(P) - 1, mpf(t)
            A = [[mpf(0)] * (n + 1) for _ in P[0]]
            W = [mpf(0)] * (n + 1)
            for i in range(n + 1):
                b = [mpf(mpmath.binomial(n, i))]  # B_i(t + h) as a polynomial in h
                for f in [(t, 1)] * i + [(1 - t, -1)] * (n - i):
                    b = [(b[m] if m < len(b) else 0) * f[0] + (b[m - 1] * f[1] if m else 0) for m in range(len(b) + 1)]
                for m in range(n + 1):
                    W[m] += mpf(w[i]) * b[m]
                    for d in range(len(P[0])):
                        A[d][m] += mpf(w[i]) * P[i][d] * b[m]
            out = []
            for a in A:
                r = []
                for k in range(K + 1):
                    r.append(((a[k] if k <= n else 0) - sum(W[m] * r[k - m] for m in range(1, min(k, n) + 1))) / W[0])
                out.append([r[k] * mpmath.factorial(k) for k in range(K + 1)])
            return [[c[k] for c in out] for k in range(K + 1)]

        # The NURBS forms: one span, and two spans joined at an n-fold knot at 1 whose second
        # span [1, 2] is the curve itself (points P[:-1] + P, weights w[:-1] + w, the
        # first span ending at P[0]), evaluated at 1 + t.
        requests = []
        for P, w, ts in cases:
            n = len(P) - 1
            requests.append({"curve": {"type": "rational_bezier", "points": P, "weights": w}, "t": ts, "derivatives": K})
            requests.append({"curve": {"type": "nurbs", "degree": n, "knots": [0] * (n + 1) + [1] * (n + 1), "points": P, "weights": w},
                             "t": ts, "derivatives": K})
            requests.append({"curve": {"type": "nurbs", "degree": n, "knots": [0] * (n + 1) + [1] * n + [2] * (n + 1),
                                       "points": P[:-1] + P, "weights": w[:-1] + w}, "t": [1 + t for t in ts[1:]], "derivatives": K})
        answers = iter(self.ok_jsonl("eval", requests))
        for P, w, ts in cases:
            spread = max(w) / min(w)
            with mpmath.workdps(int(K * abs(math.log10(spread))) + 60):
                wants = [series_derivatives(P, w, t) for t in ts]
                # The change from relative perturbations of 2^-50 in the weights (first order).
                sens = [[[mpf(0)] * len(P[0]) for _ in range(K + 1)] for _ in ts]
                for i in range(len(w)):
                    eps = mpf(10) ** -40
                    wp = list(map(mpf, w))
                    wp[i] *= 1 + eps
                    for it, t in enumerate(ts):
                        d = series_derivatives(P, wp, t)
                        for k in range(K + 1):
                            for c in range(len(P[0])):
                                sens[it][k][c] += abs(d[k][c] - wants[it][k][c]) / eps * mpf(2) ** -50
            for form in ("rational_bezier", "nurbs", "nurbs, two spans"):
                got = next(answers)["derivatives"]
                for it, t in enumerate(ts):
                    if form == "nurbs, two spans":
                        if it == 0:
                            continue
                        g_it = it - 1
                    else:
                        g_it = it
                    for k in range(3, K + 1):
                        want = wants[it][k]
                        tol = 1e-13 * float(max(abs(x) for x in want)) + float(max(sens[it][k]))
                        for c in range(len(P[0])):
                            self.assertLessEqual(abs(got[k - 1][g_it][c] - float(want[c])), tol, (form, w, t, k, c, got[k - 1][g_it], want))

    def test_curvature(self):
        # The curvature, 4 w W^3 / |v|^3: 1.4e30 at the corner for w = 1e30 (refused as a
        # zero velocity before), 1.4e-100 at t = 1/2 for w = 1e-100 (-0.0 before: the
        # part of R'' normal to the chord was rounded away). 1e-13: a few eps of the
        # numerator's and the speed's terms, cubed.
        ts = [0.25, 0.5, 0.75]
        answers = iter(self.ok_jsonl("eval", [{"curve": c, "t": ts, "curvature": True} for w in self.WS for c in self.forms(w)]))
        with mpmath.workdps(40):
            for w in self.WS:
                for c in self.forms(w):
                    got = next(answers)["curvature"]
                    for t, g in zip(ts, got):
                        self.assert_rel(g, conic_curvature(w, t), 1e-13, (w, t, c["type"]))
            # At the ends the curvature is 1 / (2 w^2): 5e199 for w = 1e-100; 5e399 for
            # w = 1e-200 is beyond double (refused, naming t); 5e-401 for w = 1e200
            # underflows to 0.
            self.assert_rel(self.ok("eval", {"curve": conic(1e-100), "t": [0], "curvature": True})["curvature"][0],
                            conic_curvature(1e-100, 0), 1e-13, "end")
            self.bad("eval", {"curve": conic(1e-200), "t": [0.5, 0], "curvature": True}, "t[1]", contains="not representable")
            self.assertEqual(self.ok("eval", {"curve": conic(1e200), "t": [1], "curvature": True})["curvature"], [0.0])

    def test_length_of_a_part(self):
        # Over [1/4, 3/4] the curve stays within 1/w of the corner: length 2.1e-30 at
        # w = 1e30 (0 before: the portion's control points round to the corner), and
        # across the legs' ends. 1e-12 relative: the quadrature's target (docs/accuracy.md).
        cases = [(w, t0, t1) for w in (1e16, 1e30, 1e300, 1e-100, 1e-200) for t0, t1 in ((0.25, 0.75), (0, 0.3), (1e-300, 1))]
        # One process for every request (each a process start less).
        answers = iter(self.ok_jsonl("length", [{"curve": c, "from": t0, "to": t1} for w, t0, t1 in cases for c in self.forms(w)]))
        with mpmath.workdps(25):  # the integrand has no cancellation; 1e-12 is asked
            for w, t0, t1 in cases:
                want = conic_length(w, t0, t1)
                for c in self.forms(w):
                    got = next(answers)["length"]
                    self.assert_rel(got, want, 1e-12, (w, t0, t1, c["type"]))

    def test_param_at_length(self):
        # The arc length up to each t returned is the one asked for within 1e-12 of the
        # length (the quadrature's target), or no double is: near t = 1 the second leg is
        # passed within 1e-100 of 1, and t = 1 answers 1.5 (the arc lengths at the doubles
        # either side of t bracket it). Before, lengths[2] = 1 gave t = 1 (arc length 2,
        # where t = 1/2 has 1 - 1e-100) at w >= 1e100.
        with mpmath.workdps(25):
            for w in (1e16, 1e100, 1e300):
                total = conic_length(w, 0, 1)
                ss = [0.25, 0.5, 1.0, 1.5, 1.75]
                arc_to = {0.0: mpf(0), 1.0: total}  # t -> the arc length from 0 (both forms mostly agree on t)
                def arc(t):
                    if t not in arc_to:
                        arc_to[t] = conic_length(w, 0, t)
                    return arc_to[t]
                for c in self.forms(w):
                    ts = self.ok("param_at_length", {"curve": c, "lengths": ss})["t"]
                    for s, t in zip(ss, ts):
                        tol = 1e-12 * float(total)
                        if abs(arc(t) - s) <= tol:
                            continue
                        # Else no double may do better: s lies between the arc lengths at the
                        # doubles either side, neither of which is within the tolerance.
                        lo = arc(math.nextafter(t, 0)) if t > 0 else mpf(0)
                        hi = arc(math.nextafter(t, 1)) if t < 1 else total
                        self.assertTrue(lo <= s <= hi and abs(lo - s) > tol and abs(hi - s) > tol,
                                        (w, c["type"], s, t, float(arc(t)), float(lo), float(hi)))

    def test_project_parameter(self):
        # The closest (farthest) point's parameter, not only its distance: where the curve
        # passes the corner within 1/w of it, the distance ties to rounding over most of
        # [0, 1], and its extremum is where the curve's direction is normal to the way to
        # q (t = 0.387 for q = (1.5, 1.2) at every huge w; 0.5 or 4e-12 before).
        # Reference: conic_extremum (60 digits). Parameters within 1/2 of 0 to 1e-12
        # relative (the bisection ends on neighbouring doubles; 1e-12 allows the rounding
        # of the slope's sign near its root, where the distance is flat); within 1/2 of 1,
        # 1 - t to 1e-12 relative plus two ulps of 1 (no double is nearer: t = 1 - 1e-40
        # answers 1 - 2^-53 or 1). Not asked: q level with the corner, (1.5, 1), whose
        # extremum moves by 1e-5 relative when q moves by one ulp (the curve's tiny
        # offset from the leg decides it).
        cases = [([1.5, 1.2], False), ([1, 1.5], False), ([2, 0.5], False), ([0.3, 0.3], True)]
        ws = (1e16, 1e30, 1e300)
        reqs = [{"curve": c, "point": q, "farthest": far} for w in ws for c in self.forms(w) for q, far in cases]
        got = iter(self.ok_jsonl("project", reqs))
        for w in ws:
            for c in self.forms(w):
                for q, far in cases:
                    r = next(got)
                    t, s, d = conic_extremum(w, q, far)
                    msg = (w, c["type"], q, far, r, float(t))
                    if t <= 0.5:
                        self.assertLessEqual(abs(r["t"] - float(t)), 1e-12 * float(t), msg)
                    else:
                        self.assertLessEqual(abs((1 - r["t"]) - float(s)), 1e-12 * float(s) + 2 * 2 ** -53, msg)
                    # The distance to 2 eps of itself (two roundings of a sum of squares),
                    # the point within 1e-15 of the curve's (the conic's at the true t).
                    self.assertLessEqual(abs(r["distance"] - float(d)), 4.5e-16 * float(d), msg)
                    want = conic_point_u(w, t / s if s > 0 else None)
                    self.assertLessEqual(math.dist(r["point"], [float(x) for x in want]), 1e-15, msg)

    def test_scaled_circle(self):
        # The NURBS circle of radius 2 with every weight times 1e300 or 1e-300 (the same
        # curve): curvature 1/2 everywhere, the first quarter pi long.
        s = math.sqrt(0.5)
        P = [[2, 0], [2, 2], [0, 2], [-2, 2], [-2, 0], [-2, -2], [0, -2], [2, -2], [2, 0]]
        for f in (1e300, 1e-300):
            c = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                 "points": P, "weights": [f * x for x in [1, s, 1, s, 1, s, 1, s, 1]]}
            got = self.ok("eval", {"curve": c, "t": [0, 0.1, 0.3, 0.9], "curvature": True})["curvature"]
            self.assert_close(got, [0.5] * 4, 1e-15)
            # 1e-12 relative: the quadrature's target.
            self.assert_rel(self.ok("length", {"curve": c, "from": 0, "to": 0.25})["length"], math.pi, 1e-12, f)


def power_form(P, weights=None):
    """The homogeneous coordinates (X, Y, W) of a (rational) Bézier curve as power-basis
    polynomials in s (lowest degree first), exact in mpf."""
    n = len(P) - 1
    w = weights or [1] * (n + 1)
    out = [[mpf(0)] * (n + 1) for _ in range(3)]
    for i in range(n + 1):
        for j in range(n - i + 1):  # C(n, i) s^i (1 - s)^(n - i), expanded
            c = math.comb(n, i) * math.comb(n - i, j) * (-1) ** j * mpf(w[i])
            for k, v in enumerate((P[i][0], P[i][1], 1)):
                out[k][i + j] += c * mpf(v)
    return out


def poly_mul(a, b):
    r = [mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def poly_sum(*ps):
    r = [mpf(0)] * max(len(p) for p in ps)
    for p in ps:
        for i, x in enumerate(p):
            r[i] += x
    return r


def poly_at(p, s):
    return sum(x * s ** i for i, x in enumerate(p))


def conic_crossings(w, P, weights=None):
    """Where the conic [1, w, 1] meets the (rational) Bézier curve with points P: sorted
    (t, s, point), at 2 log10(w) + 80 digits. The conic is the branch tau1 >= 0 of its
    implicit equation in the barycentric coordinates of its control triangle, tau0 = 1 -
    y, tau1 = x + y - 1, tau2 = 1 - x: tau1^2 = 4 w^2 tau0 tau2; substituted with the
    other curve's homogeneous coordinates, a polynomial in s; each real root in [0, 1] on
    the branch gives the point, and the conic's t from t / (1 - t) = sqrt(tau2 / tau0)."""
    with mpmath.workdps(int(2 * math.log10(w)) + 80):
        X, Y, W = power_form(P, weights)
        w = mpf(w)
        t1 = poly_sum(X, Y, [-c for c in W])
        f = poly_sum(poly_mul(t1, t1), [-4 * w * w * c for c in poly_mul(poly_sum(W, [-c for c in X]), poly_sum(W, [-c for c in Y]))])
        while f[-1] == 0:
            f.pop()
        out = []
        for r in mpmath.polyroots(f[::-1], maxsteps=400, extraprec=1000):
            if abs(mpmath.im(r)) > mpf(10) ** -40:
                continue
            s = mpmath.re(r)
            if not 0 <= s <= 1:
                continue
            x, y = poly_at(X, s) / poly_at(W, s), poly_at(Y, s) / poly_at(W, s)
            if x + y < 1 or x > 1 or y > 1:
                continue  # the other branch
            u = mpmath.sqrt((1 - x) / (1 - y)) if y < 1 else mpmath.inf
            out.append((mpf(1) if u == mpmath.inf else u / (1 + u), s, (x, y)))
        return sorted(out)


class ExtremeWeightsIntersectTest(CliTest):
    """intersect with the conic at weights 1e8 .. 1e100 (and its NURBS form), against
    lines, a cubic, a rational quadratic and another extreme conic: every crossing found
    (none was at 1e16: a leg is passed within 1e-16 of a parameter end), where it is.
    Oracle: the conic's implicit equation (conic_crossings). A parameter is right when it
    is within 1e-13 of the true one relative, or within 2 ulp of 1 (a leg passed within
    1e-30 of t = 1 has no double of its own: t = 1 is the nearest), or when the curve at it
    is within 2e-15 of the true point (a crossing within 1e-9 of the corner, where t moves
    the point by 1 / (w t^2): the parameter is known to what the coordinates resolve);
    the point within 2e-15."""

    WS = (1e8, 1e16, 1e30, 1e100)
    OTHERS = {
        "y = 1/2": ([[-1, 0.5], [2, 0.5]], None),
        "x = 1/2": ([[0.5, -1], [0.5, 2]], None),
        "y = x (through the corner)": ([[0, 0], [2, 2]], None),
        "x + y = 2 - 1e-3 (both legs)": ([[3 - 1e-3, -1], [-1, 3 - 1e-3]], None),
        "y = 1 - 1e-5 (near the corner)": ([[-1, 1 - 1e-5], [2, 1 - 1e-5]], None),
        "cubic": ([[0.3, -0.2], [1.6, 2.0], [-0.4, 0.4], [1.2, 1.3]], None),
        "rational": ([[1.4, 0], [0, 0.6], [1.4, 1.2]], [1, 0.5, 1]),
    }

    def check(self, w, got, want, a_at, b_at, msg):
        self.assertEqual(len(got), len(want), (msg, got, want))
        for g, (t, s, p) in zip(got, want):
            self.assertEqual(g["kind"], "crossing", msg)
            for k in range(2):
                self.assertLessEqual(abs(g["point"][k] - p[k]), 2e-15, (msg, g, p))
            for x, x_true, at in ((g["t"][0], t, a_at), (g["t"][1], s, b_at)):
                err = abs(mpf(x) - x_true)
                back = max(abs(v - q) for v, q in zip(at(x), p))
                self.assertTrue(err <= 1e-13 * x_true or err <= 4.5e-16 or back <= 2e-15, (msg, g, float(x_true), float(err)))

    def test_against_curves(self):
        forms = lambda w: [conic(w), {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": CONIC_P, "weights": [1, w, 1]}]
        other = lambda P, wt: bezier(P) if wt is None else {"type": "rational_bezier", "points": P, "weights": wt}
        reqs, cases = [], []
        for w in self.WS:
            for name, (P, wt) in self.OTHERS.items():
                for c in forms(w):
                    reqs.append({"curves": [c, other(P, wt)]})
                    cases.append((w, name, P, wt, False))
                reqs.append({"curves": [other(P, wt), conic(w)]})  # the other way round
                cases.append((w, name, P, wt, True))
            # Another extreme conic: its leg x = 1/2 crosses the first one's leg y = 1.
            Q = [[0.5, 0.3], [0.5, 1.5], [-0.5, 1.5]]
            reqs.append({"curves": [conic(w), {"type": "rational_bezier", "points": Q, "weights": [1, w, 1]}]})
            cases.append((w, "extreme conic", Q, [1, w, 1], False))
        answers = self.ok_jsonl("intersect", reqs)
        oracle = {}
        for (w, name, P, wt, swapped), r in zip(cases, answers):
            self.assertEqual(r["overlaps"], [], (w, name))
            if (w, name) not in oracle:
                oracle[w, name] = conic_crossings(w, P, wt)
            with mpmath.workdps(int(2 * math.log10(w)) + 80):
                want = oracle[w, name]
                X, Y, W = power_form(P, wt)
                a_at = lambda t: conic_point(w, t)
                b_at = lambda s: [poly_at(X, mpf(s)) / poly_at(W, mpf(s)), poly_at(Y, mpf(s)) / poly_at(W, mpf(s))]
                if swapped:  # sorted by the other curve's parameter, its point
                    want = sorted((s, t, p) for t, s, p in want)
                    a_at, b_at = b_at, a_at
                self.check(w, r["intersections"], want, a_at, b_at, (w, name, swapped))

    def test_work_limit_counts_the_parts(self):
        # A NURBS of 2001 quadratic spans with weights 1, 1e300, 1 each: about 5e7 units
        # of work on its pieces, but each span is intersected through a few hundred tame
        # parts, so its self-intersections would take hours: refused with the figure.
        n = 2001
        pts = [[k, k % 2] for k in range(2 * n + 1)]
        knots = [0, 0, 0] + [j for j in range(1, n) for _ in (0, 1)] + [n, n, n]
        c = {"type": "nurbs", "degree": 2, "knots": knots, "points": pts, "weights": [1 if k % 2 == 0 else 1e300 for k in range(2 * n + 1)]}
        self.bad("intersect", {"curves": [c]}, "curves[0]", contains="units of work")

    def test_self_and_identical(self):
        # A path: the conic, then a segment back across its leg x = 1 (one self-crossing
        # at y = 3/4 on the segment, t within 1 / w of 0 on the conic); the conic against
        # itself: one overlap, the whole curve.
        reqs = []
        for w in self.WS:
            seg = [[0, 1], [2, 0.5]]
            reqs.append({"curves": [{"type": "path", "segments": [conic(w), bezier(seg)]}]})
            reqs.append({"curves": [conic(w), conic(w)]})
        answers = iter(self.ok_jsonl("intersect", reqs))
        for w in self.WS:
            r = next(answers)
            with mpmath.workdps(int(2 * math.log10(w)) + 80):
                (t, s, p), = [x for x in conic_crossings(w, [[0, 1], [2, 0.5]]) if x[1] > 0]
                want = [(t, 1 + s, p)]
                self.check(w, r["intersections"], want, lambda x: conic_point(w, x),
                           lambda x: [2 * (mpf(x) - 1), 1 - (mpf(x) - 1) / 2], ("path", w))
            self.assertEqual(next(answers), {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 1.0]}]}, w)

    def test_against_its_control_polygon(self):
        # The conic against its own control polygon (a polyline, and the same as a path of
        # two segments). The conic meets the polygon only at its ends (x = 1 - t^2 / W:
        # on the leg x = 1 at t = 0 alone) but runs along it: its farthest point from the
        # polygon is at t = 1/2, 1 / (2 (1 + w)) from both legs (computed here in mpmath),
        # under the meeting distance 1e-10 of the size (sqrt 2) from w = 1e10 up: within
        # that distance the whole conic traces the whole polygon, one overlap (docs/cli.md:
        # curves within 1e-10 of their size meet; overlaps joined across pieces and
        # segments). From w = 1e10 it was one "crossing" near the corner: the overlaps
        # along the two legs ended at the corner, several tame parts apart on the conic.
        # From w = 1 / (2e-10 sqrt 2) - 1 = 3.54e9 on; below 7.07e9 the polygon's corner
        # lies beyond the distance (sqrt 2 times the conic's, 1.41e-10 at 5e9) while the
        # conic lies within it: there it was one crossing until session 14.
        polygon = {"type": "polyline", "points": CONIC_P}
        path = {"type": "path", "segments": [bezier(CONIC_P[:2]), bezier(CONIC_P[1:])]}
        ws = (3.6e9, 4e9, 5e9, 7e9, 1e10, 1e11, 1e12, 1e16, 1e30, 1e100, 1e300)
        reqs = [{"curves": [c, p]} for w in ws for c in ExtremeWeightsFormsTest.forms(w) for p in (polygon, path)]
        reqs += [{"curves": [polygon, conic(w)]} for w in ws]
        answers = iter(self.ok_jsonl("intersect", reqs))
        with mpmath.workdps(int(2 * math.log10(max(ws))) + 40):
            for w in ws:
                # The largest distance of the conic from the polygon, at t = 1/2 by symmetry
                # (1 - x = t^2 / W grows with t on [0, 1/2]).
                far = 1 - conic_point(w, mpf(1) / 2)[0]
                self.assertLess(far, mpf("1e-10") * mpmath.sqrt(2), w)
                for _ in range(4):
                    self.assertEqual(next(answers), {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 2.0]}]}, w)
            for w in ws:
                self.assertEqual(next(answers), {"intersections": [], "overlaps": [{"a": [0.0, 2.0], "b": [0.0, 1.0]}]}, w)
    @staticmethod
    def polygon_oracle(w, tol):
        """What the contract makes of the conic [1, w, 1] against its control polygon,
        derived in mpmath (at the caller's precision) from exact point-to-segment distances: the largest
        distance of the conic from the polygon, the distance of the polygon's corner from
        the conic (the farthest point of the legs from it), the stretch t in [0, t1] along
        which the conic stays within tol of the polygon from its end t = 0 (the same at
        t = 1: the conic is symmetric under t -> 1 - t, x <-> y), and whether the conic stays on the inner side of both legs (no crossing) with its
        end tangents along the legs (touches). The conic is searched in z = ln(t / (1 - t))
        (t = 1 / (1 + e^-z)), where its points spread evenly enough to sample."""
        w = mpf(w)
        legs = [(mpf(1), mpf(0)), (mpf(1), mpf(1)), (mpf(0), mpf(1))]
        def seg_dist(p, a, b):
            v = (b[0] - a[0], b[1] - a[1])
            u = ((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / (v[0] ** 2 + v[1] ** 2)
            u = min(max(u, mpf(0)), mpf(1))
            return mpmath.hypot(p[0] - a[0] - u * v[0], p[1] - a[1] - u * v[1])
        def at(z):
            return conic_point(w, 1 / (1 + mpmath.exp(-z)))
        def from_polygon(z):
            p = at(z)
            return min(seg_dist(p, legs[0], legs[1]), seg_dist(p, legs[1], legs[2]))
        def from_corner(z):
            p = at(z)
            return mpmath.hypot(p[0] - 1, p[1] - 1)
        L = mpmath.log(2 * w) + 40  # the conic within e^-40 of its ends beyond
        zs = [-L + 2 * L * k / 240 for k in range(241)]
        def extreme(f, sign):
            k = max(range(len(zs)), key=lambda i: sign * f(zs[i]))
            lo, hi = zs[max(k - 1, 0)], zs[min(k + 1, len(zs) - 1)]
            g = (mpmath.sqrt(5) - 1) / 2
            for _ in range(80):  # golden section on the bracket
                a, b = hi - g * (hi - lo), lo + g * (hi - lo)
                if sign * f(a) > sign * f(b):
                    hi = b
                else:
                    lo = a
            return (lo + hi) / 2
        z_far = extreme(from_polygon, 1)
        far = from_polygon(z_far)
        corner = from_corner(extreme(from_corner, -1))
        t1 = None
        if far > tol:  # where the conic leaves the distance, from its end t = 0
            lo, hi = -L, z_far
            for _ in range(200):
                m = (lo + hi) / 2
                lo, hi = (m, hi) if from_polygon(m) <= tol else (lo, m)
            t1 = 1 / (1 + mpmath.exp(-lo))
        inner = all(min(1 - x, 1 - y) > 0 for x, y in (at(z) for z in zs[1:-1]))
        d0, _ = conic_derivative(w, 0)
        d1, _ = conic_derivative(w, 1)
        # Sines of the angles between the end tangents and the legs there (0, 1), (-1, 0).
        tangent = abs(d0[0]) / mpmath.hypot(*d0) <= 1e-6 and abs(d1[1]) / mpmath.hypot(*d1) <= 1e-6
        return far, corner, t1, inner, tangent

    def test_sweep_against_its_control_polygon(self):
        # Below w = 3.54e9 the conic leaves the meeting distance tol (1e-10 of the size
        # sqrt 2) near the corner; the polygon's corner lies farther still. So no whole
        # monotone arc of either curve (the conic is one, each leg one) lies within the
        # distance of the other: no overlap (docs/cli.md). What is within it is a stretch
        # from each common end (t in [0, t1] on the conic, most of a leg from 1e6 up), where
        # the curves meet at the end point (distance 0) and part without crossing (the conic
        # on the inner side of both legs): one near region each, a touch at its closest
        # approach, the end point itself, tangent (the end tangents run along the legs).
        # Expected answers derived here (polygon_oracle), for the rational and NURBS forms,
        # the polygon as a polyline and as a path, either order. Before session 15: from
        # 1e3 the polygon first lost the touch at (0, 1); 5e4 .. 1e6 added touches inside
        # the stretches, 2e6 .. 1e8 partial overlaps, 1e7 .. 3e9 crossings near the corner.
        polygon = {"type": "polyline", "points": CONIC_P}
        path = {"type": "path", "segments": [bezier(CONIC_P[:2]), bezier(CONIC_P[1:])]}
        ws = (1e3, 2e3, 1e4, 5e4, 1e5, 1e6, 2e6, 1e7, 1e8, 5e8, 1e9, 3e9, 3.6e9)
        reqs = []
        for w in ws:
            for c in ExtremeWeightsFormsTest.forms(w):
                for p in (polygon, path):
                    reqs += [{"curves": [c, p]}, {"curves": [p, c]}]
        answers = iter(self.ok_jsonl("intersect", reqs))
        for w in ws:
            # 50 digits beyond the conic's distance from its ends at the search's ends
            # (about e^-80 / w^2, see polygon_oracle).
            with mpmath.workdps(int(2 * math.log10(w)) + 90):
                tol = mpf("1e-10") * mpmath.sqrt(2)
                far, corner, t1, inner, tangent = self.polygon_oracle(w, tol)
                # A leg wholly within the distance of the conic would need its corner within
                # it, which lies farther than the conic's farthest point: the conic (one
                # monotone arc) decides.
                self.assertGreater(corner, far, w)
                if far <= tol:  # the whole conic within the distance: one overlap
                    want = ({"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 2.0]}]},
                            {"intersections": [], "overlaps": [{"a": [0.0, 2.0], "b": [0.0, 1.0]}]})
                else:
                    self.assertTrue(inner and tangent and t1 < mpf(1) / 2, (w, t1))
                    ends = [{"t": [0.0, 0.0], "point": [1.0, 0.0], "kind": "tangent"},
                            {"t": [1.0, 2.0], "point": [0.0, 1.0], "kind": "tangent"}]
                    want = ({"intersections": ends, "overlaps": []},
                            {"intersections": [ends[0], {**ends[1], "t": [2.0, 1.0]}], "overlaps": []})
                for k in range(4):
                    got = next(answers), next(answers)
                    self.assertEqual(got[0], want[0], (w, k, float(far), t1 and float(t1)))
                    self.assertEqual(got[1], want[1], (w, k, "polygon first", float(far), t1 and float(t1)))

    def test_small_weights_against_its_control_polygon(self):
        # The conic [1, w, 1] off its polygon everywhere but at its ends: 1 - x = t^2 / W
        # and 1 - y = (1 - t)^2 / W, W = (1 - t)^2 + 2 w t (1 - t) + t^2 > 0, vanish at
        # t = 0 and 1 only, and its tangents there run along the legs (P1 - P0, P2 - P1):
        # two touches, at the ends, for small weights (the farthest distance from the
        # polygon, 1 / (2 (1 + w)), far beyond the meeting distance). Rational and NURBS
        # forms, polyline and path, either order. (w = 1e3 .. 3.6e9:
        # test_sweep_against_its_control_polygon.)
        polygon = {"type": "polyline", "points": CONIC_P}
        path = {"type": "path", "segments": [bezier(CONIC_P[:2]), bezier(CONIC_P[1:])]}
        ws = (1e-12, 1e-6, 0.5, 1, 10, 500)
        reqs = [{"curves": [c, p]} for w in ws for c in ExtremeWeightsFormsTest.forms(w) for p in (polygon, path)]
        reqs += [{"curves": [polygon, conic(w)]} for w in ws]
        answers = iter(self.ok_jsonl("intersect", reqs))
        ends = [{"t": [0.0, 0.0], "point": [1.0, 0.0], "kind": "tangent"}, {"t": [1.0, 2.0], "point": [0.0, 1.0], "kind": "tangent"}]
        for w in ws:
            for _ in range(4):
                self.assertEqual(next(answers), {"intersections": ends, "overlaps": []}, w)
        for w in ws:
            self.assertEqual(next(answers), {"intersections": [{**ends[0]}, {**ends[1], "t": [2.0, 1.0]}], "overlaps": []}, w)

    def test_square_and_its_diagonal(self):
        # A NURBS square of four quadratic spans with weights 1, w, 1 at its corners (each
        # span the conic, turned) against its diagonal from (-2, -2) to (2, 2): two
        # crossings, at t = 1/2 of the first and third spans by symmetry, the points
        # +-conic(w, 1/2) (mpmath), within 1 / (2 (1 + w)) of the corners. At w = 1e20 the
        # first was 1.03e-13 from the corner (the chord of the tame parts near the corner
        # cut it); the point within 2e-15 now, the parameter to what the coordinates
        # resolve (the curve at it within 2e-15 of the point), the diagonal's to 1e-15.
        corners = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]]
        ws = (1e8, 1e16, 1e20, 1e30, 1e100)
        square = lambda w: {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4], "points": corners,
                            "weights": [1, w] * 4 + [1]}
        answers = self.ok_jsonl("intersect", [{"curves": [square(w), bezier([[-2, -2], [2, 2]])]} for w in ws])
        for w, r in zip(ws, answers):
            self.assertEqual(r["overlaps"], [], w)
            self.assertEqual(len(r["intersections"]), 2, (w, r))
            with mpmath.workdps(int(2 * math.log10(w)) + 40):
                for g, span, sign in zip(r["intersections"], (0, 2), (1, -1)):
                    p = [sign * x for x in conic_point(w, mpf(1) / 2)]
                    self.assertEqual(g["kind"], "crossing", w)
                    for k in range(2):
                        self.assertLessEqual(abs(g["point"][k] - p[k]), 2e-15, (w, g, p))
                    back = [sign * x for x in conic_point(w, mpf(g["t"][0]) - span)]
                    self.assertLessEqual(max(abs(b - q) for b, q in zip(back, p)), 2e-15, (w, g))
                    self.assertLessEqual(abs(g["t"][1] - (p[0] + 2) / 4), 1e-15, (w, g))


if __name__ == "__main__":
    test_cli.BINARY = sys.argv.pop(1)
    unittest.main()
