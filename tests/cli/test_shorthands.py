#!/usr/bin/python3
"""Black-box tests of the curve shorthands `circle`, `ellipse` and `arc`, read as the exact
nurbs of the NURBS Book's construction.

Oracles, written here from closed forms: the implicit equations of the circle, the
ellipse and the plane of a 3-D circle; the points at the pieces' joints (the angles
start + i sweep / k); the nine-point circle of [PT97] Ex. 7.2 (control points on the
square, weights 1 and sqrt(2)/2, knots 0, 1/4, 1/2, 3/4 doubled); length 2 pi r, r times
the sweep, the ellipse's perimeter by mpmath (the complete elliptic integral); areas
pi r^2 and pi a b; the rational quadratic evaluated here (mpmath) from the returned
nurbs for the parametrization.

Usage: test_shorthands.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import sys
import unittest

import mpmath

import test_cli
from test_cli import CliTest


def circle(center, radius, **extra):
    return dict({"type": "circle", "center": center, "radius": radius}, **extra)


def ellipse(center, radii, **extra):
    return dict({"type": "ellipse", "center": center, "radii": radii}, **extra)


def arc(center, radius, a0, a1):
    return {"type": "arc", "center": center, "radius": radius, "start_angle": a0, "end_angle": a1}


def nurbs_point(c, t):
    """The nurbs at t by the definition (mpmath, 40 digits): sum N_i w_i P_i / sum N_i w_i,
    the B-spline basis by the Cox-de Boor recursion (right-continuous; t = last knot
    taken on the last span)."""
    with mpmath.workdps(40):
        U = [mpmath.mpf(u) for u in c["knots"]]
        p, P, w = c["degree"], c["points"], c["weights"]
        n = len(P)
        T = mpmath.mpf(t)

        def N(i, k):
            if k == 0:
                if U[i] <= T < U[i + 1] or (T == U[-1] and U[i] < U[i + 1] == U[-1]):
                    return mpmath.mpf(1)
                return mpmath.mpf(0)
            a = (T - U[i]) / (U[i + k] - U[i]) * N(i, k - 1) if U[i + k] != U[i] else 0
            b = (U[i + k + 1] - T) / (U[i + k + 1] - U[i + 1]) * N(i + 1, k - 1) if U[i + k + 1] != U[i + 1] else 0
            return a + b

        B = [N(i, p) * w[i] for i in range(n)]
        den = sum(B)
        return [float(sum(B[i] * P[i][d] for i in range(n)) / den) for d in range(len(P[0]))]


class ShorthandTest(CliTest):
    def nurbs(self, curve):
        # to_bspline of a nurbs is that nurbs (rebuilt from its pieces: an ulp or two).
        c = self.ok("to_bspline", {"curve": curve})["curve"]
        self.assertEqual(c["type"], "nurbs")
        return c

    def test_circle_is_the_nine_point_nurbs(self):
        # [PT97] Ex. 7.2, the unit circle: control points on the square, weights 1 and
        # 1/sqrt 2 (= cos 45 deg), knots 0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1. The program
        # forms the corners as center + (cos, sin)(mid angle) / cos 45: a few ulps.
        c = self.nurbs(circle([0, 0], 1))
        self.assertEqual(c["degree"], 2)
        self.assertEqual(c["knots"], [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1])
        want = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]]
        for got, p in zip(c["points"], want):
            for a, b in zip(got, p):
                self.assertAlmostEqual(a, b, delta=4e-16)
        for got, wt in zip(c["weights"], [1, 0.5 ** 0.5] * 4 + [1]):
            self.assertAlmostEqual(got, wt, delta=2e-16)

    def test_points_on_the_circle_and_ellipse(self):
        ts = [i / 97 for i in range(98)]
        for center, r in (([0, 0], 1), ([3, -2], 0.25), ([1e3, 2e3], 7)):
            pts = self.ok("eval", {"curve": circle(center, r), "t": ts})["points"]
            for p in pts:
                # |P - C| = r: the conic is exact; rounding of the nurbs evaluation, a few
                # eps of |C| + r.
                self.assertLessEqual(abs(math.hypot(p[0] - center[0], p[1] - center[1]) - r), 4e-16 * (r + max(map(abs, center))))
        for center, (a, b), rot in (([0, 0], (2, 1), 0), ([1, 1], (3, 0.5), 0.7), ([-2, 5], (1, 4), -2.5)):
            pts = self.ok("eval", {"curve": ellipse(center, [a, b], rotation=rot), "t": ts})["points"]
            for p in pts:
                dx, dy = p[0] - center[0], p[1] - center[1]
                u = dx * math.cos(rot) + dy * math.sin(rot)
                v = -dx * math.sin(rot) + dy * math.cos(rot)
                # (u / a)^2 + (v / b)^2 = 1 to a few eps (relative to the larger radius).
                self.assertLessEqual(abs((u / a) ** 2 + (v / b) ** 2 - 1), 1e-15 * max(a, b) / min(a, b) * (1 + max(map(abs, center))))

    def test_start_points_and_joints(self):
        # The curve starts at its start angle (0 for circle and ellipse) and the k pieces
        # join at the angles start + i sweep / k at the parameters i / k, k = ceil(sweep / 90 deg).
        for a0, a1 in ((0, math.pi / 2), (0.3, 2.0), (-1, 1.5), (1, 1 + 2 * math.pi), (2, 2 + 0.1), (0, 3 * math.pi / 2 + 0.01)):
            r, C = 2.0, [1, -1]
            sweep = a1 - a0
            k = max(1, math.ceil(sweep / (math.pi / 2) - 1e-12))
            c = self.nurbs(arc(C, r, a0, a1))
            self.assertEqual(len(c["points"]), 2 * k + 1)
            ts = [i / k for i in range(k + 1)]
            pts = self.ok("eval", {"curve": arc(C, r, a0, a1), "t": ts})["points"]
            for i, p in enumerate(pts):
                ang = a0 + i * sweep / k
                self.assertAlmostEqual(p[0], C[0] + r * math.cos(ang), delta=1e-15 * 4)
                self.assertAlmostEqual(p[1], C[1] + r * math.sin(ang), delta=1e-15 * 4)
            # The middle of a piece: a symmetric rational quadratic (end weights 1) is at
            # its mid angle at its mid parameter.
            mids = [(i + 0.5) / k for i in range(k)]
            pts = self.ok("eval", {"curve": arc(C, r, a0, a1), "t": mids})["points"]
            for i, p in enumerate(pts):
                ang = a0 + (i + 0.5) * sweep / k
                self.assertAlmostEqual(p[0], C[0] + r * math.cos(ang), delta=1e-15 * 4)
                self.assertAlmostEqual(p[1], C[1] + r * math.sin(ang), delta=1e-15 * 4)
        start = self.ok("eval", {"curve": circle([1, 2], 3), "t": [0, 1]})["points"]
        self.assertEqual(start, [[4, 2], [4, 2]])
        e = self.ok("eval", {"curve": ellipse([0, 0], [2, 1], rotation=math.pi / 2), "t": [0]})["points"][0]
        self.assertAlmostEqual(e[0], 0, delta=1e-15)
        self.assertAlmostEqual(e[1], 2, delta=1e-15)

    def test_parametrisation_is_the_nurbs_books(self):
        # Anywhere in the domain the program's point is the returned nurbs at t, by the
        # definition evaluated here (40 digits), and that nurbs is the construction's.
        for curve in (arc([0, 0], 1, 0.2, 2.9), ellipse([1, 2], [3, 1], rotation=0.4), circle([0, 0], 5)):
            c = self.nurbs(curve)
            ts = [0.05, 0.13, 0.37, 0.5, 0.61, 0.88, 0.99]
            pts = self.ok("eval", {"curve": curve, "t": ts})["points"]
            for t, p in zip(ts, pts):
                want = nurbs_point(c, t)
                for a, b in zip(p, want):
                    self.assertAlmostEqual(a, b, delta=1e-15 * 8)

    def test_length_and_area(self):
        for r in (1, 0.5, 3):
            L = self.ok("length", {"curve": circle([1, 1], r)})["length"]
            # The length query's accuracy (quadrature to about 1e-12 relative, docs/cli.md).
            self.assertAlmostEqual(L, 2 * math.pi * r, delta=1e-11 * r)
            A = self.ok("area", {"curve": circle([1, 1], r)})["area"]
            self.assertAlmostEqual(A, math.pi * r * r, delta=1e-12 * r * r)
        L = self.ok("length", {"curve": arc([0, 0], 2, 0.5, 2.25)})["length"]
        self.assertAlmostEqual(L, 2 * 1.75, delta=1e-11)
        a, b = 3.0, 1.0
        want = float(4 * a * mpmath.ellipe(1 - (b / a) ** 2))  # perimeter: 4 a E(e^2)
        L = self.ok("length", {"curve": ellipse([0, 0], [a, b], rotation=1.0)})["length"]
        self.assertAlmostEqual(L, want, delta=1e-11 * want)
        A = self.ok("area", {"curve": ellipse([2, -1], [a, b], rotation=0.3)})["area"]
        self.assertAlmostEqual(A, math.pi * a * b, delta=1e-12 * a * b)

    def test_arc_wraps_when_end_is_below_start(self):
        # Counter-clockwise from start to end (docs/cli.md): an end angle below the start
        # sweeps from the start direction on to the end direction, less than a full turn.
        # From 3 pi / 2 to pi / 2: the left half circle (sweep pi); from 1 to -7 (the
        # direction -7 + 4 pi): sweep -7 + 4 pi - 1 = 4 pi - 8; from 0.5 to 0.25: all but
        # a quarter radian.
        r, C = 2.0, [1, -1]
        for a0, a1, sweep in ((1.5 * math.pi, 0.5 * math.pi, math.pi), (1.0, -7.0, 4 * math.pi - 8), (0.5, 0.25, 2 * math.pi - 0.25)):
            c = arc(C, r, a0, a1)
            ts = [i / 16 for i in range(17)]
            pts = self.ok("eval", {"curve": c, "t": ts})["points"]
            # Every point on the circle, the angle running from a0 to a0 + sweep
            # (increasing: counter-clockwise), ending at the direction a1. 1e-15 * 4:
            # a few eps of the coordinates, as above.
            prev = None
            for t, p in zip(ts, pts):
                self.assertAlmostEqual(math.dist(p, C), r, delta=1e-15 * 4)
                ang = math.atan2(p[1] - C[1], p[0] - C[0])
                rel = (ang - a0) % (2 * math.pi)
                if t == 0:
                    rel = 0.0
                elif t == 1:
                    rel = sweep
                if prev is not None:
                    self.assertGreater(rel, prev, (a0, a1, t))
                prev = rel
            self.assertAlmostEqual(pts[-1][0], C[0] + r * math.cos(a1), delta=1e-15 * 8)
            self.assertAlmostEqual(pts[-1][1], C[1] + r * math.sin(a1), delta=1e-15 * 8)
            # Its length is r times the sweep (the length query's 1e-12 relative).
            self.assertAlmostEqual(self.ok("length", {"curve": c})["length"], r * sweep, delta=1e-11 * r * sweep)

    def test_any_scale(self):
        # Scale invariance: the circle of radius r about the origin is r times the unit
        # circle's points (scaling by a power of two is exact; the other radii: rounding,
        # a few eps). Only control points that overflow are refused, naming the radius.
        ts = [0, 0.1, 0.3, 0.55, 0.9]
        for r in (2.0 ** -300, 1e-99, 1e-90, 1e80, 1e200, 2.0 ** 1000):
            for curve in (circle([0, 0], r), circle([0, 0, 0], r, normal=[1, 2, 3]), ellipse([0, 0], [r, r / 2], rotation=0.3),
                          arc([0, 0], r, 0.5, 2)):
                pts = self.ok("eval", {"curve": curve, "t": ts})["points"]
                for p in pts:
                    self.assertTrue(all(map(math.isfinite, p)), (r, curve, p))
                if curve["type"] == "circle":
                    for p in pts:
                        # |P| = r: mpmath, no overflow or underflow in the norm
                        self.assertLessEqual(abs(float(mpmath.sqrt(sum(mpmath.mpf(x) ** 2 for x in p))) / r - 1), 1e-15, (r, p))
        # center + r = 2e308; the arc's middle control point at r / cos(0.75) in the
        # direction 1.25: y = 1.5e308 sin(1.25) / cos(0.75) = 1.9e308; the rotated
        # ellipse's corner (a, a) turned by 0.5: y = a (sin 0.5 + cos 0.5) = 2.3e308.
        for curve in (circle([1e308, 0], 1e308), arc([0, 0], 1.5e308, 0.5, 2)):
            self.bad("eval", {"curve": curve, "t": [0]}, "curve.radius", contains="overflow")
        self.bad("eval", {"curve": ellipse([0, 0], [1.7e308, 1.7e308], rotation=0.5), "t": [0]}, "curve.radii", contains="overflow")

    def test_full_turn_rounded_in_doubles(self):
        # end = start + 2 pi computed in doubles can be one ulp over 2 pi (start 1.739:
        # 8.022185307179587 - 1.739 = 6.283185307179587 > 2 pi) or under: the full circle,
        # closed exactly, as at start = 0; a sweep clearly over 2 pi (by 1e-9) is refused.
        for k in range(1, 200):
            a0 = 0.037 * k
            pts = self.ok("eval", {"curve": arc([1, 2], 3, a0, a0 + 2 * math.pi), "t": [0, 0.5, 1]})["points"]
            self.assertEqual(pts[0], pts[2], a0)  # closed exactly
            self.assertAlmostEqual(pts[1][0], 1 + 3 * math.cos(a0 + math.pi), delta=1e-14, msg=a0)
            self.assertAlmostEqual(pts[1][1], 2 + 3 * math.sin(a0 + math.pi), delta=1e-14, msg=a0)
        for a0 in (1.739, 1e3, -1e5):
            self.bad("eval", {"curve": arc([0, 0], 1, a0, a0 + 2 * math.pi + 1e-9 * max(1, abs(a0))), "t": [0]}, "curve.end_angle",
                     contains="2 pi")

    def test_circle_in_3d(self):
        for n in ([0, 0, 1], [0, 1, 1], [1, 2, -3], [1e-200, 0, 0], [5, 5, 5]):
            C, r = [1, -2, 0.5], 1.5
            ts = [i / 40 for i in range(41)]
            pts = self.ok("eval", {"curve": circle(C, r, normal=n), "t": ts})["points"]
            nn = math.sqrt(sum((x / max(map(abs, n))) ** 2 for x in n))
            u = [x / max(map(abs, n)) / nn for x in n]
            for p in pts:
                d = [a - b for a, b in zip(p, C)]
                self.assertLessEqual(abs(sum(a * b for a, b in zip(d, u))), 1e-15 * 8, f"normal {n}: in the plane")
                self.assertLessEqual(abs(math.sqrt(sum(x * x for x in d)) - r), 1e-15 * 8, f"normal {n}: on the circle")
            # Counter-clockwise seen from the normal's tip: (P(t) - C) x P'(t) along n.
            r2 = self.ok("eval", {"curve": circle(C, r, normal=n), "t": [0.1], "derivatives": 1})
            d = [a - b for a, b in zip(r2["points"][0], C)]
            v = r2["derivatives"][0][0]
            cr = [d[1] * v[2] - d[2] * v[1], d[2] * v[0] - d[0] * v[2], d[0] * v[1] - d[1] * v[0]]
            self.assertGreater(sum(a * b for a, b in zip(cr, u)), 0)
        # Normal z: the 2-D circle at the center's height, starting along x.
        pts = self.ok("eval", {"curve": circle([0, 0, 2], 1, normal=[0, 0, 3]), "t": [0, 0.25]})["points"]
        self.assertEqual(pts[0], [1, 0, 2])
        for a, b in zip(pts[1], [0, 1, 2]):
            self.assertAlmostEqual(a, b, delta=1e-16)
        # Normal x: the least aligned axis is y (the first of y, z), so the start is along y.
        p0 = self.ok("eval", {"curve": circle([0, 0, 0], 2, normal=[1, 0, 0]), "t": [0]})["points"][0]
        self.assertEqual(p0, [0, 2, 0])

    def test_shorthands_as_path_segments_and_in_other_commands(self):
        # A stadium: two half circles and two segments, closed: area pi r^2 + 2 r w.
        r, w = 1.0, 3.0
        path = {"type": "path", "segments": [
            {"type": "bezier", "points": [[0, -r], [w, -r]]},
            arc([w, 0], r, -math.pi / 2, math.pi / 2),
            {"type": "bezier", "points": [[w, r], [0, r]]},
            arc([0, 0], r, math.pi / 2, 3 * math.pi / 2)]}
        A = self.ok("area", {"curve": path})["area"]
        self.assertAlmostEqual(A, math.pi * r * r + 2 * r * w, delta=1e-12)
        b = self.ok("bounds", {"curve": circle([1, 2], 3)})
        self.assertEqual(len(b["min"]), 2)
        for got, want in zip(b["min"] + b["max"], [-2, -1, 4, 5]):
            self.assertAlmostEqual(got, want, delta=1e-14)

    def test_errors_name_the_field(self):
        def bad(curve, where, contains=None):
            self.bad("eval", {"curve": curve, "t": [0]}, "curve." + where if where else "curve", contains=contains)

        bad(circle([0, 0], 0), "radius", "> 0")
        bad(circle([0, 0], -1), "radius")
        bad(circle([0, 0], "1"), "radius")
        bad({"type": "circle", "center": [0, 0]}, "radius", "missing")
        bad({"type": "circle", "radius": 1}, "center", "missing")
        bad(circle([0, 0, 0], 1), "center", "2")
        bad(circle([0, 0], 1, normal=[0, 0, 1]), "center", "3")
        bad(circle([0, 0, 0], 1, normal=[0, 0, 0]), "normal", "non-zero")
        bad(circle([0, 0, 0], 1, normal=[0, 1]), "normal", "3")
        bad(circle([0, 0], 1, radii=[1, 2]), "radii", "unknown field")
        bad(circle([0, 0], 1, dim=3), "dim")
        bad(ellipse([0, 0], [1]), "radii", "2")
        bad(ellipse([0, 0], [1, 0]), "radii[1]", "> 0")
        bad(ellipse([0, 0], [1, 2], rotation="x"), "rotation")
        bad(ellipse([0, 0], [1, 2], normal=[0, 0, 1]), "normal", "unknown field")
        bad(ellipse([0, 0, 0], [1, 2]), "center")
        bad(arc([0, 0], 1, 1, 1), "end_angle", "greater")
        bad(arc([0, 0], 1, 2 * math.pi, 0), "end_angle", "ambiguous")
        bad(arc([0, 0], 1, 0, 7), "end_angle", "2 pi")
        bad({"type": "arc", "center": [0, 0], "radius": 1, "start_angle": 0}, "end_angle", "missing")
        bad(arc([0, 0], 0, 0, 1), "radius")
        self.bad("eval", {"curve": circle([0, 0], 1), "t": [0]}, "curve.radius",
                 text='{"curve": {"type": "circle", "center": [0, 0], "radius": 1e999}, "t": [0]}')
        self.bad("eval", {"curve": {"type": "circel"}, "t": [0]}, "curve.type", contains="circle")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
