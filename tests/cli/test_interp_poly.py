#!/usr/bin/python3
"""Black-box tests of the interpolating polynomial curve types `lagrange` and `catmull_rom`
against independent oracles at test time: scipy.interpolate.BarycentricInterpolator
(Debian's python3-scipy 1.10) for values, the Newton form in 50-digit mpmath for
derivatives, extrapolation and high degree, and for `catmull_rom` a direct implementation
of the Barry-Goldman pyramid (recursive lerps with the knots) written here. Also the
queries on the Bézier form (bounds, to_bezier, flatten), its degree cap, and the error
contract.

Usage: test_interp_poly.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import unittest

import mpmath
import numpy as np
from scipy.interpolate import BarycentricInterpolator

import test_cli
from test_cli import CliTest, dist_to_polyline

mpmath.mp.dps = 50


_DIVIDED = {}  # (xs, ys) -> the Newton coefficients of each coordinate, computed once


def newton_oracle(xs, ys, t, k):
    """Values p(t), p'(t), ..., p^(k)(t) of the interpolant through (xs, ys) (ys: points as
    lists), by divided differences and the Newton form differentiated exactly, in mpmath.
    The divided differences depend on the nodes only: computed once per (xs, ys)."""
    n = len(xs)
    X = [mpmath.mpf(x) for x in xs]
    dim = len(ys[0])
    key = (mpmath.mp.prec, tuple(xs), tuple(tuple(y) for y in ys))
    if key not in _DIVIDED:
        coefficients = []
        for d in range(dim):
            c = [mpmath.mpf(y[d]) for y in ys]
            for lvl in range(1, n):
                for i in range(n - 1, lvl - 1, -1):
                    c[i] = (c[i] - c[i - 1]) / (X[i] - X[i - lvl])
            coefficients.append(c)
        _DIVIDED[key] = coefficients
    out = []
    for c in _DIVIDED[key]:
        # Horner on the Newton form, carrying derivatives: q_j = value and derivatives of
        # the tail polynomial, updated by q <- (t - x_i) q + c_i.
        T = mpmath.mpf(t)
        vals = [mpmath.mpf(0)] * (k + 1)
        for i in range(n - 1, -1, -1):
            new = [mpmath.mpf(0)] * (k + 1)
            for m in range(k + 1):
                new[m] = (T - X[i]) * vals[m] + (m * vals[m - 1] if m > 0 else 0)
            new[0] += c[i]
            vals = new
        out.append(vals)
    return [[float(out[d][m]) for d in range(dim)] for m in range(k + 1)]


_DENOMINATORS = {}  # xs -> prod_(k != j) (x_j - x_k) for each j, computed once


def lebesgue(xs, t):
    """sum_j |l_j(t)| in mpmath: the condition number of interpolation at t. l_j(t) =
    prod_(k != j) (t - x_k) / prod_(k != j) (x_j - x_k); the denominators depend on the
    nodes only and are computed once per xs."""
    X = [mpmath.mpf(x) for x in xs]
    key = (mpmath.mp.prec, tuple(xs))
    if key not in _DENOMINATORS:
        _DENOMINATORS[key] = [mpmath.fprod(X[j] - X[k] for k in range(len(X)) if k != j) for j in range(len(X))]
    den = _DENOMINATORS[key]
    T = mpmath.mpf(t)
    s = 0
    for j in range(len(X)):
        s += abs(mpmath.fprod(T - X[k] for k in range(len(X)) if k != j) / den[j])
    return float(s)


def lebesgue_constant(xs):
    """max of the Lebesgue function over [min xs, max xs] (20 samples in every gap between
    consecutive nodes, in double: the value is a tolerance scale, not a result)."""
    X = np.array(sorted(xs))
    ts = np.concatenate([np.linspace(a, b, 22)[1:-1] for a, b in zip(X, X[1:])])
    diff = X[:, None] - X[None, :]
    np.fill_diagonal(diff, 1.0)
    denom = np.prod(diff, axis=1)
    num = np.prod(ts[:, None] - X[None, :], axis=1)
    L = np.abs(num[:, None] / ((ts[:, None] - X[None, :]) * denom[None, :])).sum(axis=1)
    return float(L.max())


def higham_bound(xs, t, scale, value, lam_n):
    """Higham's forward error bound for the second barycentric formula [Higham04, (3.6)],
    with Lambda(t) max |y| for sum_j |l_j(t) y_j|: u ((3n + 4) Lambda(t) max |y| +
    (3n + 2) Lambda_n |p(t)|), u = eps / 2."""
    n = len(xs)
    return EPS / 2 * ((3 * n + 4) * lebesgue(xs, t) * scale + (3 * n + 2) * lam_n * abs(value))


def lagrange(params, points, **extra):
    return dict({"type": "lagrange", "params": params, "points": points}, **extra)


def cheb1(n, a=-1.0, b=1.0):
    return [a + (b - a) * (1 - math.cos((2 * j + 1) * math.pi / (2 * n))) / 2 for j in range(n)]


EPS = 2.0 ** -52


class LagrangeTest(CliTest):
    def test_values_match_scipy_barycentric(self):
        rng = random.Random(6)
        cases = 0
        for n in (2, 3, 4, 5, 7, 10):
            for dim in (1, 2, 3):
                for uneven in (False, True):
                    if uneven:
                        xs = sorted(rng.uniform(-3, 4) for _ in range(n))
                        rng.shuffle(xs)  # any order
                    else:
                        xs = [-1 + 2.5 * j for j in range(n)]
                    ys = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]
                    lo, hi = min(xs), max(xs)
                    ts = xs + [rng.uniform(lo, hi) for _ in range(25)]
                    r = self.ok("eval", {"curve": lagrange(xs, ys), "t": ts})
                    ref = BarycentricInterpolator(xs, ys)(ts)
                    scale = max(abs(v) for y in ys for v in y)
                    lam_n = lebesgue_constant(xs)
                    for j, t in enumerate(ts):
                        # Both evaluate the same formula in double, each within Higham's
                        # bound: 1e-12 of max |y| where the Lebesgue function is small (most
                        # cases), twice the bound where it is not (close nodes).
                        tol = max(1e-12 * scale, 2 * higham_bound(xs, t, scale, max(map(abs, ref[j])), lam_n))
                        for a, b in zip(r["points"][j], ref[j]):
                            self.assertLessEqual(abs(a - b), tol, f"n={n} xs={xs} t={t}")
                    # Exact hits at the params.
                    self.assertEqual(r["points"][:n], ys)
                    cases += 1
        self.assertEqual(cases, 36)

    def test_derivatives_and_extrapolation_match_mpmath(self):
        rng = random.Random(60)
        for n in (2, 3, 4, 6, 9):
            for dim in (1, 2):
                xs = sorted(rng.uniform(-2, 2) for _ in range(n))
                rng.shuffle(xs)
                ys = [[rng.uniform(-1, 1) for _ in range(dim)] for _ in range(n)]
                lo, hi = min(xs), max(xs)
                span = hi - lo
                ts = [rng.uniform(lo, hi) for _ in range(10)] + xs[:2] + [xs[0] + 1e-11]
                ts += [lo - 0.3 * span, hi + 0.5 * span, hi + 10 * span]
                k = n + 1
                r = self.ok("eval", {"curve": lagrange(xs, ys), "t": ts, "derivatives": k})
                # Order m amplifies rounding by about (n^2 / shortest gap)^m: the tolerance
                # is 1e-11 of the Lebesgue-scaled size times that growth.
                gaps = sorted(xs)
                gap = min(b - a for a, b in zip(gaps, gaps[1:]))
                grow = n * n / gap
                for j, t in enumerate(ts):
                    want = newton_oracle(xs, ys, t, k)
                    lam = lebesgue(xs, t)
                    for m in range(k + 1):
                        got = r["points"][j] if m == 0 else r["derivatives"][m - 1][j]
                        size = max(1.0, max(abs(v) for v in want[m]))
                        tol = 1e-12 * lam * size * (1 + grow) ** m
                        if m >= n:
                            self.assertEqual(got, [0.0] * dim, f"order {m} >= n = {n}")
                        for a, b in zip(got, want[m]):
                            self.assertLessEqual(abs(a - b), tol, f"n={n} xs={xs} t={t} m={m}: {got} vs {want[m]}")

    def test_high_degree_against_mpmath(self):
        # Runge's function on 41 Chebyshev points (degree 40): Lebesgue constant ~3, so the
        # barycentric values agree with the exact interpolant to ~1e-14; on 31 equispaced
        # points the Lebesgue function reaches ~7e6 near the ends (errors ~1e-7 there).
        f = lambda x: 1 / (1 + 25 * x * x)
        # Within Higham's bound (higham_bound, max |y| = 1).
        for xs in (cheb1(41), [-1 + 2 * j / 30 for j in range(31)]):
            ys = [[f(x)] for x in xs]
            ts = [-1 + 2 * i / 97 for i in range(98)]
            lam_n = lebesgue_constant(xs)
            r = self.ok("eval", {"curve": lagrange(xs, ys), "t": ts})
            for j, t in enumerate(ts):
                want = newton_oracle(xs, ys, t, 0)[0][0]
                self.assertLessEqual(abs(r["points"][j][0] - want), higham_bound(xs, t, 1.0, want, lam_n), f"t={t}")

    def test_runge_phenomenon(self):
        # The max error to 1/(1 + 25 x^2) on [-1, 1] grows with n on equispaced nodes
        # (n = 10..40) and falls on Chebyshev nodes (n = 5..40).
        f = lambda x: 1 / (1 + 25 * x * x)
        ts = [-1 + 2 * i / 1000 for i in range(1001)]
        prev_eq, prev_ch = 0, 1
        for n in range(5, 41, 5):
            eq = [-1 + 2 * j / (n - 1) for j in range(n)]
            ch = cheb1(n)
            errs = []
            for xs in (eq, ch):
                r = self.ok("eval", {"curve": lagrange(xs, [[f(x)] for x in xs]), "t": ts})
                errs.append(max(abs(p[0] - f(t)) for p, t in zip(r["points"], ts)))
            if n >= 15:
                self.assertGreater(errs[0], prev_eq, n)
            self.assertLess(errs[1], prev_ch, n)
            prev_eq, prev_ch = errs
        self.assertGreater(prev_eq, 1e4)
        self.assertLess(prev_ch, 1e-3)

    def test_queries_on_the_bezier_form(self):
        xs, ys = [0.5, -1, 2, 0], [[0, 0], [1, 2], [3, -1], [-1, 1]]
        c = lagrange(xs, ys)
        tb = self.ok("to_bezier", {"curve": c})["curve"]
        self.assertEqual(tb["type"], "path")
        self.assertEqual(tb["breaks"], [-1, 2])
        self.assertEqual(len(tb["segments"]), 1)
        seg = tb["segments"][0]
        self.assertEqual(len(seg["points"]), 4)
        # The cubic Bézier on [-1, 2] traces the curve: compare at a few parameters.
        ts = [-1 + 3 * i / 10 for i in range(11)]
        a = self.ok("eval", {"curve": c, "t": ts})["points"]
        b = self.ok("eval", {"curve": tb, "t": ts})["points"]
        for p, q in zip(a, b):
            self.assertLessEqual(max(abs(u - v) for u, v in zip(p, q)), 1e-13)
        # Tight bounds contain the dense samples and touch them.
        box = self.ok("bounds", {"curve": c})
        dense = self.ok("eval", {"curve": c, "t": [-1 + 3 * i / 4000 for i in range(4001)]})["points"]
        for d in range(2):
            lo, hi = min(p[d] for p in dense), max(p[d] for p in dense)
            self.assertLessEqual(box["min"][d], lo + 1e-12)
            self.assertGreaterEqual(box["max"][d], hi - 1e-12)
            self.assertGreater(box["min"][d], lo - 1e-6)
            self.assertLess(box["max"][d], hi + 1e-6)
        poly = self.ok("flatten", {"curve": c, "tolerance": 1e-3})["points"]
        self.assertEqual(poly[0], [1, 2])
        self.assertEqual(poly[-1], [3, -1])
        for p in dense[::40]:
            self.assertLessEqual(dist_to_polyline(p, poly), 1e-3 * (1 + 1e-9))

    def test_bezier_form_refused_above_the_cap(self):
        xs = cheb1(17)  # degree 16
        c = lagrange(xs, [[x * x] for x in xs])
        for cmd, extra in (("bounds", {}), ("to_bezier", {}), ("flatten", {"tolerance": 0.01})):
            self.bad(cmd, dict({"curve": c}, **extra), "curve", contains="no accurate Bézier form")
        r = self.ok("eval", {"curve": c, "t": [0.5]})
        self.assertAlmostEqual(r["points"][0][0], 0.25, delta=1e-14)
        # Degree 15 is served.
        xs = cheb1(16)
        self.ok("bounds", {"curve": lagrange(xs, [[x * x] for x in xs])})

    def test_errors(self):
        P = [[0, 0], [1, 1], [2, 0], [3, 1]]
        self.bad("eval", {"curve": lagrange([0, 1, 0.5, 1], P), "t": [0]}, "curve.params[3]", contains="distinct")
        self.bad("eval", {"curve": lagrange([2, 1, 0, 2], P), "t": [0]}, "curve.params[3]", contains="repeats params[0]")
        self.bad("eval", {"curve": lagrange([0, 1, 2], P), "t": [0]}, "curve.params", contains="one parameter per point")
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3, 4], P), "t": [0]}, "curve.params")
        self.bad("eval", {"curve": lagrange([], []), "t": [0]}, "curve.points")
        self.bad("eval", {"curve": {"type": "lagrange", "points": P}, "t": [0]}, "curve.params", contains="missing")
        self.bad("eval", {"curve": {"type": "lagrange", "params": [0, 1, 2, 3]}, "t": [0]}, "curve.points", contains="missing")
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], P, weights=[1, 1, 1, 1]), "t": [0]}, "curve.weights",
                 contains="unknown field")
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], P, dim=3), "t": [0]}, "curve.dim")
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], [[0, 0], [1, 1], [2], [3, 1]]), "t": [0]}, "curve.points[2]")
        self.bad("eval", {"curve": lagrange([0, 1, "x", 3], P), "t": [0]}, "curve.params[2]")
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], P), "t": [0]}, "curve.params[1]",
                 text='{"curve": {"type": "lagrange", "params": [0, 1e999, 2, 3], "points": [[0], [1], [2], [3]]}, "t": [0]}')
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], P), "t": [0]}, "curve.points[1][0]",
                 text='{"curve": {"type": "lagrange", "params": [0, 1, 2, 3], "points": [[0], [-1e999], [2], [3]]}, "t": [0]}')
        self.bad("eval", {"curve": lagrange([-1e308, 0, 1e308, 3], P), "t": [0]}, "curve.params", contains="largest double")
        # Far extrapolation that overflows is refused for that parameter.
        self.bad("eval", {"curve": lagrange([0, 1, 2, 3], [[0], [1], [8], [27]]), "t": [0, 1e200]}, "t[1]")


class LagrangeOnePoint(CliTest):
    """Issue 15: a lagrange curve through one point is the constant (scipy's
    BarycentricInterpolator takes it); every command must serve it."""

    def test_constant_as_scipy(self):
        c = lagrange([2], [[3, 4]])
        ts = [-1e300, -5, 2, 2.5, 1e300]
        r = self.ok("eval", {"curve": c, "t": ts, "derivatives": 3})
        want = BarycentricInterpolator([2.0], np.array([[3.0, 4.0]]))(np.array(ts, dtype=float))
        self.assertEqual(r["points"], want.tolist())
        for k in range(3):
            self.assertEqual(r["derivatives"][k], [[0.0, 0.0]] * len(ts))

    def test_queries(self):
        c = lagrange([2], [[3, 4]])
        r = self.ok("bounds", {"curve": c})
        self.assertEqual((r["min"], r["max"]), ([3.0, 4.0], [3.0, 4.0]))
        self.assertEqual(self.ok("length", {"curve": c})["length"], 0.0)
        r = self.ok("project", {"curve": c, "point": [0, 0]})
        self.assertEqual(r["t"], 2.0)  # the contract: a single point answers its domain's start
        self.assertEqual(r["point"], [3.0, 4.0])
        self.assertAlmostEqual(r["distance"], 5.0, delta=1e-15)
        self.assertEqual(self.ok("param_at_length", {"curve": c, "lengths": [0]})["t"], [2.0])
        for p in self.ok("flatten", {"curve": c, "tolerance": 0.1})["points"]:
            self.assertEqual(p, [3.0, 4.0])
        tb = self.ok("to_bezier", {"curve": c})["curve"]
        self.assertEqual(tb["segments"], [{"type": "bezier", "points": [[3.0, 4.0]]}])
        self.assertEqual(tb["breaks"][0], 2.0)
        self.assertEqual(tb["breaks"][1], math.nextafter(2.0, 3.0))  # a path's breaks increase
        self.assertIn("<svg", run_render(c))


def run_render(curve):
    rc, out, err = test_cli.run("render", {"curve": curve})
    assert rc == 0, err
    return out


def barry_goldman(P, s, t, order=0):
    """The Barry-Goldman pyramid for the segment from P[1] to P[2] with knots s[0..3], at t:
    three levels of lerps with the knots (a direct implementation, in mpmath), with its
    derivatives up to `order`: a lerp (tb - t) / (tb - ta) x + (t - ta) / (tb - ta) y has
    weights linear in t, so (Leibniz) its m-th derivative is the same lerp of the m-th
    derivatives plus m (y^(m-1) - x^(m-1)) / (tb - ta). Returns [value, first, ...], each
    a list of coordinates: the derivatives of the pyramid's polynomial, exactly."""
    def lerp(a, b, ta, tb):
        h = tb - ta
        out = [[(tb - t) / h * x + (t - ta) / h * y for x, y in zip(a[0], b[0])]]
        for m in range(1, order + 1):
            out.append([(tb - t) / h * x + (t - ta) / h * y + m * (y1 - x1) / h
                        for x, y, x1, y1 in zip(a[m], b[m], a[m - 1], b[m - 1])])
        return out
    zero = [0] * len(P[0])
    J = [[list(p)] + [zero] * order for p in P]
    A1 = lerp(J[0], J[1], s[0], s[1])
    A2 = lerp(J[1], J[2], s[1], s[2])
    A3 = lerp(J[2], J[3], s[2], s[3])
    B1 = lerp(A1, A2, s[0], s[2])
    B2 = lerp(A2, A3, s[1], s[3])
    return lerp(B1, B2, s[1], s[2])


