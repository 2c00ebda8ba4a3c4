#!/usr/bin/python3
"""Black-box tests of the geometric queries (issue 8): project (nearest and farthest,
ties, intervals), length, param_at_length, eval's curvature, area, features and distance,
against closed forms and an independent high-precision oracle at test time: python3-mpmath
(curves evaluated by de Casteljau / de Boor in 30-digit arithmetic, integrals by mpmath.quad,
extrema by dense sampling refined with mpmath.findroot). Degenerate curves too: coincident
control points, zero length, cusps, huge and tiny coordinates.

Usage: test_queries.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import random
import sys
import unittest

import mpmath
from mpmath import mp, mpf

import test_cli
from test_cli import CliTest, bezier, run

mp.dps = 30

QUARTER = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, math.sqrt(0.5), 1]}


def circle(r=1.0, cx=0.0, cy=0.0, ccw=True):
    """A full circle as a path of four exact rational quarter arcs (domain [0, 4])."""
    w = [1, math.sqrt(0.5), 1]
    corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    if not ccw:
        corners = [(x, -y) for x, y in corners]
    segs = []
    for i in range(4):
        pts = [[cx + r * x, cy + r * y] for x, y in corners[2 * i:2 * i + 3]]
        segs.append({"type": "rational_bezier", "points": pts, "weights": w})
    return {"type": "path", "segments": segs}


# ---------------------------------------------------------------------------------------
# The oracle: curve pieces as functions of the parameter with analytic derivatives,
# written independently of the library. They compute in the type of their argument: a
# Python float for dense sampling, an mpf (30 digits) for references.

def bern(P, t):
    """sum_i B(i,n)(t) P_i for points P (lists), Bernstein polynomials written out."""
    n = len(P) - 1
    B = [math.comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]
    return [sum(B[i] * P[i][k] for i in range(n + 1)) for k in range(len(P[0]))]


def hodograph(P):
    n = len(P) - 1
    if n == 0:
        return [[0.0] * len(P[0])]
    return [[n * (y - x) for x, y in zip(P[i], P[i + 1])] for i in range(n)]


class BezierPiece:
    def __init__(self, P, w=None):
        self.dim = len(P[0])
        w = w or [1.0] * len(P)
        self.H = [[wi * x for x in p] + [wi] for p, wi in zip(P, w)]  # homogeneous
        self.dH = hodograph(self.H)
        self.ddH = hodograph(self.dH)

    def f(self, t):
        h = bern(self.H, t)
        return [x / h[-1] for x in h[:-1]]

    def df(self, t, k=1):
        h, d = bern(self.H, t), bern(self.dH, t)
        c = [x / h[-1] for x in h[:-1]]
        d1 = [(d[i] - d[-1] * c[i]) / h[-1] for i in range(self.dim)]
        if k == 1:
            return d1
        dd = bern(self.ddH, t)
        return [(dd[i] - 2 * d[-1] * d1[i] - dd[-1] * c[i]) / h[-1] for i in range(self.dim)]


def deboor(U, p, P, t):
    n = len(P)
    span = p
    while span < n - 1 and t >= U[span + 1]:
        span += 1
    d = [list(P[j + span - p]) for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = j + span - p
            a = (t - U[i]) / (U[i + p + 1 - r] - U[i])
            d[j] = [(1 - a) * x + a * y for x, y in zip(d[j - 1], d[j])]
    return d[p]


class SplinePiece:
    """One knot span [a, b] of a B-spline: de Boor for the point, the derivative spline
    (control points p (P_(i+1) - P_i) / (U_(i+p+1) - U_(i+1)), knots U[1:-1]) for c'."""

    def __init__(self, U, p, P):
        self.U, self.p, self.P = U, p, P
        self.dim = len(P[0])
        self.deriv = None
        if p >= 1:
            Q = [[p * (y - x) / (U[i + p + 1] - U[i + 1]) for x, y in zip(P[i], P[i + 1])] for i in range(len(P) - 1)]
            self.deriv = SplinePiece(U[1:-1], p - 1, Q)

    def f(self, t):
        return deboor(self.U, self.p, self.P, t)

    def df(self, t, k=1):
        if self.deriv is None:
            return [0.0] * self.dim
        return self.deriv.f(t) if k == 1 else self.deriv.df(t, k - 1)


class LinePiece:
    def __init__(self, a, b, t0):
        self.a, self.b, self.t0, self.dim = a, b, t0, len(a)

    def f(self, t):
        return [x + (t - self.t0) * (y - x) for x, y in zip(self.a, self.b)]

    def df(self, t, k=1):
        return [y - x for x, y in zip(self.a, self.b)] if k == 1 else [0.0] * self.dim


class Mapped:
    """A piece on [0, 1] seen on the break interval [a, b] of a path."""

    def __init__(self, piece, a, b):
        self.piece, self.a, self.b, self.dim = piece, a, b, piece.dim

    def f(self, u):
        return self.piece.f((u - self.a) / (self.b - self.a))

    def df(self, u, k=1):
        return [x / (self.b - self.a) ** k for x in self.piece.df((u - self.a) / (self.b - self.a), k)]


def norm(v):
    return sum(x * x for x in v) ** 0.5


def roots_by_sampling(g, a, b, n=200):
    """Sign changes of g on [a, b] by sampling (floats), refined in mpf by bisection-safe
    Anderson iteration."""
    out = []
    us = [a + (b - a) * i / n for i in range(n + 1)]
    vals = [g(u) for u in us]
    if not any(vals):  # zero throughout (a straight curve's other coordinates): no sign change
        return out
    for i in range(n):
        if vals[i] == 0 and 0 < i:
            out.append(mpf(us[i]))
        elif vals[i] * vals[i + 1] < 0:
            out.append(mpmath.findroot(lambda u: g(u), (mpf(us[i]), mpf(us[i + 1])), solver="anderson"))
    return out


