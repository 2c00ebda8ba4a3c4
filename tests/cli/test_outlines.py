#!/usr/bin/python3
"""Black-box tests of issue 17's outline commands: `to_svg_path` (a curve as SVG path data)
and `glyph` (a text's outlines from a font file).

Oracles written here, never the program: a small SVG path-data reader (absolute M, L, Q,
C, A, Z; arcs converted to centre form as SVG 1.1 F.6.5 says, radii scaled up as F.6.6),
de Casteljau and rational evaluation, dense two-way distance comparison (numpy), and a
TrueType reader (struct: the `head`, `hhea`, `hmtx`, `cmap` format 4, `loca`, `glyf` and
`kern` tables, with TrueType's implied on-curve points), an AFM reader for Type 1 fonts,
and a GPOS pair-kerning reader (fontTools parses the tables; the lookup rules are written
here). The fonts come from Debian packages the project's scripts install
(fonts-dejavu-core, fonts-urw-base35, python3-fonttools to edit copies of them); a test
whose font is missing fails (it is part of the build set).

Usage: test_outlines.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import re
import struct
import sys
import tempfile
import unittest

import numpy as np
from fontTools.ttLib import TTFont
from scipy.optimize import brentq

import test_cli
from test_cli import CliTest, bezier, de_casteljau, rational_point
from test_offset import polyline_distance

DEJAVU = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
NIMBUS_OTF = "/usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf"
NIMBUS_T1 = "/usr/share/fonts/type1/urw-base35/NimbusSans-Regular.t1"
NIMBUS_AFM = "/usr/share/fonts/type1/urw-base35/NimbusSans-Regular.afm"


# ---------------------------------------------------------------------------------------
# An SVG path-data reader (the subset to_svg_path writes, absolute commands), independent
# of the program.

TOKEN = re.compile(r"[MLQCAZ]|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def read_path_data(d):
    """Segments of path data d: ("L", p0, p1), ("Q", p0, c, p1), ("C", p0, c1, c2, p1),
    ("A", p0, p1, centre form) and subpaths [(start, closed)], plus the points of M alone."""
    tokens = TOKEN.findall(d)
    assert "".join(tokens).replace(" ", "") == re.sub(r"\s", "", d), f"stray characters in {d!r}"
    segs, subpaths, i, cur, start = [], [], 0, None, None

    def nums(k):
        nonlocal i
        v = [float(x) for x in tokens[i:i + k]]
        assert len(v) == k and all(not re.fullmatch("[A-Z]", x) for x in tokens[i:i + k]), d
        i += k
        return v

    while i < len(tokens):
        c = tokens[i]
        i += 1
        if c == "M":
            cur = start = tuple(nums(2))
            subpaths.append([start, False])
        elif c == "L":
            p = tuple(nums(2))
            segs.append(("L", cur, p))
            cur = p
        elif c == "Q":
            v = nums(4)
            segs.append(("Q", cur, tuple(v[0:2]), tuple(v[2:4])))
            cur = tuple(v[2:4])
        elif c == "C":
            v = nums(6)
            segs.append(("C", cur, tuple(v[0:2]), tuple(v[2:4]), tuple(v[4:6])))
            cur = tuple(v[4:6])
        elif c == "A":
            rx, ry, phi, fa, fs, x, y = nums(7)
            assert fa in (0, 1) and fs in (0, 1)
            p = (x, y)
            segs.append(("A", cur, p, arc_centre(cur, p, rx, ry, phi, fa, fs)))
            cur = p
        elif c == "Z":
            subpaths[-1][1] = True
            if cur != start:
                segs.append(("L", cur, start))
            cur = start
        else:
            raise AssertionError(f"unexpected token {c!r} in {d!r}")
    return segs, subpaths


def arc_centre(p1, p2, rx, ry, phi_deg, fa, fs):
    """SVG 1.1 F.6.5: the centre form (cx, cy, rx, ry, phi, theta1, dtheta) of an endpoint-
    form arc, with out-of-range radii scaled up (F.6.6)."""
    phi = math.radians(phi_deg)
    cp, sp = math.cos(phi), math.sin(phi)
    dx, dy = (p1[0] - p2[0]) / 2, (p1[1] - p2[1]) / 2
    x1, y1 = cp * dx + sp * dy, -sp * dx + cp * dy
    rx, ry = abs(rx), abs(ry)
    lam = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry)
    if lam > 1:
        rx, ry = rx * math.sqrt(lam), ry * math.sqrt(lam)
    num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1
    den = rx * rx * y1 * y1 + ry * ry * x1 * x1
    co = math.sqrt(max(0.0, num / den))
    if fa == fs:
        co = -co
    cx1, cy1 = co * rx * y1 / ry, -co * ry * x1 / rx
    cx = cp * cx1 - sp * cy1 + (p1[0] + p2[0]) / 2
    cy = sp * cx1 + cp * cy1 + (p1[1] + p2[1]) / 2

    def angle(ux, uy, vx, vy):
        a = math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)
        return a

    t1 = angle(1, 0, (x1 - cx1) / rx, (y1 - cy1) / ry)
    dt = angle((x1 - cx1) / rx, (y1 - cy1) / ry, (-x1 - cx1) / rx, (-y1 - cy1) / ry)
    if not fs and dt > 0:
        dt -= 2 * math.pi
    elif fs and dt < 0:
        dt += 2 * math.pi
    return (cx, cy, rx, ry, phi, t1, dt)


def arc_point(c, s):
    cx, cy, rx, ry, phi, t1, dt = c
    t = t1 + s * dt
    return (cx + rx * math.cos(t) * math.cos(phi) - ry * math.sin(t) * math.sin(phi),
            cy + rx * math.cos(t) * math.sin(phi) + ry * math.sin(t) * math.cos(phi))


def segment_point(seg, s):
    kind = seg[0]
    if kind == "A":
        return arc_point(seg[3], s)
    return tuple(de_casteljau(seg[1:], s))


def sample_segments(segs, n=400):
    pts = []
    for seg in segs:
        pts.extend(segment_point(seg, k / n) for k in range(n + 1))
    return np.array(pts)


def point_to_polyline(points, poly):
    """Distance of each point to the polyline (numpy, exact segment distance; the segments
    that can be nearest found by a cKDTree: test_offset.polyline_distance)."""
    return polyline_distance(points, poly)


def curve_samples(piece_points, weights=None, n=4000):
    """Dense samples of a Bézier (or rational Bézier) piece, by the test's own evaluators."""
    if weights is None:
        return np.array([de_casteljau(piece_points, k / n) for k in range(n + 1)])
    return np.array([rational_point(piece_points, weights, k / n) for k in range(n + 1)])


