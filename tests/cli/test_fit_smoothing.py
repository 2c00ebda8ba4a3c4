#!/usr/bin/python3
"""Black-box tests of `fit` with `smoothing`: the cubic smoothing spline of
scipy.interpolate.make_smoothing_spline, lambda given or chosen by generalised
cross-validation.

Oracles, at test time and independent of the program:
- scipy.interpolate.make_smoothing_spline(t, y, lam) on each coordinate, t the contract's
  parameters (computed here by test_knots.fit_params);
- Reinsch's dense system [GreenSilverman94, §2.3] written here in mpmath at 40 digits
  (where scipy's own rounding is the larger error: clustered parameters), and in numpy
  for the GCV criterion of several coordinates (the hat matrix formed densely);
- scipy.interpolate.CubicSpline(bc_type="natural") for lambda = 0, numpy.polyfit for the
  straight-line limit of a large lambda.
The program's curve is evaluated by scipy.interpolate.BSpline on its own knots.

Usage: test_fit_smoothing.py PATH_TO_CASTELJAU [unittest options]
"""
import os
import random
import sys
import unittest

import mpmath as mp
import numpy as np
from scipy.interpolate import BSpline, CubicSpline, make_smoothing_spline
from scipy.optimize import minimize_scalar
from scipy.spatial import cKDTree

import test_cli
from test_cli import CliTest
from test_knots import fit_params


def curve_of(c):
    return BSpline(np.array(c["knots"], dtype=float), np.array(c["points"], dtype=float), c["degree"])


def scipy_example(n=200, seed=1234):
    """make_smoothing_spline's docstring data: x in [-2, 2], y = x^3 + x^2 sin 4x + noise."""
    rng = np.random.RandomState(seed)
    x = np.sort(rng.random_sample(n) * 4 - 2)
    y = x ** 3 + x ** 2 * np.sin(4 * x) + rng.normal(scale=1.5, size=n)
    return x, y


def scipy_gcv_lambda(x, y):
    """The lambda scipy's make_smoothing_spline chooses (its private GCV search, wrapped
    to read the value), or None where this scipy has no such function."""
    import scipy.interpolate._bsplines as impl
    search = getattr(impl, "_compute_optimal_gcv_parameter", None)
    if search is None:
        return None
    seen = []

    def spy(*args):
        seen.append(search(*args))
        return seen[-1]

    impl._compute_optimal_gcv_parameter = spy
    try:
        make_smoothing_spline(x, y)
    finally:
        impl._compute_optimal_gcv_parameter = search
    return seen[-1] if seen else None


def noisy_blob(count, seed, noise):
    """Samples of r = 1 + 0.3 sin 3a at equal angles (one turn, open: a in [0, 2 pi)),
    with Gaussian noise on each coordinate; also the true shape's function."""
    rng = np.random.RandomState(seed)
    a = np.linspace(0, 2 * np.pi, count, endpoint=False)

    def shape(a):
        r = 1 + 0.3 * np.sin(3 * a)
        return np.stack([r * np.cos(a), r * np.sin(a)], axis=1)

    return (shape(a) + rng.normal(scale=noise, size=(count, 2))).tolist(), shape


def reinsch_dense(t, Y, lam):
    """Fitted values of the smoothing spline and the trace of its hat matrix, from
    Reinsch's system in numpy (dense): (R + lam Q^T Q) gamma = Q^T Y, G = Y - lam Q gamma."""
    t = np.asarray(t, dtype=float)
    Y = np.asarray(Y, dtype=float).reshape(len(t), -1)
    n, h = len(t), np.diff(t)
    Q, R = np.zeros((n, n - 2)), np.zeros((n - 2, n - 2))
    for j in range(1, n - 1):
        Q[j - 1, j - 1], Q[j, j - 1], Q[j + 1, j - 1] = 1 / h[j - 1], -1 / h[j - 1] - 1 / h[j], 1 / h[j]
        R[j - 1, j - 1] = (h[j - 1] + h[j]) / 3
        if j < n - 2:
            R[j - 1, j] = R[j, j - 1] = h[j] / 6
    M = R + lam * Q.T @ Q
    G = Y - lam * Q @ np.linalg.solve(M, Q.T @ Y)
    hat = np.eye(n) - lam * Q @ np.linalg.solve(M, Q.T)
    return G, np.trace(hat)


