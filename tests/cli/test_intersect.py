#!/usr/bin/python3
"""Black-box tests of `intersect`: closed forms (lines, the 9 crossings of y = T3(x) and
x = T3(y), a loop cubic's double point, a parabola and a circle touching lines), overlaps
(a cubic and its own halves, reversed, collinear segments, a curve running over itself),
mpmath as the oracle for the parameters of random crossings (findroot at 50 digits),
near-coincident curves (copies turned by 1e-9, circles with centres 1e-8 apart, copies a few
near-miss distances apart), touches within the near-miss distance located where the curves are closest (closed
forms, mpmath), and a seeded random property: every reported point lies on both curves, and dense polylines
find no crossing that the program missed.

Usage: test_intersect.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
from fractions import Fraction
import random
import sys
import unittest

import mpmath
import numpy as np

import test_cli
from test_cli import CliTest, bezier, de_casteljau, dist, rational_point


def split_points(P, t):
    """de Casteljau's triangle: the control points of the halves [0, t] and [t, 1]."""
    left, right, pts = [], [], [list(p) for p in P]
    while pts:
        left.append(pts[0])
        right.append(pts[-1])
        pts = [[(1 - t) * a + t * b for a, b in zip(pts[i], pts[i + 1])] for i in range(len(pts) - 1)]
    return left, right[::-1]


def mp_bezier(P, t):
    """Bernstein sum in mpmath (t an mpf)."""
    n = len(P) - 1
    return [sum(math.comb(n, i) * t ** i * (1 - t) ** (n - i) * mpmath.mpf(P[i][k]) for i in range(n + 1))
            for k in range(2)]


def mp_refine(A, B, ta, tb):
    """The root of A(s) - B(t) = 0 near (ta, tb) at 50 digits."""
    with mpmath.workdps(50):
        f = lambda s, t: [x - y for x, y in zip(mp_bezier(A, s), mp_bezier(B, t))]
        s, t = mpmath.findroot(f, (mpmath.mpf(ta), mpmath.mpf(tb)))
        return float(s), float(t)


def T3_cubics():
    """y = T3(x) = 4x^3 - 3x on [-1, 1] as a cubic in t = (x + 1) / 2, and its mirror
    x = T3(y). Control points from the end derivatives: y'(t) = 2 T3'(x) = 18 at both ends."""
    A = [[-1, -1], [-1 / 3, 5], [1 / 3, -5], [1, 1]]
    B = [[y, x] for x, y in A]
    return A, B


