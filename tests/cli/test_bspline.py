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
        cases = []
        for p in range(1, 6):
            for dim in (1, 2, 3):
                for clamped in (True, False):
                    for repeats in (False, True):
                        U, P = random_spline(rng, p, dim, clamped, repeats)
                        cases.append((p, U, P, parameters(rng, U, p, len(P))))
        # The 60 evaluations in one --jsonl process (only the responses are checked).
        answers = self.ok_jsonl("eval", [{"curve": {"type": "bspline", "degree": p, "knots": U, "points": P},
                                          "t": ts, "derivatives": p + 1} for p, U, P, ts in cases])
        for (p, U, P, ts), r in zip(cases, answers):
            n = len(P)
            k = p + 1
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
        self.assertEqual(len(cases), 60)

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
        self.bad_curve(c(degree=-1), "curve.degree", ">= 0")
        # degree 0 needs len(points) + 1 knots, each at most once (p + 1)
        self.bad_curve(c(degree=0), "curve.knots", "len(points) + degree + 1 = 4")
        self.bad_curve(c(degree=0, knots=[0, 1, 1, 2]), "curve.knots[2]", "at most once")
        # an interior knot p + 1 = 3 times is a break (allowed); 4 times is not
        big = [[0, 0], [1, 1], [2, 0], [3, 0], [4, 0], [5, 1]]
        self.ok("eval", {"curve": c(points=big, knots=[0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1]), "t": [0.5]})
        self.bad_curve(c(points=big, knots=[0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1]), "curve.knots[6]", "at most 3 times")
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

def random_jump_spline(rng, p, dim, clamped):
    """Knots on the domain [0, 1] with 1..4 distinct interior knots of multiplicities
    1..p + 1, the first one p + 1 (a break where the curve may jump); random points."""
    inner = sorted(rng.uniform(0.05, 0.95) for _ in range(rng.randint(1, 4)))
    U = []
    for j, x in enumerate(inner):
        U += [x] * (p + 1 if j == 0 else rng.randint(1, p + 1))
    U.sort()
    if clamped:
        U = [0.0] * (p + 1) + U + [1.0] * (p + 1)
    else:
        U = sorted(rng.uniform(-1, -0.01) for _ in range(p)) + [0.0] + U + [1.0] + sorted(rng.uniform(1.01, 2) for _ in range(p))
    n = len(U) - p - 1
    P = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]
    return U, P


SAW = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2, 3, 3],
       "points": [[0, 0], [1, 1], [1, 0], [2, 1], [2, 0], [3, 1]]}  # (t, t - floor(t)): jumps at 1, 2
STEPS = {"type": "bspline", "degree": 0, "knots": [0, 1, 2, 4], "points": [[0, 1], [2, 3], [5, 5]]}