def foot_distance(f, p, lo, hi):
    """The distance from p to the piece f (s -> point) over [lo, hi]: the ends, and the
    foot of the perpendicular where (f(s) - p) . f'(s) changes sign, found by brentq to
    1e-16 in s (a point on the curve is at a distance linear in the error of
    s, so minimising the distance would stop at sqrt(eps)); f' by central differences
    (its error moves the foot point at second order only)."""
    def g(x):
        a, b1, b0 = f(x), f(min(x + 1e-7, 1.0)), f(max(x - 1e-7, 0.0))
        return (a[0] - p[0]) * (b1[0] - b0[0]) + (a[1] - p[1]) * (b1[1] - b0[1])
    best = min(math.dist(f(lo), p), math.dist(f(hi), p))
    glo, ghi = g(lo), g(hi)
    if glo * ghi < 0:
        best = min(best, math.dist(f(brentq(g, lo, hi, xtol=1e-16, rtol=8.9e-16, maxiter=300)), p))
    return best


def distance_to_curve(points, fs):
    """The largest distance from the points to the curve made of the parametric pieces fs
    (each s in [0, 1] -> point): the nearest of 2000 samples per piece, then the foot point
    between its neighbours (foot_distance)."""
    n = 2000
    S = np.linspace(0, 1, n + 1)
    tables = [np.array([f(x) for x in S]) for f in fs]
    worst = 0.0
    for p in points:
        best = math.inf
        for f, C in zip(fs, tables):
            i = int(np.argmin(np.hypot(C[:, 0] - p[0], C[:, 1] - p[1])))
            best = min(best, foot_distance(f, p, S[max(i - 1, 0)], S[min(i + 1, n)]))
        worst = max(worst, best)
    return worst


def two_way_distance(a_points, a_poly, b_points, b_poly):
    """Largest distance from the samples of each curve to the dense polyline of the other."""
    return max(point_to_polyline(a_points, b_poly).max(), point_to_polyline(b_points, a_poly).max())


# ---------------------------------------------------------------------------------------