class LineTest(CliTest):
    def test_segments_cross_at_known_point(self):
        # (0,0)-(4,2) and the polyline (0,2)-(4,0)-(5,3): cross at (2, 1), t = 0.5 on both.
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [4, 2]]), {"type": "polyline", "points": [[0, 2], [4, 0], [5, 3]]}]})
        self.assertEqual(r["overlaps"], [])
        self.assertEqual(len(r["intersections"]), 1)
        x = r["intersections"][0]
        self.assert_close(x["t"], [0.5, 0.5], 1e-15)
        self.assert_close(x["point"], [2, 1], 1e-15)
        self.assertEqual(x["kind"], "crossing")

    def test_polyline_vertex_hit_once(self):
        # The segment passes through the polyline's vertex (4, 0) at t = 1 of both segments:
        # one point, not two.
        r = self.ok("intersect", {"curves": [bezier([[2, -2], [6, 2]]), {"type": "polyline", "points": [[0, 2], [4, 0], [5, 3]]}]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assert_close(r["intersections"][0]["t"], [0.5, 1.0], 1e-15)

    def test_curve_and_line_segment(self):
        # y = 0 meets the cubic (0,-1),(1,3),(2,-3),(3,1) at the three roots of its y(t),
        # found by mpmath at 50 digits; x(t) = 3t, so tb = (3 ta + 1) / 5.
        P = [[0, -1], [1, 3], [2, -3], [3, 1]]
        r = self.ok("intersect", {"curves": [bezier(P), bezier([[-1, 0], [4, 0]])]})
        with mpmath.workdps(50):
            y = lambda t: mp_bezier(P, t)[1]
            roots = sorted(float(mpmath.findroot(y, t0)) for t0 in (0.1, 0.5, 0.9))
        got = [x["t"][0] for x in r["intersections"]]
        self.assertEqual(len(got), 3, r)
        for g, w in zip(got, roots):
            self.assertAlmostEqual(g, w, delta=4e-16)
        for x in r["intersections"]:
            self.assertAlmostEqual(x["t"][1], (de_casteljau(P, x["t"][0])[0] + 1) / 5, delta=1e-15)


class NineCrossingsTest(CliTest):
    def test_T3_and_its_mirror_cross_nine_times(self):
        # x = cos(theta), y = cos(3 theta) with T3(T3(x)) = T9(x) = x: theta = pi k / 4
        # (k = 0..4) and pi k / 5 (k = 0..5), nine distinct points, all transversal.
        A, B = T3_cubics()
        r = self.ok("intersect", {"curves": [bezier(A), bezier(B)]})
        thetas = sorted(set([math.pi * k / 4 for k in range(5)] + [math.pi * k / 5 for k in range(6)]))
        want = sorted(((math.cos(th) + 1) / 2, (math.cos(3 * th) + 1) / 2) for th in thetas)
        self.assertEqual(len(want), 9)
        got = r["intersections"]
        self.assertEqual(len(got), 9, r)
        self.assertEqual(r["overlaps"], [])
        for x, (ta, tb) in zip(got, want):
            # Parameters to a few eps (Newton to full precision on a well-conditioned
            # crossing; the reference cosines carry an error of about 1 ulp).
            self.assertAlmostEqual(x["t"][0], ta, delta=8e-16)
            self.assertAlmostEqual(x["t"][1], tb, delta=8e-16)
            self.assertEqual(x["kind"], "crossing")
        self.assertEqual([x["t"][0] for x in got], sorted(x["t"][0] for x in got))

    def test_nine_crossings_through_other_types(self):
        # The same curves as a path of two halves and as a clamped bspline of one piece:
        # the same nine points in the curve's own parameters.
        A, B = T3_cubics()
        L, R = split_points(A, 0.5)
        path = {"type": "path", "segments": [bezier(L), bezier(R)], "breaks": [0, 1, 2]}
        spline = {"type": "bspline", "degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1, 1], "points": B}
        r = self.ok("intersect", {"curves": [path, spline]})
        ref = self.ok("intersect", {"curves": [bezier(A), bezier(B)]})["intersections"]
        self.assertEqual(len(r["intersections"]), 9, r)
        for x, y in zip(r["intersections"], ref):
            self.assertAlmostEqual(x["t"][0], 2 * y["t"][0], delta=1e-14)
            self.assertAlmostEqual(x["t"][1], y["t"][1], delta=1e-14)


class TangentTest(CliTest):
    def test_parabola_touches_line_once(self):
        # y(t) = (2t - 1)^2 >= 0 touches y = 0 at t = 1/2, x = 1.
        r = self.ok("intersect", {"curves": [bezier([[0, 1], [1, -1], [2, 1]]), bezier([[0, 0], [2, 0]])]})
        self.assertEqual(len(r["intersections"]), 1, r)
        x = r["intersections"][0]
        self.assertEqual(x["kind"], "tangent")
        self.assert_close(x["t"], [0.5, 0.5], 1e-15)
        self.assert_close(x["point"], [1, 0], 1e-15)

    def test_high_degree_touches(self):
        # Pieces of degree >= 4 go to the general engine, where a touch refined as a double
        # root is located to sqrt(eps / curvature) only: it must still be one `tangent`
        # point at the touch. The parabola (0,0), (1,2), (2,0) elevated exactly to degree 5
        # (apex (1, 1) at t = 1/2) against y = 1 - 1e-12: within the near-miss distance,
        # one tangent point at the apex (it was one crossing 1e-6 away).
        P = [[Fraction(0), Fraction(0)], [Fraction(1), Fraction(2)], [Fraction(2), Fraction(0)]]
        for n in range(2, 5):  # Forrest: Q_i = i/(n+1) P_(i-1) + (1 - i/(n+1)) P_i
            P = [P[0]] + [[Fraction(i, n + 1) * P[i - 1][k] + (1 - Fraction(i, n + 1)) * P[i][k] for k in range(2)]
                          for i in range(1, n + 1)] + [P[-1]]
        quintic = bezier([[float(x) for x in p] for p in P])
        r = self.ok("intersect", {"curves": [quintic, bezier([[-1, 1 - 1e-12], [3, 1 - 1e-12]])]})
        self.assertEqual(len(r["intersections"]), 1, r)
        x = r["intersections"][0]
        self.assertEqual(x["kind"], "tangent", r)
        # The apex to a few eps over the curvature (2 per unit parameter^2 here).
        self.assertLess(abs(x["t"][0] - 0.5), 1e-7, r)
        # Chebyshev polynomials T_n (n = 8, 10, 12) as the graph y = T_n(x), x in [-1, 1],
        # a Bézier curve of degree n (power to Bernstein coefficients in exact rationals):
        # T_n = cos(n acos x) reaches +-1 at x = cos(k pi / n), with zero slope inside
        # (0 < k < n): a touch of the lines y = +-1 there; the ends x = +-1 are crossings.
        for n in (8, 10, 12):
            c = [Fraction(0)] * (n + 1)  # power coefficients in x of T_n (T_(k+1) = 2x T_k - T_(k-1))
            t0, t1 = [Fraction(1)] + [Fraction(0)] * n, [Fraction(0), Fraction(1)] + [Fraction(0)] * (n - 1)
            for _ in range(n - 1):
                t0, t1 = t1, [2 * (t1[i - 1] if i else 0) - t0[i] for i in range(n + 1)]
            c = t1
            # x = 2u - 1: power coefficients in u, then Bernstein b_i = sum_j C(i,j)/C(n,j) a_j.
            a = [Fraction(0)] * (n + 1)
            for k, ck in enumerate(c):
                for j in range(k + 1):
                    a[j] += ck * math.comb(k, j) * Fraction(2) ** j * Fraction(-1) ** (k - j)
            b = [sum(Fraction(math.comb(i, j), math.comb(n, j)) * a[j] for j in range(i + 1)) for i in range(n + 1)]
            graph = bezier([[-1 + 2 * i / n, float(b[i])] for i in range(n + 1)])
            for level in (1, -1):
                r = self.ok("intersect", {"curves": [graph, bezier([[-2, level], [2, level]])]})
                want = sorted(math.cos(k * math.pi / n) for k in range(1, n) if (-1) ** k == level)
                inner = [x for x in r["intersections"] if 1e-6 < x["t"][0] < 1 - 1e-6]
                self.assertEqual(len(inner), len(want), (n, level, r))
                for x, xk in zip(inner, want):
                    self.assertEqual(x["kind"], "tangent", (n, level, x))
                    self.assertLess(abs(x["point"][0] - xk), 1e-7, (n, level, x))

    def test_rotated_touch_found_once(self):
        # The same touch rotated by several angles: rounded coordinates may make the curves
        # miss or cross twice by ~1e-16; still exactly one tangent point, at the closed form.
        for deg in (17, 30, 45, 101, 200):
            a = math.radians(deg)
            rot = lambda p: [math.cos(a) * p[0] - math.sin(a) * p[1] + 3, math.sin(a) * p[0] + math.cos(a) * p[1] - 1]
            r = self.ok("intersect", {"curves": [bezier([rot(p) for p in [[0, 1], [1, -1], [2, 1]]]),
                                                 bezier([rot(p) for p in [[0, 0], [2, 0]]])]})
            self.assertEqual(len(r["intersections"]), 1, (deg, r))
            x = r["intersections"][0]
            self.assertEqual(x["kind"], "tangent")
            # A double root: parameters to about sqrt(eps), here better thanks to the polish.
            self.assert_close(x["t"], [0.5, 0.5], 1e-7)

    def test_circle_touches_line(self):
        # Quarter circle (rational quadratic) and the line x + y = sqrt(2): touch at 45 deg.
        s = math.sqrt(2)
        circle = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, s / 2, 1]}
        r = self.ok("intersect", {"curves": [circle, bezier([[s, 0], [0, s]])]})
        self.assertEqual(len(r["intersections"]), 1, r)
        x = r["intersections"][0]
        self.assertEqual(x["kind"], "tangent")
        self.assert_close(x["point"], [s / 2, s / 2], 1e-8)
        self.assert_close(x["t"], [0.5, 0.5], 1e-7)

    def test_near_miss_not_reported(self):
        # Lifted by 1e-8 of the size (well above the 1e-10 threshold): no point; lowered by
        # 1e-12: two crossings closer than sqrt(1e-12) merge into one tangent point.
        up = self.ok("intersect", {"curves": [bezier([[0, 1 + 2e-8], [1, -1 + 2e-8], [2, 1 + 2e-8]]), bezier([[0, 0], [2, 0]])]})
        self.assertEqual(up["intersections"], [])
        down = self.ok("intersect", {"curves": [bezier([[0, 1 - 2e-12], [1, -1 - 2e-12], [2, 1 - 2e-12]]), bezier([[0, 0], [2, 0]])]})
        self.assertEqual(len(down["intersections"]), 1, down)
        self.assertEqual(down["intersections"][0]["kind"], "tangent")

    def test_endpoints_meeting(self):
        # Two curves that share an end point and leave it in different directions.
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[2, 0], [3, 1], [4, 0]])]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assertEqual(r["intersections"][0]["t"], [1.0, 0.0])
        self.assertEqual(r["intersections"][0]["kind"], "crossing")