class Oracle:
    """A curve for the oracle: pieces (piece, t0, t1) in the curve's parameter."""

    def __init__(self, pieces):
        self.pieces = pieces

    @staticmethod
    def of(curve):
        t = curve["type"]
        if t == "bezier":
            return Oracle([(BezierPiece(curve["points"]), 0.0, 1.0)])
        if t == "rational_bezier":
            return Oracle([(BezierPiece(curve["points"], curve["weights"]), 0.0, 1.0)])
        if t == "polyline":
            P = curve["points"]
            return Oracle([(LinePiece(P[i], P[i + 1], float(i)), float(i), float(i + 1)) for i in range(len(P) - 1)])
        if t == "bspline":
            U, p, P = curve["knots"], curve["degree"], curve["points"]
            ks = sorted(set(U[p:len(P) + 1]))
            sp = SplinePiece(U, p, P)
            return Oracle([(sp, ks[i], ks[i + 1]) for i in range(len(ks) - 1)])
        if t == "path":
            out = []
            k = len(curve["segments"])
            br = curve.get("breaks", list(range(k + 1)))
            for seg, a, b in zip(curve["segments"], br, br[1:]):
                for (g, t0, t1) in Oracle.of(seg).pieces:  # segments used here are on [0, 1]
                    out.append((Mapped(g, a, b), a + t0 * (b - a), a + t1 * (b - a)))
            return Oracle(out)
        raise ValueError(t)

    def piece_at(self, u):
        for g, a, b in self.pieces:
            if u <= b:
                return g
        return self.pieces[-1][0]

    def at(self, u):
        return self.piece_at(u).f(mpf(u))

    def kinks(self, g, a, b):
        """Where a coordinate of c' changes sign: |c'| can have a kink only there."""
        out = []
        for k in range(g.dim):
            out += roots_by_sampling(lambda u: g.df(u)[k], a, b)
        return sorted(out)

    def length(self, lo=None, hi=None):
        total = mpf(0)
        for g, a, b in self.pieces:
            a2 = max(a, lo) if lo is not None else a
            b2 = min(b, hi) if hi is not None else b
            if a2 >= b2:
                continue
            pts = [mpf(a2)] + [s for s in self.kinks(g, a, b) if a2 < s < b2] + [mpf(b2)]
            total += mpmath.quad(lambda u: norm(g.df(u)), pts)
        return total

    def distance_extreme(self, q, farthest=False, samples=300):
        """Extreme distance to q: every piece's ends and every sign change of
        (c(u) - q) . c'(u) (dense float samples, refined in mpf)."""
        best = None
        for g, a, b in self.pieces:
            h = lambda u: sum((x - y) * d for x, y, d in zip(g.f(u), q, g.df(u)))
            for u in [mpf(a), mpf(b)] + roots_by_sampling(h, a, b, samples):
                d = norm([x - y for x, y in zip(g.f(u), q)])
                if best is None or (d > best[1] if farthest else d < best[1]):
                    best = (u, d)
        return best


def random_cubic(rng, dim=2, scale=5.0):
    return bezier([[rng.uniform(-scale, scale) for _ in range(dim)] for _ in range(4)])


def random_rational(rng, dim=2):
    n = rng.randint(2, 4)
    return {"type": "rational_bezier", "points": [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n + 1)],
            "weights": [rng.uniform(0.3, 3) for _ in range(n + 1)]}


def random_bspline(rng, dim=2):
    p = rng.randint(2, 3)
    n = rng.randint(p + 1, p + 4)
    inner = sorted(rng.uniform(0, 1) for _ in range(n - p - 1))
    U = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
    return {"type": "bspline", "degree": p, "knots": U, "points": [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]}


def random_curves(rng, count, dim=2):
    out = []
    for i in range(count):
        kind = i % 4
        if kind == 0:
            out.append(random_cubic(rng, dim))
        elif kind == 1:
            out.append(random_rational(rng, dim))
        elif kind == 2:
            out.append(random_bspline(rng, dim))
        else:
            out.append({"type": "polyline", "points": [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(rng.randint(2, 6))]})
    return out


# ---------------------------------------------------------------------------------------

