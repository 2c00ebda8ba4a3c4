#!/usr/bin/python3
"""Black-box tests of the operations of issue 20: `solve` (parameters where a coordinate or
a . C(t) takes a value) and `refine` (many knots inserted at once).

Oracles at test time, never the program: exact rationals (fractions) for Bernstein
coefficients and polynomials built to have a known (double) root; mpmath.polyroots at 50
digits on the exact power form of the numerator; scipy.interpolate.PPoly.from_spline for
the roots of random B-splines; scipy.interpolate.BSpline and FITPACK's insert for
refinement. Every bad-input rule of docs/cli.md for both commands.

Usage: test_ops.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import time
import unittest
from fractions import Fraction
from math import comb

import mpmath
import numpy as np
from scipy.interpolate import BSpline, PPoly, insert

import test_cli
from test_bspline import random_spline
from test_cli import CliTest


# ---------------------------------------------------------------------------------------
# Independent helpers.

def bernstein_from_power(a):
    """Bernstein coefficients (exact Fractions) of sum a_k t^k of degree n = len(a) - 1:
    b_i = sum_{k <= i} C(i, k) / C(n, k) a_k [Farin02, 5.6]."""
    n = len(a) - 1
    return [sum(Fraction(comb(i, k), comb(n, k)) * a[k] for k in range(i + 1)) for i in range(n + 1)]


def power_from_bernstein(b):
    """Power coefficients (exact Fractions) of sum b_i B_(i,n)(t)."""
    n = len(b) - 1
    a = [Fraction(0)] * (n + 1)
    for i, bi in enumerate(b):
        # B_(i,n) = C(n,i) t^i (1-t)^(n-i) = C(n,i) sum_j C(n-i,j) (-1)^j t^(i+j)
        for j in range(n - i + 1):
            a[i + j] += Fraction(bi) * comb(n, i) * comb(n - i, j) * (-1) ** j
    return a


def poly_mul(p, q):
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, x in enumerate(p):
        for j, y in enumerate(q):
            out[i + j] += x * y
    return out


def real_roots_01(a, merge=1e-8):
    """Distinct real roots in [0, 1] of the exact power form a (mpmath at 50 digits);
    roots within `merge` are one (a multiple root's images)."""
    while len(a) > 1 and a[-1] == 0:
        a = a[:-1]
    if len(a) < 2:
        return []
    mpmath.mp.dps = 50
    coeffs = [mpmath.mpf(x.numerator) / x.denominator for x in reversed(a)]
    roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=400)
    out = []
    for r in roots:
        r = mpmath.mpc(r)
        # Imaginary parts of a real multiple root's images are about 1e-25^(1/m).
        if abs(r.imag) < 1e-12 and -1e-12 <= r.real <= 1 + 1e-12:
            out.append(min(1.0, max(0.0, float(r.real))))
    out.sort()
    merged = []
    for r in out:
        if not merged or r - merged[-1] > merge:
            merged.append(r)
    return merged


def bezier(points):
    return {"type": "bezier", "points": points}


def bspline(U, P, p):
    return {"type": "bspline", "degree": p, "knots": U, "points": P}


# The circle of radius 1 about the origin as the NURBS Book's nine-point construction
# [PT97, ex. 7.2]: four quadratic quarter arcs, a quarter per parameter interval of 1/4.
S2 = 2 ** -0.5
CIRCLE = {"type": "nurbs", "degree": 2,
          "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
          "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]],
          "weights": [1, S2, 1, S2, 1, S2, 1, S2, 1]}