class OverlapTest(CliTest):
    P = [[0, 0], [1, 3], [3, -1], [4, 2]]

    def test_cubic_and_its_own_halves(self):
        L, R = split_points(self.P, 0.5)
        r = self.ok("intersect", {"curves": [bezier(self.P), bezier(L)]})
        self.assertEqual(r["intersections"], [])
        self.assertEqual(len(r["overlaps"]), 1, r)
        o = r["overlaps"][0]
        self.assert_close(o["a"], [0, 0.5], 1e-12)
        self.assert_close(o["b"], [0, 1], 1e-12)
        r = self.ok("intersect", {"curves": [bezier(R[::-1]), bezier(self.P)]})
        self.assertEqual(r["intersections"], [])
        self.assertEqual(len(r["overlaps"]), 1, r)
        self.assert_close(r["overlaps"][0]["a"], [0, 1], 1e-12)
        self.assert_close(r["overlaps"][0]["b"], [1, 0.5], 1e-12)

    def test_sub_curve_of_a_path_and_a_bspline(self):
        # The middle third [1/3, 2/3] of the cubic against the cubic as a bspline on [0, 3].
        L, _ = split_points(self.P, 2 / 3)
        _, mid = split_points(L, 0.5)
        spline = {"type": "bspline", "degree": 3, "knots": [0, 0, 0, 0, 3, 3, 3, 3], "points": self.P}
        r = self.ok("intersect", {"curves": [spline, bezier(mid)]})
        self.assertEqual(r["intersections"], [])
        self.assertEqual(len(r["overlaps"]), 1, r)
        self.assert_close(r["overlaps"][0]["a"], [1, 2], 1e-11)
        self.assert_close(r["overlaps"][0]["b"], [0, 1], 1e-11)

    def test_same_curve_twice(self):
        r = self.ok("intersect", {"curves": [bezier(self.P), bezier(self.P)]})
        self.assertEqual(r, {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 1.0]}]})

    def test_collinear_segments(self):
        # (0,0)-(4,4) and the polyline (2,2)-(6,6)-(6,0): overlap on (2,2)-(4,4), and the
        # polyline's second segment does not touch the first curve.
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [4, 4]]), {"type": "polyline", "points": [[2, 2], [6, 6], [6, 0]]}]})
        self.assertEqual(r["intersections"], [])
        self.assertEqual(len(r["overlaps"]), 1, r)
        self.assert_close(r["overlaps"][0]["a"], [0.5, 1], 1e-15)
        self.assert_close(r["overlaps"][0]["b"], [0, 0.5], 1e-15)

    def test_curve_running_over_itself(self):
        # x(t) = 6t - 15t^2 + 10t^3 on y = 0 turns back at t = 1/2 -+ sqrt(5)/10 and covers
        # [x(t2), x(t1)] three times: three overlaps, no points.
        t1, t2 = 0.5 - math.sqrt(5) / 10, 0.5 + math.sqrt(5) / 10
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [2, 0], [-1, 0], [1, 0]])]})
        self.assertEqual(r["intersections"], [])
        self.assertEqual(len(r["overlaps"]), 3, r)
        x = lambda t: 6 * t - 15 * t * t + 10 * t ** 3
        for o in r["overlaps"]:
            self.assertLess(o["a"][0], o["a"][1])
            for ta, tb in zip(o["a"], o["b"]):
                self.assertAlmostEqual(x(ta), x(tb), delta=1e-12)
        starts = sorted(o["a"][0] for o in r["overlaps"])
        # The low end x(t2) is reached on the first arc at the root of x(t) = x(t2) below t1.
        s0 = float(mpmath.findroot(lambda t: 6 * t - 15 * t ** 2 + 10 * t ** 3 - x(t2), 0.05))
        self.assertAlmostEqual(starts[0], s0, delta=1e-9)
        self.assertAlmostEqual(starts[2], t1, delta=1e-9)