class ProjectTest(CliTest):
    def test_against_the_oracle(self):
        rng = random.Random(8)
        for dim in (1, 2, 3):
            for curve in random_curves(rng, 8, dim):
                q = [rng.uniform(-6, 6) for _ in range(dim)]
                for farthest in (False, True):
                    got = self.ok("project", {"curve": curve, "point": q, "farthest": farthest})
                    u, d = Oracle.of(curve).distance_extreme(q, farthest)
                    # Distances to 1e-12 relative (the oracle's 40 digits are exact here).
                    self.assertLessEqual(abs(got["distance"] - float(d)), 1e-12 * max(1.0, float(d)), (curve, q, farthest))
                    # The point is the curve's at t, at the reported distance.
                    self.assert_close(got["point"], [float(x) for x in Oracle.of(curve).at(got["t"])], 1e-12)
                    if "all_t" not in got:
                        self.assertLessEqual(abs(got["t"] - float(u)), 1e-6, (curve, q, farthest, got, u))

    def test_symmetric_tie_lists_all(self):
        # Point (0, 0.5) above the tent polyline: feet at t = 0.75 and 1.25 (distance sqrt(2)/4 each).
        got = self.ok("project", {"curve": {"type": "polyline", "points": [[-1, 0], [0, 1], [1, 0]]}, "point": [0, 0.5]})
        self.assert_close([got["t"]], [0.75], 1e-15)
        self.assert_close(got["all_t"], [0.75, 1.25], 1e-15)
        self.assertAlmostEqual(got["distance"], math.sqrt(2) / 4, delta=1e-16)

    def test_parabola_tie(self):
        # y = x^2 as a quadratic from (-1, 1) to (1, 1); from (0, 2) the nearest points are at
        # x = +-sqrt(3/2) / ... : d/dx (x^2 + (x^2 - 2)^2) = 0 -> x^2 = 3/2 outside [-1, 1],
        # so the ends tie at distance sqrt(2).
        got = self.ok("project", {"curve": bezier([[-1, 1], [0, -1], [1, 1]]), "point": [0, 2]})
        self.assertAlmostEqual(got["distance"], math.sqrt(2), delta=1e-15)
        self.assertEqual(got["all_t"], [0.0, 1.0])
        far = self.ok("project", {"curve": bezier([[-1, 1], [0, -1], [1, 1]]), "point": [0, 2], "farthest": True})
        self.assertEqual(far["t"], 0.5)
        self.assertAlmostEqual(far["distance"], 2.0, delta=1e-15)

    def test_circle_centre_is_an_interval(self):
        got = self.ok("project", {"curve": QUARTER, "point": [0, 0]})
        self.assertEqual(got["intervals"], [[0.0, 1.0]])
        self.assertEqual(got["t"], 0.0)
        self.assertAlmostEqual(got["distance"], 1.0, delta=1e-15)
        full = self.ok("project", {"curve": circle(2.0, 1.0, -1.0), "point": [1, -1], "farthest": True})
        self.assertEqual(full["intervals"], [[0.0, 4.0]])
        self.assertAlmostEqual(full["distance"], 2.0, delta=1e-15)
        # Off centre: a unique nearest point, no interval.
        off = self.ok("project", {"curve": circle(), "point": [0.5, 0]})
        self.assertNotIn("intervals", off)
        self.assertEqual(off["t"], 0.0)
        self.assertAlmostEqual(off["distance"], 0.5, delta=1e-15)

    def test_single_point_curve(self):
        got = self.ok("project", {"curve": bezier([[2, 3], [2, 3], [2, 3]]), "point": [5, 7]})
        self.assertEqual((got["t"], got["point"], got["distance"]), (0.0, [2.0, 3.0], 5.0))
        bs = {"type": "bspline", "degree": 2, "knots": [1, 1, 1, 2, 3, 3, 3], "points": [[1, 1]] * 4}
        got = self.ok("project", {"curve": bs, "point": [1, 2]})
        self.assertEqual((got["t"], got["distance"]), (1.0, 1.0))

    def test_ends_and_breaks(self):
        # Nearest at the domain's end (a segment), at a break (a polyline corner).
        got = self.ok("project", {"curve": bezier([[0, 0], [2, 0]]), "point": [3, 1]})
        self.assertEqual(got["t"], 1.0)
        got = self.ok("project", {"curve": {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1]]}, "point": [2, -1]})
        self.assertEqual((got["t"], got["point"]), (1.0, [1.0, 0.0]))

    def test_degenerate_and_scaled(self):
        # Coincident control points, a cusp, huge and tiny coordinates: same answers scaled.
        for pts in ([[0, 0], [0, 0], [1, 1], [1, 1]], [[0, 0], [1, 1], [0, 1], [1, 0]]):
            for s in (1.0, 1e150, 1e-150):
                c = bezier([[x * s for x in p] for p in pts])
                q = [0.6 * s, 0.4 * s]
                got = self.ok("project", {"curve": c, "point": q})
                u, d = Oracle.of(bezier(pts)).distance_extreme([0.6, 0.4])
                self.assertLessEqual(abs(got["distance"] / s - float(d)), 1e-12, (pts, s))

    def test_flat_minimum_is_one_answer(self):
        # The centre of curvature at a vertex: (C - q) . C' has a triple root there (the
        # distance is flat to fourth order). The symmetric cubic's vertex is t = 1/2 with
        # C(1/2) = (3/2, 3/2), C' = (3, 0), C'' = (0, -12): radius 3/4, centre (3/2, 3/4).
        got = self.ok("project", {"curve": bezier([[0, 0], [1, 2], [2, 2], [3, 0]]), "point": [1.5, 0.75]})
        self.assertNotIn("all_t", got)
        # Located as a simple root of a derivative: a few eps (it was 5e-9 off, three times).
        self.assertAlmostEqual(got["t"], 0.5, delta=1e-12)
        self.assertAlmostEqual(got["distance"], 0.75, delta=4e-16)
        # The oracle agrees on the distance (dense samples refined in 30 digits).
        u, d = Oracle.of(bezier([[0, 0], [1, 2], [2, 2], [3, 0]])).distance_extreme([1.5, 0.75])
        self.assertLessEqual(abs(got["distance"] - float(d)), 1e-15)
        # The same cubic as a B-spline on a domain of length 1e6: one answer at 5e5.
        bs = {"type": "bspline", "degree": 3, "knots": [0, 0, 0, 0, 1e6, 1e6, 1e6, 1e6], "points": [[0, 0], [1, 2], [2, 2], [3, 0]]}
        got = self.ok("project", {"curve": bs, "point": [1.5, 0.75]})
        self.assertNotIn("all_t", got)
        self.assertAlmostEqual(got["t"], 5e5, delta=1e-6)  # 1e-12 of the domain

    def test_bad_input(self):
        self.bad("project", {"curve": bezier([[0, 0], [1, 1]]), "point": [1]}, "point", contains="2 coordinates")
        self.bad("project", {"curve": bezier([[0, 0], [1, 1]])}, "point", contains="missing")
        self.bad("project", {"curve": bezier([[0, 0], [1, 1]]), "point": [1, "a"]}, "point[1]")
        self.bad("project", {"curve": bezier([[0, 0], [1, 1]]), "point": [0, 0], "farthest": 1}, "farthest")
        self.bad("project", {"curve": bezier([[0, 0], [1, 1]]), "point": [0, 0], "nearest": True}, "nearest")


