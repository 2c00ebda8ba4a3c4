#!/usr/bin/python3
"""Black-box tests of `to_quadratic`: a curve as a path of quadratic Béziers within a
tolerance, tangent-continuous where the curve is.

Oracles written here: the curves are evaluated by de Casteljau (rational ones on their
homogeneous points) independently of the program; the two-sided distance between the
curve and the response is measured on dense samples of both (scipy's cKDTree: the distance
from each sample to the nearest sample of the other curve is at most the true distance
plus half the other's largest sample spacing, which the check allows); joint tangents are
compared with the curve's own derivative directions. The segment counts are compared with
fonttools' cu2qu (`curve_to_quadratic`, python3-fonttools) at the same tolerance when it
is importable.

Usage: test_quadratic.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import unittest

import numpy as np
from scipy.spatial import cKDTree

import test_cli
from test_cli import CliTest

try:
    from fontTools.cu2qu import curve_to_quadratic
except ImportError:  # the comparison is skipped without python3-fonttools
    curve_to_quadratic = None


def de_casteljau(points, weights, s):
    """Point of a (rational) Bézier curve at the parameters s (array), homogeneous."""
    P = np.asarray(points, float)
    w = np.ones(len(P)) if weights is None else np.asarray(weights, float)
    H = np.hstack([P * w[:, None], w[:, None]])
    s = np.asarray(s, float)[:, None, None]
    cur = np.broadcast_to(H, (s.shape[0],) + H.shape).copy()
    for k in range(1, len(P)):
        cur = (1 - s) * cur[:, :-1] + s * cur[:, 1:]
    h = cur[:, 0]
    return h[:, :-1] / h[:, -1:]


def sample(curve, n):
    """Dense points of a bezier, rational_bezier or path of them (n per segment)."""
    segs = curve["segments"] if curve["type"] == "path" else [curve]
    s = np.linspace(0, 1, n + 1)
    return np.vstack([de_casteljau(c["points"], c.get("weights"), s) for c in segs])


def spacing(pts):
    return float(np.max(np.linalg.norm(np.diff(pts, axis=0), axis=1)))


def hausdorff_check(test, curve, quads, tol, n=4000):
    a = sample(curve, n)
    b = sample(quads, n)
    # Segment ends of a path repeat: spacing over consecutive samples of one segment only
    # is what matters, and the joints' repeats give zero steps, so the max is right.
    d_ab = cKDTree(b).query(a)[0].max()
    d_ba = cKDTree(a).query(b)[0].max()
    test.assertLessEqual(d_ab, tol + spacing(b) / 2)
    test.assertLessEqual(d_ba, tol + spacing(a) / 2)
    return max(d_ab, d_ba)


def direction(points, weights, at_start):
    """The curve's unit tangent at an end: the first control point that differs from the
    end point (rational: its Cartesian points, weights positive)."""
    P = np.asarray(points, float)
    order = range(1, len(P)) if at_start else range(len(P) - 2, -1, -1)
    e = P[0] if at_start else P[-1]
    for k in order:
        d = (P[k] - e) if at_start else (e - P[k])
        if np.linalg.norm(d) > 1e-12 * max(1.0, np.abs(P).max()):
            return d / np.linalg.norm(d)
    return None


def angle(a, b):
    return math.atan2(np.linalg.norm(a - np.dot(a, b) * b), np.dot(a, b))


class QuadraticTest(CliTest):
    def quad(self, curve, tol):
        r = self.ok("to_quadratic", {"curve": curve, "tolerance": tol})["curve"]
        self.assertEqual(r["type"], "path")
        for s in r["segments"]:
            self.assertEqual(s["type"], "bezier")
            self.assertEqual(len(s["points"]), 3)
        return r

    def joint_angles(self, r):
        """The output's turning angle at each joint (end tangent of one segment against the
        start tangent of the next)."""
        out = []
        segs = r["segments"]
        for a, b in zip(segs, segs[1:]):
            self.assertEqual(a["points"][2], b["points"][0], "segments meet")
            ta = direction(a["points"], None, False)
            tb = direction(b["points"], None, True)
            out.append(angle(ta, tb))
        return out

    def test_quadratic_and_line_come_back_exactly(self):
        q = test_cli.bezier([[0, 0], [1, 2], [3, -1]])
        r = self.quad(q, 1e-9)
        self.assertEqual(r["segments"], [q])
        r = self.quad(test_cli.bezier([[1, 1], [3, 5]]), 1e-9)
        self.assertEqual([s["points"] for s in r["segments"]], [[[1, 1], [2, 3], [3, 5]]])

    def test_elevated_quadratic_is_one_segment(self):
        # The cubic C1 = P0 + 2/3 (P1 - P0), C2 = P2 + 2/3 (P1 - P2) is the quadratic.
        P0, P1, P2 = np.array([0.0, 0.0]), np.array([2.0, 3.0]), np.array([5.0, 1.0])
        cubic = test_cli.bezier([P0.tolist(), (P0 + 2 / 3 * (P1 - P0)).tolist(), (P2 + 2 / 3 * (P1 - P2)).tolist(), P2.tolist()])
        r = self.quad(cubic, 1e-9)
        self.assertEqual(len(r["segments"]), 1)
        # Rounding of the 2/3 and of the tangent intersection: a few eps of the size 5.
        self.assertTrue(np.allclose(r["segments"][0]["points"], [P0, P1, P2], atol=1e-13, rtol=0))

    def test_random_cubics_against_cu2qu(self):
        rng = random.Random(11)
        ours = theirs = 0
        for i in range(40):
            pts = [[rng.uniform(0, 100), rng.uniform(0, 100)] for _ in range(4)]
            tol = (0.1, 1.0)[i % 2]
            r = self.quad(test_cli.bezier(pts), tol)
            hausdorff_check(self, test_cli.bezier(pts), r, tol)
            # Inside one cubic every joint is smooth unless it is a cusp (none in
            # random data): the output turns there by at most 1e-9 rad.
            for a in self.joint_angles(r):
                self.assertLessEqual(a, 1e-9)
            ours += len(r["segments"])
            if curve_to_quadratic is not None:
                theirs += len(curve_to_quadratic([tuple(p) for p in pts], tol)) - 2
        if curve_to_quadratic is not None:
            self.assertLessEqual(ours, theirs, "no more segments than cu2qu in all")

    def test_path_joints(self):
        # Joint 1 smooth (collinear handles), joint 2 a corner.
        path = {"type": "path", "segments": [test_cli.bezier([[0, 0], [1, 2], [2, 2], [3, 0]]),
                                             test_cli.bezier([[3, 0], [4, -2], [5, -2], [6, 0]]),
                                             test_cli.bezier([[6, 0], [6, 3], [8, 3], [9, 1]])],
                "breaks": [0, 1, 3, 4]}
        r = self.quad(path, 1e-3)
        hausdorff_check(self, path, r, 1e-3)
        self.assertEqual(r["breaks"][0], 0)
        self.assertEqual(r["breaks"][-1], 4)
        self.assertIn(1, r["breaks"])
        self.assertIn(3, r["breaks"])
        angles = self.joint_angles(r)
        corner = r["breaks"].index(3) - 1
        for i, a in enumerate(angles):
            if i == corner:
                # The corner stays a corner: directions (1, 2) in, (0, 1) out.
                self.assertAlmostEqual(a, math.atan2(1, 2), delta=1e-12)
            else:
                self.assertLessEqual(a, 1e-9)

    def test_rational_and_space_curves(self):
        quarter = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, math.sqrt(0.5), 1]}
        r = self.quad(quarter, 1e-6)
        hausdorff_check(self, quarter, r, 1e-6)
        self.assertTrue(all(a <= 1e-9 for a in self.joint_angles(r)))
        # The circle itself: every output sample within the tolerance of the unit radius
        # (the exact distance to the arc, beyond the sampled check above).
        q = sample(r, 2000)
        self.assertLessEqual(np.abs(np.linalg.norm(q, axis=1) - 1).max(), 1e-6)
        twisted = test_cli.bezier([[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]])
        r = self.quad(twisted, 1e-4)
        hausdorff_check(self, twisted, r, 1e-4)
        self.assertTrue(all(a <= 1e-9 for a in self.joint_angles(r)))

    def test_cusp_has_no_nan(self):
        cusp = test_cli.bezier([[0, 0], [1, 1], [0, 1], [1, 0]])  # a cusp at t = 1/2
        r = self.quad(cusp, 1e-3)
        self.assertTrue(all(math.isfinite(x) for s in r["segments"] for p in s["points"] for x in p))
        hausdorff_check(self, cusp, r, 1e-3)
        self.assertIn(0.5, [round(b, 12) for b in r["breaks"]])  # a joint at the cusp

    def test_scale_invariance(self):
        # Audit 16 D11: scaled by 1e-200 the cubic came back as one quadratic 400 times
        # outside the tolerance, and from 1e170 up it was refused. The problem is scale
        # invariant: at every scale the same count as at scale 1, and each response, scaled
        # back here (exactly for 2^-660, to 1e-16 otherwise), within the tolerance of the
        # unscaled curve on dense samples. 4e307 puts a coordinate at 1.6e308 (the estimate
        # of the count beforehand overflowed there), 1e-305 makes the tolerance subnormal.
        # A rational piece and a B-spline (several pieces) take the same path: their
        # counts only (the B-spline is not sampled here).
        tol = 1e-3
        curves = (test_cli.bezier([[0, 0], [1, 2], [3, 2], [4, 0]]), test_cli.bezier([[0, 0], [1, 1], [2, -1], [3, 0]]),
                  {"type": "rational_bezier", "points": [[0, 0], [1, 2], [3, 2], [4, 0]], "weights": [1, 3, 1, 2]},
                  {"type": "bspline", "degree": 3, "knots": [0, 0, 0, 0, 1, 2, 2, 2, 2],
                   "points": [[0, 0], [1, 2], [2, 2], [3, 0], [4, -1]]})
        for unit in curves:
            n1 = len(self.quad(unit, tol)["segments"])
            for s in (2.0**-660, 1e-305, 1e-300, 1e-200, 1e170, 1e300, 4e307):
                with self.subTest(curve=unit["type"], scale=s):
                    r = self.quad(dict(unit, points=[[x * s for x in p] for p in unit["points"]]), tol * s)
                    self.assertEqual(len(r["segments"]), n1)
                    if unit["type"] == "bspline":
                        continue
                    back = {"type": "path", "segments": [test_cli.bezier([[x / s for x in p] for p in q["points"]])
                                                         for q in r["segments"]]}
                    hausdorff_check(self, unit, back, tol * (1 + 1e-9))

    def test_bad_input(self):
        c = test_cli.bezier([[0, 0], [1, 2], [3, 2], [4, 0]])
        self.bad("to_quadratic", {"curve": c, "tolerance": 0}, "tolerance", contains="> 0")
        self.bad("to_quadratic", {"curve": c, "tolerance": -1}, "tolerance")
        self.bad("to_quadratic", {"curve": c, "tolerance": "small"}, "tolerance")
        self.bad("to_quadratic", {"curve": c}, "tolerance", contains="missing")
        self.bad("to_quadratic", {"tolerance": 0.1}, "curve", contains="missing")
        big = test_cli.bezier([[0, 0], [1e6, 1e6], [-1e6, 1e6], [1e6, 0]])
        err = self.bad("to_quadratic", {"curve": big, "tolerance": 1e-300}, "tolerance", contains="limit")
        self.assertRegex(err, r"[0-9]")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