class SelfTest(CliTest):
    def test_symmetric_loop(self):
        # P = (0,0),(3,3),(-1,3),(2,0) is symmetric about x = 1: x(1-t) = 2 - x(t) and
        # y(1-t) = y(t), so the double point is at x = 1, t and 1 - t, with t a root of
        # x(t) - 1 = -1 + 9t - 21t^2 + 14t^3 = (2t - 1)(7t^2 - 7t + 1): t = 1/2 - sqrt(21)/14.
        P = [[0, 0], [3, 3], [-1, 3], [2, 0]]
        r = self.ok("intersect", {"curves": [bezier(P)]})
        self.assertEqual(r["overlaps"], [])
        self.assertEqual(len(r["intersections"]), 1, r)
        x = r["intersections"][0]
        closed = 0.5 - math.sqrt(21) / 14
        with mpmath.workdps(50):
            ta = float(mpmath.findroot(lambda t: mp_bezier(P, t)[0] - 1, closed))
        self.assertAlmostEqual(ta, closed, delta=1e-15)
        self.assertAlmostEqual(x["t"][0], ta, delta=4e-16)
        self.assertAlmostEqual(x["t"][1], 1 - ta, delta=4e-16)
        self.assertAlmostEqual(x["point"][0], 1, delta=1e-15)
        self.assertEqual(x["kind"], "crossing")

    def test_no_self_intersections(self):
        for c in (bezier([[0, 0], [1, 3], [3, 3], [4, 0]]), bezier([[0, 0], [1, 1]]),
                  {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1], [0, 1]]},
                  bezier([[0, 0], [2, 2], [0, 2], [2, 0]])):  # a cusp, not a loop
            r = self.ok("intersect", {"curves": [c]})
            self.assertEqual(r, {"intersections": [], "overlaps": []}, c)

    def test_closed_polyline_and_figure_eight(self):
        # A closed square: its closing point is not a self-intersection. A bow tie polyline
        # crosses itself at (1, 1): segment 0 at t = 0.5 and segment 2 at t = 2.5.
        sq = {"type": "polyline", "points": [[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]}
        self.assertEqual(self.ok("intersect", {"curves": [sq]}), {"intersections": [], "overlaps": []})
        bow = {"type": "polyline", "points": [[0, 0], [2, 2], [2, 0], [0, 2]]}
        r = self.ok("intersect", {"curves": [bow]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assert_close(r["intersections"][0]["t"], [0.5, 2.5], 1e-15)
        self.assert_close(r["intersections"][0]["point"], [1, 1], 1e-15)

    def test_crossing_at_the_closing_point_listed_once(self):
        # A figure eight through its own closing point: the polyline passes (0, 0) at t = 0,
        # 3 and 6 (= 0): one self-intersection, (0, 3); (3, 6) is the same pair of passes.
        eight = [[0, 0], [1, 1], [1, -1], [0, 0], [-1, 1], [-1, -1], [0, 0]]
        r = self.ok("intersect", {"curves": [{"type": "polyline", "points": eight}]})
        self.assertEqual(r, {"intersections": [{"t": [0.0, 3.0], "point": [0.0, 0.0], "kind": "crossing"}], "overlaps": []})
        # The same figure as a path of line segments and as a closed Catmull-Rom / periodic
        # curve through its points: one point at the closing point, whose other pass is
        # where the curve comes back through (0, 0).
        path = {"type": "path", "segments": [bezier([eight[i], eight[i + 1]]) for i in range(6)]}
        r = self.ok("intersect", {"curves": [path]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assert_close(r["intersections"][0]["t"], [0, 3], 1e-15)
        # A smooth closed curve: the uniform cubic B-spline on the control points below
        # (the last three repeat the first three: periodic), domain [3, 9]. At t = 3 and 6
        # its point is (P_i + 4 P_i+1 + P_i+2) / 6 = (0, 0) with tangents (P_i+2 - P_i) / 2 =
        # (2, 2) and (-2, 2): a crossing at the closing point, listed once as (3, 6) (it
        # was listed again as (6, 9)).
        ctrl = [[-2, -2], [0, 0], [2, 2], [2, -2], [0, 0], [-2, 2], [-2, -2], [0, 0], [2, 2]]
        bs = {"type": "bspline", "degree": 3, "knots": list(range(13)), "points": ctrl}
        r = self.ok("intersect", {"curves": [bs]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assert_close(r["intersections"][0]["t"], [3, 6], 1e-15)
        self.assert_close(r["intersections"][0]["point"], [0, 0], 1e-15)
        self.assertEqual(r["intersections"][0]["kind"], "crossing")

    def test_crossing_near_a_stationary_end(self):
        # A raw offset (the cubic (0,0),(2,2),(0,2),(2,0) offset by 1, its first three
        # cubics): A's last two control points coincide (its velocity is zero at t = 1, the
        # offset's cusp) and A crosses C once, which the engine seeded at A's end, where
        # Newton cannot move (the crossing was missed). Oracle: the sampled polylines'
        # crossing, refined in mpmath at 50 digits.
        A = [[-0.7071067811865476, 0.7071067811865476], [-0.08456295992362872, 1.3296506024494663],
             [0.015191811099056197, 1.6524085919046994], [0.015191811099056318, 1.6524085919046998]]
        B = [[0.015191811099056318, 1.6524085919046998], [0.003275790270595831, 1.6119174521309902],
             [0.0, 1.5507070218610077], [0.0, 1.5]]
        C = [[0.0, 1.5], [-9.004923695632284e-17, 2.2353078211531567], [0.770280855301764, 2.7197978137413275],
             [1.433061226762282, 2.401364506664838]]
        found = polyline_crossings(A, C, 1000)
        self.assertEqual(len(found), 1, found)
        s, t = mp_refine(A, C, *found[0])
        # The path A, B, C (t in [0, 3]): the crossing at (s, 2 + t) is one of its two
        # self-intersections.
        # B crosses C too (away from their joint); at the joint, t = 2, the path reverses
        # (a cusp: B and C leave (0, 1.5) with one tangent and part slowly, within the
        # near-miss distance for about 4e-5 of their length), which is no
        # self-intersection (it was reported as a tangent at t = 1.9999995, 2.00000004).
        bc = [x for x in polyline_crossings(B, C, 1000) if x[0] < 0.99]
        self.assertEqual(len(bc), 1, bc)
        u, v = mp_refine(B, C, *bc[0])
        path = {"type": "path", "segments": [bezier(A), bezier(B), bezier(C)]}
        r = self.ok("intersect", {"curves": [path]})
        self.assertEqual([x["kind"] for x in r["intersections"]], ["crossing", "crossing"], r)
        self.assert_close(r["intersections"][0]["t"], [s, 2 + t], 1e-12)
        self.assert_close(r["intersections"][1]["t"], [1 + u, 2 + v], 1e-12)
        # A elevated to degree 4 (the same curve; the general engine, not the cubic fast
        # path) against C.
        A4 = [A[0]] + [[(k * A[k - 1][d] + (4 - k) * A[k][d]) / 4 for d in range(2)] for k in range(1, 4)] + [A[3]]
        r = self.ok("intersect", {"curves": [bezier(A4), bezier(C)]})
        self.assertEqual(len(r["intersections"]), 1, r)
        self.assert_close(r["intersections"][0]["t"], [s, t], 1e-12)


def random_cubic(rng):
    return [[rng.random(), rng.random()] for _ in range(4)]


def polyline_crossings(A, B, n=1500):
    """Crossings of the n-segment polylines of A and B (sampled at uniform parameters), as
    approximate parameter pairs: an independent estimate, vectorised with numpy."""
    t = np.linspace(0, 1, n + 1)

    def sample(P):
        P = np.array(P, dtype=float)
        m = len(P) - 1
        Bm = np.array([math.comb(m, i) * t ** i * (1 - t) ** (m - i) for i in range(m + 1)])
        return Bm.T @ P

    a, b = sample(A), sample(B)
    # Only the segments of chunks whose bounding boxes overlap can cross: the chunks of 30
    # segments are paired by their boxes first (each segment is in one chunk, so every
    # crossing of the polylines is found once, as by the full n x n test).
    c = 30
    chunks = [(k, min(k + c, n)) for k in range(0, n, c)]

    def boxes(P):
        return np.array([[P[i:j + 1].min(axis=0), P[i:j + 1].max(axis=0)] for i, j in chunks])

    ba, bb = boxes(a), boxes(b)
    close = np.all((ba[:, None, 0] <= bb[None, :, 1]) & (bb[None, :, 0] <= ba[:, None, 1]), axis=-1)
    out = []
    for ci, cj in zip(*np.nonzero(close)):
        (i0, i1), (j0, j1) = chunks[ci], chunks[cj]
        p, r = a[i0:i1], a[i0 + 1:i1 + 1] - a[i0:i1]
        q, s = b[j0:j1], b[j0 + 1:j1 + 1] - b[j0:j1]
        rxs = r[:, None, 0] * s[None, :, 1] - r[:, None, 1] * s[None, :, 0]
        qp = q[None, :, :] - p[:, None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            u = (qp[..., 0] * s[None, :, 1] - qp[..., 1] * s[None, :, 0]) / rxs
            v = (qp[..., 0] * r[:, None, 1] - qp[..., 1] * r[:, None, 0]) / rxs
        ok = (rxs != 0) & (u >= 0) & (u <= 1) & (v >= 0) & (v <= 1)
        i, j = np.nonzero(ok)
        out += [((i0 + i[k] + u[i[k], j[k]]) / n, (j0 + j[k] + v[i[k], j[k]]) / n) for k in range(len(i))]
    return out


class RandomPropertyTest(CliTest):
    def test_random_cubic_pairs(self):
        rng = random.Random(20261130)
        pairs = found = 0
        for _ in range(60):
            A, B = random_cubic(rng), random_cubic(rng)
            r = self.ok("intersect", {"curves": [bezier(A), bezier(B)]})
            pairs += 1
            self.assertEqual(r["overlaps"], [])
            hits = r["intersections"]
            found += len(hits)
            for h in hits:
                # On both curves to 1e-9 of the size (unit square: size <= sqrt(2)).
                self.assertLess(dist(de_casteljau(A, h["t"][0]), de_casteljau(B, h["t"][1])), 1e-9)
                self.assertLess(dist(de_casteljau(A, h["t"][0]), h["point"]), 1e-12)
                # mpmath oracle for crossings: parameters to ~1e-15 / sin(angle).
                if h["kind"] == "crossing":
                    s, t = mp_refine(A, B, h["t"][0], h["t"][1])
                    self.assertAlmostEqual(h["t"][0], s, delta=1e-13)
                    self.assertAlmostEqual(h["t"][1], t, delta=1e-13)
            # Every crossing of the dense polylines is near a reported point.
            for (ta, tb) in polyline_crossings(A, B):
                near = [h for h in hits if abs(h["t"][0] - ta) < 2e-3 and abs(h["t"][1] - tb) < 2e-3]
                self.assertTrue(near, f"missed a crossing near {(ta, tb)} of {A} and {B}: {hits}")
        self.assertGreater(found, 20)  # the sample does exercise crossings

    def test_random_rational_pairs_lie_on_both(self):
        rng = random.Random(7)
        for _ in range(20):
            A, B = random_cubic(rng), random_cubic(rng)
            wa = [rng.uniform(0.2, 5) for _ in range(4)]
            wb = [rng.uniform(0.2, 5) for _ in range(4)]
            r = self.ok("intersect", {"curves": [{"type": "rational_bezier", "points": A, "weights": wa},
                                                 {"type": "rational_bezier", "points": B, "weights": wb}]})
            for h in r["intersections"]:
                self.assertLess(dist(rational_point(A, wa, h["t"][0]), rational_point(B, wb, h["t"][1])), 1e-9)

    def test_random_self_intersections_are_double_points(self):
        rng = random.Random(11)
        loops = 0
        for _ in range(40):
            P = [[rng.uniform(-1, 1), rng.uniform(-1, 1)] for _ in range(5)]
            r = self.ok("intersect", {"curves": [bezier(P)]})
            for h in r["intersections"]:
                loops += 1
                self.assertLess(h["t"][0], h["t"][1])
                self.assertGreater(h["t"][1] - h["t"][0], 1e-6)
                self.assertLess(dist(de_casteljau(P, h["t"][0]), de_casteljau(P, h["t"][1])), 1e-9)
        self.assertGreater(loops, 3)


class HardInputTest(CliTest):
    """The general engine on near-coincident curves and at high degree, checked by mpmath."""

    def on_both(self, A, B, r, size):
        """Every reported point lies on both curves to 1e-12 of the size (mpmath, 30 digits)."""
        with mpmath.workdps(30):
            for h in r["intersections"]:
                pa = mp_bezier(A, mpmath.mpf(h["t"][0]))
                pb = mp_bezier(B, mpmath.mpf(h["t"][1]))
                self.assertLess(float(mpmath.sqrt(sum((x - y) ** 2 for x, y in zip(pa, pb)))), 1e-12 * size, h)
                self.assertLess(float(mpmath.sqrt(sum((x - y) ** 2 for x, y in zip(pa, h["point"])))), 1e-12 * size, h)

    def test_turned_copy(self):
        # A cubic and its copy turned by 1e-6 about c(0.5): one crossing there (an angle of
        # 1e-6, so parameters to about eps / 1e-6); the refined mpmath root agrees.
        P = [[0, 0], [1, 2], [3, -1], [4, 1]]
        o = mp_bezier(P, mpmath.mpf("0.5"))
        a = 1e-6
        Q = [[float(o[0]) + math.cos(a) * (x - float(o[0])) - math.sin(a) * (y - float(o[1])),
              float(o[1]) + math.sin(a) * (x - float(o[0])) + math.cos(a) * (y - float(o[1]))] for x, y in P]
        r = self.ok("intersect", {"curves": [bezier(P), bezier(Q)]})
        self.assertEqual(r["overlaps"], [])
        self.assertEqual(len(r["intersections"]), 1, r)
        self.on_both(P, Q, r, 5)
        s, t = mp_refine(P, Q, *r["intersections"][0]["t"])
        self.assert_close(r["intersections"][0]["t"], [s, t], 1e-9)
        self.assert_close([s, t], [0.5, 0.5], 1e-9)

    def test_translated_copies(self):
        # Apart by 1e-9 of the size (5): a near miss, nothing; by 1e-11: one overlap.
        P = [[0, 0], [1, 2], [3, -1], [4, 1]]
        far = self.ok("intersect", {"curves": [bezier(P), bezier([[x, y + 5e-9] for x, y in P])]})
        self.assertEqual(far, {"intersections": [], "overlaps": []})
        near = self.ok("intersect", {"curves": [bezier(P), bezier([[x, y + 5e-11] for x, y in P])]})
        self.assertEqual(near["intersections"], [])
        self.assertEqual(len(near["overlaps"]), 1, near)
        self.assert_close(near["overlaps"][0]["a"], [0, 1], 1e-12)
        self.assert_close(near["overlaps"][0]["b"], [0, 1], 1e-12)

    def test_high_degree_pair(self):
        # Two random degree-120 curves (the limit is 500): every point on both curves
        # (mpmath), sorted by ta.
        rng = random.Random(120)
        A = [[rng.random(), rng.random()] for _ in range(121)]
        B = [[rng.random(), rng.random()] for _ in range(121)]
        r = self.ok("intersect", {"curves": [bezier(A), bezier(B)]})
        self.assertGreater(len(r["intersections"]), 10)
        self.on_both(A, B, r, math.sqrt(2))
        ts = [h["t"][0] for h in r["intersections"]]
        self.assertEqual(ts, sorted(ts))
        # Degree 300 (refused up to the limit's raise from 200) against the line y = 0.5:
        # accepted, every point on the line and on the curve (de Casteljau in Python).
        C = [[i / 300, rng.random()] for i in range(301)]
        r = self.ok("intersect", {"curves": [bezier(C), bezier([[-1, 0.5], [2, 0.5]])]})
        self.assertGreater(len(r["intersections"]), 0)
        for h in r["intersections"]:
            self.assertLess(abs(h["point"][1] - 0.5), 1e-12, h)
            self.assertLess(dist(de_casteljau(C, h["t"][0]), h["point"]), 1e-12, h)


    def test_identical_high_degree_curves_are_one_overlap(self):
        # Identical curves coincide everywhere: one overlap over both domains, no point
        # (every common point lies inside it). Each pair of identical monotone arcs is an
        # overlap at once (it took seconds per pair at high degree).
        rng = random.Random(61)
        P = [[rng.random(), rng.random()] for _ in range(61)]
        r = self.ok("intersect", {"curves": [bezier(P), bezier(P)]})
        self.assertEqual(r, {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 1.0]}]})

    def test_identical_degree_500_curves_are_one_overlap(self):
        # Degree 500 (10 s before session 15, against 1 s for a random pair of that degree;
        # now a fraction of a second: docs/testing.md): a Bézier curve and its copy, and a
        # B-spline of two degree-500 pieces and its copy, each one overlap over the whole
        # domain. Timing is not asserted.
        rng = random.Random(500)
        P = [[10 * rng.random(), 10 * rng.random()] for _ in range(501)]
        r = self.ok("intersect", {"curves": [bezier(P), bezier(P)]})
        self.assertEqual(r, {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 1.0]}]})
        Q = [[10 * rng.random(), 10 * rng.random()] for _ in range(502)]
        spline = {"type": "bspline", "degree": 500, "knots": [0] * 501 + [1] + [2] * 501, "points": Q}
        r = self.ok("intersect", {"curves": [spline, spline]})
        self.assertEqual(r, {"intersections": [], "overlaps": [{"a": [0.0, 2.0], "b": [0.0, 2.0]}]})

    def test_copy_moved_within_the_distance_is_one_overlap(self):
        # A random curve and its copy moved by 1e-9 along x: 0.7 of the meeting distance
        # (1e-10 of the control box's diagonal, about 14), so the copy lies within it all
        # along: one overlap over both domains, no point. Before session 15 these answered
        # two overlaps meeting end to end and a few "crossings" between them. Before session
        # 16: (20, 7) two overlaps with a gap [0.826, 0.948] and 7 points, the others points
        # only or an overlap and points (a sliver at an arc end where the copy's shift is
        # along the tangent kept the overlaps of consecutive arcs apart).
        for n, seed in ((20, 2), (40, 3), (80, 6), (20, 7), (20, 16), (20, 31), (40, 24), (40, 34), (80, 39)):
            rng = random.Random(seed)
            P = [[10 * rng.random(), 10 * rng.random()] for _ in range(n + 1)]
            moved = [[x + 1e-9, y] for x, y in P]
            r = self.ok("intersect", {"curves": [bezier(P), bezier(moved)]})
            self.assertEqual(r, {"intersections": [], "overlaps": [{"a": [0.0, 1.0], "b": [0.0, 1.0]}]}, (n, seed))

    def test_high_degree_curve_and_its_portion_are_one_overlap(self):
        # A random degree-200 curve and its portion [0.2, 0.7] re-parametrised to [0, 1]
        # (de Casteljau's triangle here, in Python's doubles): one overlap, a from 0.2 to
        # 0.7 against the whole of b, the same way.
        rng = random.Random(200)
        P = [[10 * rng.random(), 10 * rng.random()] for _ in range(201)]
        _, right = split_points(P, 0.2)
        portion, _ = split_points(right, 0.5 / 0.8)
        r = self.ok("intersect", {"curves": [bezier(P), bezier(portion)]})
        self.assertEqual(len(r["overlaps"]), 1, r["overlaps"])
        o = r["overlaps"][0]
        self.assertAlmostEqual(o["a"][0], 0.2, delta=1e-9)
        self.assertAlmostEqual(o["a"][1], 0.7, delta=1e-9)
        self.assertEqual(o["b"], [0.0, 1.0])
        # Every other point is a crossing of P's parts outside [0.2, 0.7] with the portion:
        # on both curves (de Casteljau at the reported parameters).
        for h in r["intersections"]:
            self.assertFalse(0.2 < h["t"][0] < 0.7, h)
            self.assertLess(dist(de_casteljau(P, h["t"][0]), de_casteljau(portion, h["t"][1])), 1e-8, h)

    def test_answers_past_the_limit_are_refused(self):
        # A random 3,000-point polyline meets itself about 2.5 million times (a 114 MB
        # answer before): refused, naming the request's field and the limit.
        rng = random.Random(3000)
        poly = {"type": "polyline", "points": [[rng.random(), rng.random()] for _ in range(3000)]}
        self.bad("intersect", {"curves": [poly]}, "curves", contains="more than 100000 points")
        # Two random 2,000-point polylines (about a million crossings): refused too.
        a = {"type": "polyline", "points": [[rng.random(), rng.random()] for _ in range(2000)]}
        b = {"type": "polyline", "points": [[rng.random(), rng.random()] for _ in range(2000)]}
        self.bad("intersect", {"curves": [a, b]}, "curves", contains="more than 100000 points")
        # Below the limit the answer stands: 300 random points meet themselves thousands of times.
        small = {"type": "polyline", "points": [[rng.random(), rng.random()] for _ in range(300)]}
        r = self.ok("intersect", {"curves": [small]})
        self.assertGreater(len(r["intersections"]), 1000)



def nurbs_circle(cx, cy):
    """The unit circle about (cx, cy) as a NURBS of four rational quadratic quarters
    (weights sqrt(2)/2 at the corners) on [0, 4] [PT97, 7.5]."""
    w = math.sqrt(2) / 2
    P = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]]
    return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4],
            "points": [[x + cx, y + cy] for x, y in P], "weights": [1, w, 1, w, 1, w, 1, w, 1]}