def catmull_rom_oracle(P, alpha, closed, t, order):
    """The curve of the contract's table at t and its derivatives up to `order`, rounded
    to double (catmull_rom_jet at 50 digits)."""
    return [[float(x) for x in row] for row in catmull_rom_jet(P, alpha, closed, t, order)]


def catmull_rom_jet(P, alpha, closed, t, order):
    """The curve of the contract's table at t: the segment whose interval holds t (the
    first or last one outside the domain), by the pyramid in mpmath at the working
    precision, with the exact derivatives of its polynomial (barry_goldman). Until session
    10 the derivatives were mpmath.diff of the pyramid at 50 digits: on this file's inputs
    (5595 calls) the two agree after rounding to double, but for one derivative that is
    zero to 2e-51."""
    N = len(P)
    M = [[mpmath.mpf(x) for x in p] for p in P]
    dist = lambda a, b: mpmath.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
    d = lambda i: mpmath.mpf(1) if alpha == 0 else dist(M[(i + 1) % N], M[i % N]) ** alpha
    if closed:
        s = [mpmath.mpf(0)]
        for i in range(N):
            s.append(s[-1] + d(i))
        j = 0
        while j < N - 1 and t >= s[j + 1]:
            j += 1
        pts = [M[(j - 1) % N], M[j], M[(j + 1) % N], M[(j + 2) % N]]
        knots = [s[j] - d((j - 1) % N), s[j], s[j + 1], s[j + 1] + d((j + 1) % N)]
    else:
        s = [mpmath.mpf(0)]
        for i in range(N - 1):
            s.append(s[-1] + d(i))
        s = [x - s[1] for x in s]
        j = 0
        while j < N - 4 and t >= s[j + 2]:
            j += 1
        pts = M[j:j + 4]
        knots = s[j:j + 4]
    return barry_goldman(pts, knots, mpmath.mpf(t), order)


