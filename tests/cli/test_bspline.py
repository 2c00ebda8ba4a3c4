#!/usr/bin/python3
"""Black-box tests of the `bspline` and `nurbs` curve types against an independent oracle at
test time: scipy.interpolate.BSpline (Debian's python3-scipy) for points and derivatives,
inside the domain, at every knot and extrapolated; NURBS as the quotient of two scipy
B-splines (homogeneous numerator and weight function). Also bounds, to_bezier and flatten
through the pieces, and the knot and weight errors of the contract.

Usage: test_bspline.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import unittest

import numpy as np
from scipy.interpolate import BSpline

import test_cli
from test_cli import CliTest, dist_to_polyline, run


def random_spline(rng, p, dim, clamped, repeats):
    """A random valid knot vector and control points: n in p+1..p+7 points."""
    n = rng.randint(p + 1, p + 7)
    m = n + p + 1
    if clamped:
        inner = sorted(rng.uniform(0, 1) for _ in range(m - 2 * (p + 1)))
        U = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
    else:
        U = sorted(rng.uniform(-1, 2) for _ in range(m))
    if repeats and m - 2 * (p + 1) > 0:
        # Repeat one interior knot up to p times (its continuity drops to C^(p-mult)).
        i = rng.randint(p + 1, n - 1)
        mult = rng.randint(2, p) if p >= 2 else 1
        for k in range(1, mult):
            if i + k < n:
                U[i + k] = U[i]
        U = sorted(U)
    # Keep every run within the contract (interior <= p, ends <= p + 1) and the domain
    # non-empty; redraw otherwise.
    runs = {}
    for x in U:
        runs[x] = runs.get(x, 0) + 1
    for x, c in runs.items():
        limit = p + 1 if x in (U[0], U[-1]) else p
        if c > limit:
            return random_spline(rng, p, dim, clamped, False)
    if not U[p] < U[n]:
        return random_spline(rng, p, dim, clamped, False)
    P = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]
    return U, P


def parameters(rng, U, p, n):
    lo, hi = U[p], U[n]
    ts = [lo, hi] + [x for x in U[p:n + 1]] + [rng.uniform(lo, hi) for _ in range(20)]
    ts += [lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo)]  # extrapolation of the end pieces
    return ts


def close(a, b, scale):
    return all(abs(x - y) <= 1e-11 * scale for x, y in zip(a, b))


class BSplineOracleTest(CliTest):
    def test_points_and_derivatives_match_scipy(self):
        rng = random.Random(20261130)
        cases = 0
        for p in range(1, 6):
            for dim in (1, 2, 3):
                for clamped in (True, False):
                    for repeats in (False, True):
                        U, P = random_spline(rng, p, dim, clamped, repeats)
                        n = len(P)
                        ts = parameters(rng, U, p, n)
                        k = p + 1
                        r = self.ok("eval", {"curve": {"type": "bspline", "degree": p, "knots": U, "points": P},
                                             "t": ts, "derivatives": k})
                        ref = BSpline(np.array(U), np.array(P), p, extrapolate=True)
                        # Derivatives grow like (p / shortest span)^order: scale the tolerance by it.
                        spans = [b - a for a, b in zip(U[p:n], U[p + 1:n + 1]) if b > a]
                        grow = p / min(spans)
                        for j, t in enumerate(ts):
                            want = ref(t).tolist()
                            self.assertTrue(close(r["points"][j], want, 1 + max(map(abs, want))),
                                            f"p={p} U={U} t={t}: {r['points'][j]} vs {want}")
                            for order in range(1, k + 1):
                                want = ref(t, order).tolist()
                                got = r["derivatives"][order - 1][j]
                                self.assertTrue(close(got, want, 10 * (1 + max(map(abs, want))) * (1 + grow) ** order),
                                                f"p={p} order={order} U={U} t={t}: {got} vs {want}")
                        cases += 1
        self.assertEqual(cases, 60)

    def test_nurbs_matches_the_quotient_of_scipy_splines(self):
        rng = random.Random(7)
        for p in (1, 2, 3, 4):
            for dim in (1, 2, 3):
                U, P = random_spline(rng, p, dim, rng.random() < 0.5, True)
                w = [rng.uniform(0.2, 5) for _ in P]
                n = len(P)
                # Inside the domain: extrapolated, the weight function may vanish (a pole).
                ts = [x for x in parameters(rng, U, p, n) if U[p] <= x <= U[n]]
                r = self.ok("eval", {"curve": {"type": "nurbs", "degree": p, "knots": U, "points": P, "weights": w},
                                     "t": ts, "derivatives": 1})
                A = BSpline(np.array(U), np.array([[wi * c for c in q] for wi, q in zip(w, P)]), p)
                W = BSpline(np.array(U), np.array(w), p)
                for j, t in enumerate(ts):
                    wt = float(W(t))
                    C = (A(t) / wt).tolist()
                    dC = ((A(t, 1) - float(W(t, 1)) * A(t) / wt) / wt).tolist()
                    self.assertTrue(close(r["points"][j], C, 10 * (1 + max(map(abs, C)))), f"p={p} t={t}")
                    self.assertTrue(close(r["derivatives"][0][j], dC, 1e4 * (1 + max(map(abs, dC)))), f"p={p} t={t}")


class BSplineQueriesTest(CliTest):
    U = [0, 0, 0, 0, 0.3, 0.3, 0.7, 1, 1, 1, 1]
    P = [[0, 0], [1, 3], [2, -1], [3, 2], [4, 4], [5, -2], [6, 1]]

    def reference(self):
        return BSpline(np.array(self.U, dtype=float), np.array(self.P, dtype=float), 3)

    def curve(self):
        return {"type": "bspline", "degree": 3, "knots": self.U, "points": self.P}

    def test_to_bezier_breaks_at_the_distinct_knots(self):
        c = self.ok("to_bezier", {"curve": self.curve()})["curve"]
        self.assertEqual(c["breaks"], [0, 0.3, 0.7, 1])
        ts = [i / 97 for i in range(98)]
        got = self.ok("eval", {"curve": c, "t": ts})["points"]
        ref = self.reference()
        for t, g in zip(ts, got):
            self.assertTrue(close(g, ref(t).tolist(), 10), f"t={t}")

    def test_bounds_are_tight(self):
        r = self.ok("bounds", {"curve": self.curve()})
        xs = np.linspace(0, 1, 200001)
        S = self.reference()(xs)
        for d in range(2):
            self.assertLessEqual(r["min"][d], S[:, d].min() + 1e-12)
            self.assertGreaterEqual(r["max"][d], S[:, d].max() - 1e-12)
            # Tight: the dense samples come within (step^2 |C''|) of the box.
            self.assertLess(S[:, d].min() - r["min"][d], 1e-7)
            self.assertLess(r["max"][d] - S[:, d].max(), 1e-7)

    def test_flatten_within_tolerance(self):
        tol = 1e-3
        poly = self.ok("flatten", {"curve": self.curve(), "tolerance": tol})["points"]
        ref = self.reference()
        self.assertEqual(poly[0], [0, 0])
        self.assertEqual(poly[-1], [6, 1])
        for t in np.linspace(0, 1, 1501):
            self.assertLessEqual(dist_to_polyline(ref(t).tolist(), poly), tol * (1 + 1e-9), f"t={t}")

    def test_render_and_path_segment(self):
        rc, out, err = run("render", {"curve": self.curve()})
        self.assertEqual(rc, 0, err)
        self.assertIn("<path", out)
        path = {"type": "path", "segments": [self.curve(), {"type": "polyline", "points": [[6, 1], [7, 0]]}], "breaks": [0, 2, 3]}
        r = self.ok("eval", {"curve": path, "t": [1, 2.5]})
        self.assertTrue(close(r["points"][0], self.reference()(0.5).tolist(), 10))
        self.assertEqual(r["points"][1], [6.5, 0.5])

    def test_nurbs_circle(self):
        h = math.sqrt(0.5)
        circle = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                  "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]],
                  "weights": [1, h, 1, h, 1, h, 1, h, 1]}
        ts = [i / 64 for i in range(65)]
        for q in self.ok("eval", {"curve": circle, "t": ts})["points"]:
            self.assertAlmostEqual(math.hypot(*q), 1, delta=4e-16)
        b = self.ok("bounds", {"curve": circle})
        self.assert_close(b["min"], [-1, -1], 1e-15)
        self.assert_close(b["max"], [1, 1], 1e-15)
        c = self.ok("to_bezier", {"curve": circle})["curve"]
        self.assertEqual([s["type"] for s in c["segments"]], ["rational_bezier"] * 4)


class BSplineErrorsTest(CliTest):
    P = [[0, 0], [1, 1], [2, 0]]

    def bad_curve(self, curve, where, contains=None):
        return self.bad("eval", {"curve": curve, "t": [0.5]}, where, contains=contains)

    def test_knot_rules(self):
        c = lambda **kw: dict({"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": self.P}, **kw)
        self.ok("eval", {"curve": c(), "t": [0.5]})
        self.bad_curve(c(knots=[0, 0, 0, 1, 1]), "curve.knots", "len(points) + degree + 1 = 6")
        self.bad_curve(c(knots=[0, 0, 0.5, 0.2, 1, 1]), "curve.knots[3]", "non-decreasing")
        self.bad_curve(c(knots=[0, 0, 0, 0, 1, 1]), "curve.knots[3]", "end knot")
        self.bad_curve(c(knots=[0, 0, 1, 1, 2, 2]), "curve.knots", "empty")
        self.bad_curve(c(knots=[0, 0, 0, 1, 1, "x"]), "curve.knots[5]")
        self.bad_curve(c(degree=0), "curve.degree", ">= 1")
        self.bad_curve(c(degree=3), "curve.points", "at least 4 control points")
        self.bad_curve(c(degree=1.5), "curve.degree")
        self.bad_curve({"type": "bspline", "knots": [0, 0, 0, 1, 1, 1], "points": self.P}, "curve.degree", "missing")
        self.bad_curve(c(weights=[1, 1, 1]), "curve.weights", "unknown field")
        self.bad_curve(c(degree=1001), "curve.degree", "highest supported degree")
        self.bad_curve(c(knots=[-1e308, -1e308, -1e308, 1e308, 1e308, 1e308]), "curve.knots", "largest double")
        big = [[0, 0], [1, 1], [2, 0], [3, 0]]
        self.bad_curve(c(points=big, knots=[0, 0, 0, 0.5, 0.5, 1, 1, 1]), "curve.knots", "len(points) + degree + 1 = 7")

    def test_weights(self):
        c = lambda **kw: dict({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": self.P,
                               "weights": [1, 2, 1]}, **kw)
        self.ok("eval", {"curve": c(), "t": [0.5]})
        self.bad_curve(c(weights=[1, 0, 1]), "curve.weights[1]", "> 0")
        self.bad_curve(c(weights=[1, -2, 1]), "curve.weights[1]", "> 0")
        self.bad_curve(c(weights=[1, 1]), "curve.weights", "one weight per control point")
        self.bad_curve({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": self.P}, "curve.weights", "missing")

    def test_split_needs_an_inner_parameter(self):
        # split and elevate of bspline and nurbs: tests/cli/test_knots.py. A B-spline half
        # keeps its parameter, so a split at a domain end (an empty half) is refused.
        c = {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": self.P}
        self.bad("split", {"curve": c, "t": 1}, "t", contains="strictly inside")
        self.bad("split", {"curve": c, "t": 0}, "t", contains="strictly inside")

if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
