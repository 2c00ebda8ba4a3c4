#!/usr/bin/python3
"""Black-box tests of closed (periodic) `fit`: least squares with fewer control points than
distinct points, interpolation at the point count, the tolerance mode.

The oracle is built here at test time, independently of the program: the periodic
design matrix from scipy.interpolate.BSpline.design_matrix on the periodic knots
extended by p on either side, its columns folded modulo n (control point j is
C_(j mod n)), solved with numpy.linalg.lstsq. The knot rule is the one docs/cli.md
states (the periodic form of [PT97] eq. 9.68-9.69), written again here from that text.
The program's curve is evaluated by scipy.interpolate.BSpline on its own knots.

Usage: test_fit_closed.py PATH_TO_CASTELJAU [unittest options]
"""
import json
import os
import random
import sys
import unittest

import numpy as np
from scipy.interpolate import BSpline

import test_cli
from test_cli import CliTest
from test_knots import fit_params

# Both sides solve the same well-conditioned least-squares problem (QR against LAPACK's
# SVD-based lstsq) and evaluate de Boor against scipy: rounding of the coordinates
# (|Q| <= 3) times the system's condition number, far below this.
TOL = 1e-9


def closed_knots(t, p, n):
    """Breakpoints b_0 < ... < b_(n-1): t at the fractional index (j + delta) L / n."""
    L = len(t) - 1
    delta = 0.0 if p % 2 == 1 else 0.5
    b = []
    for j in range(n):
        x = (j + delta) * L / n
        i = min(int(x), L - 1)
        a = x - i
        b.append((1 - a) * t[i] + a * t[i + 1])
    return b