class JumpOracleTest(CliTest):
    """Degree 0 and breaks of multiplicity p + 1 against scipy.interpolate.BSpline, which
    takes the same side: the right limit at an interior knot, the last non-empty span at
    the domain's end, the end pieces continued outside (extrapolate=True)."""

    def test_points_and_derivatives_match_scipy(self):
        rng = random.Random(20261202)
        cases = []
        for p in range(0, 6):
            for dim in (1, 2, 3):
                for clamped in (True, False):
                    U, P = random_jump_spline(rng, p, dim, clamped)
                    ts = parameters(rng, U, p, len(P)) + sorted(set(U))  # every knot, also outside the domain
                    cases.append((p, U, P, ts))
        # The 36 evaluations in one --jsonl process (only the responses are checked).
        answers = self.ok_jsonl("eval", [{"curve": {"type": "bspline", "degree": p, "knots": U, "points": P},
                                          "t": ts, "derivatives": p + 1} for p, U, P, ts in cases])
        for (p, U, P, ts), r in zip(cases, answers):
            n = len(P)
            k = p + 1
            ref = BSpline(np.array(U), np.array(P), p, extrapolate=True)
            spans = [b - a for a, b in zip(U[p:n], U[p + 1:n + 1]) if b > a]
            grow = max(p, 1) / min(spans)
            size = 1 + max(abs(c) for q in P for c in q)
            for j, t in enumerate(ts):
                # de Boor's convex combinations: a few eps of max |P| inside the domain;
                # outside (at most 1.1 the domain away, spans >= 0.01 apart) the end
                # piece's polynomial amplifies it by (1 + grow)^p at most.
                inside = U[p] <= t <= U[n]
                scale = size * (1 if inside else (1 + grow) ** p)
                want = ref(t).tolist()
                self.assertTrue(all(abs(x - y) <= 1e-12 * scale for x, y in zip(r["points"][j], want)),
                                f"p={p} U={U} t={t}: {r['points'][j]} vs {want}")
                for order in range(1, k + 1):
                    want = ref(t, order).tolist()
                    got = r["derivatives"][order - 1][j]
                    # each order divides by a knot difference: (p / shortest span)^order.
                    tol = 1e-12 * scale * (1 + grow) ** order
                    self.assertTrue(all(abs(x - y) <= tol for x, y in zip(got, want)),
                                    f"p={p} order={order} U={U} t={t}: {got} vs {want}")
        self.assertEqual(len(cases), 36)

    def test_nurbs_jumps_as_the_quotient_of_scipy_splines(self):
        rng = random.Random(8)
        for p in (0, 1, 2, 3):
            U, P = random_jump_spline(rng, p, 2, rng.random() < 0.5)
            w = [rng.uniform(0.2, 5) for _ in P]
            n = len(P)
            ts = [x for x in parameters(rng, U, p, n) if U[p] <= x <= U[n]]
            r = self.ok("eval", {"curve": {"type": "nurbs", "degree": p, "knots": U, "points": P, "weights": w},
                                 "t": ts, "derivatives": 1})
            A = BSpline(np.array(U), np.array([[wi * c for c in q] for wi, q in zip(w, P)]), p)
            W = BSpline(np.array(U), np.array(w), p)
            for j, t in enumerate(ts):
                wt = float(W(t))
                C = (A(t) / wt).tolist()
                dC = ((A(t, 1) - float(W(t, 1)) * A(t) / wt) / wt).tolist()
                # a quotient of weights in [0.2, 5]: 25x the B-spline's rounding, and more for
                # the derivative (as test_nurbs_matches_the_quotient_of_scipy_splines).
                self.assertTrue(close(r["points"][j], C, 10 * (1 + max(map(abs, C)))), f"p={p} t={t}")
                self.assertTrue(close(r["derivatives"][0][j], dC, 1e4 * (1 + max(map(abs, dC)))), f"p={p} t={t}")

    def test_knot_operations_keep_the_curve(self):
        # insert up to p + 1, refine, split at a jump, elevate and to_bezier -> to_bspline,
        # each compared with scipy's evaluation of the original at random parameters and at
        # every knot (right limits).
        rng = random.Random(31)
        for p in (0, 1, 2, 3):
            U, P = random_jump_spline(rng, p, 2, True)
            c = {"type": "bspline", "degree": p, "knots": U, "points": P}
            ref = BSpline(np.array(U), np.array(P), p)
            ts = sorted(set([rng.uniform(0, 1) for _ in range(40)] + U))
            want = ref(ts)

            def traces(curve, lo=0.0, hi=1.0, what=""):
                sel = [j for j, t in enumerate(ts) if lo <= t < hi or t == hi == 1.0]
                got = self.ok("eval", {"curve": curve, "t": [ts[j] for j in sel]})["points"]
                for g, j in zip(got, sel):
                    # convex combinations (insertion, blossoms, Forrest's elevation): rounding
                    # of a few eps times max |P| <= 5.
                    self.assertTrue(close(g, want[j].tolist(), 10), f"{what} p={p} t={ts[j]}: {g} vs {want[j]}")

            x = rng.uniform(0.05, 0.95)
            r = self.ok("insert_knot", {"curve": c, "knot": x, "times": p + 1})["curve"]
            self.assertEqual(r["knots"].count(x), p + 1)
            traces(r, what="insert_knot")
            traces(self.ok("refine", {"curve": c, "knots": [x] * (p + 1)})["curve"], what="refine")
            traces(self.ok("elevate", {"curve": c, "times": 2})["curve"], what="elevate")
            e = self.ok("elevate", {"curve": c, "times": 2})["curve"]
            jump = U[p + 1] if p > 0 else U[1]
            self.assertEqual(e["knots"].count(jump), U.count(jump) + 2)  # a jump stays a jump
            a, b = self.ok("split", {"curve": c, "t": jump})["curves"]
            traces(a, 0.0, jump, "split left")
            traces(b, jump, 1.0, "split right")
            pieces = self.ok("to_bezier", {"curve": c})["curve"]
            self.assertEqual(pieces["breaks"], sorted(set(U)))
            for seg in pieces["segments"]:
                self.assertEqual(len(seg["points"]), p + 1)  # degree 0: one point
            traces(pieces, what="to_bezier")
            back = self.ok("to_bspline", {"curve": pieces})["curve"]
            traces(back, what="to_bspline")
            if p > 0:
                self.assertEqual(back["knots"].count(jump), p + 1)  # the jump: not even C^0