class LengthTest(CliTest):
    def test_closed_forms(self):
        self.assertEqual(self.ok("length", {"curve": bezier([[0, 0], [3, 4]])})["length"], 5.0)
        # A straight cubic with uneven control points: its length is the chord.
        got = self.ok("length", {"curve": bezier([[0, 0], [3, 0], [1, 0], [4, 0]])})["length"]
        # x(t) goes 0 -> 4 but not monotonically: the oracle integrates |x'|.
        want = Oracle.of(bezier([[0, 0], [3, 0], [1, 0], [4, 0]])).length()
        self.assertLessEqual(abs(got - float(want)), 1e-12 * float(want))
        self.assertAlmostEqual(self.ok("length", {"curve": QUARTER})["length"], math.pi / 2, delta=1e-15 * math.pi)
        self.assertAlmostEqual(self.ok("length", {"curve": circle(3.0)})["length"], 6 * math.pi, delta=1e-14 * 6 * math.pi)
        got = self.ok("length", {"curve": bezier([[0, 0], [3, 4]]), "from": 0.2, "to": 0.7})["length"]
        self.assertAlmostEqual(got, 2.5, delta=1e-15)
        got = self.ok("length", {"curve": circle(), "from": 0.5, "to": 2.5})["length"]
        self.assertAlmostEqual(got, math.pi, delta=1e-14)

    def test_against_mpmath_quad(self):
        rng = random.Random(88)
        for dim in (1, 2, 3):
            for curve in random_curves(rng, 8, dim):
                got = self.ok("length", {"curve": curve})["length"]
                o = Oracle.of(curve)
                with mpmath.workdps(20):  # mpmath.quad to about 1e-20: ample for 1e-12
                    want = o.length()
                self.assertLessEqual(abs(got - float(want)), 1e-12 * float(want), curve)

    def test_cusp_and_degenerate(self):
        cusp = bezier([[0, 0], [1, 1], [0, 1], [1, 0]])
        want = Oracle.of(cusp).length()
        for s in (1.0, 1e150, 1e-150):
            c = bezier([[x * s for x in p] for p in cusp["points"]])
            got = self.ok("length", {"curve": c})["length"]
            self.assertLessEqual(abs(got / s - float(want)), 1e-12 * float(want), s)
        # Coincident control points (zero speed at the ends): still the chord.
        got = self.ok("length", {"curve": bezier([[0, 0], [0, 0], [1, 1], [1, 1]])})["length"]
        self.assertAlmostEqual(got, math.sqrt(2), delta=1e-15)
        # A point curve: exactly 0, no NaN (kurbo's arc length of a point cubic).
        self.assertEqual(self.ok("length", {"curve": bezier([[1, 2]] * 4)})["length"], 0.0)
        self.assertEqual(self.ok("length", {"curve": bezier([[1, 2]])})["length"], 0.0)
        self.assertEqual(self.ok("length", {"curve": bezier([[0, 0], [3, 4]]), "from": 0.3, "to": 0.3})["length"], 0.0)

    def test_bad_range(self):
        c = bezier([[0, 0], [3, 4]])
        self.bad("length", {"curve": c, "from": -0.1}, "from", contains="domain")
        self.bad("length", {"curve": c, "to": 1.5}, "to", contains="domain")
        self.bad("length", {"curve": c, "from": 0.6, "to": 0.5}, "to")
        self.bad("length", {"curve": c, "from": "a"}, "from")


class ParamAtLengthTest(CliTest):
    def test_closed_form(self):
        # x(t) = 2t + 2t^2 on [0, 1] (control points 0, 1, 4): s = 2t + 2t^2, t = (-2 + sqrt(4 + 8s)) / 4.
        c = bezier([[0, 0], [1, 0], [4, 0]])
        ss = [0, 0.1, 1, 2.5, 3.999, 4]
        got = self.ok("param_at_length", {"curve": c, "lengths": ss})["t"]
        self.assert_close(got, [(-2 + math.sqrt(4 + 8 * s)) / 4 for s in ss], 1e-14)
        self.assertEqual(got[0], 0.0)
        self.assertEqual(got[-1], 1.0)

    def test_inverse_of_length(self):
        rng = random.Random(5)
        for curve in random_curves(rng, 8, 2):
            total = self.ok("length", {"curve": curve})["length"]
            ss = [total * rng.random() for _ in range(3)] + [total]
            ts = self.ok("param_at_length", {"curve": curve, "lengths": ss})["t"]
            o = Oracle.of(curve)
            # The arc lengths up to each t, integrated interval by interval (sorted) at 20
            # digits (mpmath.quad to about 1e-20: ample for 1e-12).
            want, prev = mpf(0), None
            with mpmath.workdps(20):
                for s, t in sorted(zip(ss, ts), key=lambda st: st[1]):
                    want += o.length(lo=prev, hi=t) if prev is None or t > prev else 0
                    prev = t
                    self.assertLessEqual(abs(float(want) - s), 1e-12 * total, (curve, s, t))

    def test_circle_equal_steps(self):
        ts = self.ok("param_at_length", {"curve": circle(), "lengths": [k * math.pi / 2 for k in range(5)]})["t"]
        self.assert_close(ts, [0, 1, 2, 3, 4], 1e-13)

    def test_bad_lengths(self):
        c = bezier([[0, 0], [3, 4]])
        self.bad("param_at_length", {"curve": c, "lengths": [1, -0.5]}, "lengths[1]", contains="[0, 5]")
        self.bad("param_at_length", {"curve": c, "lengths": [5.1]}, "lengths[0]")
        self.bad("param_at_length", {"curve": c}, "lengths", contains="missing")
        # A point curve has length 0: only 0 is valid.
        self.assertEqual(self.ok("param_at_length", {"curve": bezier([[1, 1]] * 3), "lengths": [0]})["t"], [0.0])
        self.bad("param_at_length", {"curve": bezier([[1, 1]] * 3), "lengths": [1e-3]}, "lengths[0]")