class SolveTest(CliTest):
    def solve(self, curve, value, **extra):
        return self.ok("solve", dict({"curve": curve, "value": value}, **extra))

    def test_exact_double_root_once(self):
        # y(t) = 12 (t - 3/8)^2 (t - 13/16): dyadic roots and a factor that clears the
        # thirds, so the Bernstein coefficients are exact doubles and the double root exact.
        r, s = Fraction(3, 8), Fraction(13, 16)
        y = [12 * c for c in poly_mul(poly_mul([-r, 1], [-r, 1]), [-s, 1])]
        b = bernstein_from_power(y)
        self.assertTrue(all(float(x) == x for x in b))
        P = [[i / 3, float(bi)] for i, bi in enumerate(b)]  # x(t) = t
        got = self.solve(bezier(P), 0, axis=1)
        self.assertEqual(got["intervals"], [])
        # Simple root: a few eps; the double root, found as the derivative's simple root:
        # a few eps too (exact data).
        self.assert_close(got["t"], [0.375, 0.8125], 1e-14)

    def test_rounded_tangency_not_lost(self):
        # The same with roots that are not doubles (1/3 double, s simple): the rounded
        # coefficients need not touch zero, yet the tangency must be reported, once.
        rng = random.Random(20)
        for _ in range(20):
            r = Fraction(rng.randint(1, 999), 1000)
            s = Fraction(rng.randint(1, 999), 1000)
            if abs(r - s) < Fraction(1, 20):
                continue
            y = poly_mul(poly_mul([-r, 1], [-r, 1]), [-s, 1])
            b = [float(x) for x in bernstein_from_power(y)]
            P = [[i / 3, bi] for i, bi in enumerate(b)]
            got = self.solve(bezier(P), 0, axis=1)["t"]
            # A double root under rounding of relative size eps moves by about sqrt(eps)
            # (1.5e-8) times the conditioning: 1e-6 leaves room for the cubic factor.
            self.assertEqual(len(got), 2, f"r={r} s={s}: {got}")
            self.assert_close(sorted(got), sorted([float(r), float(s)]), 1e-6, f"r={r} s={s}")

    def test_random_polynomials_against_mpmath(self):
        rng = random.Random(7)
        cases = []  # (trial, b, d, the roots, the request)
        for trial in range(40):
            n = rng.randint(1, 9)
            b = [rng.uniform(-1, 1) for _ in range(n + 1)]
            d = rng.uniform(-2, 2)
            P = [[bi, rng.uniform(-1, 1)] for bi in b]
            # direction (1, 0): the x coordinate; direction (2, 0) too (scale-free).
            want = real_roots_01([x - (Fraction(d) if k == 0 else 0)
                                  for k, x in enumerate(power_from_bernstein([Fraction(bi) for bi in b]))])
            for extra in ({"axis": 0}, {"direction": [2, 0]}):
                value = d if "axis" in extra else 2 * d
                cases.append((trial, b, d, want, dict({"curve": bezier(P), "value": value}, **extra)))
        # The 80 requests through one --jsonl process (only the responses are checked).
        for (trial, b, d, want, _), got in zip(cases, self.ok_jsonl("solve", [c[-1] for c in cases])):
            self.assertEqual(got["intervals"], [])
            # Random data: simple, well separated roots; 1e-9 allows a condition number
            # of 1e6 on the few eps of the solver.
            self.assertEqual(len(got["t"]), len(want), f"trial {trial} {b} d={d}: {got} vs {want}")
            self.assert_close(got["t"], want, 1e-9, f"trial {trial}")

    def test_rational_against_mpmath(self):
        rng = random.Random(11)
        for trial in range(30):
            n = rng.randint(1, 6)
            P = [[rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)] for _ in range(n + 1)]
            w = [rng.uniform(0.2, 5) for _ in range(n + 1)]
            a = [rng.uniform(-1, 1) for _ in range(3)]
            v = rng.uniform(-0.5, 0.5)
            # numerator sum_i w_i (a . P_i - v) B_i: exact in Fractions from the doubles.
            num = [Fraction(wi) * (sum(Fraction(ak) * Fraction(pk) for ak, pk in zip(a, Pi)) - Fraction(v))
                   for wi, Pi in zip(w, P)]
            want = real_roots_01(power_from_bernstein(num))
            got = self.solve({"type": "rational_bezier", "points": P, "weights": w}, v, direction=a)
            self.assertEqual(len(got["t"]), len(want), f"trial {trial}: {got} vs {want}")
            self.assert_close(got["t"], want, 1e-9, f"trial {trial}")  # as above

    def test_random_bsplines_against_scipy(self):
        rng = random.Random(3)
        for trial in range(30):
            p = rng.randint(1, 5)
            U, P = random_spline(rng, p, 1, trial % 2 == 0, trial % 3 == 0)
            lo, hi = U[p], U[len(P)]
            v = rng.uniform(-0.5, 0.5)
            spl = BSpline(np.array(U, float), np.array([q[0] for q in P], float), p)
            pp = PPoly.from_spline(spl, extrapolate=False)
            roots = [float(r) for r in pp.solve(v, discontinuity=False) if lo <= r <= hi]
            want = []
            for r in sorted(roots):  # PPoly reports a root at a breakpoint from both sides
                if not want or r - want[-1] > 1e-9:
                    want.append(r)
            got = self.solve(bspline(U, P, p), v, axis=0)
            self.assertEqual(got["intervals"], [])
            self.assertEqual(len(got["t"]), len(want), f"trial {trial} p={p} U={U}: {got} vs {want}")
            # random knots: pieces of width >= ~1e-3, conditioning of random data: 1e-8.
            self.assert_close(got["t"], want, 1e-8, f"trial {trial}")

    def test_circle_joints_and_tangencies(self):
        # x = 0 at the quarter breaks 1/4 and 3/4 (where two pieces meet: once each);
        # x = -1 touches at the break 1/2 (a tangency at a joint); x = 1 at both ends.
        self.assertEqual(self.solve(CIRCLE, 0, axis=0), {"t": [0.25, 0.75], "intervals": []})
        self.assertEqual(self.solve(CIRCLE, -1, axis=0), {"t": [0.5], "intervals": []})
        self.assertEqual(self.solve(CIRCLE, 1, axis=0), {"t": [0, 1], "intervals": []})
        self.assertEqual(self.solve(CIRCLE, 2, axis=0), {"t": [], "intervals": []})
        # y = x (direction (1, -1), value 0) at 45 and 225 degrees: inside the first and
        # third quarter, at the parameter where the rational quadratic has u = 1/2 (the
        # arc's symmetric point), i.e. 1/8 and 5/8.
        got = self.solve(CIRCLE, 0, direction=[1, -1])
        self.assert_close(got["t"], [0.125, 0.625], 1e-15)  # a simple root: a few eps

    def test_intervals(self):
        # polyline: point i at parameter i.
        poly = {"type": "polyline", "points": [[0, 0], [1, 0], [2, 1], [3, 0], [4, 0], [5, 0]]}
        self.assertEqual(self.solve(poly, 0, axis=1), {"t": [], "intervals": [[0, 1], [3, 5]]})
        self.assertEqual(self.solve(poly, 0.5, axis=1), {"t": [1.5, 2.5], "intervals": []})
        self.assertEqual(self.solve(poly, 1, axis=1), {"t": [2], "intervals": []})
        # x = value crosses each piece once; at a vertex once.
        self.assertEqual(self.solve(poly, 3, axis=0), {"t": [3], "intervals": []})
        # a whole Bezier on the level (y constant), and a degenerate point curve.
        self.assertEqual(self.solve(bezier([[0, 2], [1, 2], [3, 2]]), 2, axis=1), {"t": [], "intervals": [[0, 1]]})
        self.assertEqual(self.solve(bezier([[1, 1]]), 1, axis=0), {"t": [], "intervals": [[0, 1]]})
        # a path: a straight segment on the level between two curved ones, breaks 0, 1, 2, 3.
        path = {"type": "path", "segments": [bezier([[0, 1], [1, -1], [2, 0]]), bezier([[2, 0], [3, 0]]),
                                             bezier([[3, 0], [4, 0], [5, 1]])]}
        got = self.solve(path, 0, axis=1)
        # first segment: y = (1-u)^2 - 2u(1-u) = 3u^2 - 4u + 1 = (3u - 1)(u - 1): u = 1/3
        # (and u = 1, the interval's end); third: y = u^2, zero only at its start.
        self.assertEqual(got["intervals"], [[1, 2]])
        self.assert_close(got["t"], [1 / 3], 1e-15)

    def test_crossing_at_a_break_found_once(self):
        for ys in ([-1, 0, 1], [1, 0, -1], [1, 0, 1]):
            poly = {"type": "polyline", "points": [[0, ys[0]], [1, ys[1]], [2, ys[2]]]}
            self.assertEqual(self.solve(poly, 0, axis=1), {"t": [1], "intervals": []}, ys)

    def test_dimensions_1_to_4(self):
        for d in range(1, 5):
            P = [[float(i + k) for k in range(d)] for i in range(3)]  # x_k(t) = k + 2 t
            for k in range(d):
                got = self.solve(bezier(P), k + 1, axis=k)
                self.assertEqual(got, {"t": [0.5], "intervals": []})

    def test_level_near_large_coordinates(self):
        # Audit D20. y - value has the exact control values [-1, 1, 1, -1] (every coordinate
        # and difference is a double): y = -1 + 6t - 6t^2 (+ 1e13), roots (3 -+ sqrt 3) / 6,
        # not the whole curve.
        r3 = [(3 - 3 ** 0.5) / 6, (3 + 3 ** 0.5) / 6]
        big = 10 ** 13
        got = self.solve(bezier([[0, big], [1, big + 2], [3, big + 2], [4, big]]), big + 1, axis=1)
        self.assertEqual(got["intervals"], [])
        self.assert_close(got["t"], r3, 1e-15)
        got = self.solve(bezier([[big, 0], [big + 1, 1], [big + 1, 2], [big, 3]]), big + 0.5, axis=0)
        self.assertEqual(got["intervals"], [])
        self.assert_close(got["t"], r3, 1e-15)
        # 1-D at 1: [1, 1 + 2e-13, 1 + 2e-13, 1] at 1 + 1e-13 (as doubles: the oracle takes
        # the doubles' exact values). No root at 1/2, where the curve is 1 + 1.5e-13.
        P = [1.0, 1.0000000000002, 1.0000000000002, 1.0]
        v = 1.0000000000001
        want = real_roots_01(power_from_bernstein([Fraction(x) - Fraction(v) for x in P]))
        got = self.solve(bezier([[x] for x in P]), v, axis=0)
        self.assertEqual(got["intervals"], [])
        self.assertEqual(len(got["t"]), 2)
        self.assert_close(got["t"], want, 1e-12)
        # The curve on the level exactly at that scale is an interval still.
        self.assertEqual(self.solve(bezier([[0, big + 1], [1, big + 1], [2, big + 1]]), big + 1, axis=1),
                         {"t": [], "intervals": [[0, 1]]})

    def test_level_offsets_against_exact_roots(self):
        # Property: control values K + k_i h and value K + r h, with K a double of magnitude
        # 2^E (E from -30 to 60), h = 2^(E - 46) (so k_i h is 1e-14 of K and every
        # coordinate and difference is exact), k_i small integers, r a quarter: the roots are
        # those of sum (k_i - r) B_i, exact rationals, by mpmath. Tangencies occur (integer
        # data), and an all-equal case is the interval [0, 1].
        rng = random.Random(2020)
        cases = []
        for trial in range(60):
            n = rng.randint(1, 6)
            E = rng.randint(-30, 60)
            K = (rng.randint(2 ** 40, 2 ** 41 - 1)) * 2.0 ** (E - 40)
            h = 2.0 ** (E - 46)
            k = [rng.randint(-3, 3) for _ in range(n + 1)]
            r = Fraction(rng.randint(-8, 8), 4)
            if trial % 15 == 0:
                k, r = [2] * (n + 1), Fraction(2)
            ys = [K + ki * h for ki in k]
            value = K + float(r) * h
            assert all(Fraction(y) == Fraction(K) + ki * Fraction(h) for y, ki in zip(ys, k))
            assert Fraction(value) == Fraction(K) + r * Fraction(h)
            dim1 = trial % 2 == 0
            P = [[y] for y in ys] if dim1 else [[i / n, y] for i, y in enumerate(ys)]
            coeffs = [Fraction(ki) - r for ki in k]
            cases.append((trial, k, r, coeffs, {"curve": bezier(P), "value": value, "axis": 0 if dim1 else 1}))
        for (trial, k, r, coeffs, _), got in zip(cases, self.ok_jsonl("solve", [c[-1] for c in cases])):
            if all(c == 0 for c in coeffs):
                self.assertEqual(got, {"t": [], "intervals": [[0, 1]]}, f"trial {trial}")
                continue
            want = real_roots_01(power_from_bernstein(coeffs))
            self.assertEqual(got["intervals"], [], f"trial {trial} k={k} r={r}")
            self.assertEqual(len(got["t"]), len(want), f"trial {trial} k={k} r={r}: {got} vs {want}")
            # exact data: simple roots to a few eps times their conditioning; a multiple
            # root as its derivative's simple root
            self.assert_close(got["t"], want, 1e-8, f"trial {trial} k={k} r={r}")

    def test_degree_1000_and_extreme_scales(self):
        # y = t - 0.3 elevated to degree 1000 (c_i = i / 1000 - 0.3), scaled by 2^k: the one
        # root 0.3 at every scale (the coefficients are the doubles nearest i/1000 - 0.3:
        # the root moves by their rounding, a few eps).
        n = 1000
        for scale in (1.0, 2.0 ** 600, 2.0 ** -600):
            P = [[i / n, (i / n - 0.3) * scale] for i in range(n + 1)]
            got = self.solve(bezier(P), 0, axis=1)
            self.assertEqual(got["intervals"], [])
            self.assert_close(got["t"], [0.3], 1e-13, f"scale {scale}")

    def test_bad_input(self):
        c = bezier([[0, 0], [1, 2], [2, 0]])
        self.bad("solve", {"curve": c, "value": 1}, "axis", contains="axis")
        self.bad("solve", {"curve": c, "value": 1, "axis": 0, "direction": [1, 0]}, "direction", contains="not both")
        self.bad("solve", {"curve": c, "value": 1, "axis": 2}, "axis", contains="0..1")
        self.bad("solve", {"curve": c, "value": 1, "axis": -1}, "axis", contains="0..1")
        self.bad("solve", {"curve": c, "value": 1, "axis": 0.5}, "axis")
        self.bad("solve", {"curve": c, "value": 1, "direction": [1, 0, 0]}, "direction", contains="2 coordinates")
        self.bad("solve", {"curve": c, "value": 1, "direction": [0, 0]}, "direction", contains="zero")
        self.bad("solve", {"curve": c, "value": 1, "direction": [1, "a"]}, "direction[1]")
        self.bad("solve", {"curve": c, "axis": 0}, "value", contains="missing")
        self.bad("solve", {"curve": c, "axis": 0, "value": "x"}, "value")
        self.bad("solve", {"curve": c, "axis": 0, "value": 1, "values": 2}, "values")
        self.bad("solve", {"axis": 0, "value": 1}, "curve", contains="missing")


# ---------------------------------------------------------------------------------------
# solve on the types whose pieces are computed (session 18): exact pieces in Fractions
# from each type's own definition, written here, never the program's pieces.

def blossom_exact(U, p, P, s, args):
    """The blossom of span s (U_s < U_(s+1)) of the B-spline of degree p on knots U and
    points P (lists of Fractions) at args: de Boor's triangle in exact arithmetic."""
    d = [list(P[j]) for j in range(s - p, s + 1)]
    for r in range(1, p + 1):
        x = args[r - 1]
        for j in range(p, r - 1, -1):
            i = s - p + j
            a = (x - U[i]) / (U[i + p + 1 - r] - U[i])
            d[j] = [(1 - a) * u + a * v for u, v in zip(d[j - 1], d[j])]
    return d[p]