class JumpQueriesTest(CliTest):
    """What each command answers on a curve that jumps (SAW) and on degree 0 (STEPS):
    the pieces as they are, a jump treated as a path's gap (docs/cli.md)."""

    def test_to_bezier(self):
        c = self.ok("to_bezier", {"curve": SAW})["curve"]
        self.assertEqual(c["breaks"], [0, 1, 2, 3])
        self.assertEqual([s["points"] for s in c["segments"]], [[[0, 0], [1, 1]], [[1, 0], [2, 1]], [[2, 0], [3, 1]]])
        c = self.ok("to_bezier", {"curve": STEPS})["curve"]
        self.assertEqual(c["breaks"], [0, 1, 2, 4])
        self.assertEqual([s["points"] for s in c["segments"]], [[[0, 1]], [[2, 3]], [[5, 5]]])

    def test_eval_right_limits(self):
        r = self.ok("eval", {"curve": SAW, "t": [0.5, 1, 2, 3], "derivatives": 2, "curvature": True})
        self.assertEqual(r["points"], [[0.5, 0.5], [1, 0], [2, 0], [3, 1]])
        self.assertEqual(r["derivatives"][0], [[1, 1]] * 4)
        self.assertEqual(r["derivatives"][1], [[0, 0]] * 4)
        self.assertEqual(r["curvature"], [0, 0, 0, 0])  # straight pieces
        r = self.ok("eval", {"curve": STEPS, "t": [-1, 0, 1, 1.5, 2, 4, 5], "derivatives": 1})
        self.assertEqual(r["points"], [[0, 1], [0, 1], [2, 3], [2, 3], [5, 5], [5, 5], [5, 5]])
        self.assertEqual(r["derivatives"][0], [[0, 0]] * 7)

    def test_flatten_refuses_a_jump_beyond_the_tolerance(self):
        self.bad("flatten", {"curve": SAW, "tolerance": 0.5}, "curve", contains="apart")
        self.bad("flatten", {"curve": STEPS, "tolerance": 0.5}, "curve", contains="apart")
        # a jump within the tolerance is bridged: the polyline keeps both limits
        small = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2], "points": [[0, 0], [1, 0], [1, 0.001], [2, 0]]}
        pts = self.ok("flatten", {"curve": small, "tolerance": 0.01})["points"]
        self.assertEqual(pts, [[0, 0], [1, 0], [1, 0.001], [2, 0]])

    def test_length_sums_the_pieces(self):
        # three teeth of length sqrt 2; the jumps add nothing
        self.assertAlmostEqual(self.ok("length", {"curve": SAW})["length"], 3 * math.sqrt(2), delta=1e-13)
        self.assertAlmostEqual(self.ok("length", {"curve": SAW, "from": 0.5, "to": 1.5})["length"], math.sqrt(2), delta=1e-13)
        t = self.ok("param_at_length", {"curve": SAW, "lengths": [1.5 * math.sqrt(2)]})["t"]
        self.assertAlmostEqual(t[0], 1.5, delta=1e-12)
        self.assertEqual(self.ok("length", {"curve": STEPS})["length"], 0)  # points do not move

    def test_bounds_project_distance(self):
        b = self.ok("bounds", {"curve": SAW})
        self.assertEqual((b["min"], b["max"]), ([0, 0], [3, 1]))
        b = self.ok("bounds", {"curve": STEPS})
        self.assertEqual((b["min"], b["max"]), ([0, 1], [5, 5]))
        # (1, 0.9) is nearest the first tooth's end region: foot (0.95, 0.95) at t = 0.95
        r = self.ok("project", {"curve": SAW, "point": [1, 0.9]})
        self.assertAlmostEqual(r["t"], 0.95, delta=1e-12)
        self.assertAlmostEqual(r["distance"], 0.05 * math.sqrt(2), delta=1e-12)
        # a step is nearest where its point is: the whole step [1, 2) at distance 0
        r = self.ok("project", {"curve": STEPS, "point": [2, 3]})
        self.assertEqual(r["distance"], 0)
        self.assertEqual(r["t"], 1)
        # nearest the second tooth's top (2, 1), its left limit at the jump t = 2: the pieces
        # as they are (evaluation at 2 gives the right limit (2, 0), 1.1 away), reported at
        # the double below 2, where evaluation gives that left limit to rounding
        below2 = math.nextafter(2, -math.inf)
        r = self.ok("project", {"curve": SAW, "point": [2, 1.1]})
        self.assertEqual(r["t"], below2)
        self.assertEqual(r["point"], self.ok("eval", {"curve": SAW, "t": [below2]})["points"][0])
        self.assertLess(max(abs(r["point"][0] - 2), abs(r["point"][1] - 1)), 1e-15)
        self.assertAlmostEqual(r["distance"], 0.1, delta=1e-15)
        d = self.ok("distance", {"curves": [SAW, {"type": "bezier", "points": [[1.5, 2], [2.5, 2]]}]})
        self.assertAlmostEqual(d["distance"], 1, delta=1e-15)  # from the same top (2, 1) to (2, 2)
        self.assertEqual(d["t"][0], below2)
        self.assertAlmostEqual(d["t"][1], 0.5, delta=1e-15)
        self.assertEqual(d["points"][0], r["point"])

    def test_area_refuses_a_jump(self):
        closed_with_jump = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2],
                            "points": [[0, 0], [1, 0], [1, 1], [0, 0]]}
        self.bad("area", {"curve": closed_with_jump}, "curve", contains="apart")
        self.bad("area", {"curve": STEPS}, "curve")

    def test_intersect_and_solve_take_the_pieces_as_they_are(self):
        line = {"type": "bezier", "points": [[0, 0.5], [3, 0.5]]}
        r = self.ok("intersect", {"curves": [SAW, line]})
        ts = [x["t"][0] for x in r["intersections"]]
        self.assertEqual(len(ts), 3)
        for got, want in zip(ts, [0.5, 1.5, 2.5]):
            self.assertAlmostEqual(got, want, delta=1e-12)
        r = self.ok("solve", {"curve": SAW, "value": 0.5, "axis": 1})
        for got, want in zip(r["t"], [0.5, 1.5, 2.5]):
            self.assertAlmostEqual(got, want, delta=1e-12)
        self.assertEqual(len(r["t"]), 3)
        # the step [1, 2) holds y = 3; at 2 the curve is (5, 5): the interval ends at the
        # double below 2 (the last step [2, 4] includes the domain's end)
        r = self.ok("solve", {"curve": STEPS, "value": 3, "axis": 1})
        self.assertEqual((r["t"], r["intervals"]), ([], [[1, math.nextafter(2, -math.inf)]]))
        r = self.ok("solve", {"curve": STEPS, "value": 5, "axis": 1})
        self.assertEqual((r["t"], r["intervals"]), ([], [[2, 4]]))

    def test_solve_does_not_answer_a_left_limit(self):
        # Audit D3. x(t) = 2t on [0, 1), then 3 - 2 (t - 1) on [1, 2] (the right limit 3 at
        # the jump t = 1). x = 2 is only the left limit at 1: the one parameter is 1.5; 3 is
        # the value at 1; 2.5 lies inside the jump and is taken at 1.25 by the second piece.
        c = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2], "points": [[0], [2], [3], [1]]}
        ref = BSpline(np.array([0, 0, 1, 1, 2, 2], float), np.array([0, 2, 3, 1], float), 1)
        for value, want in ((2, [1.5]), (3, [1]), (2.5, [1.25]), (1, [0.5, 2]), (0, [0])):
            got = self.ok("solve", {"curve": c, "value": value, "axis": 0})
            self.assertEqual(got, {"t": want, "intervals": []}, value)
            for t in want:  # scipy takes the right limit at the knot too
                self.assertEqual(float(ref(t)), value, (value, t))
        # The same jump in y only: x continuous (x = t), so x = 1 holds at the break itself.
        c2 = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2], "points": [[0, 0], [1, 2], [1, 3], [2, 1]]}
        self.assertEqual(self.ok("solve", {"curve": c2, "value": 1, "axis": 0}), {"t": [1], "intervals": []})
        self.assertEqual(self.ok("solve", {"curve": c2, "value": 2, "axis": 1}), {"t": [1.5], "intervals": []})
        # A step on the level keeps its left end and stops below the next knot; a level
        # crossed by the jump and held by the next step starts there.
        steps = {"type": "bspline", "degree": 0, "knots": [0, 1, 2, 3], "points": [[1], [2], [2]]}
        self.assertEqual(self.ok("solve", {"curve": steps, "value": 1, "axis": 0}),
                         {"t": [], "intervals": [[0, math.nextafter(1, -math.inf)]]})
        self.assertEqual(self.ok("solve", {"curve": steps, "value": 2, "axis": 0}), {"t": [], "intervals": [[1, 3]]})

    def test_points_at_a_jump_are_the_curve_at_their_parameters(self):
        # Audit D12. J jumps from (1, 0) to (1, 1) at t = 1 (eval at 1: (1, 1)). Its left
        # limit (1, 0) is reported at the double below 1, where eval gives it to rounding.
        J = {"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1, 2, 2], "points": [[0, 0], [1, 0], [1, 1], [2, 1]]}
        below1 = math.nextafter(1, -math.inf)

        def at(t):
            return self.ok("eval", {"curve": J, "t": [t]})["points"][0]

        def near(p, q, tol=1e-15):
            return max(abs(x - y) for x, y in zip(p, q)) <= tol

        r = self.ok("project", {"curve": J, "point": [1, -0.1]})
        self.assertEqual(r["t"], below1)
        self.assertEqual(r["point"], at(r["t"]))
        self.assertTrue(near(r["point"], [1, 0]))
        self.assertAlmostEqual(r["distance"], 0.1, delta=1e-15)
        # the right limit is attained at 1 itself
        r = self.ok("project", {"curve": J, "point": [1, 1.1]})
        self.assertEqual((r["t"], r["point"]), (1, [1, 1]))
        d = self.ok("distance", {"curves": [J, {"type": "bezier", "points": [[1, -1], [1, -0.5]]}]})
        self.assertEqual(d["t"], [below1, 1])
        self.assertEqual(d["points"][0], at(below1))
        self.assertAlmostEqual(d["distance"], 0.5, delta=1e-15)
        r = self.ok("intersect", {"curves": [J, {"type": "bezier", "points": [[1, -1], [1, 2]]}]})
        got = [(x["t"][0], x["point"]) for x in r["intersections"]]
        self.assertEqual([t for t, _ in got], [below1, 1])
        for t, q in got:
            self.assertTrue(near(q, at(t)), (t, q))
        self.assertTrue(near(got[0][1], [1, 0]) and near(got[1][1], [1, 1]))
        # A property over a sawtooth: every answer's point is the curve at its parameter.
        rng = random.Random(12)
        queries = [[rng.uniform(-0.5, 3.5), rng.uniform(-0.5, 1.5)] for _ in range(40)]
        # points just above each tooth's top: the left limits (k, 1), k = 1, 2, 3
        queries += [[k + 0.05, 1.2] for k in (1, 2)] + [[3.1, 1.1]]
        answers = self.ok_jsonl("project", [{"curve": SAW, "point": q} for q in queries])
        evals = self.ok("eval", {"curve": SAW, "t": [r["t"] for r in answers]})["points"]
        for q, r, e in zip(queries, answers, evals):
            self.assertTrue(near(r["point"], e, 4e-16 * 4), (q, r, e))
            # the distance: brute force over the closed teeth (t, t - k) on [k, k + 1]
            want = min(math.dist(q, (k + u, u)) for k in range(3) for u in np.linspace(0, 1, 20001))
            self.assertLessEqual(r["distance"], want + 1e-12, (q, r))
            self.assertGreater(r["distance"], want - 1e-4, (q, r))

    def test_intersect_once_per_step(self):
        # Audit D17. Steps (0, 0) on [0, 1), (0.5, 0) on [1, 2), (1, 1) on [2, 3]; the line
        # y = 2x - 1 passes (0.5, 0) and (1, 1): each step that rests on it is one contact,
        # at the step's first parameter.
        steps = {"type": "bspline", "degree": 0, "knots": [0, 1, 2, 3], "points": [[0, 0], [0.5, 0], [1, 1]]}
        line = {"type": "bezier", "points": [[0, -1], [1, 1]]}
        want = [([1, 0.5], [0.5, 0]), ([2, 1], [1, 1])]
        r = self.ok("intersect", {"curves": [steps, line]})
        self.assertEqual([(x["t"], x["point"]) for x in r["intersections"]], want)
        self.assertEqual(r["overlaps"], [])
        r = self.ok("intersect", {"curves": [line, steps]})
        self.assertEqual([(x["t"], x["point"]) for x in r["intersections"]], [([0.5, 1], [0.5, 0]), ([1, 2], [1, 1])])
        # two steps at the same point in a row are one stretch: one contact at its start
        steps2 = {"type": "bspline", "degree": 0, "knots": [0, 1, 2, 3, 4], "points": [[0, 0], [0.5, 0], [0.5, 0], [1, 1]]}
        r = self.ok("intersect", {"curves": [steps2, line]})
        self.assertEqual([(x["t"], x["point"]) for x in r["intersections"]], [([1, 0.5], [0.5, 0]), ([3, 1], [1, 1])])
        # a point segment of a path on the line: once, at its start
        path = {"type": "path", "segments": [{"type": "bezier", "points": [[0, 1], [0.5, 1]]},
                                             {"type": "bezier", "points": [[0.75, 0.5], [0.75, 0.5]]},
                                             {"type": "bezier", "points": [[1, 1], [2, 1]]}]}
        r = self.ok("intersect", {"curves": [path, line]})
        self.assertEqual([(x["t"], x["point"]) for x in r["intersections"]], [([1, 0.75], [0.75, 0.5]), ([2, 1], [1, 1])])

    def test_operations_on_jumps(self):
        # remove_knot of a jump knot: refused within the tolerance (the curve is not
        # continuous there), accepted when the jump is within twice the tolerance
        r = self.ok("remove_knot", {"curve": SAW, "knot": 1})
        self.assertEqual(r["removed"], 0)
        self.assertEqual(r["curve"]["knots"], SAW["knots"])
        r = self.ok("remove_knot", {"curve": SAW, "knot": 1, "tolerance": 0.5})
        self.assertEqual(r["removed"], 1)
        self.assertEqual(r["curve"]["points"][1], [1, 0.5])  # the midpoint of the two limits
        # insertion past p + 1 is refused
        self.bad("insert_knot", {"curve": SAW, "knot": 1}, "times", contains="p + 1")
        self.bad("refine", {"curve": STEPS, "knots": [1]}, "knots[0]", contains="p + 1")
        # to_bspline of a path with a gap: the break p + 1 times, the gap kept
        path = {"type": "path", "segments": [{"type": "bezier", "points": [[0, 0], [1, 1]]},
                                             {"type": "bezier", "points": [[1, 2], [2, 2], [3, 0]]}]}
        b = self.ok("to_bspline", {"curve": path})["curve"]
        self.assertEqual(b["knots"], [0, 0, 0, 1, 1, 1, 2, 2, 2])
        self.assertEqual(self.ok("eval", {"curve": b, "t": [1]})["points"], [[1, 2]])
        # reduce keeps the jump; degree 1 to 0 is one constant (the mean), within tolerance
        cubic = self.ok("elevate", {"curve": SAW, "times": 2})["curve"]
        r = self.ok("reduce", {"curve": cubic, "times": 2, "tolerance": 1e-9})
        self.assertEqual(r["curve"]["knots"], SAW["knots"])
        self.bad("reduce", {"curve": SAW, "tolerance": 0.1}, "tolerance")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