class CurvatureTest(CliTest):
    def test_circle_signs(self):
        ts = [0, 0.3, 1, 2.5, 4]
        got = self.ok("eval", {"curve": circle(2.0), "t": ts, "curvature": True})["curvature"]
        self.assert_close(got, [0.5] * len(ts), 1e-14)
        got = self.ok("eval", {"curve": circle(2.0, ccw=False), "t": ts, "curvature": True})["curvature"]
        self.assert_close(got, [-0.5] * len(ts), 1e-14)
        # Without the flag there is no curvature field.
        self.assertNotIn("curvature", self.ok("eval", {"curve": circle(), "t": [0]}))

    def test_against_mpmath(self):
        rng = random.Random(3)
        for dim in (2, 3):
            for _ in range(4):
                c = random_cubic(rng, dim)
                ts = [rng.random() for _ in range(5)]
                got = self.ok("eval", {"curve": c, "t": ts, "curvature": True})["curvature"]
                g = BezierPiece(c["points"])
                for t, k in zip(ts, got):
                    d1, d2 = g.df(mpf(t)), g.df(mpf(t), 2)
                    sp = mpmath.sqrt(sum(x * x for x in d1))
                    if dim == 2:
                        want = (d1[0] * d2[1] - d1[1] * d2[0]) / sp ** 3
                    else:
                        cr = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]]
                        want = mpmath.sqrt(sum(x * x for x in cr)) / sp ** 3
                    self.assertLessEqual(abs(k - float(want)), 1e-10 * max(1, abs(float(want))), (c, t))
                    if dim == 3:
                        self.assertGreaterEqual(k, 0)

    def test_independent_of_the_domains_scale(self):
        # Curvature is geometric: the cubic (0,0), (1,2), (2,2), (3,0) as a B-spline on
        # [0, L] has -36 / 45^(3/2) at its start and -4/3 at its middle for every L (it was
        # 0 at L = 1e200 and refused at L = 1e-160: derivatives under- and overflowing).
        for L in (1e-300, 1e-200, 1e-160, 1.0, 1e160, 1e200, 1e300):
            bs = {"type": "bspline", "degree": 3, "knots": [0] * 4 + [L] * 4, "points": [[0, 0], [1, 2], [2, 2], [3, 0]]}
            got = self.ok("eval", {"curve": bs, "t": [0, L / 2, L], "curvature": True})["curvature"]
            self.assert_close(got, [-36 / 45 ** 1.5, -4 / 3, -36 / 45 ** 1.5], 1e-14, L)
            fr = self.ok("eval", {"curve": bs, "t": [L / 2], "frame": True})["frame"]
            self.assert_close(fr["curvature"], [-4 / 3], 1e-14, L)
            # A path of the cubic on breaks [0, L] likewise.
            path = {"type": "path", "segments": [bezier([[0, 0], [1, 2], [2, 2], [3, 0]])], "breaks": [0, L]}
            got = self.ok("eval", {"curve": path, "t": [L / 2], "curvature": True})["curvature"]
            self.assert_close(got, [-4 / 3], 1e-14, L)

    def test_line_and_cusp(self):
        got = self.ok("eval", {"curve": bezier([[0], [1], [3]]), "t": [0.5], "curvature": True})["curvature"]
        self.assertEqual(got, [0.0])
        self.bad("eval", {"curve": bezier([[0, 0], [1, 1], [0, 1], [1, 0]]), "t": [0.2, 0.5], "curvature": True}, "t[1]",
                 contains="velocity is zero")
        self.bad("eval", {"curve": bezier([[0, 0], [1, 1]]), "t": [0.5], "curvature": "yes"}, "curvature")


def hugging_quadratic(w, nurbs=False):
    """The rational quadratic (1,0), (1,1), (0,1) with weights 1, w, 1 (as a NURBS of one piece)."""
    c = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, w, 1]}
    if nurbs:
        c = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": c["points"], "weights": c["weights"]}
    return c


class ExtremeWeightsTest(CliTest):
    """Weights 1, W, 1 with W up to 1e30: the curve hugs its control polygon and passes each
    leg within about 1 / W of a parameter end. The curve is its own mirror image in the line
    x = y with t -> 1 - t (w_0 = w_2, P_2 the mirror of P_0, P_1 on the line), so its speed
    is symmetric: the arc length over [0, 1/2] is integrated (mpmath.quad, breakpoints
    spaced geometrically from 1e-3 / W to 1/2 so that the quadrature sees the leg) and the
    length from t > 1/2 to 1 is the one from 0 to 1 - t (exact in double). Every parameter
    integrated over is then within [0, 1/2], where 20 digits resolve t ~ 1e-33 relatively:
    20 digits for the lengths (the checks are at 1e-12; the 45-digit integration of both
    halves it replaces agreed to 1e-21). The nearest point is minimised in 45 digits over
    the whole parameter (t within 1e-30 of 1 needs 31)."""

    @staticmethod
    def breakpoints(w):
        """0, then geometric from 1e-3 / w up to 1/2, then their mirror images up to 1."""
        out = ExtremeWeightsTest.half_breakpoints(w)[:-1]
        mid = out[1:]
        return out + [mpf("0.5")] + [1 - x for x in reversed(mid)] + [mpf(1)]

    @staticmethod
    def half_breakpoints(w):
        out, k = [mpf(0)], mpf(1) / mpf(w) * mpf("1e-3")
        while k < mpf("0.5"):
            out.append(k)
            k *= 4
        return out + [mpf("0.5")]

    def test_length_project_param_at_length(self):
        for w in (1e8, 1e30):
            with mpmath.workdps(20):
                g = BezierPiece([[mpf(1), mpf(0)], [mpf(1), mpf(1)], [mpf(0), mpf(1)]], [mpf(1), mpf(w), mpf(1)])
                speed = lambda u: norm(g.df(u))
                half = self.half_breakpoints(w)
                # The integral over each interval between breakpoints, once: the length up to
                # a parameter s <= 1/2 is the sum of the whole intervals before it plus one part.
                pieces = [mpmath.quad(speed, [a, b]) for a, b in zip(half, half[1:])]
                total = 2 * mpmath.fsum(pieces)

                def length_to(s):
                    k = sum(1 for x in half[1:] if x < s)  # whole intervals before s
                    return mpmath.fsum(pieces[:k]) + mpmath.quad(speed, [half[k], s])

            with mpmath.workdps(45):
                g45 = BezierPiece([[mpf(1), mpf(0)], [mpf(1), mpf(1)], [mpf(0), mpf(1)]], [mpf(1), mpf(w), mpf(1)])
                pts = self.breakpoints(w)
                # The nearest point to (1, 3/2): golden-section search on a grid over the
                # breakpoints (the distance is unimodal: a convex curve seen from outside).
                q = [mpf(1), mpf("1.5")]
                dist = lambda u: norm([x - y for x, y in zip(g45.f(u), q)])
                grid = [a + (b - a) * i / 8 for a, b in zip(pts, pts[1:]) for i in range(8)] + [mpf(1)]
                i = min(range(len(grid)), key=lambda i: dist(grid[i]))
                lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
                for _ in range(200):  # the bracket shrinks by (2/3)^200 = 1e-35
                    m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
                    if dist(m1) < dist(m2):
                        hi = m2
                    else:
                        lo = m1
                dmin = dist((lo + hi) / 2)
                arc_to = {}  # t -> the reference arc length from 0 to t
                for nurbs in (False, True):
                    c = hugging_quadratic(w, nurbs)
                    got = self.ok("length", {"curve": c})["length"]
                    self.assertLessEqual(abs(got - float(total)), 1e-12 * float(total), (w, nurbs))
                    pr = self.ok("project", {"curve": c, "point": [1, 1.5]})
                    self.assertLessEqual(abs(pr["distance"] - float(dmin)), 1e-12, (w, nurbs, pr))
                    self.assertNotIn("all_t", pr)
                    # The arc length up to each parameter returned is the one asked for, to
                    # 1e-12 of the length plus what the double nearest the answer allows: the
                    # speed there times one ulp of t (near t = 1 the second leg runs at a
                    # speed of about W per unit of t, so that 1e-8 is the best at W = 1e8).
                    ss = [0.5, 1.0, 1.5]
                    ts = self.ok("param_at_length", {"curve": c, "lengths": ss})["t"]
                    for s, t in zip(ss, ts):
                        if t not in arc_to:  # the rational_bezier and nurbs forms mostly agree on t
                            with mpmath.workdps(20):
                                # 1 - t is exact in double for t in [1/2, 1] (Sterbenz).
                                arc_to[t] = length_to(mpf(t)) if t <= 0.5 else total - length_to(mpf(1 - t))
                        with mpmath.workdps(20):
                            slack = 1e-12 * float(total) + float(speed(mpf(min(t, 1 - t)))) * math.ulp(t)
                        self.assertLessEqual(abs(arc_to[t] - s), slack, (w, nurbs, s, t))

    def test_project_lists_only_ties_its_parameters_reach(self):
        # (1/2, 1/2) is 1/2 from both legs (x = 1 and y = 1; the curve is within about 1/W
        # of them there), at mirror-image parameters t and 1 - t with t ~ 1/(2W). From
        # W = 1e15 the double nearest 1 - t is not close enough: at W = 1e16 it is 1.0, the
        # far end (0, 1), 0.707 away; it was listed in all_t. Every parameter answered
        # must evaluate to a point at the distance (1e-12), and the distance is 1/2.
        for w in (1e8, 1e15, 1e16, 1e30):
            for nurbs in (False, True):
                c = hugging_quadratic(w, nurbs)
                pr = self.ok("project", {"curve": c, "point": [0.5, 0.5]})
                self.assertLessEqual(abs(pr["distance"] - 0.5), 1e-12, (w, nurbs, pr))
                ts = pr.get("all_t", [pr["t"]])
                self.assertEqual(len(ts), 2 if w == 1e8 else 1, (w, nurbs, pr))
                for x, y in self.ok("eval", {"curve": c, "t": ts})["points"]:
                    self.assertLessEqual(abs(math.hypot(x - 0.5, y - 0.5) - 0.5), 1e-12, (w, nurbs, pr))