def mp_nurbs_circle(c, u):
    """That curve at u in mpmath: quarter i = floor(u) is the rational quadratic on control
    points 2i .. 2i + 2 at t = u - i."""
    i = min(int(u), 3)
    t = mpmath.mpf(u) - i
    P, w = c["points"][2 * i:2 * i + 3], c["weights"][2 * i:2 * i + 3]
    b = [(1 - t) ** 2, 2 * t * (1 - t), t ** 2]
    den = sum(b[k] * w[k] for k in range(3))
    return [sum(b[k] * w[k] * mpmath.mpf(P[k][j]) for k in range(3)) / den for j in range(2)]


class NearCoincidentTest(CliTest):
    """Curves within a few near-miss distances (1e-10 of the size) along long stretches:
    decided on the separation polynomial of near-parallel parts (algo/intersect/band.hpp),
    checked by mpmath and closed forms."""

    on_both = HardInputTest.on_both

    def test_copy_turned_by_1e9(self):
        # A cubic and its copy turned by 1e-9 about c(t0) cross there once, at an angle of
        # 1e-9 (below the 1e-6 of `tangent`): parameters to about eps / 1e-9 (2e-7) of the
        # mpmath crossing of the rounded control points, and of t0 itself.
        P = [[0, 0], [1, 2], [3, -1], [4, 1]]
        for t0 in (0.0, 0.3, 0.5, 1.0):
            o = [float(x) for x in mp_bezier(P, mpmath.mpf(t0))]
            a = 1e-9
            Q = [[o[0] + math.cos(a) * (x - o[0]) - math.sin(a) * (y - o[1]),
                  o[1] + math.sin(a) * (x - o[0]) + math.cos(a) * (y - o[1])] for x, y in P]
            r = self.ok("intersect", {"curves": [bezier(P), bezier(Q)]})
            self.assertEqual(r["overlaps"], [], t0)
            self.assertEqual(len(r["intersections"]), 1, (t0, r))
            x = r["intersections"][0]
            self.assertEqual(x["kind"], "tangent")
            self.assert_close(x["t"], [t0, t0], 1e-6)
            self.on_both(P, Q, r, 5)
            if 0 < t0 < 1:
                s, t = mp_refine(P, Q, t0, t0)
                self.assert_close(x["t"], [s, t], 1e-6)

    def test_circles_with_close_centres(self):
        # Unit circles with centres d apart cross at c / 2 +- n sqrt(1 - d^2 / 4) (n normal
        # to the offset c) at an angle of d: two points, `tangent` below 1e-6, never an
        # overlap, whether the crossings fall on joints of the quarters (offset along x: at
        # (d/2, +-1)) or inside them (diagonal offset). Points on both circles to 1e-12 of
        # the size (mpmath), at the closed form to 4 eps / d (the conditioning of a crossing
        # at angle d). At d = 1.4e-5 .. 2.4e-5 along x the crossings lie between joints of
        # the two circles d apart, within d^2 / 2 of each other there: not an overlap.
        for d in (3e-10, 1e-8, 1e-7, 1e-5, 1.4e-5, 2.2e-5):
            for diagonal in (False, True):
                u = [math.sqrt(0.5), math.sqrt(0.5)] if diagonal else [1.0, 0.0]
                c = [d * u[0], d * u[1]]
                A, B = nurbs_circle(0, 0), nurbs_circle(*c)
                r = self.ok("intersect", {"curves": [A, B]})
                self.assertEqual(r["overlaps"], [], (d, diagonal))
                self.assertEqual(len(r["intersections"]), 2, (d, diagonal, r))
                h = math.sqrt(1 - d * d / 4)
                expected = [[c[0] / 2 - u[1] * h, c[1] / 2 + u[0] * h], [c[0] / 2 + u[1] * h, c[1] / 2 - u[0] * h]]
                found = sorted(range(2), key=lambda k: dist(r["intersections"][k]["point"], expected[0]))
                for k, e in zip(found, expected):
                    x = r["intersections"][k]
                    self.assertLess(dist(x["point"], e), 4 * 2.2e-16 / d, (d, diagonal, x, e))
                    self.assertEqual(x["kind"], "tangent" if d < 1e-6 else "crossing", (d, diagonal))
                    with mpmath.workdps(30):
                        pa, pb = mp_nurbs_circle(A, x["t"][0]), mp_nurbs_circle(B, x["t"][1])
                        self.assertLess(float(mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(pa, pb)))), 1e-12 * 2.83, x)
                        self.assertLess(float(mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(pa, x["point"])))), 1e-12 * 2.83, x)

    def test_copies_one_to_three_near_miss_distances_apart(self):
        # Translated along the normal of the chord by k 1e-10 of the size (5): the curves are
        # k (0.65 .. 1) 1e-10 of the size apart (the cosine of the tangent's angle to the
        # chord). At k = 2, 3 farther than the near-miss distance everywhere: nothing. At
        # k = 0.5 within it everywhere: one overlap.
        P = [[0, 0], [1, 2], [3, -1], [4, 1]]
        n = [-1 / math.sqrt(17), 4 / math.sqrt(17)]
        for k in (2, 3, 0.5):
            Q = [[x + k * 5e-10 * n[0], y + k * 5e-10 * n[1]] for x, y in P]
            r = self.ok("intersect", {"curves": [bezier(P), bezier(Q)]})
            self.assertEqual(r["intersections"], [], k)
            if k > 1:
                self.assertEqual(r["overlaps"], [], k)
            else:
                self.assertEqual(len(r["overlaps"]), 1, r)
                self.assert_close(r["overlaps"][0]["a"], [0, 1], 1e-12)


