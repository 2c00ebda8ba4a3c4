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


if __name__ == "__main__":
    test_cli.BINARY = sys.argv.pop(1)
    unittest.main()