def nurbs_exact_pieces(U, p, P, w):
    """[(lo, hi, homogeneous Bézier points (w q, w))] of a NURBS, exact (the blossoms of
    the homogeneous points w_j P_j, as Fractions of the given doubles)."""
    Uf = [Fraction(x) for x in U]
    H = [[Fraction(x) * Fraction(wi) for x in q] + [Fraction(wi)] for q, wi in zip(P, w)]
    out = []
    for s in range(p, len(P)):
        if Uf[s] < Uf[s + 1]:
            a, b = Uf[s], Uf[s + 1]
            out.append((a, b, [blossom_exact(Uf, p, H, s, [a] * (p - j) + [b] * j) for j in range(p + 1)]))
    return out


def hermite_exact_pieces(u, P, m):
    """The cubic Hermite pieces P_i, P_i + h m_i / 3, P_(i+1) - h m_(i+1) / 3, P_(i+1),
    h = u_(i+1) - u_i, exact, weight 1."""
    out = []
    for i in range(len(u) - 1):
        h = Fraction(u[i + 1]) - Fraction(u[i])
        a = [Fraction(x) for x in P[i]]
        b = [Fraction(x) for x in P[i + 1]]
        c1 = [x + h * Fraction(t) / 3 for x, t in zip(a, m[i])]
        c2 = [x - h * Fraction(t) / 3 for x, t in zip(b, m[i + 1])]
        out.append((Fraction(u[i]), Fraction(u[i + 1]), [q + [Fraction(1)] for q in (a, c1, c2, b)]))
    return out


def natural_spline_tangents(u, P):
    """The natural cubic spline's first derivatives at the params, exact: the tridiagonal
    system h_i m_(i-1) + 2 (h_(i-1) + h_i) m_i + h_(i-1) m_(i+1) = 3 (h_i d_(i-1) +
    h_(i-1) d_i) with 2 m_0 + m_1 = 3 d_0 and m_(n-1) + 2 m_n = 3 d_(n-1) (second
    derivative 0 at the ends), by elimination in Fractions."""
    n = len(u) - 1
    uf = [Fraction(x) for x in u]
    h = [uf[i + 1] - uf[i] for i in range(n)]
    dim = len(P[0])
    out = [[None] * dim for _ in range(n + 1)]
    for k in range(dim):
        y = [Fraction(q[k]) for q in P]
        d = [(y[i + 1] - y[i]) / h[i] for i in range(n)]
        A = [[Fraction(0)] * (n + 1) for _ in range(n + 1)]
        r = [Fraction(0)] * (n + 1)
        A[0][0], A[0][1], r[0] = 2, 1, 3 * d[0]
        A[n][n - 1], A[n][n], r[n] = 1, 2, 3 * d[n - 1]
        for i in range(1, n):
            A[i][i - 1], A[i][i], A[i][i + 1] = h[i], 2 * (h[i - 1] + h[i]), h[i - 1]
            r[i] = 3 * (h[i] * d[i - 1] + h[i - 1] * d[i])
        for c in range(n + 1):
            for rr in range(c + 1, n + 1):
                if A[rr][c] != 0:
                    f = A[rr][c] / A[c][c]
                    A[rr] = [x - f * z for x, z in zip(A[rr], A[c])]
                    r[rr] -= f * r[c]
        m = [Fraction(0)] * (n + 1)
        for i in range(n, -1, -1):
            m[i] = (r[i] - sum(A[i][j] * m[j] for j in range(i + 1, n + 1))) / A[i][i]
        for i in range(n + 1):
            out[i][k] = m[i]
    return out


def catmull_rom_exact_pieces(P):
    """The uniform (alpha 0) open Catmull-Rom curve: tangents (P_(i+1) - P_(i-1)) / 2,
    segment j from P_(j+1) to P_(j+2) on [j, j + 1]."""
    Q = [[Fraction(x) for x in q] for q in P]
    m = {i: [(x - y) / 2 for x, y in zip(Q[i + 1], Q[i - 1])] for i in range(1, len(Q) - 1)}
    return [(Fraction(j), Fraction(j + 1), [Q[j + 1] + [1], [x + t / 3 for x, t in zip(Q[j + 1], m[j + 1])] + [1],
                                             [x - t / 3 for x, t in zip(Q[j + 2], m[j + 2])] + [1], Q[j + 2] + [1]])
            for j in range(len(Q) - 3)]


def lagrange_exact_pieces(u, P):
    """The interpolating polynomial's Bernstein coefficients on [min u, max u], exact: the
    collocation system at the nodes solved in Fractions."""
    n = len(u) - 1
    lo, hi = Fraction(min(u)), Fraction(max(u))
    s = [(Fraction(x) - lo) / (hi - lo) for x in u]
    rows = [[comb(n, k) * si ** k * (1 - si) ** (n - k) for k in range(n + 1)] + [Fraction(q[c]) for c in range(len(P[0]))]
            for si, q in zip(s, P)]
    for c in range(n + 1):
        piv = next(r for r in range(c, n + 1) if rows[r][c] != 0)
        rows[c], rows[piv] = rows[piv], rows[c]
        for r in range(n + 1):
            if r != c and rows[r][c] != 0:
                f = rows[r][c] / rows[c][c]
                rows[r] = [x - f * z for x, z in zip(rows[r], rows[c])]
    b = [[x / rows[i][i] for x in rows[i][n + 1:]] + [Fraction(1)] for i in range(n + 1)]
    return [(lo, hi, b)]


def onto(pieces, lo, hi):
    """Pieces on their own domain mapped affinely onto [lo, hi] (a path's segment)."""
    a, b = pieces[0][0], pieces[-1][1]
    f = lambda x: lo + (x - a) * (hi - lo) / (b - a)
    return [(f(x), f(y), H) for x, y, H in pieces]


def exact_level_set(pieces, direction, value):
    """(roots, intervals) of a . C = value on exact pieces [(lo, hi, homogeneous points)]:
    on each piece the numerator sum_k a_k H_k - value w in Bernstein form, its real roots
    by mpmath on the exact power form; a piece where it vanishes identically is an
    interval. Roots within 1e-9 are one (a break seen from both sides, a multiple root)."""
    v = Fraction(value)
    a = [Fraction(x) for x in direction]
    roots, intervals = [], []
    for lo, hi, H in pieces:
        f = [sum(ak * h[k] for k, ak in enumerate(a)) - v * h[-1] for h in H]
        if all(x == 0 for x in f):
            if intervals and intervals[-1][1] == lo:
                intervals[-1][1] = hi
            else:
                intervals.append([lo, hi])
            continue
        for t in real_roots_01(power_from_bernstein(f)):
            roots.append(float(lo + Fraction(t) * (hi - lo)))
    roots.sort()
    out = []
    for r in roots:
        if any(float(x) - 1e-9 <= r <= float(y) + 1e-9 for x, y in intervals):
            continue
        if not out or r - out[-1] > 1e-9:
            out.append(r)
    return out, [[float(x), float(y)] for x, y in intervals]


def scales():
    """(K, h): K at 1, 1e6 and 1e13 and h = 2^(floor(log2 K) - 30), so that every K + k h
    (k a small integer) is a double and the curve's variation is 1e-9 of K."""
    return [(K, 2.0 ** (math.frexp(K)[1] - 31)) for K in (1.0, 1e6, 1e13)]