def nurbs_circle_r(cx, cy, r):
    """The circle of radius r about (cx, cy), built as nurbs_circle (quarter i on [i, i + 1]:
    the joints u = 0, 1, 2, 3 at angles 0, 90, 180, 270 degrees)."""
    c = nurbs_circle(0, 0)
    c["points"] = [[cx + r * x, cy + r * y] for x, y in c["points"]]
    return c


def mp_line_touch(C, L, t0):
    """The parameter t of the Bézier C where its tangent is parallel to the segment L, near t0,
    and the foot parameter of C(t) on L (mpmath at 50 digits, on the double inputs)."""
    with mpmath.workdps(50):
        n = len(C) - 1
        D = [[n * (mpmath.mpf(C[i + 1][k]) - mpmath.mpf(C[i][k])) for k in range(2)] for i in range(n)]
        v = [mpmath.mpf(L[1][k]) - mpmath.mpf(L[0][k]) for k in range(2)]
        f = lambda t: (lambda d: d[0] * v[1] - d[1] * v[0])(mp_bezier(D, t))
        t = mpmath.findroot(f, mpmath.mpf(t0))
        p = mp_bezier(C, t)
        u = sum((p[k] - mpmath.mpf(L[0][k])) * v[k] for k in range(2)) / sum(x * x for x in v)
        return float(t), float(u)