def stacked_gcv(t, Y, lam):
    """GCV of the stacked residuals, as docs/cli.md defines it:
    (|Y - G|^2 / (n d)) / (1 - tr(A) / n)^2."""
    Y = np.asarray(Y, dtype=float)
    n, d = Y.shape
    G, tr = reinsch_dense(t, Y, lam)
    return (np.sum((Y - G) ** 2) / (n * d)) / (1 - tr / n) ** 2


def reinsch_mp(t, y, lam, dps=40):
    """Fitted values of the smoothing spline of one coordinate, Reinsch's system at dps
    digits: (R + lam Q^T Q) gamma = Q^T y, G = y - lam Q gamma. Q (n x (n-2)) has three
    entries a column and R is tridiagonal, so the matrix is symmetric pentadiagonal and
    positive definite: it is formed by its diagonals and solved by banded Gaussian
    elimination without pivoting (stable for SPD), in plain lists of mpf. 40 digits: the
    system's condition number (2e3 to 2.5e9 for the lambdas of the test, measured at 60
    digits) leaves over 30 digits, far beyond the double results compared against it."""
    with mp.workdps(dps):
        T = [mp.mpf(v) for v in t]
        Y = [mp.mpf(v) for v in y]
        n = len(T)
        h = [T[i + 1] - T[i] for i in range(n - 1)]
        m = n - 2
        # Column j of Q (interior node j + 1): rows j, j + 1, j + 2.
        q = [(1 / h[j], -1 / h[j] - 1 / h[j + 1], 1 / h[j + 1]) for j in range(m)]
        L = mp.mpf(lam)
        # A[i][k] is the entry (i, i + k - 2) of R + L Q^T Q.
        A = [[mp.mpf(0)] * 5 for _ in range(m)]
        for j in range(m):
            A[j][2] = (h[j] + h[j + 1]) / 3 + L * mp.fsum(c * c for c in q[j])
            if j + 1 < m:
                A[j][3] = A[j + 1][1] = h[j + 1] / 6 + L * (q[j][1] * q[j + 1][0] + q[j][2] * q[j + 1][1])
            if j + 2 < m:
                A[j][4] = A[j + 2][0] = L * q[j][2] * q[j + 2][0]
        b = [q[j][0] * Y[j] + q[j][1] * Y[j + 1] + q[j][2] * Y[j + 2] for j in range(m)]
        for i in range(m):  # elimination below the diagonal
            for r in (1, 2):
                if i + r < m:
                    f = A[i + r][2 - r] / A[i][2]
                    for k in range(2 - r, 5 - r):
                        A[i + r][k] -= f * A[i][k + r]
                    b[i + r] -= f * b[i]
        gamma = [mp.mpf(0)] * m
        for i in range(m - 1, -1, -1):  # back substitution
            s = b[i]
            for k in (3, 4):
                if i + k - 2 < m:
                    s -= A[i][k] * gamma[i + k - 2]
            gamma[i] = s / A[i][2]
        G = list(Y)
        for j in range(m):
            for r in range(3):
                G[j + r] -= L * q[j][r] * gamma[j]
        return np.array([float(v) for v in G])