class SolveComputedPiecesTest(CliTest):
    """Curves whose pieces are computed (nurbs and the shorthands, hermite, cubic_spline,
    catmull_rom, lagrange, paths of them) against exact roots of their definitions at
    scales 1, 1e6 and 1e13: the noise bound per type (docs/cli.md) must be true (no root
    lost at a tangency, a flat stretch still an interval) and tight (a level 1e-13 of the
    coordinates away is resolved: roots, not an interval)."""

    def check(self, cases):
        answers = self.ok_jsonl("solve", [c[-1] for c in cases])
        for (name, pieces, tol, req), got in zip(cases, answers):
            a = req.get("direction") or [1.0 if k == req["axis"] else 0.0 for k in range(len(pieces[0][2][0]) - 1)]
            want, intervals = exact_level_set(pieces, a, req["value"])
            self.assertEqual(len(got["intervals"]), len(intervals), f"{name}: {got} vs {want} {intervals}")
            for g, w in zip(got["intervals"], intervals):
                self.assertAlmostEqual(g[0], w[0], delta=1e-12, msg=name)
                # an interval before a break ends there (no jump in these curves)
                self.assertAlmostEqual(g[1], w[1], delta=1e-12, msg=name)
            self.assertEqual(len(got["t"]), len(want), f"{name}: {got} vs {want} {intervals}")
            self.assert_close(got["t"], want, tol, name)

    def random_cases(self, rng, K, h):
        """Random curves of every computed type with data K + k h (k integers in [-3, 3]),
        values K + r h (r a quarter): the pieces' rounding is about 1e-7 of the variation."""
        level = lambda: K + rng.randint(-12, 12) / 4 * h
        val = lambda: K + rng.randint(-3, 3) * h
        cases = []
        for trial in range(4):
            # NURBS: dyadic and decimal knots, weights with and without exact quotients.
            p = rng.randint(1, 3)
            n = p + 1 + rng.randint(0, 3)
            inner = sorted(rng.sample([0.125, 0.25, 0.3, 0.5, 0.6, 0.75, 0.9], n - p - 1))
            U = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
            P = [[i / n, val()] for i in range(n)]
            w = [rng.choice([0.5, 1.0, 2.0, 0.75, 1.5, 0.3]) for _ in range(n)]
            v = level()
            cases.append((f"nurbs {trial} K={K}", nurbs_exact_pieces(U, p, P, w), 1e-5,
                          {"curve": {"type": "nurbs", "degree": p, "knots": U, "points": P, "weights": w}, "value": v, "axis": 1}))
            # Hermite and the natural cubic spline on uneven params.
            m = rng.randint(2, 5)
            u = [0.0]
            for _ in range(m):
                u.append(u[-1] + rng.choice([0.5, 1.0, 1.5, 0.3]))
            P1 = [[val()] for _ in u]
            T = [[rng.randint(-6, 6) * h] for _ in u]
            cases.append((f"hermite {trial} K={K}", hermite_exact_pieces(u, P1, T), 1e-5,
                          {"curve": {"type": "hermite", "params": u, "points": P1, "tangents": T}, "value": v, "axis": 0}))
            cases.append((f"cubic_spline {trial} K={K}", hermite_exact_pieces(u, P1, natural_spline_tangents(u, P1)), 1e-5,
                          {"curve": {"type": "cubic_spline", "params": u, "points": P1}, "value": v, "axis": 0}))
            # Catmull-Rom (uniform), Lagrange on equispaced params.
            P2 = [[float(i), val()] for i in range(rng.randint(4, 7))]
            cases.append((f"catmull_rom {trial} K={K}", catmull_rom_exact_pieces(P2), 1e-5,
                          {"curve": {"type": "catmull_rom", "points": P2, "alpha": 0}, "value": v, "axis": 1}))
            ul = [float(j) for j in range(rng.randint(2, 5))]
            P3 = [[val()] for _ in ul]
            cases.append((f"lagrange {trial} K={K}", lagrange_exact_pieces(ul, P3), 1e-4,
                          {"curve": {"type": "lagrange", "params": ul, "points": P3}, "value": v, "axis": 0}))
            # A path: a Hermite segment then a NURBS segment (1-D), on [0, 1] and [1, 2].
            if P1[-1][0] == P1[-1][0]:
                nurbs1 = {"type": "nurbs", "degree": p, "knots": U, "points": [[P1[-1][0]]] + [[q[1]] for q in P[1:]], "weights": w}
                pieces = onto(hermite_exact_pieces(u, P1, T), 0, 1) + onto(
                    nurbs_exact_pieces(U, p, nurbs1["points"], w), 1, 2)
                cases.append((f"path {trial} K={K}", pieces, 1e-5,
                              {"curve": {"type": "path", "segments": [
                                  {"type": "hermite", "params": u, "points": P1, "tangents": T}, nurbs1]},
                               "value": v, "axis": 0}))
        return cases

    def test_random_curves_of_each_type_at_three_scales(self):
        rng = random.Random(1818)
        cases = []
        for K, h in scales():
            cases += self.random_cases(rng, K, h)
        self.check(cases)

    def test_tangencies_and_intervals_of_each_type(self):
        cases = []
        for K, h in scales():
            # NURBS of degree 2, weights 1, 2, 1/2, 1, 3/4, 3/2: y touches K - h at the knot
            # 1/4 (both pieces' numerators vanish doubly there) and is K + h on [3/4, 1].
            U = [0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1]
            ys = [K + h, K - h, K - h, K + h, K + h, K + h]
            w = [1, 2, 0.5, 1, 0.75, 1.5]
            P = [[i / 5, y] for i, y in enumerate(ys)]
            c = {"type": "nurbs", "degree": 2, "knots": U, "points": P, "weights": w}
            for v in (K - h, K + h, K):
                cases.append((f"nurbs tangency K={K} v={v}", nurbs_exact_pieces(U, 2, P, w), 1e-5, {"curve": c, "value": v, "axis": 1}))
            # Hermite: a maximum K + h at u = 1 (tangent 0), flat at K + 2 h on [2, 3].
            u, P1, T = [0, 1, 2, 3, 4], [[K], [K + h], [K + 2 * h], [K + 2 * h], [K]], [[h], [0], [0], [0], [-h]]
            for v in (K + h, K + 2 * h):
                cases.append((f"hermite K={K} v={v}", hermite_exact_pieces(u, P1, T), 1e-5,
                              {"curve": {"type": "hermite", "params": u, "points": P1, "tangents": T}, "value": v, "axis": 0}))
            # Natural splines: symmetric data peak at the middle param (a double root there);
            # constant data are one interval.
            u, P1 = [0, 1, 2], [[K], [K + h], [K]]
            cases.append((f"cubic_spline peak K={K}", hermite_exact_pieces(u, P1, natural_spline_tangents(u, P1)), 1e-5,
                          {"curve": {"type": "cubic_spline", "params": u, "points": P1}, "value": K + h, "axis": 0}))
            P1 = [[K + h]] * 4
            cases.append((f"cubic_spline flat K={K}", hermite_exact_pieces([0, 1, 2, 3], P1, [[0]] * 4), 1e-5,
                          {"curve": {"type": "cubic_spline", "params": [0, 1, 2, 3], "points": P1}, "value": K + h, "axis": 0}))
            # Catmull-Rom: a peak at a joint (tangent 0) and a flat segment.
            P2 = [[0, K - h], [1, K], [2, K + h], [3, K], [4, K - h]]
            cases.append((f"catmull_rom peak K={K}", catmull_rom_exact_pieces(P2), 1e-5,
                          {"curve": {"type": "catmull_rom", "points": P2, "alpha": 0}, "value": K + h, "axis": 1}))
            P2 = [[0, K], [1, K + h], [2, K + h], [3, K + h], [4, K + h], [5, K]]
            cases.append((f"catmull_rom flat K={K}", catmull_rom_exact_pieces(P2), 1e-5,
                          {"curve": {"type": "catmull_rom", "points": P2, "alpha": 0}, "value": K + h, "axis": 1}))
            # Lagrange: the parabola through K, K + h, K peaks at its middle param; equal
            # points are an interval.
            for pts in ([[K], [K + h], [K]], [[K + h]] * 3):
                cases.append((f"lagrange {pts} K={K}", lagrange_exact_pieces([0, 1, 2], pts), 1e-4,
                              {"curve": {"type": "lagrange", "params": [0, 1, 2], "points": pts}, "value": K + h, "axis": 0}))
        self.check(cases)

    def test_levels_within_1e13_of_the_coordinates(self):
        # The audit's case for every computed type: data 1e13 + k (1e-13 of the coordinates),
        # value 1e13 + 1 (or + 1/2). The old bound, 16 (n + 2) (d + 1) eps of the size,
        # answered an interval or lost the roots; the pieces' own rounding (a few 1e-3 here)
        # still moves the roots, hence the tolerances.
        big = 1e13
        cases = []
        # NURBS quadratic, one span and two: numerator w (y - v) = [-1, 2 2 - ..]: two roots.
        for w in ([1, 2, 1], [1, 0.75, 1], [0.5, 1.5, 2]):
            P = [[0, big], [1, big + 2], [2, big]]
            c = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": P, "weights": w}
            cases.append((f"nurbs one span {w}", nurbs_exact_pieces(c["knots"], 2, P, w), 1e-12, {"curve": c, "value": big + 1, "axis": 1}))
        U = [0, 0, 0, 0.3, 1, 1, 1]
        P = [[0, big], [1, big + 2], [2, big + 2], [3, big]]
        w = [1, 0.7, 1.3, 1]
        c = {"type": "nurbs", "degree": 2, "knots": U, "points": P, "weights": w}
        cases.append(("nurbs two spans", nurbs_exact_pieces(U, 2, P, w), 1e-3, {"curve": c, "value": big + 1, "axis": 1}))
        cases.append(("nurbs two spans, direction", nurbs_exact_pieces(U, 2, P, w), 1e-3,
                      {"curve": c, "value": -2 * (big + 1), "direction": [0, -2]}))
        u, P1, T = [0, 1, 2], [[big], [big + 2], [big]], [[3], [0], [-3]]
        cases.append(("hermite", hermite_exact_pieces(u, P1, T), 1e-3,
                      {"curve": {"type": "hermite", "params": u, "points": P1, "tangents": T}, "value": big + 1, "axis": 0}))
        u, P1 = [0, 1, 2.5, 3], [[big], [big + 2], [big + 2], [big]]
        cases.append(("cubic_spline", hermite_exact_pieces(u, P1, natural_spline_tangents(u, P1)), 1e-3,
                      {"curve": {"type": "cubic_spline", "params": u, "points": P1}, "value": big + 1, "axis": 0}))
        P2 = [[0, big - 2], [1, big], [2, big + 2], [3, big + 2], [4, big], [5, big - 2]]
        cases.append(("catmull_rom", catmull_rom_exact_pieces(P2), 1e-3,
                      {"curve": {"type": "catmull_rom", "points": P2, "alpha": 0}, "value": big + 1, "axis": 1}))
        u, P3 = [0, 1, 2, 3], [[big], [big + 8], [big + 8], [big]]
        cases.append(("lagrange", lagrange_exact_pieces(u, P3), 1e-2,
                      {"curve": {"type": "lagrange", "params": u, "points": P3}, "value": big + 4, "axis": 0}))
        # A path: a Bézier segment (given) before the Lagrange one (its bound read from the
        # path's second piece).
        lin = [[big - 4], [big]]
        pieces = onto([(Fraction(0), Fraction(1), [[Fraction(x[0]), Fraction(1)] for x in lin])], 0, 1) + onto(
            lagrange_exact_pieces(u, P3), 1, 2)
        cases.append(("path bezier + lagrange", pieces, 1e-2,
                      {"curve": {"type": "path", "segments": [{"type": "bezier", "points": lin},
                                                              {"type": "lagrange", "params": u, "points": P3}]},
                       "value": big + 4, "axis": 0}))
        self.check(cases)

    def test_shorthands_at_1e13(self):
        # A circle, an ellipse and an arc about (1e13, 1e13): x = centre + r / 2 at two
        # parameters (one on the arc of 0..3 pi / 2), y = centre + r touches at the top
        # (a quarter break); each root's point by eval within 4 ulps of 1e13 of the level.
        # The old bound answered intervals ([0, 1/4] and [3/4, 1] for the circle).
        K = 1e13
        curves = [({"type": "circle", "center": [K, K], "radius": 1}, 1, 2),
                  ({"type": "ellipse", "center": [K, K], "radii": [3, 1]}, 3, 2),
                  ({"type": "arc", "center": [K, K], "radius": 1, "start_angle": 0, "end_angle": 3 * math.pi / 2}, 1, 1)]
        reqs, levels = [], []
        for c, r, count in curves:
            reqs.append({"curve": c, "value": K + r / 2, "axis": 0})
            levels.append((0, K + r / 2, count))
            reqs.append({"curve": c, "value": K + 1, "axis": 1})
            levels.append((1, K + 1, 1))
        answers = self.ok_jsonl("solve", reqs)
        ulp = math.ulp(K)
        for req, (axis, v, count), got in zip(reqs, levels, answers):
            self.assertEqual(got["intervals"], [], req)
            self.assertEqual(len(got["t"]), count, f"{req}: {got}")
            pts = self.ok("eval", {"curve": req["curve"], "t": got["t"]})["points"]
            for p in pts:
                self.assertLessEqual(abs(p[axis] - v), 4 * ulp, f"{req}: {got} {pts}")
        # The top of the circle is the quarter break 1/4, once.
        self.assert_close(answers[1]["t"], [0.25], 1e-6)