class ToSvgPathExactTest(CliTest):
    def d(self, curve, **extra):
        return self.ok("to_svg_path", dict({"curve": curve}, **extra))

    def test_polynomial_pieces_are_written_as_given(self):
        # Control points come back digit for digit (shortest round-trip numbers).
        cases = [
            ([[0, 0], [4, 0]], "M 0 0 L 4 0"),
            ([[0, 0], [1, 2], [2, 0]], "M 0 0 Q 1 2 2 0"),
            ([[0, 0], [1, 2], [3, 2], [4, 0]], "M 0 0 C 1 2 3 2 4 0"),
            ([[0.1, -2.5], [1e-7, 3e5], [3, 2], [-4, 0.3333333333333333]],
             "M 0.1 -2.5 C 1e-07 3e+05 3 2 -4 0.3333333333333333"),
            ([[0, 0], [1e20, -1e-300]], "M 0 0 L 1e+20 -1e-300"),
            ([[1, 2]], "M 1 2"),
        ]
        for pts, want in cases:
            r = self.d(bezier(pts))
            self.assertEqual(r["d"], want)
            self.assertIs(r["exact"], True)
            self.assertEqual(r["max_deviation"], 0)
            segs, _ = read_path_data(r["d"])
            for seg in segs:
                self.assertEqual([list(p) for p in seg[1:]], [[float(x) for x in p] for p in pts])

    def test_round_trip_of_random_cubics_is_bitwise(self):
        rng = random.Random(17)
        for _ in range(50):
            pts = [[rng.uniform(-1e3, 1e3) * 10 ** rng.randint(-8, 8) for _ in range(2)] for _ in range(4)]
            segs, _ = read_path_data(self.d(bezier(pts))["d"])
            self.assertEqual([list(p) for p in segs[0][1:]], pts)

    def test_joints_gaps_and_closing(self):
        square = {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]}
        self.assertEqual(self.d(square)["d"], "M 0 0 L 1 0 L 1 1 L 0 1 L 0 0 Z")
        gap = {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), bezier([[2, 0], [3, 1], [4, 0]])]}
        self.assertEqual(self.d(gap)["d"], "M 0 0 L 1 0 M 2 0 Q 3 1 4 0")
        joined = {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), bezier([[1, 0], [3, 1], [4, 0]])]}
        self.assertEqual(self.d(joined)["d"], "M 0 0 L 1 0 Q 3 1 4 0")
        # A point piece where the path already is adds nothing; apart, it is a lone M.
        dot = {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), bezier([[1, 0]]), bezier([[5, 5]])]}
        self.assertEqual(self.d(dot)["d"], "M 0 0 L 1 0 M 5 5")
        # Two closed subpaths.
        two = {"type": "path", "segments": [{"type": "polyline", "points": [[0, 0], [1, 0], [0, 1], [0, 0]]},
                                            {"type": "polyline", "points": [[5, 5], [6, 5], [5, 6], [5, 5]]}]}
        self.assertEqual(self.d(two)["d"], "M 0 0 L 1 0 L 0 1 L 0 0 Z M 5 5 L 6 5 L 5 6 L 5 5 Z")

    def test_bspline_pieces(self):
        # A uniform cubic B-spline: its pieces are cubics (C), continuing one subpath; the
        # read-back path matches the test's own B-spline evaluation densely.
        knots = [0, 0, 0, 0, 1, 2, 3, 3, 3, 3]
        P = [[0, 0], [1, 2], [2, -1], [3, 3], [4, 0], [5, 1]]
        r = self.d({"type": "bspline", "degree": 3, "knots": knots, "points": P})
        self.assertIs(r["exact"], True)
        self.assertEqual(r["d"].count("C"), 3)
        self.assertEqual(r["d"].count("M"), 1)
        segs, _ = read_path_data(r["d"])
        got = sample_segments(segs, 200)

        def de_boor(u):
            # Cox-de Boor recursion written out.
            def N(i, p, u):
                if p == 0:
                    return 1.0 if knots[i] <= u < knots[i + 1] or (u == 3 and knots[i] < knots[i + 1] == 3) else 0.0
                a = 0.0 if knots[i + p] == knots[i] else (u - knots[i]) / (knots[i + p] - knots[i]) * N(i, p - 1, u)
                b = 0.0 if knots[i + p + 1] == knots[i + 1] else \
                    (knots[i + p + 1] - u) / (knots[i + p + 1] - knots[i + 1]) * N(i + 1, p - 1, u)
                return a + b
            return [sum(N(i, 3, u) * P[i][k] for i in range(len(P))) for k in range(2)]

        want = np.array([de_boor(3 * k / 1500) for k in range(1501)])
        # Both sampled densely: the polyline chord error is below 1e-5 at these spacings.
        self.assertLess(two_way_distance(got, got, want, want), 1e-4)

    def check_conic(self, P, w, d, tol):
        """The path data's arcs against the rational quadratic (P, w), both ways."""
        segs, _ = read_path_data(d)
        self.assertTrue(all(s[0] == "A" for s in segs), d)
        self.assertEqual(segs[0][1], tuple(float(x) for x in P[0]))
        self.assertEqual(segs[-1][2], tuple(float(x) for x in P[2]))
        arcs = [lambda x, c=seg[3]: arc_point(c, x) for seg in segs]
        conic = [lambda x: rational_point(P, w, x)]
        arc_samples = np.array([arc_point(seg[3], k / 40) for seg in segs for k in range(41)])
        conic_samples = np.array([rational_point(P, w, k / 80) for k in range(81)])
        self.assertLess(distance_to_curve(arc_samples, conic), tol)
        self.assertLess(distance_to_curve(conic_samples, arcs), tol)

    def test_quarter_circle_is_one_arc(self):
        r = self.d(test_cli.QUARTER_CIRCLE)
        self.assertIs(r["exact"], True)
        m = re.fullmatch(r"M 1 0 A (\S+) (\S+) 0 0 1 (\S+) 1", r["d"])
        self.assertIsNotNone(m, r["d"])
        rx, ry, x_end = map(float, m.groups())
        self.assertAlmostEqual(rx, 1, delta=1e-15)  # radius from a 2x2 SVD: a few ulps
        self.assertAlmostEqual(ry, 1, delta=1e-15)
        self.assertEqual(x_end, 0)

    @staticmethod
    def nurbs_circle(centre, radius, affine=None):
        """The NURBS Book's circle (7.3: nine control points of a square, weights 1 and
        sqrt(2)/2, knots doubled at the quarters), its control points optionally mapped by
        an affine map (A, b): the rational form is affine invariant."""
        sq = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
        pts = [[centre[0] + radius * x, centre[1] + radius * y] for x, y in sq]
        if affine:
            A, b = affine
            pts = [[A[0][0] * x + A[0][1] * y + b[0], A[1][0] * x + A[1][1] * y + b[1]] for x, y in pts]
        h = math.sqrt(2) / 2
        return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                "points": pts, "weights": [1, h, 1, h, 1, h, 1, h, 1]}

    def test_nurbs_circle_is_four_arcs(self):
        for centre, radius in (([0, 0], 1), ([3.5, -2], 0.25), ([1e6, 1e6], 1e3)):
            r = self.d(self.nurbs_circle(centre, radius))
            self.assertIs(r["exact"], True)
            self.assertEqual(r["d"].count("A"), 4, r["d"])
            self.assertTrue(r["d"].endswith(" Z"), r["d"])
            segs, subpaths = read_path_data(r["d"])
            self.assertEqual(len(subpaths), 1)
            scale = max(abs(centre[0]), abs(centre[1]), radius)
            for seg in segs:
                cx, cy, rx, ry, phi, t1, dt = seg[3]
                # Centre and radii recovered by the reader to a few ulps of the coordinates.
                self.assertLess(math.hypot(cx - centre[0], cy - centre[1]), 1e-12 * scale)
                self.assertLess(abs(rx - radius), 1e-12 * scale)
                self.assertLess(abs(ry - radius), 1e-12 * scale)
                self.assertAlmostEqual(dt, math.pi / 2, delta=1e-9)  # counter-clockwise quarter
            pts = sample_segments(segs, 500)
            dist = np.hypot(pts[:, 0] - centre[0], pts[:, 1] - centre[1])
            self.assertLess(np.abs(dist - radius).max(), 1e-12 * scale)

    def test_rotated_ellipse_radii_and_rotation(self):
        # The unit circle mapped by rotation(30 deg) diag(3, 1) plus (1, 2): an ellipse with
        # radii (3, 1) rotated by 30 degrees. Every arc has those radii and rotation (mod
        # 180), and the points satisfy the implicit equation.
        rot = math.pi / 6
        c, s = math.cos(rot), math.sin(rot)
        A = [[3 * c, -s], [3 * s, c]]
        r = self.d(self.nurbs_circle([0, 0], 1, (A, [1, 2])))
        self.assertIs(r["exact"], True)
        arcs = list(re.finditer(r"A (\S+) (\S+) (\S+) (\d) (\d)", r["d"]))
        self.assertEqual(len(arcs), 4)
        for m in arcs:
            rx, ry, phi = map(float, m.groups()[:3])
            self.assertAlmostEqual(rx, 3, delta=1e-13)  # a 2x2 SVD: a few ulps of 3
            self.assertAlmostEqual(ry, 1, delta=1e-13)
            self.assertAlmostEqual((phi - 30 + 90) % 180 - 90, 0, delta=1e-11)
        segs, _ = read_path_data(r["d"])
        pts = sample_segments(segs, 300) - np.array([1, 2])
        u = pts[:, 0] * c + pts[:, 1] * s
        v = -pts[:, 0] * s + pts[:, 1] * c
        self.assertLess(np.abs((u / 3) ** 2 + v ** 2 - 1).max(), 1e-12)

    def test_random_elliptic_rational_quadratics(self):
        # Any positive end weights, middle weight below sqrt(w0 w2): an elliptical arc.
        rng = random.Random(4)
        for _ in range(30):
            P = [[rng.uniform(-5, 5), rng.uniform(-5, 5)] for _ in range(3)]
            w0, w2 = rng.uniform(0.2, 5), rng.uniform(0.2, 5)
            w1 = math.sqrt(w0 * w2) * rng.uniform(0.05, 0.98)
            w = [w0, w1, w2]
            r = self.d({"type": "rational_bezier", "points": P, "weights": w})
            self.assertIs(r["exact"], True, r)
            # 1e-11: the arcs' radii (up to ~25 here) and rotation rounded once, the
            # reader's centre from them (sweeps below 91 degrees: well conditioned), about
            # 100 ulps of the radius.
            self.check_conic(P, w, r["d"], 1e-11)
            if w1 / math.sqrt(w0 * w2) < 0.7:
                self.assertEqual(r["d"].count("A"), 2, r["d"])  # split beyond ~91 degrees

    def test_parabola_and_line_forms(self):
        r = self.d({"type": "rational_bezier", "points": [[0, 0], [1, 2], [2, 0]], "weights": [2, 2, 2]})
        self.assertEqual(r["d"], "M 0 0 Q 1 2 2 0")
        r = self.d({"type": "rational_bezier", "points": [[0, 0], [1, 2], [2, 0]], "weights": [1, 2, 4]})
        self.assertEqual(r["d"], "M 0 0 Q 1 2 2 0")  # w1 / sqrt(w0 w2) = 1
        r = self.d({"type": "rational_bezier", "points": [[0, 0], [1, 1], [2, 2]], "weights": [1, 0.5, 1]})
        self.assertEqual(r["d"], "M 0 0 L 2 2")  # collinear, middle point between the ends