class TouchLocationTest(CliTest):
    """Touches within the near-miss distance (1e-10 of the size): a near miss, or two
    crossings closer than that, give one tangent point where the curves are closest (or
    farthest apart between the crossings): the extremum of their separation, where the
    tangents are parallel. Checked against closed forms (the apex of a parabola, the points
    on the line of the centres of two circles) and mpmath (a cubic and a line parallel to
    its tangent)."""

    def one_touch(self, r, msg):
        self.assertEqual(r["overlaps"], [], msg)
        self.assertEqual(len(r["intersections"]), 1, (msg, r))
        x = r["intersections"][0]
        self.assertEqual(x["kind"], "tangent", msg)
        return x

    def test_parabola_and_line_near_its_apex(self):
        # y = 4 t (1 - t) peaks at t = 1/2, (1, 1); the line y = 1 + d from x = -1 to 3 has
        # tb = 1/2 below it. d < 0: two crossings 2 sqrt(-d) apart in t (3.2e-6 at -1e-11,
        # the middle of the points merged used to give t = 0.5000008); d > 0: a near miss
        # within the distance (4e-10 here). Both: the apex, to 1e-14 (g = u_a x u_b has
        # slope 4 there, rounded to a few eps).
        for d in (-1e-11, 1e-11, -1e-10, 1e-10, -3e-10, 3e-10, -1e-12):
            r = self.ok("intersect", {"curves": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[-1, 1 + d], [3, 1 + d]])]})
            x = self.one_touch(r, d)
            self.assert_close(x["t"], [0.5, 0.5], 1e-14, d)
            self.assert_close(x["point"], [1, 1], 1e-14, d)
        # Farther than the distance: nothing above, two crossings below.
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[-1, 1 + 6e-10], [3, 1 + 6e-10]])]})
        self.assertEqual(r["intersections"], [])
        r = self.ok("intersect", {"curves": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[-1, 1 - 6e-10], [3, 1 - 6e-10]])]})
        self.assertEqual([x["kind"] for x in r["intersections"]], ["crossing", "crossing"], r)

    def test_touch_on_a_joint_of_pieces(self):
        # The parabola's halves as a path on [0, 2]: the apex is the joint, t = 1. The NURBS
        # unit circle against y = 1 + d: the top (0, 1) is the joint u = 1 of its quarters,
        # tb = 1/2 on the line from x = -2 to 2.
        halves = {"type": "path", "segments": [bezier([[0, 0], [0.5, 1], [1, 1]]), bezier([[1, 1], [1.5, 1], [2, 0]])]}
        for d in (-1e-11, 1e-11, -1e-10):
            r = self.ok("intersect", {"curves": [halves, bezier([[-1, 1 + d], [3, 1 + d]])]})
            x = self.one_touch(r, d)
            self.assert_close(x["t"], [1, 0.5], 1e-14, d)
            r = self.ok("intersect", {"curves": [nurbs_circle(0, 0), bezier([[-2, 1 + d], [2, 1 + d]])]})
            x = self.one_touch(r, d)
            self.assert_close(x["t"], [1, 0.5], 1e-14, d)
            self.assert_close(x["point"], [0, 1], 1e-14, d)

    def test_cubic_and_a_line_parallel_to_its_tangent(self):
        # The line through c(t0) + d n along the tangent at t0 (n the unit normal): the
        # touch is where c's tangent is parallel to the line (mpmath on the rounded line),
        # at the foot of that point on the line.
        P = [[0, 0], [1, 2], [3, -1], [4, 1]]
        for t0 in (0.3, 0.7):
            with mpmath.workdps(30):
                p = [float(x) for x in mp_bezier(P, mpmath.mpf(t0))]
                D = [[3 * (P[i + 1][k] - P[i][k]) for k in range(2)] for i in range(3)]
                v = [float(x) for x in mp_bezier(D, mpmath.mpf(t0))]
            s = math.hypot(*v)
            v = [v[0] / s, v[1] / s]
            n = [-v[1], v[0]]
            for d in (-1e-11, 1e-11, -2e-10, 2e-10):
                L = [[p[0] - 2 * v[0] + d * n[0], p[1] - 2 * v[1] + d * n[1]],
                     [p[0] + 2 * v[0] + d * n[0], p[1] + 2 * v[1] + d * n[1]]]
                r = self.ok("intersect", {"curves": [bezier(P), bezier(L)]})
                x = self.one_touch(r, (t0, d))
                ta, tb = mp_line_touch(P, L, t0)
                self.assertLess(abs(ta - t0), 1e-9)  # the oracle found the touch near t0
                self.assert_close(x["t"], [ta, tb], 1e-13, (t0, d))

    def test_circles_touching(self):
        # Circles of radius 1 and r whose centres are 1 + r + d apart (outside each other)
        # or 1 - r + d (inside) along the direction phi: they touch, within d, at the unit
        # circle's point (cos phi, sin phi) and the other's point nearest it on the line of
        # centres. phi = pi/2 puts the touch on joints of the quarters of both circles.
        for phi in (math.pi / 2, 0.5):
            u = [math.cos(phi), math.sin(phi)]
            for inside, r in ((False, 1.0), (True, 0.5)):
                for d in (-1e-11, 1e-11, -1e-10):
                    k = (1 - r if inside else 1 + r) + d
                    c = [k * u[0], k * u[1]]
                    A, B = nurbs_circle(0, 0), nurbs_circle_r(c[0], c[1], r)
                    res = self.ok("intersect", {"curves": [A, B]})
                    msg = (phi, inside, d)
                    x = self.one_touch(res, msg)
                    pb = [c[0] + r * u[0], c[1] + r * u[1]] if inside else [c[0] - r * u[0], c[1] - r * u[1]]
                    self.assertLess(dist(x["point"], u), 1e-14, msg)
                    with mpmath.workdps(30):
                        self.assertLess(dist([float(y) for y in mp_nurbs_circle(A, x["t"][0])], u), 1e-14, msg)
                        self.assertLess(dist([float(y) for y in mp_nurbs_circle(B, x["t"][1])], pb), 1e-14, msg)

    def test_closing_point_of_a_closed_curve_listed_once(self):
        # The NURBS circle passes (1, 0) at u = 0 and again at u = 4: a crossing or touch
        # there is one point (u = 0 or 4), not two. The line y = 0 crosses there; the unit
        # circle about (2 + d, 0) touches there (at its own u = 2); the line x = 1 - 1e-11 a
        # near miss within the distance, the circle second.
        def at_closing(u):
            return min(abs(u), abs(u - 4))
        r = self.ok("intersect", {"curves": [nurbs_circle(0, 0), bezier([[0, 0], [2, 0]])]})
        self.assertEqual(len(r["intersections"]), 1, r)
        x = r["intersections"][0]
        self.assertEqual(x["kind"], "crossing")
        self.assertLess(at_closing(x["t"][0]), 1e-15)
        self.assert_close(x["point"], [1, 0], 1e-15)
        for d in (-1e-11, 1e-11, -1e-10):
            r = self.ok("intersect", {"curves": [nurbs_circle(0, 0), nurbs_circle(2 + d, 0)]})
            x = self.one_touch(r, d)
            self.assertLess(at_closing(x["t"][0]), 1e-14, d)
            self.assertLess(abs(x["t"][1] - 2), 1e-14, d)
            self.assertLess(dist(x["point"], [1, 0]), 1e-14, d)
        r = self.ok("intersect", {"curves": [bezier([[1 - 1e-11, -1], [1 - 1e-11, 1]]), nurbs_circle(0, 0)]})
        x = self.one_touch(r, "line")
        self.assertLess(abs(x["t"][0] - 0.5), 1e-14)
        self.assertLess(at_closing(x["t"][1]), 1e-14)