class WorkLimitTest(CliTest):
    def test_queries_past_the_work_limit_are_refused(self):
        # A B-spline of degree 300 on 3000 control points: 2700 pieces of degree 300, about
        # 2.4e8 units of (degree + 1)^2 work (over 30 s per query before, a minute for its
        # Bézier pieces alone): refused at once, naming the curve and the figures.
        rng = random.Random(300)
        n, p = 3000, 300
        U = [0.0] * (p + 1) + [i / (n - p) for i in range(1, n - p)] + [1.0] * (p + 1)
        bs = {"type": "bspline", "degree": p, "knots": U, "points": [[rng.uniform(-9, 9), rng.uniform(-9, 9)] for _ in range(n)]}
        for cmd, extra in (("length", {}), ("features", {}), ("project", {"point": [0, 0]}), ("param_at_length", {"lengths": [0]})):
            self.bad(cmd, dict({"curve": bs}, **extra), "curve", contains="more than the limit of 10000000")
        self.bad("distance", {"curves": [bezier([[0, 0], [1, 1]]), bs]}, "curves[1]", contains="units of work")
        # A path of Bézier segments of degree 300: checked on its pieces.
        seg = bezier([[rng.uniform(-9, 9), rng.uniform(-9, 9)] for _ in range(301)])
        self.bad("length", {"curve": {"type": "path", "segments": [seg] * 120}}, "curve", contains="Bézier pieces")
        # A cubic B-spline on 6000 control points (6000 pieces, 96,000 units) is answered.
        n, p = 6000, 3
        U = [0.0] * (p + 1) + [i / (n - p) for i in range(1, n - p)] + [1.0] * (p + 1)
        cubic = {"type": "bspline", "degree": p, "knots": U, "points": [[rng.uniform(-9, 9), rng.uniform(-9, 9)] for _ in range(n)]}
        self.assertGreater(self.ok("length", {"curve": cubic})["length"], 0)

    def test_conversions_past_the_work_limit_are_refused(self):
        # The commands that make a curve's Bézier pieces check the work before making them:
        # on the degree 300 B-spline above, bounds, flatten, to_bezier, area and render took
        # 3 s to minutes each (time growing as p^3 before the conversion was made O(p^2) a
        # span); now each is refused with the figure, (3000 - 300) x 301^2 = 244622700
        # units, in well under a second of the program's CPU time.
        import resource

        rng = random.Random(300)
        n, p = 3000, 300
        U = [0.0] * (p + 1) + [i / (n - p) for i in range(1, n - p)] + [1.0] * (p + 1)
        bs = {"type": "bspline", "degree": p, "knots": U, "points": [[rng.uniform(-9, 9), rng.uniform(-9, 9)] for _ in range(n)]}
        for cmd, extra in (("bounds", {}), ("bounds", {"from": 0.25, "to": 0.5}), ("flatten", {"tolerance": 1e-3}), ("to_bezier", {}),
                           ("area", {}), ("render", {}), ("eval", {"t": [0.5], "curvature": True})):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            self.bad(cmd, dict({"curve": bs}, **extra), "curve", contains="about 244622700 units of work")
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            self.assertLess(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 1.0, cmd)
        self.bad("render", {"curves": [bezier([[0, 0], [1, 1]]), bs]}, "curves[1]", contains="units of work")

    def test_large_conversion_within_the_limit_is_answered(self):
        # Degree 50 on 3000 control points: 2950 pieces, 2950 x 51^2 = 7672950 units (the
        # limit is 1e7). The control points are the blossoms of x = t^2 - t, y = t^3 - t^2
        # (the blossom of t^k is e_k(u_1..u_p) / C(p, k)), so the B-spline is that closed
        # cubic exactly: its box is [-1/4, 0] x [-4/27, 0], its area 1/60 (Green's theorem,
        # integral of (t^4 - 2 t^3 + t^2) / 2), and every Bézier point is a blossom too.
        n, p = 3000, 50
        U = [0.0] * (p + 1) + [i / (n - p) for i in range(1, n - p)] + [1.0] * (p + 1)

        def blossom(u):
            e = [1.0, 0.0, 0.0, 0.0]  # elementary symmetric sums e_0..e_3 of u
            for x in u:
                e = [1.0, e[1] + x, e[2] + x * e[1], e[3] + x * e[2]]
            b2, b3 = e[2] / math.comb(len(u), 2), e[3] / math.comb(len(u), 3)
            return [b2 - e[1] / len(u), b3 - b2]

        curve = {"type": "bspline", "degree": p, "knots": U, "points": [blossom(U[i + 1:i + p + 1]) for i in range(n)]}
        box = self.ok("bounds", {"curve": curve})
        self.assert_close(box["min"] + box["max"], [-0.25, -4 / 27, 0, 0], 1e-12)
        self.assertAlmostEqual(self.ok("area", {"curve": curve})["area"], 1 / 60, delta=1e-12)
        path = self.ok("to_bezier", {"curve": curve})["curve"]
        self.assertEqual(len(path["segments"]), n - p)
        for k in (0, 1475, n - p - 1):
            a, b = path["breaks"][k], path["breaks"][k + 1]
            want = [blossom([a] * (p - j) + [b] * j) for j in range(p + 1)]
            self.assert_close(path["segments"][k]["points"], want, 1e-12, k)
        points = self.ok("flatten", {"curve": curve, "tolerance": 1e-3})["points"]
        self.assert_close(points[0] + points[-1], [0, 0, 0, 0], 1e-15)
        for x, y in points:  # on the curve: t from x (two roots), then y
            roots = [(1 + s * math.sqrt(max(0.0, 1 + 4 * x))) / 2 for s in (-1, 1)]
            self.assertLessEqual(min(abs(y - (t ** 3 - t ** 2)) for t in roots), 1e-7, (x, y))
        # (render passes the same check; it is left out here: it draws this curve as 2950
        # polylines and 3000 control points, 16 MB of SVG and 1.2 s of CPU.)


