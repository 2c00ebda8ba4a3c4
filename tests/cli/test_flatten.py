#!/usr/bin/python3
"""Black-box tests of the three `flatten` methods (uniform, subdivision, optimal): every
method's polyline within the tolerance of the curve by dense sampling with a de Casteljau
and a rational evaluator written here (cubics with cusps, loops and inflections, the
quarter circle, a NURBS circle, a path), the optimal method's count below the others, the
default method, and bad methods.

Usage: test_flatten.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import unittest

import mpmath
import numpy as np

import test_cli
from test_cli import CliTest, QUARTER_CIRCLE, bezier, de_casteljau, rational_point

METHODS = ("uniform", "subdivision", "optimal")


class FlattenMethodsTest(CliTest):
    def flat(self, curve, tol, method):
        return self.ok("flatten", {"curve": curve, "tolerance": tol, "method": method})["points"]

    def check(self, point_at, poly, tol, samples=3000):
        """Largest distance from samples of the curve to the polyline (numpy, vectorised
        over segments)."""
        a = np.array(poly[:-1], dtype=float)
        ab = np.array(poly[1:], dtype=float) - a
        l2 = np.maximum((ab * ab).sum(axis=1), 1e-300)
        worst = 0.0
        for i in range(samples + 1):
            p = np.array(point_at(i / samples), dtype=float)
            s = np.clip(((p - a) * ab).sum(axis=1) / l2, 0, 1)
            d = np.sqrt((((a + s[:, None] * ab) - p) ** 2).sum(axis=1)).min()
            worst = max(worst, d)
        self.assertLessEqual(worst, tol)
        return worst

    def test_cubics_with_cusp_loop_inflection(self):
        curves = {
            "cusp": [[0, 0], [2, 2], [0, 2], [2, 0]],  # cusp at t = 1/2 (x' = 6 (1 - 2t)^2 = y' = 0)
            "loop": [[0, 0], [3, 3], [-1, 3], [2, 0]],
            "inflection": [[0, 0], [1, 3], [3, -1], [4, 2]],
            "end_cusp": [[0, 0], [0, 0], [1, 2], [3, 0]],
        }
        for name, P in curves.items():
            for method in METHODS:
                for tol in (0.1, 1e-3):
                    poly = self.flat(bezier(P), tol, method)
                    self.assertEqual(poly[0], [float(x) for x in P[0]])
                    self.assertEqual(poly[-1], [float(x) for x in P[-1]])
                    with self.subTest(curve=name, method=method, tol=tol):
                        self.check(lambda t: de_casteljau(P, t), poly, tol)

    def test_quarter_circle_and_nurbs_circle(self):
        P, w = QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"]
        s = math.sqrt(2) / 2
        circle = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4],
                  "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]],
                  "weights": [1, s, 1, s, 1, s, 1, s, 1]}
        fewest = math.ceil(math.pi / math.acos(1 - 1e-3))  # chords of angle <= 2 acos(1 - h)
        for method in METHODS:
            poly = self.flat(QUARTER_CIRCLE, 1e-3, method)
            self.check(lambda t: rational_point(P, w, t), poly, 1e-3)
            full = self.flat(circle, 1e-3, method)
            for v in full:
                self.assertAlmostEqual(math.hypot(*v), 1, delta=1e-15)
            for a, b in zip(full, full[1:]):
                self.assertGreaterEqual(math.hypot((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), 1 - 1e-3)
            self.assertGreaterEqual(len(full) - 1, fewest)
            if method == "optimal":
                self.assertLessEqual(len(full) - 1, 1.06 * fewest)

    def test_path_of_mixed_segments(self):
        path = {"type": "path", "segments": [bezier([[0, 0], [1, 2], [2, 0]]), bezier([[2, 0], [2, 0], [3, 1], [4, -1]])]}
        for method in METHODS:
            poly = self.flat(path, 1e-3, method)
            self.check(lambda u: de_casteljau([[0, 0], [1, 2], [2, 0]], u * 2) if u <= 0.5
                       else de_casteljau([[2, 0], [2, 0], [3, 1], [4, -1]], 2 * u - 1), poly, 1e-3)

    def test_point_segments_add_no_vertex(self):
        # A path through a zero-length segment: the straight line 0 -> 2 on the x axis is
        # flattened to its three distinct vertices, none written twice in a row; a curve
        # that is a single point gives that point twice.
        path = {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), bezier([[1, 0]]), bezier([[1, 0], [2, 0]])]}
        point = {"type": "path", "segments": [bezier([[3, 4]]), bezier([[3, 4], [3, 4]])]}
        for method in METHODS:
            self.assertEqual(self.flat(path, 0.1, method), [[0, 0], [1, 0], [2, 0]])
            self.assertEqual(self.flat(point, 0.1, method), [[3, 4], [3, 4]])

    def test_counts_and_default(self):
        rng = random.Random(42)
        totals = dict.fromkeys(METHODS, 0)
        # The 40 curves' requests (each method, then the default) in one --jsonl process:
        # only the responses are checked here.
        requests = []
        for _ in range(40):
            P = [[rng.uniform(0, 100), rng.uniform(0, 100)] for _ in range(4)]
            requests += [{"curve": bezier(P), "tolerance": 0.1, "method": m} for m in METHODS]
            requests.append({"curve": bezier(P), "tolerance": 0.1})
        rc, answers, err = test_cli.run_jsonl("flatten", requests)
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual(len(answers), len(requests))
        k = len(METHODS) + 1
        for i in range(0, len(answers), k):
            got = dict(zip(METHODS, (a["points"] for a in answers[i:i + len(METHODS)])))
            for method in METHODS:
                totals[method] += len(got[method]) - 1
            self.assertEqual(answers[i + len(METHODS)]["points"], got["optimal"])
        self.assertLess(totals["optimal"], totals["subdivision"])
        self.assertLess(totals["subdivision"], totals["uniform"])

    def test_bad_method(self):
        c = bezier([[0, 0], [1, 1], [2, 0]])
        self.bad("flatten", {"curve": c, "tolerance": 0.1, "method": "fast"}, "method", contains="optimal")
        self.bad("flatten", {"curve": c, "tolerance": 0.1, "method": 3}, "method")
        self.bad("flatten", {"curve": c, "tolerance": 0, "method": "uniform"}, "tolerance")


class FlattenEstimateTest(CliTest):
    """The size estimate made before flattening (Wang's count summed over the pieces,
    docs/cli.md) is a finite figure for coordinates near the largest double: the second
    differences and the quotient overflow in plain double arithmetic (it said "about inf
    vertices" before)."""

    def figure(self, err):
        return float(err.split("about ", 1)[1].split(" vertices", 1)[0])

    def test_huge_coordinates(self):
        # Wang's count of a quadratic: sqrt(2 * 1 / 8 * |P0 - 2 P1 + P2| / tol), in mpmath.
        def wang(P, tol):
            d = [mpmath.mpf(P[0][k]) - 2 * mpmath.mpf(P[1][k]) + mpmath.mpf(P[2][k]) for k in range(2)]
            return mpmath.ceil(mpmath.sqrt(mpmath.mpf(1) / 4 * mpmath.norm(d) / mpmath.mpf(tol)))
        cases = [([[-1.7e308, 0], [1.7e308, 1.7e308], [-1.7e308, 0]], 1),
                 ([[-1.7e308, 0], [1.7e308, 1.7e308], [-1.7e308, 0]], 1e-300),
                 ([[0, 0], [1e300, 1e300], [2e300, 0]], 1e-300),
                 ([[0, 0], [1e300, 1e300], [2e300, 0]], 1e-290)]
        for P, tol in cases:
            err = self.bad("flatten", {"curve": bezier(P), "tolerance": tol, "method": "uniform"}, "tolerance",
                           contains="vertices, more than the limit of 1000000")
            # 1e-14 relative: the rounding of a few products and square roots.
            want = wang(P, tol)
            self.assertLessEqual(abs(self.figure(err) - float(want)), 1e-14 * float(want), (P, tol, err))
        # A tolerance that leaves a few steps answers, with the ends as given.
        P = [[0, 0], [1e300, 1e300], [2e300, 0]]
        r = self.ok("flatten", {"curve": bezier(P), "tolerance": 1e299, "method": "uniform"})
        self.assertEqual(r["points"][0], P[0])
        self.assertEqual(r["points"][-1], P[-1])
        self.assertEqual(len(r["points"]) - 1, int(wang(P, 1e299)))


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