class BadInputTest(CliTest):
    def test_errors(self):
        line = bezier([[0, 0], [1, 1]])
        self.bad("intersect", {"curves": []}, "curves", contains="one curve")
        self.bad("intersect", {"curves": [line, line, line]}, "curves", contains="got 3")
        self.bad("intersect", {"curves": line}, "curves", contains="array")
        self.bad("intersect", {}, "curves", contains="missing")
        self.bad("intersect", {"curves": [line, bezier([[0, 0, 0], [1, 1, 1]])]}, "curves[1]", contains="2-D")
        self.bad("intersect", {"curves": [bezier([[0], [1]])]}, "curves[0]", contains="2-D")
        self.bad("intersect", {"curves": [line, {"type": "bezier", "points": [[0, 0], [1, "x"]]}]}, "curves[1].points[1][1]")
        self.bad("intersect", {"curves": [line, line], "tolerance": 1}, "tolerance", contains="unknown")
        high = bezier([[i / 500, (i % 7) / 7] for i in range(502)])  # degree 501
        self.bad("intersect", {"curves": [line, high]}, "curves[1]", contains="degree 500")


def intersect_work(a, b=None):
    """The documented up-front estimate (docs/cli.md, intersect): over pairs of Bézier
    pieces of degrees n and m, (n + 1)(m + 1)(n + m + 2) / 2; for one curve, over its pairs
    of distinct pieces. Pieces are given by their point counts n + 1; equal counts are
    grouped (a 16,000-point polyline has 1.3e8 pairs), the sum taken over the groups."""
    from collections import Counter
    pair = lambda x, y: x * y * (x + y) // 2
    ca = Counter(a)
    if b is None:
        items = sorted(ca.items())
        total = 0
        for i, (x, nx) in enumerate(items):
            total += nx * (nx - 1) // 2 * pair(x, x)  # pairs within the group
            total += sum(nx * ny * pair(x, y) for y, ny in items[i + 1:])
        return total
    return sum(nx * ny * pair(x, y) for x, nx in ca.items() for y, ny in Counter(b).items())


class WorkLimitTest(CliTest):
    LIMIT = 10 ** 9

    def test_runaway_requests_are_refused_with_the_figure(self):
        rng = random.Random(20000)
        walk = lambda n: {"type": "polyline", "points": [[rng.uniform(-1, 1) + i, rng.uniform(-1, 1)] for i in range(n)]}
        # Two 20,000-point polylines: 19,999^2 pairs of segments, 8 units each.
        want = intersect_work([2] * 19999, [2] * 19999)
        self.assertEqual(want, 8 * 19999 ** 2)
        err = self.bad("intersect", {"curves": [walk(20000), walk(20000)]}, "curves",
                       contains=f"about {want} units of work")
        self.assertIn(f"limit of {self.LIMIT}", err)
        # One 16,000-point polyline's self-intersections: 15,999 * 15,998 / 2 pairs.
        want = intersect_work([2] * 15999)
        self.assertGreater(want, self.LIMIT)
        self.bad("intersect", {"curves": [walk(16000)]}, "curves[0]", contains=f"about {want} units of work")
        # Eight degree-500 pieces against a degree-500 curve: 8 pairs of 501 * 501 * 1002 / 2.
        bez = lambda: bezier([[rng.random(), rng.random()] for _ in range(501)])
        path = {"type": "path", "segments": [bez() for _ in range(8)]}
        self.bad("intersect", {"curves": [path, bez()]}, "curves", contains=f"about {intersect_work([501] * 8, [501])} units")
        # A B-spline is estimated before its pieces are made (for 2,700 pieces of degree 300
        # that alone takes a minute): at most n - p pieces of degree p.
        bs = {"type": "bspline", "degree": 300, "knots": [0] * 301 + list(range(1, 2700)) + [2700] * 301,
              "points": [[i, rng.random()] for i in range(3000)]}
        self.bad("intersect", {"curves": [bs]}, "curves[0]", contains=f"about {intersect_work([301] * 2700)} units")
        self.bad("intersect", {"curves": [bezier([[0, 0], [1, 1]]), bs]}, "curves[1]",
                 contains=f"about {2700 * 301 ** 2} units of work (pieces x (degree + 1)^2)")

    def test_reasonable_requests_run(self):
        # Under the limit: two 1,000-point polylines (8e6 units) and two degree-500 curves
        # (1.3e8) answer; polylines that meet nowhere give nothing.
        rng = random.Random(1000)
        a = {"type": "polyline", "points": [[i / 1000, rng.random()] for i in range(1000)]}
        b = {"type": "polyline", "points": [[i / 1000, 2 + rng.random()] for i in range(1000)]}
        self.assertEqual(self.ok("intersect", {"curves": [a, b]}), {"intersections": [], "overlaps": []})
        self.assertLess(intersect_work([501], [501]), self.LIMIT)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
