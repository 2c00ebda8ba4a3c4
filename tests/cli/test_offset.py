#!/usr/bin/python3
"""Black-box tests of `offset`: the offset C(t) + d N(t) of a plane curve as cubics.

Oracle: the exact offset evaluated in the test, independently of the program: the input
curve and its derivative by de Casteljau on the control points and on the hodograph
(rational pieces by the quotient rule), N the unit tangent turned +90 degrees, in mpmath
at 30 digits for the distances that decide a test (the worst sample of each cubic is
re-measured there; the bulk is screened in floating point). Closed forms where they
exist: the offset of a circle is the concentric circle of radius r - d (r + d on the
right), of a line a parallel line, of the parabola y = x^2 the curve
(x - 2 d x / s, x^2 + d / s), s = sqrt(1 + 4 x^2), whose swallowtail (for d > 1/2, the
radius of curvature at the vertex) closes on the axis (test_parabola_cusps_trimmed).

Distances are measured both ways on dense samples: every output cubic at 64 parameters
against the exact offset (nearest of 4000 exact samples, then a Newton projection), and
the exact offset at 2000 parameters against the output (nearest of 64 samples per cubic,
then a Newton projection). A sample spacing cannot hide an excursion: the projection is a
true distance at each sample, and the error of a cubic between two of 64 samples changes
by less than 1e-3 of its size (it has a few bumps per cubic).

Usage: test_offset.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import sys
import unittest

import mpmath
import numpy as np
from scipy.spatial import cKDTree

import test_cli
from test_cli import CliTest

mpmath.mp.dps = 30


# ---------------------------------------------------------------------------------------
# The exact offset, written in the test.

def bezier_eval(P, t):
    """Points of the Bézier curve P (array (n+1, 2)) at the parameters t (array)."""
    P = np.asarray(P, dtype=float)
    t = np.asarray(t, dtype=float)[:, None]
    pts = [np.broadcast_to(p, (t.shape[0], 2)) for p in P]
    while len(pts) > 1:
        pts = [(1 - t) * pts[i] + t * pts[i + 1] for i in range(len(pts) - 1)]
    return pts[0]


def hodograph(P):
    P = np.asarray(P, dtype=float)
    n = len(P) - 1
    return n * (P[1:] - P[:-1])


class Piece:
    """A polynomial or rational Bézier piece on [0, 1]: point and first derivative."""

    def __init__(self, P, w=None):
        self.P = np.asarray(P, dtype=float)
        self.w = None if w is None else np.asarray(w, dtype=float)

    def point_and_derivative(self, t):
        if self.w is None:
            dP = hodograph(self.P) if len(self.P) > 1 else np.zeros((1, 2))
            return bezier_eval(self.P, t), bezier_eval(dP, t)
        H = np.column_stack([self.P * self.w[:, None], self.w])
        h = bezier_eval(H[:, :2], t), bezier_eval(H[:, 2:].repeat(2, 1), t)[:, :1]
        dH = hodograph(H)
        dh = bezier_eval(dH[:, :2], t), bezier_eval(dH[:, 2:].repeat(2, 1), t)[:, :1]
        c = h[0] / h[1]
        return c, (dh[0] - c * dh[1]) / h[1]

    def mp_point_and_derivative(self, t):
        """The same in mpmath (30 digits), for one parameter."""
        t = mpmath.mpf(t)
        n = len(self.P) - 1
        w = [mpmath.mpf(1)] * (n + 1) if self.w is None else [mpmath.mpf(x) for x in self.w]
        B = [math.comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]
        dB = [math.comb(n, i) * (i * t ** (i - 1) * (1 - t) ** (n - i) if i > 0 else 0)
              - math.comb(n, i) * ((n - i) * t ** i * (1 - t) ** (n - i - 1) if i < n else 0) for i in range(n + 1)]
        den = sum(w[i] * B[i] for i in range(n + 1))
        dden = sum(w[i] * dB[i] for i in range(n + 1))
        num = [sum(w[i] * B[i] * mpmath.mpf(self.P[i][k]) for i in range(n + 1)) for k in range(2)]
        dnum = [sum(w[i] * dB[i] * mpmath.mpf(self.P[i][k]) for i in range(n + 1)) for k in range(2)]
        c = [x / den for x in num]
        d = [(dnum[k] - c[k] * dden) / den for k in range(2)]
        return c, d


class ExactOffset:
    """C(t) + d N(t) over a list of pieces (each on [0, 1], one after the other)."""

    def __init__(self, pieces, d):
        self.pieces, self.d = pieces, d

    def samples(self, per_piece):
        out = []
        for pc in self.pieces:
            t = np.linspace(0, 1, per_piece)
            c, v = pc.point_and_derivative(t)
            sp = np.linalg.norm(v, axis=1)
            keep = sp > 1e-12 * max(1.0, sp.max())
            n = np.column_stack([-v[:, 1], v[:, 0]])[keep] / sp[keep][:, None]
            out.append(np.column_stack([c[keep] + self.d * n, np.full(keep.sum(), len(out)), t[keep]]))
        return np.vstack(out)

    def mp_point(self, i, t):
        c, v = self.pieces[i].mp_point_and_derivative(t)
        s = mpmath.sqrt(v[0] ** 2 + v[1] ** 2)
        if s == 0:  # zero speed at an end: the limit normal, from just inside
            t = mpmath.mpf(t)
            return self.mp_point(i, t + mpmath.mpf(10) ** -25 if t < 0.5 else t - mpmath.mpf(10) ** -25)
        return [c[0] - self.d * v[1] / s, c[1] + self.d * v[0] / s]

    def mp_distance(self, q, i, t0, span):
        """The distance from q to the exact offset of piece i near t0 (mpmath: the minimum
        of the squared distance over [t0 - span, t0 + span] clipped to [0, 1], by golden
        section at 30 digits)."""
        q = [mpmath.mpf(q[0]), mpmath.mpf(q[1])]

        def f(t):
            p = self.mp_point(i, t)
            return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2

        a, b = mpmath.mpf(max(0.0, t0 - span)), mpmath.mpf(min(1.0, t0 + span))
        r = (mpmath.sqrt(5) - 1) / 2
        x1, x2 = b - r * (b - a), a + r * (b - a)
        f1, f2 = f(x1), f(x2)
        for _ in range(70):
            if f1 <= f2:
                b, x2, f2 = x2, x1, f1
                x1 = b - r * (b - a)
                f1 = f(x1)
            else:
                a, x1, f1 = x1, x2, f2
                x2 = a + r * (b - a)
                f2 = f(x2)
        return float(mpmath.sqrt(min(f1, f2, f(a), f(b))))


def cubics_of(resp):
    c = resp["curve"]
    assert c["type"] == "path", c
    out = []
    for s in c["segments"]:
        assert s["type"] == "bezier" and len(s["points"]) == 4, s
        out.append(np.asarray(s["points"], dtype=float))
    return out


def nearest_distances(points, cloud):
    """For each point, the distance to the nearest of cloud and its index (cKDTree)."""
    best, idx = cKDTree(cloud[:, :2]).query(points)
    return best, idx


def segment_distances(points, a, ab, l2):
    """The distance from each points[k] to the segment from a[k] along ab[k] (l2 = |ab|^2)."""
    s = np.clip(((points - a) * ab).sum(-1) / l2, 0, 1)
    return np.sqrt(((points - (a + s[..., None] * ab)) ** 2).sum(-1))


def polyline_distance(points, poly):
    """Distance from each point to a polyline (array (m, d)), exact for the polyline: the
    minimum over its segments of the exact segment distance. Only the segments that can be
    nearest are measured: with c the segment's midpoint and r its half length, its distance
    is at least |p - c| - r, so none beyond the nearest midpoint's segment distance plus the
    largest r can be (scipy.spatial.cKDTree over the midpoints finds those). The same
    minimum as measuring every segment (checked on this file's and test_outlines.py's
    inputs: identical), at a fraction of the cost."""
    points = np.asarray(points, dtype=float)
    a = poly[:-1]
    ab = poly[1:] - a
    l2 = np.maximum((ab ** 2).sum(1), 1e-300)
    mid = a + ab / 2
    rmax = np.sqrt(l2.max()) / 2
    tree = cKDTree(mid)
    _, j = tree.query(points)
    upper = segment_distances(points, a[j], ab[j], l2[j])
    # Slack above the bound for the rounding of the distances (relative 1e-9 of the scale).
    scale = np.abs(points).max() + np.abs(poly).max()
    near = tree.query_ball_point(points, upper + rmax + 1e-9 * scale)
    counts = np.fromiter((len(c) for c in near), dtype=int, count=len(points))
    rows = np.repeat(np.arange(len(points)), counts)
    cols = np.fromiter((i for c in near for i in c), dtype=int, count=int(counts.sum()))
    out = upper.copy()
    np.minimum.at(out, rows, segment_distances(points[rows], a[cols], ab[cols], l2[cols]))
    return out


def curve_distance(points, beziers, at_least=None, n=4001):
    """The distance from each point to the connected curve made of the Bézier pieces
    (control points), from below, and the distance to the nearest of its dense points
    (from above). Below: the nearest of the curve's points at n equal parameters a piece
    less half the longest chord between them (a point of a chord is that near one of its
    ends) and the chord's sagitta bound max|B''| h^2 / 8 (h = 1 / (n - 1); |B''| at most
    the largest control point of the second hodograph); where that is below `at_least`,
    the exact distance to the polyline less the sagitta instead."""
    polys, sag = [], 0.0
    for P in beziers:
        P = np.asarray(P, dtype=float)
        polys.append(bezier_eval(P, np.linspace(0, 1, n)))
        if len(P) > 2:
            sag = max(sag, np.linalg.norm(hodograph(hodograph(P)), axis=1).max() / (n - 1) ** 2 / 8)
    poly = np.vstack(polys)
    points = np.asarray(points, dtype=float)
    above, _ = cKDTree(poly).query(points)
    below = above - np.sqrt((np.diff(poly, axis=0) ** 2).sum(1).max()) / 2 - sag
    if at_least is not None:
        loose = below < at_least
        if loose.any():
            below[loose] = polyline_distance(points[loose], poly) - sag
    return below, above


def parts_of(cubics):
    """The output split where a cubic does not start at the previous one's end."""
    parts = [[cubics[0]]]
    for a, b in zip(cubics, cubics[1:]):
        if np.array_equal(a[3], b[0]):
            parts[-1].append(b)
        else:
            parts.append([b])
    return parts