# ---------------------------------------------------------------------------------------

# Refinement is a sum of convex combinations per new point (A5.4): a few eps of the
# coordinates (|P| <= 5 here) per inserted knot; 1e-12 leaves room for tens of knots.
TOL = 1e-12


def scipy_insert_all(U, P, p, X):
    """The control points after inserting X one by one with FITPACK's insert (clamped)."""
    t = np.array(U, dtype=float)
    c = np.vstack([np.array(P, dtype=float), np.zeros((p + 1, len(P[0])))]).T
    for x in X:
        t, c, _ = insert(x, (t, c, p))
        c = np.array(c)
    return np.array(c).T[:len(U) + len(X) - p - 1]


class RefineTest(CliTest):
    def assert_traces(self, curve, ref, lo, hi, tol=10 * TOL):
        ts = [lo + (hi - lo) * i / 40 for i in range(41)]
        got = self.ok("eval", {"curve": curve, "t": ts})["points"]
        for t, g in zip(ts, got):
            want = np.atleast_1d(ref(t)).tolist()
            self.assertLessEqual(max(abs(a - b) for a, b in zip(g, want)), tol, f"t={t}")

    def test_bspline_against_fitpack(self):
        rng = random.Random(5)
        for trial in range(25):
            p = rng.randint(1, 5)
            U, P = random_spline(rng, p, 2, True, trial % 2 == 0)
            lo, hi = U[p], U[len(P)]
            X = sorted(rng.uniform(lo, hi) for _ in range(rng.randint(1, 8)))
            if trial % 3 == 0 and p >= 2:
                X = sorted(X + [X[0]])  # a repeated new knot
            r = self.ok("refine", {"curve": bspline(U, P, p), "knots": X})["curve"]
            self.assertEqual(r["type"], "bspline")
            self.assertEqual(r["knots"], sorted(U + X))
            self.assertTrue(np.allclose(np.array(r["points"]), scipy_insert_all(U, P, p, X), rtol=0, atol=TOL), f"trial {trial}")
            ref = BSpline(np.array(U, float), np.array(P, float), p)
            self.assert_traces(r, ref, lo, hi)

    def test_nurbs_unchanged(self):
        rng = random.Random(6)
        for trial in range(10):
            p = rng.randint(1, 4)
            U, P = random_spline(rng, p, 2, trial % 2 == 0, False)
            w = [rng.uniform(0.3, 4) for _ in P]
            lo, hi = U[p], U[len(P)]
            X = sorted(rng.uniform(lo, hi) for _ in range(5))
            r = self.ok("refine", {"curve": dict(bspline(U, P, p), type="nurbs", weights=w), "knots": X})["curve"]
            self.assertEqual(r["type"], "nurbs")
            self.assertEqual(r["knots"], sorted(U + X))
            A = BSpline(np.array(U, float), np.array([[wi * c for c in q] for wi, q in zip(w, P)]), p)
            W = BSpline(np.array(U, float), np.array(w, float), p)
            self.assert_traces(r, lambda t: A(t) / float(W(t)), lo, hi, 1e-11)  # a quotient: 10x

    def test_circle(self):
        # every inserted knot is there (0.25 already has multiplicity p: once more makes a
        # break, p + 1, allowed; twice more is refused below).
        r = self.ok("refine", {"curve": CIRCLE, "knots": [0.1, 0.3, 0.3, 0.6]})["curve"]
        self.assertEqual(r["knots"], sorted(CIRCLE["knots"] + [0.1, 0.3, 0.3, 0.6]))
        self.bad("refine", {"curve": CIRCLE, "knots": [0.1, 0.25, 0.25]}, "knots[2]", contains="multiplicity")
        ts = [i / 16 for i in range(17)]
        for q in self.ok("eval", {"curve": r, "t": ts})["points"]:
            self.assertAlmostEqual(q[0] ** 2 + q[1] ** 2, 1, delta=1e-14)  # on the unit circle
        self.assertEqual(self.ok("refine", {"curve": CIRCLE, "knots": []})["curve"]["knots"], CIRCLE["knots"])

    def test_many_knots_at_once_is_fast(self):
        # 20000 knots into a cubic: A5.4 is O(n + r p); one at a time would be O(r (n + r)).
        U = [0.0] * 4 + [i / 10 for i in range(1, 10)] + [1.0] * 4
        P = [[i, (-1) ** i] for i in range(len(U) - 4)]
        X = [(i + 0.5) / 20000 for i in range(20000)]
        start = time.time()
        r = self.ok("refine", {"curve": bspline(U, P, 3), "knots": X})["curve"]
        # parsing and writing 20000 numbers dominates; a generous 5 s on a loaded machine.
        self.assertLess(time.time() - start, 5)
        self.assertEqual(len(r["points"]), len(P) + len(X))
        self.assert_traces(r, BSpline(np.array(U), np.array(P, float), 3), 0, 1)

    def test_bad_input(self):
        c = bspline([0, 0, 0, 0.5, 1, 1, 1], [[0, 0], [1, 1], [2, 0], [3, 1]], 2)
        self.bad("refine", {"curve": c, "knots": [0.2, 0.1]}, "knots[1]", contains="non-decreasing")
        self.bad("refine", {"curve": c, "knots": [0.2, 1.5]}, "knots[1]", contains="domain")
        self.bad("refine", {"curve": c, "knots": [-0.1]}, "knots[0]", contains="domain")
        # the copy of a knot that goes past p + 1 is named (0.5 is a knot of c once: its
        # third copy, knots[3], makes p + 2 = 4; the message gives the total)
        self.bad("refine", {"curve": c, "knots": [0.2, 0.5, 0.5, 0.5]}, "knots[3]", contains="multiplicity 4")
        self.bad("refine", {"curve": c, "knots": [0.2, 0.5, 0.5, 0.5, 0.5]}, "knots[3]", contains="multiplicity 5")
        c1 = bspline([0, 0, 1, 2, 2], [[0, 0], [1, 1], [2, 0]], 1)  # degree 1, knot 1 once
        self.bad("refine", {"curve": c1, "knots": [0.2, 1, 1]}, "knots[2]", contains="multiplicity 3")
        self.bad("refine", {"curve": c, "knots": [0.2, 0]}, "knots[1]")
        self.bad("refine", {"curve": c, "knots": [0]}, "knots[0]", contains="multiplicity")  # clamped end
        self.bad("refine", {"curve": c, "knots": [0.1, "a"]}, "knots[1]")
        self.bad("refine", {"curve": c, "knots": 0.5}, "knots")
        self.bad("refine", {"curve": c}, "knots", contains="missing")
        self.bad("refine", {"curve": bezier([[0, 0], [1, 1]]), "knots": [0.5]}, "curve.type", contains="bspline")


# ---------------------------------------------------------------------------------------

def bezier_point(P, t):
    """de Casteljau, written here."""
    Q = [list(map(float, q)) for q in P]
    while len(Q) > 1:
        Q = [[(1 - t) * a + t * b for a, b in zip(Q[j], Q[j + 1])] for j in range(len(Q) - 1)]
    return Q[0]


def frac_bezier(P, t):
    """de Casteljau in Fractions (t a Fraction, points exact doubles)."""
    Q = [[Fraction(c) for c in q] for q in P]
    while len(Q) > 1:
        Q = [[(1 - t) * a + t * b for a, b in zip(Q[j], Q[j + 1])] for j in range(len(Q) - 1)]
    return Q[0]