class ToSvgPathApproximationTest(CliTest):
    def measured(self, r, pieces):
        """The test's own two-way distance between the read-back cubics and the pieces."""
        segs, _ = read_path_data(r["d"])
        self.assertTrue(all(s[0] == "C" for s in segs), r["d"])
        got = sample_segments(segs, 300)
        want = np.concatenate([curve_samples(*p, n=3000) for p in pieces])
        return two_way_distance(got, got, want, want), len(segs)

    def test_tolerance_required(self):
        quintic = bezier([[0, 0], [1, 3], [2, -2], [3, 4], [4, -1], [5, 0]])
        self.bad("to_svg_path", {"curve": quintic}, "tolerance", contains="required")
        hyperbola = {"type": "rational_bezier", "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 2, 1]}
        self.bad("to_svg_path", {"curve": hyperbola}, "tolerance", contains="required")

    def test_quintic_within_tolerance(self):
        P = [[0, 0], [1, 3], [2, -2], [3, 4], [4, -1], [5, 0]]
        for tol in (1e-1, 1e-3, 1e-6):
            r = self.ok("to_svg_path", {"curve": bezier(P), "tolerance": tol})
            self.assertIs(r["exact"], False)
            self.assertLessEqual(r["max_deviation"], tol)
            dist, n = self.measured(r, [(P, None)])
            self.assertEqual(n, r["cubics"])
            # The Hausdorff distance is at most the distance at equal parameters; 1e-5 of
            # slack for the test's polylines (chord error at 3000 samples on size ~5).
            self.assertLessEqual(dist, tol + 1e-5, tol)

    def test_hyperbola_within_tolerance(self):
        P, w = [[0, 0], [1, 1], [2, 0]], [1, 3, 1]
        r = self.ok("to_svg_path", {"curve": {"type": "rational_bezier", "points": P, "weights": w}, "tolerance": 1e-4})
        dist, _ = self.measured(r, [(P, w)])
        self.assertLessEqual(dist, 1e-4 + 1e-5)

    def test_elevated_cubic_needs_one_cubic(self):
        # A cubic elevated to degree 5 (Forrest's formula, exact rationals here) is its own
        # Hermite cubic: the fewest is one, at rounding level.
        from fractions import Fraction
        Q = [[0, 0], [1, 3], [3, 3], [4, 0]]
        for _ in range(2):
            n = len(Q)
            Q = [[float(Fraction(i, n) * Fraction(Q[i - 1][k]) + Fraction(n - i, n) * Fraction(Q[i][k])) if 0 < i < n
                  else float(Q[0 if i == 0 else n - 1][k]) for k in range(2)] for i in range(n + 1)]
        r = self.ok("to_svg_path", {"curve": bezier(Q), "tolerance": 1e-9})
        self.assertEqual(list(r), ["d", "exact", "max_deviation", "cubics"])  # docs/cli.md: exactly these
        self.assertEqual(r["cubics"], 1)
        self.assertLess(r["max_deviation"], 1e-12)

    def test_fewer_cubics_for_larger_tolerance(self):
        P = [[0, 0], [1, 3], [2, -2], [3, 4], [4, -1], [5, 0], [6, 2]]
        counts = [self.ok("to_svg_path", {"curve": bezier(P), "tolerance": t})["cubics"] for t in (1e-1, 1e-3, 1e-5)]
        self.assertEqual(counts, sorted(counts))
        self.assertLess(counts[0], counts[2])

    def test_mixed_path_keeps_exact_pieces(self):
        quartic = [[2, 0], [3, 2], [4, -2], [5, 2], [6, 0]]
        path = {"type": "path", "segments": [bezier([[0, 0], [2, 0]]), bezier(quartic)]}
        r = self.ok("to_svg_path", {"curve": path, "tolerance": 1e-3})
        self.assertTrue(r["d"].startswith("M 0 0 L 2 0 C "), r["d"])
        self.assertEqual(r["d"].count("M"), 1)

    def test_bad_input(self):
        self.bad("to_svg_path", {"curve": bezier([[0, 0, 0], [1, 1, 1]])}, "curve", contains="2-D")
        self.bad("to_svg_path", {"curve": bezier([[0, 0], [1, 1]]), "tolerance": 0}, "tolerance")
        self.bad("to_svg_path", {"curve": bezier([[0, 0], [1, 1]]), "tolerance": -1}, "tolerance")
        quintic = bezier([[0, 0], [1, 3], [2, -2], [3, 4], [4, -1], [5, 0]])
        self.bad("to_svg_path", {"curve": quintic, "tolerance": 1e-300}, "tolerance", contains="too small")
        self.bad("to_svg_path", {}, "curve", contains="missing")


# ---------------------------------------------------------------------------------------
# A TrueType reader (the tables glyph's answers are checked against).

class TrueType:
    def __init__(self, path):
        with open(path, "rb") as f:
            self.data = f.read()
        n = struct.unpack(">H", self.data[4:6])[0]
        self.tables = {}
        for i in range(n):
            tag, _, off, length = struct.unpack(">4sIII", self.data[12 + 16 * i:28 + 16 * i])
            self.tables[tag.decode()] = (off, length)
        head = self.table("head")
        self.units_per_em = struct.unpack(">H", head[18:20])[0]
        self.long_loca = struct.unpack(">h", head[50:52])[0] == 1
        self.n_hmetrics = struct.unpack(">H", self.table("hhea")[34:36])[0]
        self.cmap = self.read_cmap()

    def table(self, tag):
        off, length = self.tables[tag]
        return self.data[off:off + length]

    def read_cmap(self):
        t = self.table("cmap")
        n = struct.unpack(">H", t[2:4])[0]
        for i in range(n):
            pid, eid, off = struct.unpack(">HHI", t[4 + 8 * i:12 + 8 * i])
            if (pid, eid) == (3, 1) and struct.unpack(">H", t[off:off + 2])[0] == 4:
                s = t[off:]
                segx2 = struct.unpack(">H", s[6:8])[0]
                seg = segx2 // 2
                ends = struct.unpack(f">{seg}H", s[14:14 + segx2])
                starts = struct.unpack(f">{seg}H", s[16 + segx2:16 + 2 * segx2])
                deltas = struct.unpack(f">{seg}h", s[16 + 2 * segx2:16 + 3 * segx2])
                ro_at = 16 + 3 * segx2
                offsets = struct.unpack(f">{seg}H", s[ro_at:ro_at + segx2])
                m = {}
                for k in range(seg):
                    for c in range(starts[k], ends[k] + 1):
                        if c == 0xFFFF:
                            continue
                        if offsets[k] == 0:
                            g = (c + deltas[k]) & 0xFFFF
                        else:
                            at = ro_at + 2 * k + offsets[k] + 2 * (c - starts[k])
                            g = struct.unpack(">H", s[at:at + 2])[0]
                            g = (g + deltas[k]) & 0xFFFF if g else 0
                        m[c] = g
                return m
        raise AssertionError("no format-4 Unicode cmap")

    def advance(self, gid):
        h = self.table("hmtx")
        i = min(gid, self.n_hmetrics - 1)
        return struct.unpack(">H", h[4 * i:4 * i + 2])[0]

    def kern(self, left, right):
        t = self.table("kern")
        off = 4
        total = 0
        for _ in range(struct.unpack(">H", t[2:4])[0]):
            _, length, coverage = struct.unpack(">HHH", t[off:off + 6])
            if coverage >> 8 == 0 and coverage & 1:  # format 0, horizontal
                npairs = struct.unpack(">H", t[off + 6:off + 8])[0]
                for k in range(npairs):
                    l, r, v = struct.unpack(">HHh", t[off + 14 + 6 * k:off + 20 + 6 * k])
                    if (l, r) == (left, right):
                        total += v
            off += length
        return total

    def contours(self, gid):
        """The simple glyph's contours: lists of (x, y, on_curve)."""
        loca = self.table("loca")
        if self.long_loca:
            a, b = struct.unpack(">II", loca[4 * gid:4 * gid + 8])
        else:
            a, b = (2 * x for x in struct.unpack(">HH", loca[2 * gid:2 * gid + 4]))
        g = self.table("glyf")[a:b]
        if not g:
            return []
        nc = struct.unpack(">h", g[0:2])[0]
        assert nc >= 0, "composite glyph"
        ends = struct.unpack(f">{nc}H", g[10:10 + 2 * nc])
        npts = ends[-1] + 1
        ilen = struct.unpack(">H", g[10 + 2 * nc:12 + 2 * nc])[0]
        p = 12 + 2 * nc + ilen
        flags = []
        while len(flags) < npts:
            f = g[p]
            p += 1
            flags.append(f)
            if f & 8:
                flags.extend([f] * g[p])
                p += 1

        def coords(short, same):
            nonlocal p
            out, v = [], 0
            for f in flags:
                if f & short:
                    d = g[p]
                    p += 1
                    v += d if f & same else -d
                elif not f & same:
                    v += struct.unpack(">h", g[p:p + 2])[0]
                    p += 2
                out.append(v)
            return out

        xs = coords(2, 16)
        ys = coords(4, 32)
        out, start = [], 0
        for e in ends:
            out.append([(xs[i], ys[i], bool(flags[i] & 1)) for i in range(start, e + 1)])
            start = e + 1
        return out


def quadratic_pieces(contour):
    """A TrueType contour's quadratic pieces (lines as [a, midpoint, b]), with the implied
    on-curve point halfway between consecutive off-curve points."""
    pts = list(contour)
    n = len(pts)
    # Start at an on-curve point (or at the implied midpoint of the first two).
    k = next((i for i, p in enumerate(pts) if p[2]), None)
    if k is None:
        mid = ((pts[0][0] + pts[1][0]) / 2, (pts[0][1] + pts[1][1]) / 2, True)
        pts = [mid] + pts[1:] + pts[:1]
    else:
        pts = pts[k:] + pts[:k]
    pts = pts + [pts[0]]
    pieces, cur, ctrl = [], (pts[0][0], pts[0][1]), None
    for x, y, on in pts[1:]:
        if on:
            if ctrl is None:
                if (x, y) != cur:
                    pieces.append((cur, ((cur[0] + x) / 2, (cur[1] + y) / 2), (x, y)))
            else:
                pieces.append((cur, ctrl, (x, y)))
            cur, ctrl = (x, y), None
        else:
            if ctrl is not None:
                mid = ((ctrl[0] + x) / 2, (ctrl[1] + y) / 2)
                pieces.append((cur, ctrl, mid))
                cur = mid
            ctrl = (x, y)
    return pieces


def read_afm(path):
    widths, kerns = {}, {}
    with open(path, encoding="latin-1") as f:
        lines = f.readlines()
    for line in lines:
        m = re.match(r"C (-?\d+) ; WX (-?\d+) ; N (\S+) ;", line)
        if m and int(m.group(1)) > 0:
            widths[chr(int(m.group(1)))] = int(m.group(2))
        m = re.match(r"KPX (\S+) (\S+) (-?\d+)", line)
        if m:
            kerns[(m.group(1), m.group(2))] = int(m.group(3))
    return widths, kerns


# ---------------------------------------------------------------------------------------
# GPOS pair kerning, read here (OpenType GPOS chapter): the `kern` feature of the script's
# default language system (DFLT when the font lists no such script), its lookups applied
# in LookupList order and summed, in each lookup the first subtable that applies to the
# pair: format 1 (glyph pairs) applies when it lists the second glyph in the first's pair
# set, format 2 (class pairs) whenever it covers the first glyph (class 0 included).

def gpos_kern_lookups(font, script):
    gpos = font["GPOS"].table
    scripts = {r.ScriptTag: r.Script for r in gpos.ScriptList.ScriptRecord}
    langsys = (scripts.get(script) or scripts["DFLT"]).DefaultLangSys
    records = gpos.FeatureList.FeatureRecord
    indices = sorted({i for f in langsys.FeatureIndex if records[f].FeatureTag == "kern"
                      for i in records[f].Feature.LookupListIndex})
    return [gpos.LookupList.Lookup[i] for i in indices]


def gpos_pair_kern(lookups, left, right, formats=None):
    """The x advance adjustment of glyph `left` (a name) before `right`, in font units;
    `formats` collects the subtable formats that applied."""
    total = 0
    for lookup in lookups:
        for st in lookup.SubTable:
            if lookup.LookupType == 9:
                st = st.ExtSubTable
            assert st.LookupType == 2, "the oracle reads pair adjustment lookups only"
            # Kerning of the first glyph's advance only: what these fonts hold.
            assert st.ValueFormat1 in (0, 4) and st.ValueFormat2 == 0, (st.ValueFormat1, st.ValueFormat2)
            cov = st.Coverage.glyphs
            if left not in cov:
                continue
            if st.Format == 1:
                rec = [r for r in st.PairSet[cov.index(left)].PairValueRecord if r.SecondGlyph == right]
                if not rec:
                    continue
                value = rec[0].Value1
            else:
                c1 = st.ClassDef1.classDefs.get(left, 0)
                c2 = st.ClassDef2.classDefs.get(right, 0)
                value = st.Class1Record[c1].Class2Record[c2].Value1
            total += getattr(value, "XAdvance", 0) or 0
            if formats is not None:
                formats.add(st.Format)
            break
    return total


class GposLayout:
    """The pen positions of a text in a font with GPOS kerning, computed here."""

    def __init__(self, path):
        self.font = TTFont(path)
        self.cmap = self.font.getBestCmap()
        self.upem = self.font["head"].unitsPerEm
        self.formats = set()

    def kern(self, a, b, script="latn"):
        return gpos_pair_kern(gpos_kern_lookups(self.font, script), self.cmap[ord(a)], self.cmap[ord(b)], self.formats)

    def layout(self, text, size=None, script="latn"):
        s = 1 if size is None else size / self.upem
        lookups = gpos_kern_lookups(self.font, script)
        names = [self.cmap[ord(c)] for c in text]
        origins, advances, pen = [], [], 0
        for i, g in enumerate(names):
            if i:
                pen += s * gpos_pair_kern(lookups, names[i - 1], g, self.formats)
            origins.append(pen)
            advances.append(s * self.font["hmtx"][g][0])
            pen += advances[-1]
        return origins, advances


class GlyphTest(CliTest):
    @classmethod
    def setUpClass(cls):
        cls.tt = TrueType(DEJAVU)

    def glyphs(self, font, text, **extra):
        return self.ok("glyph", dict({"font": font, "text": text}, **extra))

    def test_dejavu_advances_and_kerning_from_the_tables(self):
        # DejaVu's kerning is read from GPOS (test_gpos_class_pair_kerning); its `kern`
        # table holds the same values for these pairs.
        text = "AVATAR Wally To."
        r = self.glyphs(DEJAVU, text)
        self.assertEqual(r["units_per_em"], 2048)
        self.assertEqual(r["units_per_em"], self.tt.units_per_em)
        self.assertEqual(r["format"], "TrueType")
        pen, prev = 0, None
        for ch, g in zip(text, r["glyphs"]):
            gid = self.tt.cmap[ord(ch)]
            if prev is not None:
                pen += self.tt.kern(prev, gid)
            self.assertEqual(g["char"], ch)
            self.assertEqual(g["origin"], [pen, 0])
            self.assertEqual(g["advance"], self.tt.advance(gid))
            pen += self.tt.advance(gid)
            prev = gid
        self.assertNotEqual(self.tt.kern(self.tt.cmap[ord("A")], self.tt.cmap[ord("V")]), 0)
        self.assertIsNone(r["glyphs"][6]["curve"])  # the space

    def test_dejavu_outlines_match_glyf(self):
        text = "lobe&Q8%@g"
        r = self.glyphs(DEJAVU, text)
        for ch, g in zip(text, r["glyphs"]):
            contours = self.tt.contours(self.tt.cmap[ord(ch)])
            ox = g["origin"][0]
            self.assertEqual(g["curve"]["type"], "path")
            got = g["curve"]["segments"]
            self.assertEqual(len(got), len(contours), ch)
            for c_got, c_want in zip(got, contours):
                pieces = [tuple((p[0] - ox, p[1]) for p in s["points"]) for s in c_got["segments"]]
                self.assertTrue(all(s["type"] == "bezier" and len(s["points"]) == 3 for s in c_got["segments"]))
                # Closed: each piece starts where the previous ends, the last where the first starts.
                for a, b in zip(pieces, pieces[1:] + pieces[:1]):
                    self.assertEqual(a[-1], b[0])
                want = quadratic_pieces(c_want)
                as_float = lambda ps: sorted(tuple((float(x), float(y)) for x, y in p) for p in ps)
                self.assertEqual(as_float(pieces), as_float(want), ch)

    def test_size_scales(self):
        r1 = self.glyphs(DEJAVU, "Ag")
        r2 = self.glyphs(DEJAVU, "Ag", size=64)
        s = 64 / 2048
        for a, b in zip(r1["glyphs"], r2["glyphs"]):
            self.assertAlmostEqual(b["advance"], a["advance"] * s, delta=1e-12)
            self.assertAlmostEqual(b["origin"][0], a["origin"][0] * s, delta=1e-12)
            for ca, cb in zip(a["curve"]["segments"], b["curve"]["segments"]):
                for sa, sb in zip(ca["segments"], cb["segments"]):
                    # One multiplication by 64 / 2048 (exact: a power of two) per coordinate.
                    self.assertEqual([[x * s for x in p] for p in sa["points"]], sb["points"])

    def assert_layout(self, r, text, origins, advances, delta=0):
        self.assertEqual([g["char"] for g in r["glyphs"]], list(text))
        for ch, g, x, a in zip(text, r["glyphs"], origins, advances):
            self.assertEqual(g["origin"][1], 0)
            if delta:
                self.assertAlmostEqual(g["origin"][0], x, delta=delta, msg=ch)
                self.assertAlmostEqual(g["advance"], a, delta=delta, msg=ch)
            else:
                self.assertEqual(g["origin"][0], x, ch)
                self.assertEqual(g["advance"], a, ch)

    def test_gpos_glyph_pair_kerning(self):
        # Nimbus Sans (CFF): kerning only in GPOS, glyph pairs (PairPos format 1).
        gp = GposLayout(NIMBUS_OTF)
        self.assertNotIn("kern", gp.font)
        self.assertEqual((gp.kern("A", "V"), gp.kern("T", "o"), gp.kern("W", "a")), (-71, -91, -37))
        text = "AVATAR Wally To. Wa"
        r = self.glyphs(NIMBUS_OTF, text)
        self.assertIs(r["kerning"], True)
        # Font units: integer sums, exact.
        self.assert_layout(r, text, *gp.layout(text))
        # Scaled: each kerning and advance times size / unitsPerEm then summed, as the
        # program does; 1e-12 is a few ulps of positions below 600.
        r = self.glyphs(NIMBUS_OTF, text, size=50)
        self.assert_layout(r, text, *gp.layout(text, size=50), delta=1e-12)
        self.assertEqual(gp.formats, {1})

    def test_gpos_class_pair_kerning(self):
        # DejaVu Sans (TrueType): GPOS class pairs (PairPos format 2) in two lookups for
        # Latin; its `kern` table is not read.
        gp = GposLayout(DEJAVU)
        self.assertEqual((gp.kern("A", "V"), gp.kern("T", "o"), gp.kern("W", "a")), (-131, -348, -131))
        self.assertEqual(len(gpos_kern_lookups(gp.font, "latn")), 2)
        text = "AVATAR Wally To. Wa -V (f) r, y."
        r = self.glyphs(DEJAVU, text)
        self.assert_layout(r, text, *gp.layout(text))
        r = self.glyphs(DEJAVU, text, size=12)
        self.assert_layout(r, text, *gp.layout(text, size=12), delta=1e-12)  # as above
        self.assertEqual(gp.formats, {2})

    def test_pairs_without_kerning_are_unchanged(self):
        for font in (NIMBUS_OTF, DEJAVU):
            gp = GposLayout(font)
            for pair in ("ll", "AR", "Hn", "mn"):
                self.assertEqual(gp.kern(*pair), 0, (font, pair))
                g = self.glyphs(font, pair)["glyphs"]
                self.assertEqual(g[0]["origin"], [0, 0])
                self.assertEqual(g[1]["origin"], [g[0]["advance"], 0], (font, pair))

    def test_one_glyph_per_character(self):
        # Nothing but pair positioning: Nimbus Sans's GSUB ligatures (f i, f f l) are not
        # formed, DejaVu's combining acute stays apart from its e, the precomposed e-acute
        # is not decomposed, a zero-width joiner and Arabic letters (no contextual forms)
        # are kept, one glyph each.
        gp = GposLayout(NIMBUS_OTF)
        self.assertIn("liga", {f.FeatureTag for f in gp.font["GSUB"].table.FeatureList.FeatureRecord})
        text = "office ffle fi"
        self.assert_layout(self.glyphs(NIMBUS_OTF, text), text, *gp.layout(text))
        tt = TrueType(DEJAVU)
        for text in ("Ve\u0301\u00e9", "A\u200dV", "\u0633\u0644\u0627\u0645 AV"):
            r = self.glyphs(DEJAVU, text)
            self.assertEqual([g["char"] for g in r["glyphs"]], list(text))
            self.assertEqual([g["advance"] for g in r["glyphs"]], [tt.advance(tt.cmap[ord(c)]) for c in text])
        gp = GposLayout(DEJAVU)
        text = "Ve\u0301\u00e9"
        self.assert_layout(self.glyphs(DEJAVU, text), text, *gp.layout(text))

    def test_each_script_run_uses_its_language_system(self):
        # DejaVu's Latin kerning is in a lookup only its `latn` script lists (DFLT, grek
        # lack it): a text that starts in Greek still kerns its Latin word.
        gp = GposLayout(DEJAVU)
        self.assertEqual(gp.kern("A", "V", script="DFLT"), 0)
        self.assertEqual(gp.kern("A", "V", script="grek"), 0)
        r = self.glyphs(DEJAVU, "\u03a9 AV")["glyphs"]
        self.assertEqual(r[3]["origin"][0] - r[2]["origin"][0], r[2]["advance"] + gp.kern("A", "V"))
        self.assertEqual(gp.kern("A", "V"), -131)

    def dejavu_copy(self, tmp, name, edit):
        font = TTFont(DEJAVU)
        edit(font)
        path = os.path.join(tmp, name)
        font.save(path)
        return path

    def test_gpos_first_else_the_kern_table(self):
        # Copies of DejaVu Sans whose `kern` table says A V = +500 (GPOS: -131): with
        # GPOS's kern feature the table is not read; without GPOS, or with a GPOS whose
        # kern feature is renamed (to `dist`, which the program does not apply either),
        # the kern table is read as before (the test's struct reader is the oracle).
        tt = TrueType(DEJAVU)
        a, v = tt.cmap[ord("A")], tt.cmap[ord("V")]

        def set_av(font):
            names = font.getGlyphOrder()
            hits = 0
            for sub in font["kern"].kernTables:
                if (names[a], names[v]) in sub.kernTable:
                    sub.kernTable[(names[a], names[v])] = 500
                    hits += 1
            self.assertEqual(hits, 1)

        def drop_gpos(font):
            set_av(font)
            del font["GPOS"]

        def rename_kern(font):
            set_av(font)
            for rec in font["GPOS"].table.FeatureList.FeatureRecord:
                if rec.FeatureTag == "kern":
                    rec.FeatureTag = "dist"

        text = "AVATAR Wally To."
        with tempfile.TemporaryDirectory() as tmp:
            both = self.dejavu_copy(tmp, "both.ttf", set_av)
            g = self.glyphs(both, "AV")["glyphs"]
            self.assertEqual(g[1]["origin"][0], g[0]["advance"] - 131)
            for name, edit in (("kern_only.ttf", drop_gpos), ("renamed.ttf", rename_kern)):
                path = self.dejavu_copy(tmp, name, edit)
                k = TrueType(path)
                self.assertEqual(k.kern(a, v), 500)
                r = self.glyphs(path, text)
                self.assertIs(r["kerning"], True)
                pen, prev = 0, None
                for ch, g in zip(text, r["glyphs"]):
                    gid = k.cmap[ord(ch)]
                    if prev is not None:
                        pen += k.kern(prev, gid)
                    self.assertEqual(g["origin"], [pen, 0], (name, ch))
                    pen += k.advance(gid)
                    prev = gid

    def test_thai_and_hangul_runs_keep_their_kerning(self):
        # A small TrueType font (fontTools' FontBuilder: one box outline per glyph, its own
        # advance) with Thai and Hangul characters and a GPOS `kern` feature of glyph pairs
        # for the thai and hang scripts (fontTools' feature compiler). HarfBuzz's Thai
        # shaper decomposes SARA AM (U+0E33) and its Hangul shaper composes conjoining jamo
        # into a syllable the text also holds: not one glyph per character, so these runs
        # had no kerning at all. They are shaped again by the default shaper with the
        # script's tag and kern as every other run: pen positions from the GPOS reader
        # here, pair by pair. (No pair starts at the tone mark U+0E48: HarfBuzz does not
        # kern after a combining mark, with the Thai shaper or without, which the reader
        # here does not model.)
        from fontTools.feaLib.builder import addOpenTypeFeaturesFromString
        from fontTools.fontBuilder import FontBuilder
        from fontTools.pens.ttGlyphPen import TTGlyphPen

        chars = {0x0E01: 1401, 0x0E02: 1380, 0x0E33: 1251, 0x0E48: 1024, 0xAC00: 2025, 0xB098: 1255, 0x1100: 1540, 0x1161: 1298}
        names = [".notdef"] + ["u%04X" % cp for cp in chars]
        fb = FontBuilder(2048, isTTF=True)
        fb.setupGlyphOrder(names)
        fb.setupCharacterMap({cp: "u%04X" % cp for cp in chars})
        glyphs = {}
        for name in names:
            pen = TTGlyphPen(None)
            for x, y in ((100, 0), (100, 1000), (600, 1000), (600, 0)):
                (pen.lineTo if (x, y) != (100, 0) else pen.moveTo)((x, y))
            pen.closePath()
            glyphs[name] = pen.glyph()
        fb.setupGlyf(glyphs)
        fb.setupHorizontalMetrics({n: (chars.get(int(n[1:], 16), 1000) if n != ".notdef" else 1000, 100) for n in names})
        fb.setupHorizontalHeader(ascent=1900, descent=-500)
        fb.setupNameTable({"familyName": "Kern test", "styleName": "Regular"})
        fb.setupOS2()
        fb.setupPost()
        addOpenTypeFeaturesFromString(fb.font, """
            languagesystem DFLT dflt; languagesystem thai dflt; languagesystem hang dflt;
            feature kern {
              pos u0E01 u0E02 -100; pos u0E02 u0E01 -50; pos u0E01 u0E33 -20; pos u0E33 u0E01 -70;
              pos u1100 u1161 -40; pos uAC00 uB098 -120; pos u1161 uAC00 -5;
            } kern;""")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "thai_hangul.ttf")
            fb.save(path)
            gp = GposLayout(path)
            for text, script in (("\u0e01\u0e02\u0e01\u0e33\u0e01", "thai"), ("\u0e01\u0e48\u0e33\u0e01\u0e02", "thai"),
                                 ("\u1100\u1161\uac00\ub098", "hang"), ("\uac00\ub098\uac00", "hang")):
                r = self.glyphs(path, text)
                self.assertIs(r["kerning"], True)
                origins, advances = gp.layout(text, script=script)
                self.assert_layout(r, text, origins, advances)
                # The kerning moved the pen (not the advances alone).
                self.assertNotEqual(origins[-1], sum(advances[:-1]), text)

    def test_cff_and_type1_are_cubic_and_closed(self):
        for font, fmt in ((NIMBUS_OTF, "CFF"), (NIMBUS_T1, "Type 1")):
            r = self.glyphs(font, "Sag")
            self.assertEqual(r["format"], fmt)
            self.assertEqual(r["units_per_em"], 1000)
            for g in r["glyphs"]:
                for c in g["curve"]["segments"]:
                    segs = c["segments"]
                    self.assertTrue(all(len(s["points"]) == 4 for s in segs), font)
                    self.assertEqual(segs[-1]["points"][-1], segs[0]["points"][0])

    def test_type1_advances_and_kerning_from_the_afm(self):
        widths, kerns = read_afm(NIMBUS_AFM)
        text = "AVATAR"
        r = self.glyphs(NIMBUS_T1, text)
        self.assertIs(r["kerning"], True)
        pen = 0
        for i, (ch, g) in enumerate(zip(text, r["glyphs"])):
            if i:
                pen += kerns.get((text[i - 1], ch), 0)
            self.assertEqual(g["origin"], [pen, 0], ch)
            self.assertEqual(g["advance"], widths[ch])
            pen += widths[ch]
        self.assertEqual(kerns[("A", "V")], -71)

    def test_w3_printable_ascii(self):
        # The W3 glyph dataset: every printable ASCII character of DejaVu Sans, one request.
        text = "".join(chr(c) for c in range(0x20, 0x7F))
        r = self.glyphs(DEJAVU, text)
        self.assertEqual(len(r["glyphs"]), 95)
        self.assertEqual([g["char"] for g in r["glyphs"]], list(text))
        self.assertEqual([g["curve"] is None for g in r["glyphs"]], [c == " " for c in text])

    def test_to_svg_path_of_a_glyph(self):
        # A glyph's curve goes straight into to_svg_path: quadratics, one closed subpath
        # per contour.
        g = self.glyphs(DEJAVU, "o")["glyphs"][0]
        r = self.ok("to_svg_path", {"curve": g["curve"]})
        self.assertIs(r["exact"], True)
        self.assertEqual(r["d"].count("M"), 2)
        self.assertEqual(r["d"].count("Z"), 2)
        self.assertNotIn("C", r["d"])

    def test_errors(self):
        self.bad("glyph", {"font": "/nonexistent/font.ttf", "text": "a"}, "font", contains="no such file")
        self.bad("glyph", {"font": os.path.abspath(__file__), "text": "a"}, "font", contains="not a font")
        self.bad("glyph", {"font": "/", "text": "a"}, "font", contains="not a regular file")
        self.bad("glyph", {"font": "", "text": "a"}, "font")
        self.bad("glyph", {"font": DEJAVU, "text": "ab\u4e2d"}, "text[2]", contains="U+4E2D")
        self.bad("glyph", {"font": DEJAVU, "text": "a", "size": 0}, "size")
        self.bad("glyph", {"font": DEJAVU, "text": "a" * 10001}, "text", contains="10000")
        self.bad("glyph", {"text": "a"}, "font", contains="missing")
        self.bad("glyph", {"font": DEJAVU, "text": 3}, "text")
        # Bytes that are not UTF-8 never reach the command: the JSON reader refuses them.
        self.bad("glyph", where="request", text=b'{"font": "x", "text": "\xff"}', contains="malformed JSON")

    def test_empty_text(self):
        self.assertEqual(self.glyphs(DEJAVU, "")["glyphs"], [])


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