class Periodic:
    """The periodic spline of degree p with breakpoints b (period 1) and control points C."""

    def __init__(self, b, p, C=None):
        self.b, self.p, self.n = np.array(b), p, len(b)
        # knot(j) = b[j mod n] + floor(j / n) for j = -p .. n + p.
        self.T = np.array([self.b[j % self.n] + j // self.n for j in range(-p, self.n + p + 1)])
        self.C = C

    def design(self, u):
        u = np.atleast_1d(np.asarray(u, dtype=float))
        u = np.where(u < self.b[0], u + 1, u)  # into [b_0, b_0 + 1), one period
        u = np.where(u >= self.b[0] + 1, u - 1, u)
        A = BSpline.design_matrix(u, self.T, self.p).toarray()  # n + p columns
        F = np.zeros((len(u), self.n))
        for i in range(A.shape[1]):
            F[:, (i - self.p) % self.n] += A[:, i]
        return F

    def __call__(self, u):
        return self.design(u) @ self.C


def lstsq_fit(Q, p, n, kind="chord"):
    """(oracle spline, closed parameters) of the periodic least-squares problem."""
    t = fit_params(Q, kind, closed=True)
    S = Periodic(closed_knots(t, p, n), p)
    S.C = np.linalg.lstsq(S.design(t[:-1]), np.array(Q, dtype=float), rcond=None)[0]
    return S, t


def curve_of(c):
    return BSpline(np.array(c["knots"], dtype=float), np.array(c["points"], dtype=float), c["degree"], extrapolate=True)


def blob(count, dim=2, seed=0, noise=0.0):
    """Points around a closed, non-convex curve, unevenly spaced, optionally noisy."""
    rng = random.Random(seed)
    a = np.sort(np.array([rng.uniform(0, 2 * np.pi) for _ in range(count)]))
    r = 1 + 0.3 * np.sin(3 * a) + np.array([rng.gauss(0, noise) for _ in a])
    pts = np.stack([r * np.cos(a), r * np.sin(a), 0.5 * np.cos(2 * a), 0.2 * np.sin(a)], axis=1)[:, :dim]
    return pts.tolist()


def periodic_count(c):
    """n from the written curve: n + p points for odd p, n + p + 1 for even p."""
    p = c["degree"]
    return len(c["points"]) - p - (1 if p % 2 == 0 else 0)


def open_shape(count, seed=0, noise=0.0):
    """Points along an open curve with a sharp bump, unevenly spaced, optionally noisy."""
    rng = random.Random(seed)
    xs = sorted(rng.uniform(0, 6) for _ in range(count))
    return [[x + rng.gauss(0, noise), np.sin(x) + 0.5 * np.exp(-8 * (x - 3) ** 2) + rng.gauss(0, noise)] for x in xs]


def has_averaging_knots(c, t, closed):
    """Whether the program's curve has the knots docs/cli.md gives a count (eq. 9.68-9.69,
    open or periodic) rather than knots of its own placement."""
    p = c["degree"]
    if closed:
        n = periodic_count(c)
        inner = sorted({u for u in c["knots"] if 0 < u < 1})
        want = sorted(b for b in closed_knots(t, p, n) if b > 0)
    else:
        n = len(c["points"]) - 1
        inner, m = c["knots"][p + 1:n + 1], len(t) - 1
        d = (m + 1) / (n - p + 1)
        want = [(1 - (j * d - int(j * d))) * t[int(j * d) - 1] + (j * d - int(j * d)) * t[min(int(j * d), m)]
                for j in range(1, n - p + 1)]
    return len(inner) == len(want) and np.allclose(inner, want, rtol=0, atol=1e-12)


class ClosedFitTest(CliTest):
    def fit(self, **req):
        return self.ok("fit", dict(req, closed=True))

    def check_max_error(self, r, Q, closed, tol, kind="chord"):
        """max_error recomputed here: scipy's BSpline evaluating the program's curve at the
        data parameters; within the tolerance."""
        t = np.array(fit_params(Q, kind, closed=closed))
        got = curve_of(r["curve"])(t[:-1] if closed else t)
        err = np.max(np.linalg.norm(got - np.array(Q), axis=1))
        self.assertAlmostEqual(r["max_error"], err, delta=1e-12)
        self.assertLessEqual(err, tol)

    def check_against_oracle(self, r, Q, p, n, kind="chord"):
        c = r["curve"]
        self.assertEqual((c["knots"][p], c["knots"][len(c["points"])]), (0, 1), "domain [0, 1]")
        self.assertEqual(periodic_count(c), n)
        S, t = lstsq_fit(Q, p, n, kind)
        xs = np.linspace(0, 1, 201)
        got = curve_of(c)
        self.assertLess(np.max(np.abs(got(xs) - S(xs))), TOL, f"p={p} n={n} {kind}")
        err = np.max(np.linalg.norm(S(t[:-1]) - np.array(Q), axis=1))
        self.assertAlmostEqual(r["max_error"], err, delta=1e-10)
        return got

    def test_least_squares_matches_numpy(self):
        for p in (1, 2, 3, 4, 5):
            for kind in ("uniform", "chord", "centripetal"):
                Q = blob(30, dim=2 + p % 2, seed=p, noise=0.02)
                for n in sorted({p + 1, p + 2, 9, 17, 29}):
                    r = self.fit(points=Q, degree=p, control_points=n, parametrization=kind)
                    self.check_against_oracle(r, Q, p, n, kind)

    def test_dimensions_1_and_4(self):
        for dim in (1, 4):
            Q = blob(25, dim=dim, seed=11, noise=0.01)
            self.check_against_oracle(self.fit(points=Q, degree=3, control_points=8, parametrization="uniform"),
                                      Q, 3, 8, "uniform")

    def test_seam_is_c_p_minus_1(self):
        for p in (1, 2, 3, 4, 5):
            Q = blob(40, seed=20 + p, noise=0.05)
            for n in (p + 1, 12, 39):
                c = self.fit(points=Q, degree=p, control_points=n)["curve"]
                s = curve_of(c)
                for k in range(p):
                    a, b = s(0.0, k), s(1.0, k)
                    scale = max(1.0, np.max(np.abs(a)))
                    self.assertLess(np.max(np.abs(a - b)), 1e-9 * scale, f"p={p} n={n} derivative {k}")

    def test_point_count_is_interpolation(self):
        # control_points = L: the least-squares problem has the interpolant as its exact
        # solution (residual 0), and the program's curve passes through every point.
        for p in (1, 2, 3, 4, 5):
            Q = blob(15, seed=30 + p)
            r = self.fit(points=Q, degree=p, control_points=15)
            self.assertLessEqual(r["max_error"], 1e-12)
            got = self.check_against_oracle(r, Q, p, 15)
            t = fit_params(Q, closed=True)
            self.assertTrue(np.allclose(got(t[:-1]), Q, atol=1e-12))
            # The same curve as closed interpolation without a count (tolerance below rounding).
            r2 = self.fit(points=Q, degree=p, tolerance=1e-14)
            self.assertEqual(periodic_count(r2["curve"]), 15)
            xs = np.linspace(0, 1, 50)
            self.assertTrue(np.allclose(curve_of(r2["curve"])(xs), got(xs), atol=1e-12))

    def test_repeated_closing_point(self):
        Q = blob(20, seed=40, noise=0.01)
        a = self.fit(points=Q, degree=3, control_points=7)
        b = self.fit(points=Q + [Q[0]], degree=3, control_points=7)
        self.assertEqual(a, b)

    def test_tolerance_finds_few_points(self):
        Q = blob(80, seed=50)  # a smooth closed curve: few control points suffice
        for p in (2, 3):
            for tol in (1e-2, 1e-3, 1e-4):
                r = self.fit(points=Q, degree=p, tolerance=tol)
                n = periodic_count(r["curve"])
                self.check_max_error(r, Q, True, tol)
                self.assertLess(n, len(Q), f"p={p} tol={tol}: interpolation is the fallback, not the answer")
                if has_averaging_knots(r["curve"], fit_params(Q, closed=True), True):
                    self.check_against_oracle(r, Q, p, n)  # else its own knot placement
                # The count is at most the fewest with the knots of eq. 9.68-9.69 (the search
                # tries every count below, 80 points): one fewer with those knots fails.
                if n > p + 1:
                    fewer = self.fit(points=Q, degree=p, control_points=n - 1)
                    self.assertGreater(fewer["max_error"], tol, f"p={p} tol={tol}")
        # Below what any fewer points reach: interpolation.
        r = self.fit(points=Q[:8], degree=3, tolerance=1e-13)
        self.assertEqual(periodic_count(r["curve"]), 8)

    def test_tolerance_count_against_a_scan(self):
        # Issue 15: on 200 noisy samples of a closed shape at 0.03 the bisection returned 69
        # control points where 54 met the tolerance (max_error is not monotone in the
        # count). The fewest count that passes with the knots of eq. 9.68-9.69 is found
        # here by an exhaustive scan through control_points (one --jsonl process); the
        # search's answer may not exceed it (before the knot placement it was exactly it)
        # and must meet the tolerance (max_error recomputed by scipy). On the 0.03 cases
        # the knot placement meets it with strictly fewer (measured: closed 24 -> 16, open
        # 58 -> 37, docs/cli.md); at 0.015, near the noise (Gaussian, sigma 0.01: the
        # largest of 200 samples is about 0.028), it need not.
        cases = [(blob(200, seed=15, noise=0.01), True), (open_shape(200, seed=15, noise=0.01), False),
                 (blob(200, seed=17, noise=0.01), True), (open_shape(200, seed=17, noise=0.01), False)]
        for i, (Q, closed) in enumerate(cases):
            counts = range(4, len(Q) + 1)
            rc, answers, err = test_cli.run_jsonl(
                "fit", [{"points": Q, "degree": 3, "control_points": m, "closed": closed} for m in counts])
            self.assertIn(rc, (0, 2), err)  # 2: some line refused; never an internal error
            self.assertEqual(len(answers), len(counts))
            for tol in (0.03, 0.015):
                r = self.ok("fit", {"points": Q, "degree": 3, "tolerance": tol, "closed": closed})
                n = periodic_count(r["curve"]) if closed else len(r["curve"]["points"])
                self.check_max_error(r, Q, closed, tol)
                # A near-singular count is refused: it does not pass either.
                first = next(m for m, a in zip(counts, answers) if "error" not in a and a["max_error"] <= tol)
                self.assertLessEqual(n, first, f"case {i} closed={closed} tol={tol}")
                if tol == 0.03:
                    self.assertLess(n, first, f"case {i} closed={closed}: the knot placement lowers the count")
                if has_averaging_knots(r["curve"], fit_params(Q, closed=closed), closed):
                    self.assertEqual(n, first, f"case {i}: with those knots the count is the scan's")

    def test_noisy_circle_converges_to_circle(self):
        # Least squares averages the noise: a circle of radius 2 sampled at 400 points with
        # noise 0.01 is recovered to within a few noise sigmas with 12 control points.
        rng = random.Random(60)
        a = np.linspace(0, 2 * np.pi, 400, endpoint=False)
        Q = [[2 * np.cos(x) + rng.gauss(0, 0.01), 2 * np.sin(x) + rng.gauss(0, 0.01)] for x in a]
        c = self.fit(points=Q, degree=3, control_points=12)["curve"]
        r = np.linalg.norm(curve_of(c)(np.linspace(0, 1, 1000)), axis=1)
        self.assertLess(np.max(np.abs(r - 2)), 0.02)

    def test_large_input_is_fast(self):
        # O(L p^2): 20000 points and 2000 control points in well under the test timeout.
        Q = blob(20000, seed=70, noise=0.001)
        r = self.fit(points=Q, degree=3, control_points=2000)
        self.assertEqual(periodic_count(r["curve"]), 2000)
        self.assertLess(r["max_error"], 0.01)

    def test_bad_input(self):
        Q = blob(6, seed=80)
        self.bad("fit", {"points": Q, "degree": 3, "control_points": 3, "closed": True}, "control_points",
                 contains="4..6")
        self.bad("fit", {"points": Q, "degree": 3, "control_points": 7, "closed": True}, "control_points")
        self.bad("fit", {"points": Q + [Q[0]], "degree": 3, "control_points": 7, "closed": True}, "control_points")
        self.bad("fit", {"points": Q, "degree": 3, "tolerance": 0, "closed": True}, "tolerance")
        self.bad("fit", {"points": Q[:3], "degree": 3, "control_points": 3, "closed": True}, "points")
        self.bad("fit", {"points": Q, "degree": 3, "control_points": 5, "closed": True, "start_derivative": [1, 0]},
                 "start_derivative")
        # Equal consecutive points under chord: the shared parametrization's message
        # (curves/parametrization.hpp), naming the later point; for a closed fit the
        # closing step Q_last -> Q_0 too (one repeated closing point is dropped, a second
        # stays and equals Q_0).
        self.bad("fit", {"points": Q[:3] + [Q[2]] + Q[3:], "degree": 3, "control_points": 5}, "points[3]",
                 contains="equals points[2]")
        self.bad("fit", {"points": Q + [Q[0], Q[0]], "degree": 3, "control_points": 5, "closed": True},
                 "points[0]", contains="equals points[6]")
        # Coordinates near the largest double: the rotations overflow; reported, never output
        # as inf or NaN.
        B = np.array(blob(40, seed=81))
        huge = (B * (1.7e308 / np.max(np.abs(B)))).tolist()
        self.bad("fit", {"points": huge, "degree": 3, "control_points": 10, "closed": True, "parametrization": "uniform"},
                 "points", contains="not finite")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