def catmull_rom(points, **extra):
    return dict({"type": "catmull_rom", "points": points}, **extra)


class CatmullRomTest(CliTest):
    def test_uniform_closed_form(self):
        # Uniform segment j: f(j) = p[j+1] exactly, f'(j) = (p[j+2] - p[j]) / 2 to a few ulps
        # (the derivative of the Bézier form, 3 (B_1 - B_0) with B_1 = B_0 + m / 3).
        P = [[0, 0], [1, 3], [4, 4], [6, 1], [9, 2], [10, -1]]
        ts = [0, 1, 2, 3]
        r = self.ok("eval", {"curve": catmull_rom(P, alpha=0), "t": ts, "derivatives": 1})
        for j in range(4):
            self.assertEqual(r["points"][j], P[j + 1])
            for got, want in zip(r["derivatives"][0][j], [(a - b) / 2 for a, b in zip(P[j + 2], P[j])]):
                self.assertAlmostEqual(got, want, delta=1e-14)

    def test_matches_the_barry_goldman_pyramid(self):
        rng = random.Random(66)
        for alpha in (0, 0.5, 1, 0.3):
            for closed in (False, True):
                for dim in (1, 2, 3):
                    N = rng.randint(3 if closed else 4, 8)
                    P = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(N)]
                    c = catmull_rom(P, alpha=alpha, closed=closed)
                    tb = self.ok("to_bezier", {"curve": c})["curve"]
                    breaks = tb["breaks"]
                    self.assertEqual(len(tb["segments"]), N if closed else N - 3)
                    lo, hi = breaks[0], breaks[-1]
                    ts = breaks + [rng.uniform(lo, hi) for _ in range(12)] + [lo - 0.2 * (hi - lo), hi + 0.2 * (hi - lo)]
                    r = self.ok("eval", {"curve": c, "t": ts, "derivatives": 2})
                    scale = max(abs(x) for p in P for x in p)
                    # Knot intervals as short as ~1e-2 here: a derivative of order k grows
                    # like 1 / shortest^k; the tolerance scales with it.
                    shortest = min(b - a for a, b in zip(breaks, breaks[1:]))
                    for j, t in enumerate(ts):
                        want = catmull_rom_oracle(P, alpha, closed, t, 2)
                        # The second derivative jumps at a joint: there the library's
                        # right-hand segment and the oracle's (chosen by the 50-digit knot,
                        # which may lie just above the double break) may differ.
                        at_joint = any(abs(t - b) <= 1e-9 * (hi - lo) for b in breaks[1:-1])
                        for k in range(2 if at_joint else 3):
                            got = r["points"][j] if k == 0 else r["derivatives"][k - 1][j]
                            tol = 1e-12 * scale * (1 + 1 / shortest) ** k * (1 + abs(t - lo) / (hi - lo)) ** 3
                            for a, b in zip(got, want[k]):
                                self.assertLessEqual(abs(a - b), tol,
                                                     f"alpha={alpha} closed={closed} P={P} t={t} k={k}: {got} vs {want[k]}")

    def test_any_scale_matches_the_pyramid(self):
        # Issue 15: intervals |dP|^alpha multiplied together overflowed from 1e154 (chordal
        # became the control polygon: length 5.84e200 for 6.08e200) and underflowed below
        # 1e-154 (an error of 6.7e-6 at 1e-160, a false "got inf" at 1e-200). The mpmath
        # pyramid takes any scale.
        unit = [[0, 0], [1, 3], [4, 4], [6, 1], [9, 2]]
        for scale in (1e154, 1e200, 1e300, 1e-160, 1e-200, 1e-300):
            for alpha in (0.5, 0.75, 1):
                P = [[x * scale for x in p] for p in unit]
                c = catmull_rom(P, alpha=alpha)
                breaks = self.ok("to_bezier", {"curve": c})["curve"]["breaks"]
                ts = [breaks[0] + f * (breaks[-1] - breaks[0]) for f in (0.1, 0.35, 0.5, 0.8, 1)]
                r = self.ok("eval", {"curve": c, "t": ts})
                for t, got in zip(ts, r["points"]):
                    want = catmull_rom_oracle(P, alpha, False, t, 0)[0]
                    for a, b in zip(got, want):
                        # A few eps of the scale (rounded knots move the parameter by eps).
                        self.assertLessEqual(abs(a - b), 1e-13 * scale, f"scale={scale} alpha={alpha} t={t}")

    def test_chordal_length_scales(self):
        # The chordal length at 1e200 is 1e200 times the unit one (an exact invariance of
        # alpha = 1: knots and curve scale together), and the unit one is mpmath's quadrature
        # of the pyramid's speed.
        unit = [[0, 0], [1, 3], [4, 4], [6, 1], [9, 2]]
        L1 = self.ok("length", {"curve": catmull_rom(unit, alpha=1)})["length"]
        breaks = self.ok("to_bezier", {"curve": catmull_rom(unit, alpha=1)})["curve"]["breaks"]
        # The speed in mpmath (not rounded to double, so that the quadrature converges) at
        # 20 digits: the check is at 1e-12.
        with mpmath.workdps(20):
            speed = lambda t: mpmath.sqrt(mpmath.fsum(x * x for x in catmull_rom_jet(unit, 1, False, t, 1)[1]))
            want = float(mpmath.quad(speed, breaks))
        self.assertAlmostEqual(L1, want, delta=1e-12 * want)
        for scale in (1e200, 1e-200):
            L = self.ok("length", {"curve": catmull_rom([[x * scale for x in p] for p in unit], alpha=1)})["length"]
            self.assertAlmostEqual(L / scale, L1, delta=1e-13 * L1)

    def test_unrepresentable_parameter_is_refused_naming_points(self):
        # |dP| = 2e308 at alpha 1 is no double; at alpha 0.5 (1.41e154) it is, and is served.
        P = [[-1e308], [1e308], [-1e308], [1e308]]
        self.bad("eval", {"curve": catmull_rom(P, alpha=1), "t": [0]}, "curve.points", contains="overflows")
        r = self.ok("eval", {"curve": catmull_rom(P, alpha=0.5), "t": [0]})
        self.assertEqual(r["points"], [[1e308]])
        # 1e-310 apart at alpha 1: below the normal range.
        self.bad("eval", {"curve": catmull_rom([[0], [1e-310], [2e-310], [3e-310]], alpha=1), "t": [0]}, "curve.points",
                 contains="underflows")

    def test_overflow_message_quotes_the_users_parameter(self):
        # Issue 15: extrapolating far outside a tiny curve overflowed, and the message quoted
        # the segment's own parameter (4.47e148) where the request said 0.1.
        s = 1e-149
        P = [[0, 0], [1 * s, 3 * s], [4 * s, 4 * s], [6 * s, 1 * s], [9 * s, 2 * s]]
        rc, out, err = test_cli.run("eval", {"curve": catmull_rom(P, alpha=1), "t": [0.1], "derivatives": 3})
        self.assertEqual(rc, 2, err)
        self.assertTrue(err.startswith("error: t[0]: "), err)
        self.assertIn("t = 0.1 ", err)

    def test_closed_curve_closes_with_c1(self):
        P = [[0, 0], [4, 0], [5, 3], [1, 4]]
        c = catmull_rom(P, closed=True)
        tb = self.ok("to_bezier", {"curve": c})["curve"]
        hi = tb["breaks"][-1]
        r = self.ok("eval", {"curve": c, "t": [0, hi, hi - 1e-9], "derivatives": 1})
        self.assertEqual(r["points"][0], P[0])
        self.assertEqual(r["points"][1], P[0])
        # The tangent arriving at the end equals the one leaving the start.
        for a, b in zip(r["derivatives"][0][2], r["derivatives"][0][0]):
            self.assertAlmostEqual(a, b, delta=1e-7)

    def test_errors(self):
        P = [[0, 0], [1, 1], [2, 0], [3, 1]]
        self.bad("eval", {"curve": catmull_rom(P[:3]), "t": [0]}, "curve.points", contains="at least 4")
        self.bad("eval", {"curve": catmull_rom(P[:2], closed=True), "t": [0]}, "curve.points", contains="at least 3")
        self.bad("eval", {"curve": catmull_rom([[0, 0], [1, 1], [1, 1], [3, 1]]), "t": [0]}, "curve.points[2]",
                 contains="equals points[1]")
        self.ok("eval", {"curve": catmull_rom([[0, 0], [1, 1], [1, 1], [3, 1]], alpha=0), "t": [0]})
        self.bad("eval", {"curve": catmull_rom(P, alpha=1.5), "t": [0]}, "curve.alpha", contains="[0, 1]")
        self.bad("eval", {"curve": catmull_rom(P, alpha=-0.1), "t": [0]}, "curve.alpha")
        self.bad("eval", {"curve": catmull_rom(P, alpha="x"), "t": [0]}, "curve.alpha")
        self.bad("eval", {"curve": catmull_rom(P, closed="yes"), "t": [0]}, "curve.closed")
        self.bad("eval", {"curve": catmull_rom(P, tension=0.5), "t": [0]}, "curve.tension", contains="unknown field")
        self.bad("eval", {"curve": catmull_rom(P, dim=3), "t": [0]}, "curve.dim")
        self.bad("eval", {"curve": catmull_rom([[0, 0], [1, 1], [2], [3, 1]]), "t": [0]}, "curve.points[2]")
        self.bad("eval", {"curve": catmull_rom(P), "t": [0]}, "curve.points[1][1]",
                 text='{"curve": {"type": "catmull_rom", "points": [[0, 0], [1, 1e999], [2, 0], [3, 1]]}, "t": [0]}')
        self.bad("eval", {"curve": catmull_rom(P), "t": [float("nan")]}, "request",
                 text='{"curve": {"type": "catmull_rom", "points": [[0, 0], [1, 1], [2, 0], [3, 1]]}, "t": [NaN]}')