def cubic_samples(cubics, m=64):
    t = np.linspace(0, 1, m)
    return np.vstack([bezier_eval(B, t) for B in cubics])


class OffsetTest(CliTest):
    def offset(self, curve, d, tol, **extra):
        return self.ok("offset", dict({"curve": curve, "distance": d, "tolerance": tol}, **extra))

    def assert_path(self, cubics):
        for B in cubics:
            self.assertTrue(np.all(np.isfinite(B)), B)
        for a, b in zip(cubics, cubics[1:]):
            self.assertTrue(np.array_equal(a[3], b[0]), f"the path is continuous: {a[3]} vs {b[0]}")

    def assert_within(self, cubics, exact, tol, both_ways=True):
        """Every output point within tol of the exact offset (and, both_ways, every exact
        point within tol of the output). The screening distance to the dense exact
        samples' polyline overestimates the distance to the curve by at most the chord
        sagitta; the worst points are re-measured in mpmath."""
        dense = exact.samples(4000)
        out = cubic_samples(cubics)
        # Output -> exact: polyline screen per piece, then mpmath on the 8 worst.
        d_poly = np.full(len(out), np.inf)
        for i in range(len(exact.pieces)):
            sel = dense[dense[:, 2] == i]
            if len(sel) > 1:
                d_poly = np.minimum(d_poly, polyline_distance(out, sel[:, :2]))
        worst = np.argsort(d_poly)[-8:]
        _, idx = nearest_distances(out[worst], dense)
        for w, j in zip(worst, idx):
            i, t0 = int(dense[j, 2]), dense[j, 3]
            dist = min(d_poly[w], exact.mp_distance(out[w], i, t0, 2e-3))
            self.assertLessEqual(dist, tol, f"output point {out[w]} is {dist} from the exact offset")
        if not both_ways:
            return
        # Exact -> output: against the output's dense polyline (64 points a cubic: its
        # sagitta is below 1e-4 of tol for the curvatures here), then exactly (Newton on
        # the nearest cubic) for the worst.
        ex = exact.samples(2000)[:, :2]
        d_back = polyline_distance(ex, out)
        for w in np.argsort(d_back)[-8:]:
            best = math.inf
            for B in cubics:
                t = np.linspace(0, 1, 257)
                pts = bezier_eval(B, t)
                k = int(((pts - ex[w]) ** 2).sum(1).argmin())
                u = t[k]
                for _ in range(30):  # Newton on (B(u) - q) . B'(u)
                    p = bezier_eval(B, [u])[0]
                    d1 = bezier_eval(hodograph(B), [u])[0]
                    d2 = bezier_eval(hodograph(hodograph(B)), [u])[0]
                    den = d1 @ d1 + (p - ex[w]) @ d2
                    if den <= 0:
                        break
                    u = min(1.0, max(0.0, u - (p - ex[w]) @ d1 / den))
                best = min(best, float(np.linalg.norm(bezier_eval(B, [u])[0] - ex[w])), float(np.linalg.norm(pts[k] - ex[w])))
            self.assertLessEqual(best, tol, f"exact offset point {ex[w]} is {best} from the output")

    # -----------------------------------------------------------------------------------

    def test_line_is_a_parallel_line(self):
        # The offset of a segment is the segment moved by d along (0, 1) turned: exact
        # (the cubic through the thirds), to rounding.
        r = self.offset({"type": "bezier", "points": [[0, 0], [2, 0]]}, 1, 1e-6)
        cs = cubics_of(r)
        self.assertEqual(len(cs), 1)
        # Exactly representable values: the rounding of thirds only (1 ulp of 2).
        self.assert_close(cs[0].tolist(), [[0, 1], [2 / 3, 1], [4 / 3, 1], [2, 1]], 1e-15)
        r = self.offset({"type": "bezier", "points": [[1, 1], [3, 3], [4, 4]]}, -math.sqrt(2), 1e-9)
        for B in cubics_of(r):
            for p in B:  # on the line y = x - 2 (right of travel along (1, 1)), to rounding
                self.assertAlmostEqual(p[1], p[0] - 2, delta=1e-12)

    def test_circle_arcs_are_concentric(self):
        # A rational quarter circle of radius 1 (counter-clockwise): left is inward, radius
        # 1 - d; right radius 1 + |d|. Every point of the cubics within tol of the circle.
        quarter = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, math.sqrt(0.5), 1]}
        for d, tol in ((0.25, 1e-6), (-0.5, 1e-6), (0.9, 1e-9), (-3, 1e-4)):
            cs = cubics_of(self.offset(quarter, d, tol))
            self.assert_path(cs)
            r = 1 - d
            pts = cubic_samples(cs, 200)
            err = np.abs(np.linalg.norm(pts, axis=1) - r).max()
            self.assertLessEqual(err, tol, (d, tol))
            self.assertLess(np.linalg.norm(cs[0][0] - [r, 0]), 1e-14 * r + 1e-15)
            self.assertLess(np.linalg.norm(cs[-1][3] - [0, r]), 1e-14 * r + 1e-15)
            # Near the fewest: a quarter circle needs one cubic down to 2.7e-4 r of error,
            # two to about 4e-6 r (the error falls as the sixth power of the angle).
            if tol * 1.0 >= 2.8e-4 * r:
                self.assertEqual(len(cs), 1, (d, tol))

    def test_cubic_both_ways(self):
        # An S-shaped cubic with an inflection, both sides, against the exact offset.
        P = [[0, 0], [1, 3], [3, -2], [4, 1]]
        for d, tol in ((0.3, 1e-4), (-0.3, 1e-4), (0.05, 1e-7)):
            cs = cubics_of(self.offset({"type": "bezier", "points": P}, d, tol))
            self.assert_path(cs)
            self.assert_within(cs, ExactOffset([Piece(P)], d), tol)

    def test_rational_and_degree_five(self):
        P = [[0, 0], [1, 2], [2, -1], [3, 2], [4, 0], [5, 1]]
        cs = cubics_of(self.offset({"type": "bezier", "points": P}, 0.1, 1e-5))
        self.assert_within(cs, ExactOffset([Piece(P)], 0.1), 1e-5)
        R = {"type": "rational_bezier", "points": [[0, 0], [1, 2], [3, 1]], "weights": [1, 3, 0.5]}
        cs = cubics_of(self.offset(R, -0.2, 1e-6))
        self.assert_within(cs, ExactOffset([Piece(R["points"], R["weights"])], -0.2), 1e-6)

    def test_zero_derivative_at_an_end(self):
        # Coincident first control points: C'(0) = 0, the tangent there is the limit
        # (P2 - P0 direction); no NaN, within the tolerance both ways.
        P = [[0, 0], [0, 0], [1, 1], [2, 0]]
        cs = cubics_of(self.offset({"type": "bezier", "points": P}, 0.2, 1e-6))
        self.assert_path(cs)
        self.assert_within(cs, ExactOffset([Piece(P)], 0.2), 1e-6)
        # Its start: C(0) + d N with N the limit normal, (-1, 1) / sqrt 2.
        self.assert_close(cs[0][0].tolist(), [-0.2 / math.sqrt(2), 0.2 / math.sqrt(2)], 1e-12)

    def test_zero_distance_is_the_curve(self):
        P = [[0, 0], [1, 3], [3, 3], [4, 0]]
        cs = cubics_of(self.offset({"type": "bezier", "points": P}, 0, 1e-9))
        self.assertEqual(len(cs), 1)
        self.assert_close(cs[0].tolist(), P, 1e-14)

    def parabola_offset(self, x, d):
        s = np.sqrt(1 + 4 * x * x)
        return np.column_stack([x - 2 * d * x / s, x * x + d / s])

    def test_glyph_piece_across_its_offset_cusp(self):
        # A glyph's quadratic (W11's glyph piece 18, em 2048) offset by d = 204.8 (1e-1 em)
        # to its left, untrimmed: its radius of curvature falls below d near the end
        # (numpy, below), so the exact offset has a cusp there and runs backwards after it.
        # The offset is smooth in t through the cusp (its velocity (1 - d kappa) C' only
        # passes through zero), and one cubic follows it within the tolerance both ways
        # (the mpmath oracle), where the stretches on either side took one each.
        Q = np.array([[354.0, 973.0], [354.0, 887.0], [410.0, 839.0]])
        d, tol = 204.8, 2.048
        t = np.linspace(0, 1, 2001)[:, None]
        v = 2 * ((1 - t) * (Q[1] - Q[0]) + t * (Q[2] - Q[1]))
        a = 2 * (Q[2] - 2 * Q[1] + Q[0])
        g = 1 - d * (v[:, 0] * a[1] - v[:, 1] * a[0]) / np.linalg.norm(v, axis=1) ** 3
        self.assertEqual(int(np.count_nonzero(np.diff(np.sign(g)))), 1)  # one cusp of the offset
        cs = cubics_of(self.offset({"type": "bezier", "points": Q.tolist()}, d, tol, trim=False))
        self.assertEqual(len(cs), 1)
        self.assert_within(cs, ExactOffset([Piece(Q.tolist())], d), tol)

    def test_parabola_cusps_trimmed(self):
        # y = x^2 on [-1, 1] (the quadratic Bézier (-1, 1), (0, -1), (1, 1)), travelled
        # left to right: left is up, towards the centre of curvature. Its radius of
        # curvature at the vertex is 1/2; at d = 1 the offset has two cusps where
        # (1 + 4 x^2)^(3/2) = 2 d, x = +-0.383, and a swallowtail that crosses itself on the
        # axis where sqrt(1 + 4 x^2) = 2 d: x = +-sqrt(3)/2, the point (0, 3/4 + 1/2).
        parabola = {"type": "bezier", "points": [[-1, 1], [0, -1], [1, 1]]}
        d, tol = 1.0, 1e-5
        raw = cubics_of(self.offset(parabola, d, tol, trim=False))
        self.assert_path(raw)
        self.assert_within(raw, ExactOffset([Piece(parabola["points"])], d), tol)
        # The raw offset passes through both cusps (the closed form at x = +-0.383).
        xc = math.sqrt((2 ** (2 / 3) - 1) / 4)
        cusp = self.parabola_offset(np.array([-xc, xc]), d)
        pts = cubic_samples(raw, 400)
        for c in cusp:
            self.assertLess(np.linalg.norm(pts - c, axis=1).min(), 2e-3)  # the sample spacing near it
        trimmed = cubics_of(self.offset(parabola, d, tol))
        self.assert_path(trimmed)
        # Nothing of the swallowtail is left: every point at least d - tol from the
        # parabola (the loop's points are closer), at most d + tol.
        xs = np.linspace(-1.5, 1.5, 30001)
        par = np.column_stack([xs, xs * xs])
        pts = cubic_samples(trimmed, 200)
        dist_to_parabola = polyline_distance(pts, par)  # the polyline's sagitta: (1e-4)^2 kappa / 8 < 3e-9
        self.assertGreaterEqual(dist_to_parabola.min(), d - tol - 3e-9)
        self.assertLessEqual(dist_to_parabola.max(), d + tol + 3e-9)
        # The two branches meet at the self-intersection (0, 1.25): the cubics' crossing,
        # within tol / sin(60 deg) of it (each branch within tol, crossing at 120 degrees).
        ends = [B[3] for B in trimmed[:-1]]
        self.assertLess(min(np.linalg.norm(e - [0, 1.25]) for e in ends), tol / math.sin(math.pi / 3))
        # The kept part is the exact offset outside the loop, both ways (x beyond +-sqrt(3)/2).
        ex = self.parabola_offset(np.concatenate([np.linspace(-1, -0.8661, 500), np.linspace(0.8661, 1, 500)]), d)
        self.assertLessEqual(polyline_distance(ex, cubic_samples(trimmed, 256)).max(), tol)

    def test_parabola_touching_radius(self):
        # d = 1/2: |d| equals the radius of curvature at the vertex, where the offset's
        # speed vanishes without reversing: no NaN, within the tolerance, nothing trimmed.
        parabola = {"type": "bezier", "points": [[-1, 1], [0, -1], [1, 1]]}
        cs = cubics_of(self.offset(parabola, 0.5, 1e-6))
        self.assert_path(cs)
        self.assert_within(cs, ExactOffset([Piece(parabola["points"])], 0.5), 1e-6)

    def test_corner_joins(self):
        # The polyline (0,0) -> (2,0) -> (2,2) turns left by 90 degrees at (2, 0); at d =
        # -0.5 (right) that corner is outer.
        L = {"type": "polyline", "points": [[0, 0], [2, 0], [2, 2]]}
        tol = 1e-6
        # round: an arc of radius 0.5 about (2, 0) from (2, -0.5) to (2.5, 0).
        cs = cubics_of(self.offset(L, -0.5, tol))
        self.assert_path(cs)
        self.assert_close(cs[0][0].tolist(), [0, -0.5], 1e-15)
        self.assert_close(cs[-1][3].tolist(), [2.5, 2], 1e-15)
        arc = [B for B in cs if B[0][0] >= 2 - 1e-12 and B[3][1] <= 1e-12 and not np.array_equal(B[0], B[3])]
        self.assertGreaterEqual(len(arc), 1)
        pts = cubic_samples(arc, 200)
        self.assertLessEqual(np.abs(np.linalg.norm(pts - [2, 0], axis=1) - 0.5).max(), tol)
        self.assert_close(arc[0][0].tolist(), [2, -0.5], 1e-12)
        self.assert_close(arc[-1][3].tolist(), [2.5, 0], 1e-12)
        # miter: the lines y = -0.5 and x = 2.5 meet at (2.5, -0.5); the ratio 1/cos(45
        # deg) = 1.414 is within the default limit 4.
        cs = cubics_of(self.offset(L, -0.5, tol, join="miter"))
        self.assertEqual(len(cs), 4)
        self.assert_close(cs[1][0].tolist(), [2, -0.5], 1e-15)
        self.assert_close(cs[1][3].tolist(), [2.5, -0.5], 1e-15)  # a few ulps of 2.5 (a unit vector, a cosine)
        self.assert_close(cs[2][3].tolist(), [2.5, 0], 1e-15)
        # past the limit (1.2 < 1.414) the miter is a bevel, as SVG's stroke-miterlimit.
        for req in ({"join": "miter", "miter_limit": 1.2}, {"join": "bevel"}):
            cs = cubics_of(self.offset(L, -0.5, tol, **req))
            self.assertEqual(len(cs), 3)
            B = cs[1]
            self.assert_close(B[0].tolist(), [2, -0.5], 1e-15)
            self.assert_close(B[3].tolist(), [2.5, 0], 1e-15)
            for p in B:  # a straight line: every control point on the chord
                u, v = B[3] - B[0], p - B[0]
                self.assertLess(abs(u[0] * v[1] - u[1] * v[0]), 1e-15)
        # The inner side (d = +0.5): the two offset lines cross at (1.5, 0.5), where the
        # trim cuts them; without trim the raw line between the offset ends is kept.
        cs = cubics_of(self.offset(L, 0.5, tol))
        self.assert_path(cs)
        self.assertEqual(len(cs), 2)
        self.assert_close(cs[0][3].tolist(), [1.5, 0.5], 1e-12)
        self.assert_close(cs[0][0].tolist(), [0, 0.5], 1e-15)
        self.assert_close(cs[1][3].tolist(), [1.5, 2], 1e-15)
        raw = cubics_of(self.offset(L, 0.5, tol, trim=False))
        self.assertEqual(len(raw), 3)
        self.assert_close(raw[1][0].tolist(), [2, 0.5], 1e-15)
        self.assert_close(raw[1][3].tolist(), [1.5, 0], 1e-15)

    def test_closed_square(self):
        # The counter-clockwise unit square: outward (d < 0) four round corners; inward
        # (d > 0) the square [0.1, 0.9]^2 with its corners cut at the crossings, the one at
        # the closing point too.
        sq = {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]}
        cs = cubics_of(self.offset(sq, -0.1, 1e-6))
        self.assert_path(cs)
        self.assertTrue(np.array_equal(cs[-1][3], cs[0][0]), "closed")
        pts = cubic_samples(cs, 100)
        # Every point 0.1 from the square (distance to its boundary polyline).
        d = polyline_distance(pts, np.array(sq["points"], dtype=float))
        self.assertLessEqual(np.abs(d - 0.1).max(), 1e-6)
        cs = cubics_of(self.offset(sq, 0.1, 1e-6))
        self.assert_path(cs)
        self.assertEqual(len(cs), 4)
        corners = sorted(tuple(np.round(B[0], 9)) for B in cs)
        self.assertEqual(corners, [(0.1, 0.1), (0.1, 0.9), (0.9, 0.1), (0.9, 0.9)])
        self.assertLess(np.linalg.norm(cs[-1][3] - cs[0][0]), 1e-12)

    def test_closed_circle(self):
        # Four rational quarters of the unit circle (counter-clockwise, a closed path).
        w = math.sqrt(0.5)
        quarters = [{"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, w, 1]},
                    {"type": "rational_bezier", "points": [[0, 1], [-1, 1], [-1, 0]], "weights": [1, w, 1]},
                    {"type": "rational_bezier", "points": [[-1, 0], [-1, -1], [0, -1]], "weights": [1, w, 1]},
                    {"type": "rational_bezier", "points": [[0, -1], [1, -1], [1, 0]], "weights": [1, w, 1]}]
        circle = {"type": "path", "segments": quarters}
        for d in (0.25, -0.25):
            cs = cubics_of(self.offset(circle, d, 1e-7))
            self.assert_path(cs)
            pts = cubic_samples(cs, 100)
            self.assertLessEqual(np.abs(np.linalg.norm(pts, axis=1) - (1 - d)).max(), 1e-7)
            self.assertLess(np.linalg.norm(cs[-1][3] - cs[0][0]), 1e-14)
        # Inward by more than the radius (past the centre): the raw offset, the circle of
        # radius 0.5 traversed clockwise, is 0.5 from the curve: nothing is left (as for the
        # square at 0.6); untrimmed it is returned.
        self.bad("offset", {"curve": circle, "distance": 1.5, "tolerance": 1e-7}, "distance", contains="trimmed offset is empty")
        cs = cubics_of(self.offset(circle, 1.5, 1e-7, trim=False))
        pts = cubic_samples(cs, 100)
        self.assertLessEqual(np.abs(np.linalg.norm(pts, axis=1) - 0.5).max(), 1e-7)

    def test_input_cusp(self):
        # The cubic (0,0), (2,2), (0,2), (2,0) has a cusp at t = 1/2 (C'(1/2) = 0): a
        # reversal of the tangent, closed on the offset by a half circle of radius |d| round
        # the cusp point (1, 1.5).
        P = [[0, 0], [2, 2], [0, 2], [2, 0]]
        cs = cubics_of(self.offset({"type": "bezier", "points": P}, 0.1, 1e-6, trim=False))
        self.assert_path(cs)
        pts = cubic_samples(cs, 64)
        self.assertTrue(np.all(np.isfinite(pts)))
        self.assertLess(np.abs(np.linalg.norm(pts - [1, 1.5], axis=1)).min(), 0.1 + 1e-6)
        # The arc over the cusp's tip: 64 samples a cubic find its top to 1e-5 (r (dphi)^2 / 8).
        self.assertGreater(pts[:, 1].max(), 1.5 + 0.1 - 1e-5)
        self.assertLess(pts[:, 1].max(), 1.5 + 0.1 + 1e-6)

    def test_huge_and_tiny_coordinates(self):
        for s in (1e200, 1e-200):
            r = self.offset({"type": "bezier", "points": [[0, 0], [2 * s, 0]]}, s, s * 1e-6)
            cs = cubics_of(r)
            self.assert_close((cs[0][0] / s).tolist(), [0, 1], 1e-15)  # powers of two and s: exact up to the scaling
            self.assert_close((cs[-1][3] / s).tolist(), [2, 1], 1e-15)
            quarter = {"type": "rational_bezier", "points": [[s, 0], [s, s], [0, s]], "weights": [1, math.sqrt(0.5), 1]}
            pts = cubic_samples(cubics_of(self.offset(quarter, 0.25 * s, 1e-6 * s)), 100)
            self.assertLessEqual(np.abs(np.linalg.norm(pts / s, axis=1) - 0.75).max(), 1e-6)

    def test_fewer_than_uniform(self):
        # Near the fewest: a cubic's offset at 1e-4 takes no more cubics than the number
        # that halving the parameter uniformly needs (2^k parts with Hermite cubics, the
        # exact offset's end points and derivatives; counted in the test on 64 samples a
        # cubic against the exact offset's dense polyline).
        P = [[0, 0], [1, 3], [3, -2], [4, 1]]
        d, tol = 0.3, 1e-4
        cs = cubics_of(self.offset({"type": "bezier", "points": P}, d, tol))
        pc = Piece(P)

        def hermite(a, b):
            ts = np.array([a, b])
            c, v = pc.point_and_derivative(ts)
            dv = bezier_eval(hodograph(hodograph(P)), ts)
            sp = np.linalg.norm(v, axis=1)
            kappa = (v[:, 0] * dv[:, 1] - v[:, 1] * dv[:, 0]) / sp ** 3
            n = np.column_stack([-v[:, 1], v[:, 0]]) / sp[:, None]
            o = c + d * n
            do = v * (1 - d * kappa)[:, None] * (b - a)
            return np.array([o[0], o[0] + do[0] / 3, o[1] - do[1] / 3, o[1]])

        ex = ExactOffset([pc], d).samples(5000)[:, :2]  # chords' sagitta below 1e-6 (offset curvature < 30)
        k = 0
        while True:
            n = 2 ** k
            parts = [hermite(i / n, (i + 1) / n) for i in range(n)]
            if polyline_distance(cubic_samples(parts, 64), ex).max() <= tol:
                break
            k += 1
        self.assertLessEqual(len(cs), n, f"{len(cs)} cubics against {n} uniform")

    # The trimmed offset: the points of the raw offset at least |d| from the curve.

    def assert_trimmed(self, beziers, d, tol, cubics, margin=0.02):
        """Every output point at least |d| - tol from the curve (curve_distance, from
        below), and every point of the exact offset that is |d| from the curve (its own
        foot the nearest) within tol of the output, except within `margin` of an exact
        point that is nearer (where the trim cuts, the cut moves by up to tol / sin of the
        crossing angle)."""
        out = cubic_samples(cubics, 64)
        floor = abs(d) - tol * (1 + 1e-6)
        near, _ = curve_distance(out, beziers, floor)
        self.assertGreaterEqual(near.min(), floor, f"an output point is {near.min()} from the curve")
        exact = ExactOffset([Piece(P) for P in beziers], d).samples(1000)[:, :2]
        below, above = curve_distance(exact, beziers)  # a point of the offset is at most |d| away
        bad = exact[below < abs(d) - 1e-3 * abs(d)]
        good = exact[above >= abs(d) - 1e-9]
        if len(bad):
            good = good[nearest_distances(good, bad)[0] > margin]
        if len(good):
            back = np.min([polyline_distance(good, cubic_samples(part, 400)) for part in parts_of(cubics)], axis=0)
            self.assertLessEqual(back.max(), tol * 1.01, f"exact point {good[back.argmax()]} is {back.max()} from the output")

    def test_trim_rectangle_past_half_height(self):
        # The 2 x 1 rectangle (counter-clockwise) inward by more than its half height: every
        # point of the raw offset is nearer than |d| to the opposite side: nothing is left
        # (the unit square at 0.6 too). The open U likewise. At 0.45 the inner rectangle.
        rect = {"type": "polyline", "points": [[0, 0], [2, 0], [2, 1], [0, 1], [0, 0]]}
        U = {"type": "polyline", "points": [[0, 0], [3, 0], [3, 1], [0, 1]]}
        square = {"type": "polyline", "points": [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]}
        for curve, d in ((rect, 0.6), (rect, 0.55), (U, 0.6), (square, 0.6)):
            self.bad("offset", {"curve": curve, "distance": d, "tolerance": 1e-3}, "distance", contains="trimmed offset is empty")
        cs = cubics_of(self.offset(rect, 0.45, 1e-3))
        self.assert_path(cs)
        self.assertEqual(sorted(tuple(np.round(B[0], 9)) for B in cs), [(0.45, 0.45), (0.45, 0.55), (1.55, 0.45), (1.55, 0.55)])
        lines = [[a, b] for a, b in zip(rect["points"], rect["points"][1:])]
        self.assert_trimmed(lines, 0.45, 1e-3, cs)

    def test_trim_input_cusp_symmetric(self):
        # K has a cusp at (1, 1.5) and is symmetric about x = 1 (K(1 - t) mirrored). The
        # trimmed offset keeps exactly the points |d| from K: symmetric within 2 tol, on the
        # inner side (d = -0.2) the loop round the cusp cut at the crossing of the branches'
        # offsets (the V meets there; the round cap over the tip is a part of its own).
        K = [[0, 0], [2, 2], [0, 2], [2, 0]]
        tol = 1e-3
        for d in (-0.2, 1.0):
            cs = cubics_of(self.offset({"type": "bezier", "points": K}, d, tol))
            self.assert_trimmed([K], d, tol, cs)
            pts = cubic_samples(cs, 200)
            mirrored = pts * [-1, 1] + [2, 0]
            back = np.min([polyline_distance(mirrored, cubic_samples(part, 2000)) for part in parts_of(cs)], axis=0)
            self.assertLessEqual(back.max(), 2 * tol)
            for part in parts_of(cs):
                self.assert_path(part)
            if d == -0.2:
                # The V: a part ends and one starts at the crossing on x = 1.
                ends = [p[-1][3] for p in parts_of(cs)] + [p[0][0] for p in parts_of(cs)]
                self.assertTrue(any(abs(e[0] - 1) < 2 * tol and e[1] < 1.2 for e in ends), ends)

    def test_trim_peanut_waist(self):
        # A closed peanut (uniform Catmull-Rom through 16 points of x = 2 cos u, y = sin u
        # (0.25 + 0.75 cos^2 u), written as cubic Béziers here), counter-clockwise, waist
        # half height 0.25: inward by 0.3 the offsets of the two sides cross at the waist,
        # and the lens between the crossings is nearer than 0.3 to the curve: two closed
        # loops are left, one per lobe.
        u = 2 * np.pi * np.arange(16) / 16
        P = np.column_stack([2 * np.cos(u), np.sin(u) * (0.25 + 0.75 * np.cos(u) ** 2)])
        beziers = [[P[i], P[i] + (P[(i + 1) % 16] - P[i - 1]) / 6, P[(i + 1) % 16] - (P[(i + 2) % 16] - P[i]) / 6, P[(i + 1) % 16]]
                   for i in range(16)]
        curve = {"type": "path", "segments": [{"type": "bezier", "points": np.asarray(B).tolist()} for B in beziers]}
        tol = 1e-3
        cs = cubics_of(self.offset(curve, 0.3, tol))
        parts = parts_of(cs)
        self.assertEqual(len(parts), 2)
        for part in parts:
            self.assertLess(np.linalg.norm(part[-1][3] - part[0][0]), 1e-9, "each lobe's loop is closed")
            xs = cubic_samples(part, 16)[:, 0]
            self.assertTrue(xs.max() < 0 or xs.min() > 0, "one lobe each")
        self.assert_trimmed(beziers, 0.3, tol, cs)
        # Outward nothing is cut.
        cs = cubics_of(self.offset(curve, -0.3, tol))
        self.assert_path(cs)
        self.assert_trimmed(beziers, -0.3, tol, cs)

    def test_degree_zero_jumps_are_gaps(self):
        # A degree-0 B-spline is constant pieces; where they jump the offset is refused as
        # a gap, as for a degree-1 spline with a jump (not as a single point).
        req = {"distance": 1, "tolerance": 1e-3}
        step0 = {"type": "bspline", "degree": 0, "knots": [0, 1, 2, 3], "points": [[0, 0], [1, 1], [3, 3]]}
        step1 = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2], "points": [[0, 0], [1, 0], [1, 1], [2, 1]]}
        self.bad("offset", dict(req, curve=step0), "curve", contains="gap of 1.414214")
        self.bad("offset", dict(req, curve=step1), "curve", contains="gap of 1.000000")

    def test_bad_input(self):
        cubic = {"type": "bezier", "points": [[0, 0], [1, 3], [3, 3], [4, 0]]}
        req = {"curve": cubic, "distance": 0.5, "tolerance": 1e-3}
        self.bad("offset", dict(req, curve={"type": "bezier", "points": [[0, 0, 0], [1, 1, 1]]}), "curve", contains="2-D")
        self.bad("offset", dict(req, tolerance=0), "tolerance", contains="> 0")
        self.bad("offset", dict(req, tolerance=-1), "tolerance")
        self.bad("offset", {"curve": cubic, "tolerance": 1e-3}, "distance", contains="missing")
        self.bad("offset", {"curve": cubic, "distance": 1}, "tolerance", contains="missing")
        self.bad("offset", dict(req, join="square"), "join", contains="unknown")
        self.bad("offset", dict(req, join="miter", miter_limit=0.5), "miter_limit", contains=">= 1")
        # miter_limit belongs to join miter (the contract: a field of another choice is an error)
        self.bad("offset", dict(req, join="bevel", miter_limit=2), "miter_limit", contains="'bevel'")
        self.bad("offset", dict(req, join="round", miter_limit=2), "miter_limit", contains="'round'")
        self.bad("offset", dict(req, miter_limit=2), "miter_limit", contains="default")
        self.ok("offset", dict(req, join="miter", miter_limit=2))
        self.bad("offset", dict(req, trim="yes"), "trim")
        self.bad("offset", dict(req, distance="1"), "distance")
        self.bad("offset", dict(req, curve={"type": "bezier", "points": [[1, 1], [1, 1]]}), "curve", contains="point")
        self.bad("offset", dict(req, tolerance=1e-300), "tolerance")
        gap = {"type": "path", "segments": [{"type": "bezier", "points": [[0, 0], [1, 0]]},
                                             {"type": "bezier", "points": [[2, 0], [3, 0]]}]}
        self.bad("offset", dict(req, curve=gap), "curve", contains="gap")
        # The work limit, before any work, with the figure.
        walk = {"type": "polyline", "points": [[i, (i * 7919) % 13] for i in range(6000)]}
        self.bad("offset", dict(req, curve=walk), "tolerance", contains="limit")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