def frac_de_boor(p, U, P, t):
    """de Boor's algorithm in Fractions on a clamped knot vector (the span of t, the
    last non-empty one at the right end)."""
    U = [Fraction(u) for u in U]
    n = len(P) - 1
    k = max(i for i in range(p, n + 1) if U[i] <= t and U[i] < U[i + 1])
    d = [[Fraction(c) for c in P[j + k - p]] for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            a = (t - U[j + k - p]) / (U[j + 1 + k - r] - U[j + k - p])
            d[j] = [(1 - a) * u + a * v for u, v in zip(d[j - 1], d[j])]
    return d[p]


def multiplicities(U):
    out = {}
    for u in U:
        out[u] = out.get(u, 0) + 1
    return out


def curve_oracle(c):
    """A bspline / nurbs response as a callable (scipy.interpolate.BSpline)."""
    U, P, p = np.array(c["knots"], float), np.array(c["points"], float), c["degree"]
    if c["type"] == "bspline":
        b = BSpline(U, P, p)
        return lambda t: b(t)
    w = np.array(c["weights"], float)
    A, W = BSpline(U, P * w[:, None], p), BSpline(U, w, p)
    return lambda t: A(t) / float(W(t))


def vector_oracle(c):
    """curve_oracle taking an array of parameters too."""
    U, P, p = np.array(c["knots"], float), np.array(c["points"], float), c["degree"]
    if c["type"] == "bspline":
        return BSpline(U, P, p)
    w = np.array(c["weights"], float)
    A, W = BSpline(U, P * w[:, None], p), BSpline(U, w, p)
    return lambda t: A(t) / np.expand_dims(W(t), -1)


class ToBSplineTest(CliTest):
    def convert(self, curve):
        return self.ok("to_bspline", {"curve": curve})["curve"]

    def assert_traces(self, got, ref, lo, hi, tol=1e-12, count=81):
        f = curve_oracle(got)
        for j in range(count):
            t = lo + (hi - lo) * j / (count - 1)
            g, w = np.atleast_1d(f(t)), np.atleast_1d(ref(t))
            self.assertLessEqual(float(np.max(np.abs(g - w))), tol, f"t={t}")

    def test_uniform_cubic_round_trip(self):
        # to_bezier then to_bspline gives back the knots (C^2 joints: multiplicity 1).
        U = [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]
        rng = random.Random(9)
        P = [[rng.uniform(-3, 3), rng.uniform(-3, 3)] for _ in range(8)]
        path = self.ok("to_bezier", {"curve": bspline(U, P, 3)})["curve"]
        got = self.convert(path)
        self.assertEqual((got["type"], got["degree"], got["knots"]), ("bspline", 3, U))
        # Blossoming and two removals per knot: a few hundred eps of |P| <= 3.
        self.assertTrue(np.allclose(np.array(got["points"]), np.array(P), rtol=0, atol=1e-12))

    def test_random_bsplines_keep_their_knots(self):
        # Random clamped splines with repeated knots: a knot of multiplicity m is C^(p-m)
        # there (random points: not more), so it comes back with multiplicity m.
        rng = random.Random(12)
        for trial in range(20):
            p = rng.randint(1, 5)
            U, P = random_spline(rng, p, 2, True, trial % 2 == 0)
            got = self.convert(bspline(U, P, p))
            self.assertEqual(got["knots"], U, f"trial {trial}")
            self.assert_traces(got, BSpline(np.array(U, float), np.array(P, float), p), U[p], U[len(P)])

    def test_one_polynomial_in_two_pieces(self):
        # A cubic cut at 1/2 (exact dyadic halves), as a path on breaks 0, 1, 2: one
        # polynomial, so the knot goes away and the cubic's points come back.
        P = [[0, 0], [1, 3], [3, 3], [4, 0]]
        L = [[0, 0], [0.5, 1.5], [1.25, 2.25], [2, 2.25]]
        R = [[2, 2.25], [2.75, 2.25], [3.5, 1.5], [4, 0]]
        got = self.convert({"type": "path", "segments": [bezier(L), bezier(R)]})
        self.assertEqual(got["knots"], [0, 0, 0, 0, 2, 2, 2, 2])
        self.assertTrue(np.allclose(np.array(got["points"]), np.array(P), rtol=0, atol=1e-14))

    def test_mixed_degrees_corner_and_gap(self):
        line, par = bezier([[0, 0], [1, 1]]), bezier([[1, 1], [2, 2], [3, 0]])
        got = self.convert({"type": "path", "segments": [line, par]})
        # C^1 here? the line's elevated points (0,0),(0.5,0.5),(1,1) and (1,1),(2,2): the
        # velocities at the joint, 2 (0.5, 0.5) against 2 (1, 1), differ: C^0, multiplicity 2.
        self.assertEqual((got["degree"], got["knots"]), (2, [0, 0, 0, 1, 1, 2, 2, 2]))
        ref = lambda t: bezier_point([[0, 0], [0.5, 0.5], [1, 1]], t) if t < 1 else bezier_point(par["points"], t - 1)
        self.assert_traces(got, ref, 0, 2)
        # Same speed at the joint: the line from (-1,-1) to (1,1) then the parabola: C^1.
        got = self.convert({"type": "path", "segments": [bezier([[-1, -1], [1, 1]]), par]})
        self.assertEqual(got["knots"], [0, 0, 0, 1, 2, 2, 2])
        # A gap (not even C^0): the break p + 1 times, the B-spline jumps there as the path
        # does (the right piece's start at the break).
        gap = {"type": "path", "segments": [line, bezier([[1, 2], [2, 2], [3, 0]])]}
        got = self.convert(gap)
        self.assertEqual((got["degree"], got["knots"]), (2, [0, 0, 0, 1, 1, 1, 2, 2, 2]))
        self.assertEqual(got["points"], [[0, 0], [0.5, 0.5], [1, 1], [1, 2], [2, 2], [3, 0]])
        self.assertEqual(self.ok("eval", {"curve": got, "t": [1]})["points"], [[1, 2]])

    def test_polyline_hermite_and_spline(self):
        got = self.convert({"type": "polyline", "points": [[0, 0], [1, 2], [2, 0], [3, 1]]})
        self.assertEqual((got["degree"], got["knots"], got["points"]), (1, [0, 0, 1, 2, 3, 3], [[0, 0], [1, 2], [2, 0], [3, 1]]))
        # A Hermite curve is C^1 (multiplicity 2 in a cubic), a natural cubic spline C^2 (1).
        herm = {"type": "hermite", "params": [0, 1, 3], "points": [[0, 0], [1, 1], [3, 0]],
                "tangents": [[1, 0], [1, 1], [1, -1]]}
        self.assertEqual(multiplicities(self.convert(herm)["knots"])[1], 2)
        spline = {"type": "cubic_spline", "params": [0, 1, 2.5, 3], "points": [[0], [1], [-1], [2]]}
        got = self.convert(spline)
        self.assertEqual(got["knots"], [0, 0, 0, 0, 1, 2.5, 3, 3, 3, 3])
        # against scipy's natural spline
        from scipy.interpolate import CubicSpline
        cs = CubicSpline([0, 1, 2.5, 3], [0, 1, -1, 2], bc_type="natural")
        self.assert_traces(got, lambda t: [cs(t)], 0, 3, 1e-12)

    def test_rational_circle(self):
        got = self.convert(CIRCLE)
        self.assertEqual((got["type"], got["degree"], got["knots"]), ("nurbs", 2, CIRCLE["knots"]))
        self.assert_traces(got, curve_oracle(CIRCLE), 0, 1, 1e-14)
        # A path of the four quarter arcs as rational Beziers (weights 1, 1/sqrt 2, 1).
        arcs = [{"type": "rational_bezier", "points": [CIRCLE["points"][2 * i + k] for k in range(3)],
                 "weights": [1, S2, 1]} for i in range(4)]
        got = self.convert({"type": "path", "segments": arcs})
        self.assertEqual((got["type"], got["knots"]), ("nurbs", [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]))
        f = curve_oracle(got)
        for j in range(33):
            x, y = f(4 * j / 32)
            self.assertAlmostEqual(x * x + y * y, 1, delta=1e-14)  # on the unit circle: rounding

    def test_small_defects_keep_their_knot(self):
        # Audit 16, D13: two cubic pieces C^1 at t = 1 whose second derivative jumps by
        # eps (the right piece's third point moved by eps from the C^2 continuation). Any
        # eps above rounding keeps the double knot, and the B-spline traces both pieces
        # exactly: compared at rational t with the pieces and the result evaluated in
        # Fractions (de Casteljau, de Boor), to a few ulps of the size (about 7).
        A = [[0, 0], [1, 2], [2, 2], [3, 0]]
        b2 = [1 - 4 * 2 + 4 * 3, 2 - 4 * 2 + 4 * 0]  # a1 - 4 a2 + 4 a3: the C^2 continuation
        # The rule's threshold here lies between 3e-13 (removed: within K eps of the
        # propagated magnitudes) and 1e-12 (kept); eps = 0 is one C^2 curve: a single knot.
        for eps in [1e-3, 1e-8, 1e-11, 1e-12, 0]:
            B = [[3, 0], [4, -2], [b2[0], b2[1] + eps], [7, 1]]
            got = self.convert({"type": "path", "segments": [bezier(A), bezier(B)]})
            self.assertEqual(multiplicities(got["knots"])[1], 1 if eps == 0 else 2, f"eps={eps}")
            worst = 0
            for j in range(41):
                t = Fraction(j, 20)
                want = frac_bezier(A, t) if t < 1 else frac_bezier(B, t - 1)
                g = frac_de_boor(got["degree"], got["knots"], got["points"], t)
                worst = max(worst, max(abs(float(x - y)) for x, y in zip(g, want)))
            self.assertLessEqual(worst, 8 * 2.0 ** -52 * 7, f"eps={eps}")
        # The rule is relative: the same pieces scaled by 1e-310 (subnormal) and 1e307 (the
        # bound must not overflow into accepting anything) keep the same knots.
        for scale in [1e-310, 1e307]:
            for eps, want in [(1e-3, [1, 1]), (0, [1])]:
                B = [[3, 0], [4, -2], [b2[0], b2[1] + eps], [7, 1]]
                segs = [bezier([[x * scale for x in q] for q in P]) for P in (A, B)]
                got = self.convert({"type": "path", "segments": segs})
                self.assertEqual(got["knots"], [0] * 4 + want + [2] * 4, f"scale {scale} eps {eps}")
        # A gap of 1e-12 is a gap: the break p + 1 times, both end points kept exactly.
        gap = self.convert({"type": "path", "segments": [bezier(A), bezier([[3, 1e-12], [4, -2], [5, 0], [7, 1]])]})
        self.assertEqual(multiplicities(gap["knots"])[1], 4)
        self.assertIn([3, 1e-12], gap["points"])

    def test_rounding_of_splines_keeps_their_continuity(self):
        # The rule "knots removed to rounding" on the curves whose pieces are exactly C^k in
        # real arithmetic and rounded in doubles: natural cubic splines (C^2: single knots),
        # Hermite curves and uniform Catmull-Rom (C^1: double knots), seeded random data at
        # scales 1e-3..1e3, offsets up to 1e5 and random params (interval ratios up to 20).
        # The result against scipy's CubicSpline / CubicHermiteSpline (the Catmull-Rom
        # tangents (p[j+2] - p[j]) / 2 of the contract), to 1e-13 of the data's magnitude.
        from scipy.interpolate import CubicHermiteSpline, CubicSpline
        rng = random.Random(17)
        for trial in range(12):
            n, scale = rng.randint(4, 9), 10.0 ** rng.uniform(-3, 3)
            off = rng.choice([0, scale * rng.uniform(-100, 100)])
            x = [0.0]
            for _ in range(n - 1):
                x.append(x[-1] + rng.uniform(0.1, 2))
            y = [off + scale * rng.uniform(-1, 1) for _ in range(n)]
            mag = abs(off) + scale
            spline = self.convert({"type": "cubic_spline", "params": x, "points": [[v] for v in y]})
            self.assertEqual(spline["knots"], [x[0]] * 4 + x[1:-1] + [x[-1]] * 4, f"trial {trial}")
            self.assert_traces(spline, CubicSpline(x, y, bc_type="natural"), x[0], x[-1], 1e-13 * mag)
            m = [scale * rng.uniform(-3, 3) for _ in range(n)]
            herm = self.convert({"type": "hermite", "params": x, "points": [[v] for v in y], "tangents": [[v] for v in m]})
            self.assertEqual(herm["knots"], [x[0]] * 4 + [k for k in x[1:-1] for _ in range(2)] + [x[-1]] * 4)
            self.assert_traces(herm, CubicHermiteSpline(x, y, m), x[0], x[-1], 1e-13 * mag)
            cr = self.convert({"type": "catmull_rom", "points": [[v] for v in y], "alpha": 0})
            self.assertEqual(cr["knots"], [0] * 4 + [k for k in range(1, n - 3) for _ in range(2)] + [n - 3] * 4)
            tang = [(y[j + 1] - y[j - 1]) / 2 for j in range(1, n - 1)]
            self.assert_traces(cr, CubicHermiteSpline(range(n - 2), y[1:-1], tang), 0, n - 3, 1e-13 * mag)

    def test_bad_input(self):
        self.bad("to_bspline", {}, "curve", contains="missing")
        self.bad("to_bspline", {"curve": bezier([[0, 0], [1, 1]]), "tolerance": 1}, "tolerance")
        self.bad("to_bspline", {"curve": {"type": "bezier", "points": [[0, 0], [1]]}}, "curve.points[1]")


class ReduceTest(CliTest):
    def reduce(self, curve, tolerance, **extra):
        return self.ok("reduce", dict({"curve": curve, "tolerance": tolerance}, **extra))

    @staticmethod
    def measured(f, g, lo, hi, breaks=(), vectorised=False):
        """max |f - g| by 20001 samples plus the breaks (where a fit's error often peaks,
        at a kink of |f - g|), and a bounded scalar search on each side of the best
        (vectorised: f and g take the array of samples at once)."""
        from scipy.optimize import minimize_scalar
        ts = np.unique(np.concatenate([np.linspace(lo, hi, 20001), [b for b in breaks if lo <= b <= hi]]))
        if vectorised:
            d = np.linalg.norm((np.asarray(f(ts)) - np.asarray(g(ts))).reshape(len(ts), -1), axis=1)
        else:
            d = [float(np.linalg.norm(np.atleast_1d(f(t)) - np.atleast_1d(g(t)))) for t in ts]
        j = int(np.argmax(d))
        best = d[j]
        dist = lambda t: -float(np.linalg.norm(np.atleast_1d(f(t)) - np.atleast_1d(g(t))))
        for a, b in ((ts[max(0, j - 1)], ts[j]), (ts[j], ts[min(len(ts) - 1, j + 1)])):
            if b > a:
                best = max(best, -minimize_scalar(dist, bounds=(a, b), method="bounded", options={"xatol": 1e-14}).fun)
        return best

    def test_elevated_bezier_comes_back_exactly(self):
        # Degree elevation in exact rationals: Q_i = i/(n+1) P_(i-1) + (1 - i/(n+1)) P_i.
        P = [[Fraction(0), Fraction(0)], [Fraction(1), Fraction(3)], [Fraction(3), Fraction(3)], [Fraction(4), Fraction(-1)]]
        n = 3
        Q = [[float(Fraction(i, n + 1) * (P[i - 1][k] if i > 0 else 0) + (1 - Fraction(i, n + 1)) * (P[i][k] if i <= n else 0))
              for k in range(2)] for i in range(n + 2)]
        got = self.reduce(bezier(Q), 1e-9)
        self.assertTrue(np.allclose(np.array(got["curve"]["points"]), np.array(P, dtype=float), rtol=0, atol=1e-13))
        self.assertLess(got["max_error"], 1e-13)  # rounding of the solve only

    def test_cubic_to_quadratic_least_squares(self):
        # Oracle: the L2 problem with both ends kept, solved here by numpy on 2001 Gauss
        # points (exact for these polynomial integrands), and the error measured here.
        P = np.array([[0, 0], [1, 2], [3, 2.5], [4, 0]], float)
        xg, wg = np.polynomial.legendre.leggauss(40)
        t = (xg + 1) / 2
        B3 = np.array([[comb(3, i) * s ** i * (1 - s) ** (3 - i) for i in range(4)] for s in t])
        B2 = np.array([[comb(2, i) * s ** i * (1 - s) ** (2 - i) for i in range(3)] for s in t])
        target = B3 @ P - np.outer(B2[:, 0], P[0]) - np.outer(B2[:, 2], P[3])
        sw = np.sqrt(wg)[:, None]
        mid = np.linalg.lstsq(B2[:, 1:2] * sw, target * sw, rcond=None)[0]
        want = np.vstack([P[0], mid[0], P[3]])
        got = self.reduce(bezier(P.tolist()), 1)
        self.assertTrue(np.allclose(np.array(got["curve"]["points"]), want, rtol=0, atol=1e-12))
        err = self.measured(lambda s: bezier_point(P.tolist(), s), lambda s: bezier_point(want.tolist(), s), 0, 1)
        self.assertLessEqual(abs(got["max_error"] - err), 1e-9 * err)  # the contract's 1e-9 relative
        # refused below that error, with the figure
        msg = self.bad("reduce", {"curve": bezier(P.tolist()), "tolerance": err / 2}, "tolerance", contains="moves the curve")
        self.assertIn(str(round(err, 6))[:6], msg)

    def test_times_and_constant(self):
        P = [[0, 0], [1, 2], [2, -1], [3, 3], [4, 1]]
        got = self.reduce(bezier(P), 10, times=2)
        self.assertEqual(len(got["curve"]["points"]), 3)
        self.assertEqual(got["curve"]["points"][0], [0, 0])  # ends kept
        self.assertEqual(got["curve"]["points"][-1], [4, 1])
        # degree 1 -> 0: the mean, the midpoint; max error half the length.
        got = self.reduce(bezier([[0, 0], [4, 3]]), 3)
        self.assert_close(got["curve"]["points"], [[2, 1.5]], 1e-15)
        self.assertAlmostEqual(got["max_error"], 2.5, delta=1e-12)

    def test_bspline_reports_its_true_error(self):
        rng = random.Random(4)
        for trial in range(8):
            p = rng.randint(2, 4)
            U, P = random_spline(rng, p, 2, True, False)
            got = self.reduce(bspline(U, P, p), 100)
            c = got["curve"]
            self.assertEqual((c["type"], c["degree"]), ("bspline", p - 1))
            lo, hi = U[p], U[len(P)]
            self.assertEqual((c["knots"][0], c["knots"][-1]), (lo, hi))
            err = self.measured(BSpline(np.array(U, float), np.array(P, float), p), curve_oracle(c), lo, hi, U, vectorised=True)
            # Our measurement: 20001 samples and a local search; the program's: 1e-9
            # relative. The pieces are smooth, so both find the same maximum.
            self.assertLessEqual(abs(got["max_error"] - err), 1e-8 * max(err, 1e-300), f"trial {trial}")

    def test_bspline_exactly_reducible(self):
        # A quadratic polynomial as a clamped cubic B-spline with a knot at 1/2: elevation
        # in exact rationals, then knot insertion by Boehm's formula, both written here.
        P = [Fraction(0), Fraction(2), Fraction(-1)]
        Q = [P[0], (P[0] + 2 * P[1]) / 3, (2 * P[1] + P[2]) / 3, P[2]]
        U = [0, 0, 0, 0, 1, 1, 1, 1]
        u = Fraction(1, 2)
        # Boehm: a_i = (u - U_i) / (U_(i+3) - U_i) for i = 1..3.
        R = [Q[0]] + [(1 - (u - U[i]) / (U[i + 3] - U[i])) * Q[i - 1] + (u - U[i]) / (U[i + 3] - U[i]) * Q[i] for i in (1, 2, 3)] + [Q[3]]
        c = bspline([0, 0, 0, 0, 0.5, 1, 1, 1, 1], [[float(x)] for x in R], 3)
        got = self.reduce(c, 1e-12)
        self.assertEqual(got["curve"]["degree"], 2)
        self.assertLess(got["max_error"], 1e-14)  # exact data, exact reduction: rounding

    def test_nurbs(self):
        # A quarter circle elevated to degree 3 (homogeneous elevation in exact arithmetic
        # of the weights' squares is not rational: in floats, then reduced back).
        s2 = 2 ** -0.5
        H = [[1, 0, 1], [s2, s2, s2], [0, 1, 1]]  # (w x, w y, w)
        E = [H[0]] + [[(1 / 3) * H[0][k] + (2 / 3) * H[1][k] for k in range(3)],
                      [(2 / 3) * H[1][k] + (1 / 3) * H[2][k] for k in range(3)]] + [H[2]]
        c = {"type": "nurbs", "degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1, 1],
             "points": [[h[0] / h[2], h[1] / h[2]] for h in E], "weights": [h[2] for h in E]}
        got = self.reduce(c, 1e-12)
        self.assertEqual((got["curve"]["type"], got["curve"]["degree"]), ("nurbs", 2))
        self.assertLess(got["max_error"], 1e-14)  # rounding of the elevation here
        f = curve_oracle(got["curve"])
        for j in range(17):
            x, y = f(j / 16)
            self.assertAlmostEqual(x * x + y * y, 1, delta=1e-14)

    # The audit's cubic (two pieces, C2 at 1): A5.11 refused tolerance 0.3 on its bound
    # (0.42) and returned a curve 0.123 off at 0.5, another 0.204 off at 0.6.
    AUDIT_CUBIC = bspline([0, 0, 0, 0, 1, 2, 2, 2, 2], [[0, 0], [1, 2], [2, 2], [3, 0], [4, 1]], 3)

    def check_measured(self, curve, got, msg=""):
        """The response's max_error against our own measurement (scipy, mpmath-free:
        dense samples, the breaks, a local search), to 1e-8 relative; returns it."""
        lo, hi = curve["knots"][curve["degree"]], curve["knots"][len(curve["points"])]
        err = self.measured(vector_oracle(curve), vector_oracle(got["curve"]), lo, hi, curve["knots"], vectorised=True)
        self.assertLessEqual(abs(got["max_error"] - err), 1e-8 * max(err, 1e-300), msg)
        return err

    def test_decided_on_the_measured_error_and_monotone(self):
        c = self.AUDIT_CUBIC
        answers = [self.reduce(c, tol) for tol in (0.21, 0.3, 0.5, 0.6, 1e9)]
        # One answer at every tolerance that admits it: the tolerance only decides.
        for got in answers[1:]:
            self.assertEqual(got, answers[0])
        got = answers[0]
        self.assertEqual((got["curve"]["degree"], got["curve"]["knots"]), (2, [0, 0, 0, 1, 2, 2, 2]))  # C1 at 1, as docs/cli.md says
        self.assertEqual((got["curve"]["points"][0], got["curve"]["points"][-1]), ([0, 0], [4, 1]))  # ends kept
        err = self.check_measured(c, got)
        self.assertLessEqual(err, 0.21)
        # Near the least possible: the min-max over the two free points (Nelder-Mead on
        # 1001 samples, here: a value from below) is 0.1294; the program's fit is within
        # 2 % of it.
        from scipy.optimize import minimize
        ts = np.linspace(0, 2, 1001)
        A = BSpline(np.array(c["knots"], float), np.array(c["points"], float), 3)(ts)
        W = np.array([0, 0, 0, 1, 2, 2, 2], float)
        worst = lambda x: float(np.max(np.linalg.norm(BSpline(W, np.vstack([[0, 0], x.reshape(2, 2), [4, 1]]), 2)(ts) - A, axis=1)))
        x = np.array(got["curve"]["points"][1:3], float).ravel()
        for _ in range(2):
            x = minimize(worst, x, method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-12, "maxiter": 2000}).x
        self.assertLess(worst(x), 0.1295)
        self.assertLessEqual(err, 1.02 * worst(x))
        # Refused just below the measured error, with that figure (not a bound).
        msg = self.bad("reduce", {"curve": c, "tolerance": err * (1 - 1e-6)}, "tolerance", contains="moves the curve by")
        self.assertIn(repr(got["max_error"])[:10], msg)

    def test_scale_invariance(self):
        # The same answer, scaled, for the audit's cubic and a NURBS on it at 1e-300 and
        # 1e300 (squares of such differences under- or overflow: the distances are scaled).
        base = self.reduce(self.AUDIT_CUBIC, 1)["max_error"]
        nurbs = dict(self.AUDIT_CUBIC, type="nurbs", weights=[1, 2, 0.5, 1, 3])
        nbase = self.reduce(nurbs, 1)["max_error"]
        for s in (1e-300, 1e300):
            for c, want in ((self.AUDIT_CUBIC, base), (nurbs, nbase)):
                scaled = dict(c, points=[[s * v for v in q] for q in c["points"]])
                got = self.reduce(scaled, 1e308)
                self.assertAlmostEqual(got["max_error"] / s, want, delta=1e-12 * want, msg=f"{c['type']} at {s}")

    def test_quarter_circle_to_its_chord(self):
        # Degree 2 to 1 with the ends kept: the chord, whose largest distance at equal
        # parameters is at t = 1/2 (symmetry): |(1, 1)/sqrt(2) - (1, 1)/2| = 1 - sqrt(2)/2.
        c = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[1, 0], [1, 1], [0, 1]],
             "weights": [1, S2, 1]}
        chord = float(1 - mpmath.sqrt(2) / 2)
        got = self.reduce(c, 0.5)
        self.assertEqual(got["curve"]["degree"], 1)
        self.assert_close(got["curve"]["points"], [[1, 0], [0, 1]], 1e-15)
        self.assertAlmostEqual(got["max_error"], chord, delta=1e-15)
        self.check_measured(c, got)
        self.bad("reduce", {"curve": c, "tolerance": 0.29}, "tolerance", contains="0.2928932188")

    def test_nurbs_of_any_weights(self):
        # The audit's NURBS (weights 0.08 .. 15): A5.11 needs a weight <= 0, yet a lower
        # degree curve within 1e9 exists; the answer's error is measured, its weights > 0.
        c = {"type": "nurbs", "degree": 4, "knots": [0, 0, 0, 0, 0, 4, 4, 4, 4, 4],
             "points": [[-1.01, 4.36], [0.56, -2.6], [2.41, 1.74], [1.84, -0.36], [-2.78, 1.41]],
             "weights": [13.45, 0.08, 7.92, 0.45, 14.97]}
        got = self.reduce(c, 1e9, times=3)
        self.assertEqual(got["curve"]["degree"], 1)
        self.check_measured(c, got)
        # A seeded batch as the audit drew it (weights e^U(-3, 3), 14 of 35 refused there):
        # every one answered, the error measured, weights > 0, the clamped ends kept, and
        # no worse than the chord between the ends (a lower-degree curve the fit can hold:
        # its error measured here too).
        rng = np.random.default_rng(35)
        for trial in range(12):
            p = int(rng.integers(2, 5))
            n = p + 1 + int(rng.integers(0, 4))
            inner = sorted(rng.uniform(0, 1, n - p - 1).round(3).tolist())
            U = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
            P = rng.uniform(-5, 5, (n, 2)).round(2)
            c = {"type": "nurbs", "degree": p, "knots": U, "points": P.tolist(), "weights": np.exp(rng.uniform(-3, 3, n)).tolist()}
            r = int(rng.integers(1, p))
            got = self.reduce(c, 1e9, times=r)
            msg = f"trial {trial}: {c}, times {r}"
            self.assertEqual(got["curve"]["degree"], p - r, msg)
            self.assertTrue(all(w > 0 for w in got["curve"]["weights"]), msg)
            self.assertEqual([got["curve"]["points"][0], got["curve"]["points"][-1]], [P[0].tolist(), P[-1].tolist()], msg)
            err = self.check_measured(c, got, msg)
            chord = self.measured(vector_oracle(c), lambda t: np.multiply.outer(1 - t, P[0]) + np.multiply.outer(t, P[-1]), 0, 1, U,
                                  vectorised=True)
            self.assertLessEqual(err, chord * (1 + 1e-9), msg)
            # monotone: the same answer at a tolerance just above its error, refused below
            self.assertEqual(self.reduce(c, got["max_error"] * (1 + 1e-9), times=r), got, msg)
            self.bad("reduce", {"curve": c, "tolerance": got["max_error"] * (1 - 1e-6), "times": r}, "tolerance")

    def test_work_limit(self):
        # pieces x ((p + 1)^3, x4 for a NURBS, + 1000) above 3e7 is refused before any fit:
        # 30,000 quadratic pieces (30000 x 1027), one NURBS piece of degree 300
        # (4 x 301^3 + 1000), counted by hand.
        n = 30002
        quad = bspline([0.0] * 3 + [float(i) for i in range(1, n - 2)] + [float(n - 2)] * 3,
                       [[i % 7, (i * i) % 5] for i in range(n)], 2)
        self.bad("reduce", {"curve": quad, "tolerance": 1e9}, "curve", contains="about 30810000 units of work")
        p = 300
        nurbs = {"type": "nurbs", "degree": p, "knots": [0] * (p + 1) + [1] * (p + 1),
                 "points": [[i % 3, i % 5] for i in range(p + 1)], "weights": [1 + (i % 2) for i in range(p + 1)]}
        self.bad("reduce", {"curve": nurbs, "tolerance": 1e9}, "curve", contains=f"about {4 * 301 ** 3 + 1000} units of work")

    def test_impossible_reduction_refused_with_the_measured_figure(self):
        # The parabola (2t, 4t(1 - t)) to degree 1 with its ends kept: the only such line
        # is the chord (2t, 0), 4t(1 - t) away, 1 at t = 1/2.
        c = bspline([0, 0, 0, 1, 1, 1], [[0, 0], [1, 2], [2, 0]], 2)
        self.bad("reduce", {"curve": c, "tolerance": 0.99}, "tolerance", contains="moves the curve by 1 (measured")
        got = self.reduce(c, 1)
        self.assertEqual(got["max_error"], 1)

    def test_bad_input(self):
        c = bezier([[0, 0], [1, 2], [2, 0]])
        self.bad("reduce", {"curve": c}, "tolerance", contains="missing")
        self.bad("reduce", {"curve": c, "tolerance": 0}, "tolerance", contains="> 0")
        self.bad("reduce", {"curve": c, "tolerance": -1}, "tolerance", contains="> 0")
        self.bad("reduce", {"curve": c, "tolerance": 1, "times": 0}, "times", contains="1..")
        self.bad("reduce", {"curve": c, "tolerance": 1, "times": 3}, "times", contains="1..")
        self.bad("reduce", {"curve": c, "tolerance": 1, "times": 1.5}, "times")
        self.bad("reduce", {"curve": c, "tolerance": 1e-6}, "tolerance", contains="moves the curve")
        self.bad("reduce", {"curve": {"type": "polyline", "points": [[0, 0], [1, 1]]}, "tolerance": 1}, "curve.type")
        self.bad("reduce", {"curve": {"type": "rational_bezier", "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 2, 1]},
                            "tolerance": 1}, "curve.type")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