class SmoothingFitTest(CliTest):
    def fit(self, points, smoothing, **extra):
        return self.ok("fit", dict({"points": points, "degree": 3, "smoothing": smoothing}, **extra))

    def check_knots(self, c, t):
        self.assertEqual(c["type"], "bspline")
        self.assertEqual(c["degree"], 3)
        want = [t[0]] * 3 + list(t) + [t[-1]] * 3
        self.assertEqual(len(c["knots"]), len(want))
        # The knots are the parameters: the program's chord lengths against numpy's, to rounding.
        self.assertLess(max(abs(a - b) for a, b in zip(c["knots"], want)), 1e-15)
        self.assertEqual(len(c["points"]), len(t) + 2)

    def test_given_lambda_matches_scipy(self):
        # Points along a curve with noise, every parametrization, lambda over ten decades.
        # Each coordinate against make_smoothing_spline(t, y_c, lam), on a dense grid.
        rng = np.random.RandomState(7)
        s = np.sort(rng.uniform(0, 3, 60))
        pts = np.stack([s, np.sin(2 * s), 0.3 * np.cos(s)], axis=1) + rng.normal(scale=0.05, size=(60, 3))
        grid = np.linspace(0, 1, 501)
        worst = 0.0
        for kind in ("uniform", "chord", "centripetal"):
            for dim in (1, 2, 3):
                P = pts[:, :dim]
                t = fit_params(P.tolist(), kind)
                for lam in (0.0, 1e-9, 1e-6, 1e-4, 1e-2, 1.0):
                    r = self.fit(P.tolist(), lam, parametrization=kind)
                    self.assertEqual(r["smoothing"], lam)
                    self.assertEqual(list(r), ["curve", "max_error", "smoothing"])  # docs/cli.md: exactly these
                    c = r["curve"]
                    self.check_knots(c, t)
                    got = curve_of(c)(grid)
                    want = np.stack([make_smoothing_spline(t, P[:, k], lam=lam)(grid) for k in range(dim)], axis=1)
                    err = np.max(np.abs(got - want)) / max(1.0, np.max(np.abs(want)))
                    worst = max(worst, err)
                    # Both solve one banded SPD system per lambda (condition number at
                    # most about 1e4 for these well-spread parameters): 1e-9 leaves room.
                    self.assertLess(err, 1e-9, f"{kind} d={dim} lambda={lam}")
                    fitted = curve_of(c)(t)
                    self.assertAlmostEqual(r["max_error"], np.max(np.linalg.norm(fitted - P, axis=1)), delta=1e-12)
        print(f"\n  given lambda vs scipy: largest relative difference {worst:.2e}", file=sys.stderr)

    def test_scipy_docstring_example(self):
        # make_smoothing_spline's own example (its docstring's data): the fit's parameters
        # come from the points, so its ordinates are fitted as 1-D points at uniform
        # parameters, and scipy is given those parameters as its abscissas.
        x, y = scipy_example()
        t = np.linspace(0, 1, len(y))
        pts = [[v] for v in y]
        r = self.fit(pts, "gcv", parametrization="uniform")
        theirs = scipy_gcv_lambda(t, y)
        if theirs is not None:
            print(f"\n  docstring example: scipy's lambda {theirs!r}", file=sys.stderr)
        grid = np.linspace(0, 1, 801)
        want = make_smoothing_spline(t, y)(grid)
        got = curve_of(r["curve"])(grid)[:, 0]
        err = np.max(np.abs(got - want)) / np.max(np.abs(want))
        print(f"\n  docstring example, gcv: lambda {r['smoothing']!r}, relative difference {err:.2e}", file=sys.stderr)
        # The same criterion minimised by the same bounded Brent iteration: the lambdas
        # agree to rounding, then the splines as for a given lambda.
        self.assertLess(err, 1e-9)
        self.assertGreater(r["smoothing"], 0)
        for lam in (1e-6, 1e-4, 1e-2):
            got = curve_of(self.fit(pts, lam, parametrization="uniform")["curve"])(grid)[:, 0]
            want = make_smoothing_spline(t, y, lam=lam)(grid)
            self.assertLess(np.max(np.abs(got - want)) / np.max(np.abs(want)), 1e-9, f"lambda={lam}")

    def test_uneven_parameters_against_mpmath(self):
        # The docstring example's points (x, y) as 2-D points, chord parameters (steps from
        # 1e-4 to 5e-2 of the whole): scipy's natural-spline basis has a penalty matrix with
        # entries of order 1 / h^3 and loses digits as lambda grows, so the oracle here is
        # Reinsch's system at 40 digits; scipy's own distance from it is printed.
        x, y = scipy_example(n=80)
        P = np.stack([x, y], axis=1)
        tc = np.array(fit_params(P.tolist(), "chord"))
        for lam in (1e-8, 1e-5, 1e-3, 1e-1):
            got = curve_of(self.fit(P.tolist(), lam)["curve"])(tc)
            for k in range(2):
                want = reinsch_mp(tc, P[:, k], lam)
                err = np.max(np.abs(got[:, k] - want)) / np.max(np.abs(want))
                sci = np.max(np.abs(make_smoothing_spline(tc, P[:, k], lam=lam)(tc) - want)) / np.max(np.abs(want))
                print(f"\n  uneven, lambda {lam}, coordinate {k}: program {err:.1e}, scipy {sci:.1e} from mpmath", file=sys.stderr)
                # Reinsch's system as a banded least-squares problem (QR): the square root
                # of the normal matrix's condition number (which grows like n^4 and
                # lambda / h_min^3) times the rounding of |y|: 1e-12 measured, 1e-10 allowed.
                self.assertLess(err, 1e-10, f"lambda={lam} coordinate {k}")

    def test_noisy_gcv_matches_scipy(self):
        # 1-D points (noisy samples of a function) under two parametrizations: scipy's gcv
        # at the same parameters. Both minimise the same criterion by the same bounded
        # Brent iteration, but each evaluates it with its own rounding, and the last
        # parabolic steps can land a few 1e-10 apart (measured up to 8e-8 relative in
        # lambda): lambda is compared within the iteration's tolerance xatol = 1e-5, and
        # the curve against make_smoothing_spline at the program's lambda to 1e-9; the
        # curves of the two gcv choices are printed.
        worst_lam, worst_curve = 0.0, 0.0
        for seed, n in ((1, 30), (2, 100), (3, 250)):
            rng = np.random.RandomState(seed)
            y = np.sin(np.linspace(0, 4, n)) * 3 + rng.normal(scale=0.3, size=n)
            for kind in ("uniform", "centripetal"):
                t = fit_params([[v] for v in y], kind)
                r = self.fit([[v] for v in y], "gcv", parametrization=kind)
                lam = r["smoothing"]
                grid = np.linspace(0, 1, 301)
                got = curve_of(r["curve"])(grid)[:, 0]
                scale = np.max(np.abs(got))
                want = make_smoothing_spline(t, y, lam=lam)(grid)
                self.assertLess(np.max(np.abs(got - want)) / scale, 1e-9, f"seed={seed} n={n} {kind} lambda={lam}")
                theirs = scipy_gcv_lambda(t, y)
                if theirs is not None:
                    self.assertLess(abs(lam - theirs), 1e-5, f"seed={seed} n={n} {kind}")
                    worst_lam = max(worst_lam, abs(lam - theirs) / theirs)
                worst_curve = max(worst_curve, np.max(np.abs(got - make_smoothing_spline(t, y)(grid))) / scale)
        print(f"\n  noisy gcv vs scipy's gcv: lambda {worst_lam:.1e} relative, curve {worst_curve:.1e} relative", file=sys.stderr)

    def test_gcv_does_not_depend_on_the_scale(self):
        # Audit 16 D7: both terms of the objective are quadratic in the values, so GCV's
        # lambda is the same at every scale; before, 1e-200 gave lambda 12 (an almost
        # straight fit, squared residuals underflowing) and 1e160 was refused. Against the
        # unscaled answer: lambda within the iteration's tolerance xatol = 1e-5 (the
        # rounding of a scale that is not a power of two may move the last Brent step),
        # exactly for 2^-660; the control points scaled back within 1e-9 of the largest.
        rng = np.random.default_rng(0)
        x = np.linspace(0, 1, 12)
        y = np.sin(3 * x) + 0.1 * rng.standard_normal(12)
        cases = (([[v] for v in y], "uniform"), ([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]], "chord"))
        for pts, kind in cases:
            base = self.fit(pts, "gcv", parametrization=kind)
            P0 = np.array(base["curve"]["points"])
            for s in (2.0**-660, 1e-300, 1e-200, 1e160, 1e300):
                with self.subTest(n=len(pts), scale=s):
                    r = self.fit([[v * s for v in p] for p in pts], "gcv", parametrization=kind)
                    # chord parameters at 1e-300: the same to rounding
                    knots = np.subtract(r["curve"]["knots"], base["curve"]["knots"])
                    self.assertLess(np.max(np.abs(knots)), 1e-15)
                    back = np.array(r["curve"]["points"]) / s
                    if s == 2.0**-660:
                        self.assertEqual(r["smoothing"], base["smoothing"])
                        self.assertTrue(np.array_equal(back, P0))
                    self.assertLess(abs(r["smoothing"] - base["smoothing"]), 1e-5)
                    self.assertLess(np.max(np.abs(back - P0)) / np.max(np.abs(P0)), 1e-9)

    def test_gcv_of_several_coordinates_is_the_stacked_criterion(self):
        # d = 2 and 3: lambda minimises the stacked GCV (numpy's dense hat matrix here):
        # the bounded minimisation of that criterion by scipy.optimize lands on the same
        # lambda within its tolerance (xatol 1e-5), and the curve is each coordinate's
        # make_smoothing_spline at the returned lambda.
        for dim, seed in ((2, 11), (3, 12)):
            rng = np.random.RandomState(seed)
            s = np.linspace(0, 3, 70)
            P = np.stack([np.cos(s), np.sin(s), 0.2 * s], axis=1)[:, :dim] + rng.normal(scale=0.03, size=(70, dim))
            t = fit_params(P.tolist(), "chord")
            r = self.fit(P.tolist(), "gcv")
            self.assertEqual(list(r), ["curve", "max_error", "smoothing"])
            lam = r["smoothing"]
            best = minimize_scalar(lambda l: stacked_gcv(t, P, l), bounds=(0, len(t)), method="bounded")
            self.assertLess(abs(lam - best.x), 1e-5, f"d={dim}: {lam} vs {best.x}")
            g = stacked_gcv(t, P, lam)
            for f in (0.9, 1.1):
                self.assertLessEqual(g, stacked_gcv(t, P, lam * f) * (1 + 1e-12), f"d={dim}: not a minimum")
            grid = np.linspace(0, 1, 301)
            got = curve_of(r["curve"])(grid)
            for k in range(dim):
                want = make_smoothing_spline(t, P[:, k], lam=lam)(grid)
                self.assertLess(np.max(np.abs(got[:, k] - want)), 1e-9)

    def test_lambda_zero_is_natural_interpolation(self):
        rng = np.random.RandomState(5)
        P = rng.normal(size=(12, 2)).tolist()
        t = fit_params(P, "centripetal")
        r = self.fit(P, 0, parametrization="centripetal")
        self.assertLess(r["max_error"], 1e-12)
        grid = np.linspace(0, 1, 200)
        want = CubicSpline(t, np.array(P), bc_type="natural")(grid)
        self.assertLess(np.max(np.abs(curve_of(r["curve"])(grid) - want)), 1e-12)

    def test_large_lambda_tends_to_the_regression_line(self):
        # The penalty forces C'' -> 0: the least-squares line in t of each coordinate
        # (numpy.polyfit). At lambda 1e8 the difference is of order 1 / lambda.
        rng = np.random.RandomState(6)
        P = rng.normal(size=(25, 2))
        t = fit_params(P.tolist(), "uniform")
        r = self.fit(P.tolist(), 1e8, parametrization="uniform")
        grid = np.linspace(0, 1, 50)
        got = curve_of(r["curve"])(grid)
        for k in range(2):
            line = np.polyval(np.polyfit(t, P[:, k], 1), grid)
            self.assertLess(np.max(np.abs(got[:, k] - line)), 1e-6)

    def test_two_points_give_the_line(self):
        r = self.fit([[0, 0], [2, 1]], 0.5)
        c = curve_of(r["curve"])
        for u in (0, 0.25, 1):
            self.assertLess(np.max(np.abs(c(u) - np.array([2 * u, u]))), 1e-15)

    def test_gcv_beats_a_tolerance_fit_on_noisy_samples(self):
        # The case: 200 noisy samples (sigma 0.02) of a known shape. The tolerance
        # fit at 0.02 follows the noise; the gcv fit stays closer to the true shape. The
        # distance to the shape: from 2000 points of each fitted curve to a 20000-point
        # polyline of the true curve (nearest vertex; its spacing 3e-4 bounds the error),
        # over the middle 90% of the parameter (an open fit of a closed shape has free ends).
        pts, shape = noisy_blob(200, seed=3, noise=0.02)
        truth = shape(np.linspace(0, 2 * np.pi, 20000, endpoint=False))
        truth_tree = cKDTree(truth)

        def off(curve):
            u = np.linspace(0.05, 0.95, 2000)
            C = curve_of(curve)(u)
            d, _ = truth_tree.query(C)  # the nearest vertex (scipy.spatial.cKDTree)
            return np.max(d), np.sqrt(np.mean(d ** 2))

        g = self.fit(pts, "gcv")
        tol = self.ok("fit", {"points": pts, "degree": 3, "tolerance": 0.02})
        gm, grms = off(g["curve"])
        tm, trms = off(tol["curve"])
        print(f"\n  200 noisy samples: gcv lambda {g['smoothing']:.3g}: max {gm:.4f} rms {grms:.4f}; "
              f"tolerance 0.02: max {tm:.4f} rms {trms:.4f}", file=sys.stderr)
        self.assertLess(gm, tm)
        self.assertLess(grms, trms)

    def test_bad_requests_name_the_field(self):
        P = [[0, 0], [1, 1], [2, 0], [3, 1]]
        base = {"points": P, "degree": 3}
        self.bad("fit", dict(base, smoothing=-1), "smoothing", contains=">= 0")
        self.bad("fit", dict(base, smoothing="GCV"), "smoothing", contains="gcv")
        self.bad("fit", dict(base, smoothing=True), "smoothing")
        self.bad("fit", dict(base, smoothing=[1]), "smoothing")
        self.bad("fit", dict(base, smoothing=1, degree=5), "degree", contains="3")
        self.bad("fit", dict(base, smoothing=1, control_points=4), "control_points")
        self.bad("fit", dict(base, smoothing="gcv", tolerance=0.1), "tolerance")
        self.bad("fit", dict(base, smoothing=1, closed=True), "closed")
        self.bad("fit", dict(base, smoothing=1, start_derivative=[1, 0]), "start_derivative")
        self.bad("fit", dict(base, smoothing=1, end_derivative=[1, 0]), "end_derivative")
        self.bad("fit", {"points": [[0, 0]], "degree": 3, "smoothing": 1}, "points")
        self.bad("fit", {"points": [[0, 0], [1, 0]], "degree": 3, "smoothing": "gcv"}, "points", contains="3")
        self.bad("fit", {"points": [[0, 0], [1, 0], [1, 0], [2, 0]], "degree": 3, "smoothing": 1}, "points[2]")
        self.bad("fit", {"points": [[0, 0], [1, 0]], "degree": 3}, "control_points", contains="smoothing")
        # The work limit: gcv on more than 300000 points is refused up front.
        many = [[float(i % 7)] for i in range(300001)]
        self.bad("fit", {"points": many, "degree": 3, "smoothing": "gcv", "parametrization": "uniform"}, "points",
                 contains="work limit")
        # closed: false is not a contradiction.
        self.fit(P, 1, closed=False)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