class AreaTest(CliTest):
    def test_polygons_and_circles(self):
        square = [[0, 0], [2, 0], [2, 1], [0, 1], [0, 0]]
        self.assertEqual(self.ok("area", {"curve": {"type": "polyline", "points": square}})["area"], 2.0)
        self.assertEqual(self.ok("area", {"curve": {"type": "polyline", "points": square[::-1]}})["area"], -2.0)
        got = self.ok("area", {"curve": circle(3.0, 10.0, -7.0)})["area"]
        self.assertAlmostEqual(got, 9 * math.pi, delta=1e-13 * 9 * math.pi)
        got = self.ok("area", {"curve": circle(3.0, ccw=False)})["area"]
        self.assertAlmostEqual(got, -9 * math.pi, delta=1e-13 * 9 * math.pi)

    def test_cubic_loops_against_mpmath(self):
        rng = random.Random(11)
        for _ in range(6):
            P = [[rng.uniform(-5, 5), rng.uniform(-5, 5)] for _ in range(3)]
            pts = P + [P[0]]
            got = self.ok("area", {"curve": bezier(pts)})["area"]
            g = BezierPiece(pts)
            want = mpmath.quad(lambda t: (g.f(t)[0] * g.df(t)[1] - g.f(t)[1] * g.df(t)[0]) / 2, [0, 1])
            scale = max(abs(x) for p in pts for x in p) ** 2
            self.assertLessEqual(abs(got - float(want)), 1e-14 * scale, pts)

    def test_translation_invariant_far_away(self):
        # The same unit square far from the origin: exactly 1 (coordinates relative to the start).
        sq = [[1e8, 1e8], [1e8 + 1, 1e8], [1e8 + 1, 1e8 + 1], [1e8, 1e8 + 1], [1e8, 1e8]]
        self.assertEqual(self.ok("area", {"curve": {"type": "polyline", "points": sq}})["area"], 1.0)

    def test_bad(self):
        self.bad("area", {"curve": bezier([[0, 0], [1, 1], [2, 0]])}, "curve", contains="closed")
        self.bad("area", {"curve": bezier([[0, 0, 0], [1, 1, 1], [0, 0, 0]])}, "curve", contains="dimension 2")


class FeaturesTest(CliTest):
    def test_closed_forms(self):
        got = self.ok("features", {"curve": bezier([[0, 0], [1, 1], [2, -1], [3, 0]])})
        self.assert_close(got["inflections"], [0.5], 1e-15)
        self.assert_close(got["extrema"][1], [0.5 - math.sqrt(3) / 6, 0.5 + math.sqrt(3) / 6], 1e-15)
        self.assertEqual(got["extrema"][0], [])
        self.assertEqual(got["cusps"], [])
        cusp = self.ok("features", {"curve": bezier([[0, 0], [1, 1], [0, 1], [1, 0]])})
        self.assert_close(cusp["cusps"], [0.5], 1e-8)  # a double root of x': eps^(1/2) at worst
        self.assertEqual(cusp["inflections"], [])
        # A polyline's corner is an extremum of y at the break.
        got = self.ok("features", {"curve": {"type": "polyline", "points": [[0, 0], [1, 1], [2, 0], [3, 0]]}})
        self.assertEqual(got["extrema"], [[], [1.0]])
        # Straight lines and conics have no inflections.
        self.assertEqual(self.ok("features", {"curve": bezier([[0, 0], [1, 1], [3, 3], [4, 4]])})["inflections"], [])
        self.assertEqual(self.ok("features", {"curve": circle()})["inflections"], [])
        # A flat point (y = x^4 near 0) is not an inflection.
        flat = bezier([[-1, 1], [-0.5, -1], [0, 5 / 3 - 2], [0.5, -1], [1, 1]])
        self.assertEqual(self.ok("features", {"curve": flat})["inflections"], [])
        # 3-D: extrema only.
        got = self.ok("features", {"curve": bezier([[0, 0, 0], [1, 2, -1], [2, 0, 1]])})
        self.assertEqual((got["inflections"], got["cusps"]), ([], []))
        self.assert_close(got["extrema"], [[], [0.5], [1 / 3]], 1e-15)  # z = 3t^2 - 2t

    def test_random_cubics_against_sampling(self):
        rng = random.Random(21)
        for _ in range(10):
            c = random_cubic(rng)
            got = self.ok("features", {"curve": c})
            g = BezierPiece(c["points"])
            def cross(t):
                d1, d2 = g.df(t), g.df(t, 2)
                return d1[0] * d2[1] - d1[1] * d2[0]
            want = [float(r) for r in roots_by_sampling(cross, 0.0, 1.0, 400)]
            self.assert_close(got["inflections"], want, 1e-12)
            for k in range(2):
                want = [float(r) for r in roots_by_sampling(lambda t: g.df(t)[k], 0.0, 1.0, 400)]
                self.assert_close(got["extrema"][k], want, 1e-12)