def reflected(P):
    """The contract's phantom end points around P: 2 P_0 - P_1 first, 2 P_(N-1) - P_(N-2) last."""
    first = [2 * a - b for a, b in zip(P[0], P[1])]
    last = [2 * a - b for a, b in zip(P[-1], P[-2])]
    return [first] + [list(p) for p in P] + [last]


class CatmullRomReflectTest(CliTest):
    def test_matches_the_pyramid_on_the_reflected_points(self):
        # ends "reflect": the open curve of the N + 2 points with the phantoms, by the
        # pyramid oracle above on that list (its parameter starts at its second point,
        # P_0). The program forms a phantom in double (2 P_0 - P_1 rounded once): a few
        # eps of the scale, below the tolerance of the pyramid test.
        rng = random.Random(67)
        for alpha in (0, 0.5, 1, 0.3):
            for dim in (1, 2, 3):
                for N in (2, 3, 4, rng.randint(5, 9)):
                    P = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(N)]
                    c = catmull_rom(P, alpha=alpha, ends="reflect")
                    tb = self.ok("to_bezier", {"curve": c})["curve"]
                    breaks = tb["breaks"]
                    self.assertEqual(len(tb["segments"]), N - 1)
                    lo, hi = breaks[0], breaks[-1]
                    self.assertEqual(lo, 0)
                    ts = breaks + [rng.uniform(lo, hi) for _ in range(8)]
                    r = self.ok("eval", {"curve": c, "t": ts, "derivatives": 1})
                    scale = max(abs(x) for p in P for x in p)
                    shortest = min(b - a for a, b in zip(breaks, breaks[1:]))
                    E = reflected(P)
                    for j, t in enumerate(ts):
                        want = catmull_rom_oracle(E, alpha, False, t, 1)
                        for k in range(2):
                            got = r["points"][j] if k == 0 else r["derivatives"][0][j]
                            tol = 1e-12 * scale * (1 + 1 / shortest) ** k
                            for a, b in zip(got, want[k]):
                                self.assertLessEqual(abs(a - b), tol, f"alpha={alpha} N={N} P={P} t={t} k={k}")

    def test_runs_through_every_point(self):
        # The breaks are the points' parameters: the curve is at points[j] there, exactly
        # (the Bézier pieces' end points are the points).
        P = [[0, 0], [1, 2], [3, 3], [4, 1], [6, 0], [7, 2], [8, 5], [9, 4]]  # a robot path through 8 waypoints
        for alpha in (0, 0.5, 1):
            c = catmull_rom(P, alpha=alpha, ends="reflect")
            breaks = self.ok("to_bezier", {"curve": c})["curve"]["breaks"]
            self.assertEqual(len(breaks), len(P))
            pts = self.ok("eval", {"curve": c, "t": breaks})["points"]
            self.assertEqual(pts, [[float(x) for x in p] for p in P])
            # The knot intervals are |P_(i+1) - P_i|^alpha (the phantoms' intervals repeat
            # the end ones and do not show in the domain).
            want = [0.0]
            for a, b in zip(P, P[1:]):
                want.append(want[-1] + (math.dist(a, b) ** alpha if alpha else 1.0))
            for a, b in zip(breaks, want):
                self.assertAlmostEqual(a, b, delta=1e-14 * want[-1])
        # The default (and "inner") is the contract's curve from points[1] to points[N-2].
        inner = self.ok("eval", {"curve": catmull_rom(P, ends="inner"), "t": [0]})["points"][0]
        self.assertEqual(inner, [1, 2])
        self.assertEqual(self.ok("eval", {"curve": catmull_rom(P), "t": [0]})["points"][0], [1, 2])

    def test_two_points_give_the_segment(self):
        # Phantoms 2 P_0 - P_1 and 2 P_1 - P_0 on the line: the curve is the segment, at
        # constant speed for alpha 0 (the tangents are P_1 - P_0 at both ends).
        P = [[1, 1], [4, 5]]
        r = self.ok("eval", {"curve": catmull_rom(P, alpha=0, ends="reflect"), "t": [0, 0.25, 0.5, 1], "derivatives": 1})
        for t, p, v in zip([0, 0.25, 0.5, 1], r["points"], r["derivatives"][0]):
            self.assertAlmostEqual(p[0], 1 + 3 * t, delta=1e-15)
            self.assertAlmostEqual(p[1], 1 + 4 * t, delta=1e-15)
            self.assertAlmostEqual(v[0], 3, delta=1e-14)
            self.assertAlmostEqual(v[1], 4, delta=1e-14)

    def test_errors(self):
        P = [[0, 0], [1, 1], [2, 0], [3, 1]]
        self.bad("eval", {"curve": catmull_rom(P, closed=True, ends="reflect"), "t": [0]}, "curve.ends", contains="open")
        self.bad("eval", {"curve": catmull_rom(P, closed=True, ends="inner"), "t": [0]}, "curve.ends", contains="open")
        self.bad("eval", {"curve": catmull_rom(P, ends="mirror"), "t": [0]}, "curve.ends", contains="reflect")
        self.bad("eval", {"curve": catmull_rom(P, ends=1), "t": [0]}, "curve.ends")
        self.bad("eval", {"curve": catmull_rom(P[:1], ends="reflect"), "t": [0]}, "curve.points", contains="at least 2")
        self.bad("eval", {"curve": catmull_rom(P[:3], ends="inner"), "t": [0]}, "curve.points", contains="at least 4")
        self.bad("eval", {"curve": catmull_rom([[0, 0], [0, 0], [1, 1]], ends="reflect"), "t": [0]}, "curve.points[1]",
                 contains="equals points[0]")
        self.bad("eval", {"curve": catmull_rom([[0, 0], [1, 1], [1, 1]], ends="reflect"), "t": [0]}, "curve.points[2]",
                 contains="equals points[1]")
        # A phantom point beyond the largest double is refused naming the points.
        self.bad("eval", {"curve": catmull_rom([[1.5e308], [-1e308], [0]], ends="reflect", alpha=0), "t": [0]}, "curve.points",
                 contains="phantom")

if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