class DistanceTest(CliTest):
    def test_closed_forms(self):
        got = self.ok("distance", {"curves": [bezier([[0, 0], [2, 0]]), bezier([[1, 1], [1, 3]])]})
        self.assertEqual((got["distance"], got["t"]), (1.0, [0.5, 0.0]))
        # Concentric circles: the radii's difference, at any parameters (a constant distance).
        got = self.ok("distance", {"curves": [circle(1.0), circle(2.5)]})
        self.assertAlmostEqual(got["distance"], 1.5, delta=1e-14)
        # Crossing curves: 0 at the crossing.
        got = self.ok("distance", {"curves": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[0, 1], [2, 1]])]})
        self.assertLessEqual(got["distance"], 1e-15)
        self.assertLessEqual(abs(got["points"][0][1] - 1), 1e-14)
        # The same curve twice: 0.
        c = random_cubic(random.Random(1))
        self.assertEqual(self.ok("distance", {"curves": [c, c]})["distance"], 0.0)

    def test_random_pairs_against_oracle(self):
        rng = random.Random(42)
        for i in range(12):
            dim = 2 if i < 8 else 3
            a, b = random_curves(rng, 2, dim) if i % 2 else (random_cubic(rng, dim), random_cubic(rng, dim, 3.0))
            b = dict(b)
            # Move b away so that most pairs do not cross.
            shift = [rng.uniform(-4, 4) for _ in range(dim)]
            b["points"] = [[x + s for x, s in zip(p, shift)] for p in b["points"]]
            got = self.ok("distance", {"curves": [a, b]})
            want = self.oracle(a, b)
            # Never below the true minimum (beyond rounding), and within the guaranteed 1e-7
            # relative of it (in practice the Newton refinement gives full precision).
            self.assertGreaterEqual(got["distance"], float(want) - 1e-13, (a, b))
            self.assertLessEqual(got["distance"], float(want) * (1 + 1e-7) + 1e-13, (a, b, got, want))
            self.assertLessEqual(abs(got["distance"] - float(want)), 1e-12 * max(1, float(want)), (a, b, got, want))
            oa, ob = Oracle.of(a), Oracle.of(b)
            self.assert_close(got["points"][0], [float(x) for x in oa.at(got["t"][0])], 1e-12)
            self.assert_close(got["points"][1], [float(x) for x in ob.at(got["t"][1])], 1e-12)

    @staticmethod
    def oracle(a, b, n=100):
        """Dense float grid on both curves; the best pairs refined by Newton on the
        gradient of |a(s) - b(t)|^2 in mpf; and the exact projections of every piece's
        ends on the other curve (a minimum may lie at an end)."""
        oa, ob = Oracle.of(a), Oracle.of(b)
        def grid(o):
            return [(g, lo, hi, lo + (hi - lo) * i / n) for g, lo, hi in o.pieces for i in range(n + 1)]
        ga, gb = grid(oa), grid(ob)
        fa = [x[0].f(x[3]) for x in ga]
        fb = [x[0].f(x[3]) for x in gb]
        pairs = sorted((sum((x - y) ** 2 for x, y in zip(pa, pb)), i, j) for i, pa in enumerate(fa) for j, pb in enumerate(fb))
        best = mpf(pairs[0][0]) ** 0.5
        for _, i, j in pairs[:6]:
            (g, la, ha, s), (h, lb, hb, t) = ga[i], gb[j]
            s, t = mpf(s), mpf(t)
            for _ in range(40):
                r = [x - y for x, y in zip(g.f(s), h.f(t))]
                a1, b1, a2, b2 = g.df(s), h.df(t), g.df(s, 2), h.df(t, 2)
                dot = lambda u, v: sum(x * y for x, y in zip(u, v))
                gs, gt = dot(r, a1), -dot(r, b1)
                # Newton on the gradient of |r|^2 / 2, with its exact Hessian.
                h00, h01, h11 = dot(a1, a1) + dot(r, a2), -dot(a1, b1), dot(b1, b1) - dot(r, b2)
                det = h00 * h11 - h01 * h01
                if det == 0:
                    break
                s2 = min(max(s - (h11 * gs - h01 * gt) / det, mpf(la)), mpf(ha))
                t2 = min(max(t - (h00 * gt - h01 * gs) / det, mpf(lb)), mpf(hb))
                if abs(s2 - s) < mpf(10) ** -25 and abs(t2 - t) < mpf(10) ** -25:
                    break
                s, t = s2, t2
            best = min(best, norm([x - y for x, y in zip(g.f(s), h.f(t))]))
        for o, other in ((oa, ob), (ob, oa)):
            for g, lo, hi in o.pieces:
                for u in (lo, hi):
                    best = min(best, other.distance_extreme([mpf(x) for x in g.f(mpf(u))], samples=100)[1])
        return best

    def test_bad(self):
        self.bad("distance", {"curves": [bezier([[0, 0], [1, 1]])]}, "curves", contains="two")
        self.bad("distance", {"curves": [bezier([[0, 0], [1, 1]]), bezier([[0], [1]])]}, "curves[1]", contains="dimension")
        self.bad("distance", {"curves": [bezier([[0, 0], [1, 1]]), {"type": "bezier"}]}, "curves[1].points")
        self.bad("distance", {"curves": 3}, "curves")


if __name__ == "__main__":
    test_cli.BINARY = sys.argv.pop(1)
    unittest.main()
