#!/usr/bin/python3
"""Black-box tests of `basis`: the basis functions of a kind, their derivatives, and the
matrix view of the cubic kinds.

Oracles at test time, never the program: the textbook matrices as exact rationals
(Fractions) [Foley90, 11.2; CatmullRom74]; the power basis times those matrices for the
values; scipy.interpolate.BSpline.design_matrix and BSpline.basis_element for B-splines;
the Lagrange basis by its product formula and its derivatives by exact polynomial
arithmetic (Fractions); the Bernstein polynomials from their definition. Invariants:
partition of unity (derivatives summing to 0). Every bad-input rule of docs/cli.md.

Usage: test_basis.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import random
import sys
import unittest
from fractions import Fraction as F
from math import comb

import numpy as np
from scipy.interpolate import BSpline

import test_cli
from test_cli import CliTest

HERMITE = [[1, 0, 0, 0], [0, 0, 1, 0], [-3, 3, -2, -1], [2, -2, 1, 1]]
CATMULL_ROM = [[F(x, 2) for x in r] for r in [[0, 2, 0, 0], [-1, 0, 1, 0], [2, -5, 4, -1], [-1, 3, -3, 1]]]
UNIFORM_BSPLINE = [[F(x, 6) for x in r] for r in [[1, 4, 1, 0], [-3, 0, 3, 0], [3, -6, 3, 0], [-1, 3, -3, 1]]]
BERNSTEIN3 = [[1, 0, 0, 0], [-3, 3, 0, 0], [3, -6, 3, 0], [-1, 3, -3, 1]]


def mat_mul(a, b):
    return [[sum(F(a[i][k]) * F(b[k][j]) for k in range(len(b))) for j in range(len(b[0]))] for i in range(len(a))]


def mat_inv(m):
    """Exact inverse (Gauss-Jordan on Fractions); None when singular."""
    n = len(m)
    a = [[F(x) for x in row] + [F(int(i == j)) for j in range(n)] for i, row in enumerate(m)]
    for c in range(n):
        p = next((r for r in range(c, n) if a[r][c] != 0), None)
        if p is None:
            return None
        a[c], a[p] = a[p], a[c]
        a[c] = [x / a[c][c] for x in a[c]]
        for r in range(n):
            if r != c and a[r][c] != 0:
                a[r] = [x - a[r][c] * y for x, y in zip(a[r], a[c])]
    return [row[n:] for row in a]


def cardinal_matrix(s):
    """Hermite's M times the map [P0..P3] -> [P1, P2, c (P2 - P0), c (P3 - P1)],
    c = (1 - s) / 2 (the contract: tangents (1 - s) times Catmull-Rom's)."""
    c = (1 - F(s)) / 2
    h = [[0, 1, 0, 0], [0, 0, 1, 0], [-c, 0, c, 0], [0, -c, 0, c]]
    return mat_mul(HERMITE, h)


def power_row(t, j):
    """d^j/dt^j [1, t, t^2, t^3] (exact for a Fraction t)."""
    out = []
    for e in range(4):
        c = 1
        for q in range(j):
            c *= e - q
        out.append(c * F(t) ** (e - j) if e >= j else F(0))
    return out


def poly_deriv(a):
    return [k * a[k] for k in range(1, len(a))] or [F(0)]


def poly_eval(a, t):
    s = F(0)
    for c in reversed(a):
        s = s * t + c
    return s


def lagrange_poly(x, j):
    """Power coefficients (exact) of l_j(t) = prod_{m != j} (t - x_m) / (x_j - x_m)."""
    a = [F(1)]
    for m, xm in enumerate(x):
        if m == j:
            continue
        d = F(x[j]) - F(xm)
        a = [F(0)] + a  # times t
        for i in range(len(a) - 1):
            a[i] -= F(xm) * a[i + 1]
        a = [c / d for c in a]
    return a


# Values of O(1) basis functions from a few exact-rational products, rounded: a few ulps.
TIGHT = 1e-14


class BasisTest(CliTest):
    def basis(self, **req):
        return self.ok("basis", req)

    def assert_matrix(self, got, want, tol=TIGHT):
        self.assert_close(got, [[float(x) for x in row] for row in want], tol)

    def test_cubic_matrices_exact(self):
        for kind, m, extra in [("hermite", HERMITE, {}), ("catmull_rom", CATMULL_ROM, {}),
                               ("uniform_bspline", UNIFORM_BSPLINE, {}), ("bernstein", BERNSTEIN3, {"degree": 3}),
                               ("cardinal", CATMULL_ROM, {"tension": 0})]:
            r = self.basis(kind=kind, t=[0.5], **extra)
            # Entries are k/2 or k/6: one rounding each (the 1/6 ones), so 1 ulp.
            self.assert_matrix(r["matrix"], m, 1e-16)
            self.assert_matrix(r["basis_matrix"], m, 1e-16)
            self.assert_matrix(r["constraint"], mat_inv(m), 1e-16)
        # The integer ones are exactly the textbook's.
        self.assertEqual(self.basis(kind="hermite", t=[0])["matrix"], HERMITE)
        self.assertEqual(self.basis(kind="bernstein", degree=3, t=[0])["matrix"], BERNSTEIN3)
        self.assertEqual(self.basis(kind="hermite", t=[0])["constraint"], [[float(x) for x in r] for r in mat_inv(HERMITE)])

    def test_cardinal_tension(self):
        # M, B and C against the exact rationals for the given double s: M by the contract's
        # definition (Hermite's M times the tangent map), C = M^-1 by Gauss-Jordan on
        # Fractions (not the program's closed form). Each entry is asked to be within half
        # an ulp of the exact value (plus 1e-6 ulp: the double-double's near ties), i.e.
        # the nearest double or at a tie its neighbour, also near s = 1 (C ~ 1 / (1 - s))
        # and at s < 2^-53 (1 - s not a double). s = 1 - 2^-52 and 1 - 2^-53: M invertible,
        # so C is not null there.
        rng = random.Random(20)
        tensions = [0, 0.25, 0.5, 0.9, 1 / 3, 0.1, 1e-20, 2.0 ** -54, 2.0 ** -53 * 3, 0.999, 1 - 1e-6, 1 - 1e-12,
                    1 - 2.0 ** -52, 1 - 2.0 ** -53]
        tensions += [rng.random() for _ in range(8)] + [1 - rng.random() * 10.0 ** -rng.randint(2, 15) for _ in range(8)]
        for s in tensions:
            m = cardinal_matrix(F(s))
            c = mat_inv(m)
            self.assertIsNotNone(c, s)
            r = self.basis(kind="cardinal", tension=s, t=[0.3])
            for name, got, want in [("matrix", r["matrix"], m), ("basis_matrix", r["basis_matrix"], m), ("constraint", r["constraint"], c)]:
                for i in range(4):
                    for j in range(4):
                        exact, g = F(want[i][j]), got[i][j]
                        half_ulp = F(math.ulp(float(exact))) / 2
                        self.assertTrue(abs(F(g) - exact) <= half_ulp * (1 + F(1, 10 ** 6)),
                                        f"s={s!r} {name}[{i}][{j}] = {g!r}, exact {float(exact)!r}")
        r = self.basis(kind="cardinal", tension=1, t=[0.3])
        self.assertIsNone(r["constraint"])
        self.assertIsNone(mat_inv(cardinal_matrix(1)))  # the oracle agrees it is singular
        self.assert_matrix(r["matrix"], cardinal_matrix(1))
        # Tension 0 is Catmull-Rom: the same doubles as kind catmull_rom.
        cr, c0 = self.basis(kind="catmull_rom", t=[0.3]), self.basis(kind="cardinal", tension=0, t=[0.3])
        self.assertEqual([cr[k] for k in ("matrix", "constraint")], [c0[k] for k in ("matrix", "constraint")])

    def test_cubic_values_and_derivatives(self):
        ts = [0, 0.25, 0.5, 0.8, 1, -0.5, 1.75]
        for kind, m, extra in [("hermite", HERMITE, {}), ("catmull_rom", CATMULL_ROM, {}),
                               ("uniform_bspline", UNIFORM_BSPLINE, {}), ("cardinal", cardinal_matrix(F(1, 4)), {"tension": 0.25}),
                               ("bernstein", BERNSTEIN3, {"degree": 3})]:
            r = self.basis(kind=kind, t=ts, derivatives=4, **extra)
            self.assertEqual(len(r["derivatives"]), 4)
            for j in range(5):
                table = r["values"] if j == 0 else r["derivatives"][j - 1]
                want = [[float(v) for v in mat_mul([power_row(F(t), j)], m)[0]] for t in ts]
                # O(1) values (|t| <= 1.75: powers <= 5.4, entries <= 3): a few ulps of 1e2.
                self.assert_close(table, want, 1e-13, f"{kind} order {j}")
            if kind != "hermite":  # Hermite's tangent functions do not sum to 1
                for row in r["values"]:
                    self.assertAlmostEqual(sum(row), 1, delta=1e-14)  # partition of unity: rounding of 4 terms
        # Hermite: h00 + h01 = 1, and the interpolation conditions.
        r = self.basis(kind="hermite", t=[0, 1], derivatives=1)
        self.assertEqual(r["values"], [[1, 0, 0, 0], [0, 1, 0, 0]])
        self.assertEqual(r["derivatives"][0], [[0, 0, 1, 0], [0, 0, 0, 1]])

    def test_bernstein(self):
        for n in [0, 1, 2, 5, 9]:
            ts = [0, 0.1, 0.5, 0.77, 1, 1.3]
            r = self.basis(kind="bernstein", degree=n, t=ts, derivatives=2)
            self.assertEqual("matrix" in r, n == 3)
            for j in range(3):
                table = r["values"] if j == 0 else r["derivatives"][j - 1]
                for t, row in zip(ts, table):
                    want = []
                    for i in range(n + 1):
                        a = [F(0)] * (n + 1)  # C(n,i) t^i (1-t)^(n-i), exact power form
                        for q in range(n - i + 1):
                            a[i + q] += comb(n, i) * comb(n - i, q) * (-1) ** q
                        for _ in range(j):
                            a = poly_deriv(a)
                        want.append(float(poly_eval(a, F(t))))
                    # |values| <= n^2 2^n at |t| <= 1.3: rounding of O(n) terms, relative 1e-12.
                    self.assert_close(row, want, 1e-12 * max(1, n * n), f"n={n} order {j} t={t}")
                    self.assertAlmostEqual(sum(row), 1 if j == 0 else 0, delta=1e-11 * (1 + n * n))

    def test_bspline_against_scipy(self):
        rng = random.Random(7)
        for p in [0, 1, 2, 3, 5]:
            for trial in range(4):
                nfun = p + 1 + rng.randint(0, 6)
                inner = sorted(rng.choice([rng.random(), 0.5]) for _ in range(nfun - p - 1))
                if p == 0:
                    knots = [0.0] + sorted(set(inner)) + [1.0]
                    nfun = len(knots) - 1
                else:
                    # clamped, interior multiplicity <= p (0.5 may repeat)
                    while any(inner.count(x) > p for x in inner):
                        inner = sorted(rng.random() for _ in range(nfun - p - 1))
                    knots = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
                ts = sorted(rng.random() for _ in range(8)) + [0.0, 0.5, 1.0 - 1e-12]
                k = min(p, 3)
                r = self.basis(kind="bspline", degree=p, knots=knots, t=ts, derivatives=k)
                self.assertEqual(len(r["values"][0]), len(knots) - p - 1)
                for j in range(k + 1):
                    table = r["values"] if j == 0 else r["derivatives"][j - 1]
                    for f in range(nfun):
                        if knots[f] == knots[f + p + 1]:
                            continue
                        b = BSpline.basis_element(knots[f:f + p + 2], extrapolate=False)
                        for i, t in enumerate(ts):
                            want = b(t, nu=j)  # piecewise: fine across repeated knots
                            want = 0.0 if np.isnan(want) else float(want)
                            # Derivatives scale by 1 / (knot gap)^j: relative to that scale.
                            scale = max(1.0, max(abs(x) for x in [want, table[i][f]]))
                            if t in knots[f:f + p + 2]:
                                continue  # scipy's basis_element and the span rule differ at knots (left/right limits)
                            self.assertLessEqual(abs(table[i][f] - want), 1e-9 * scale, f"p={p} f={f} t={t} j={j}")
                for row in r["values"]:
                    self.assertAlmostEqual(sum(row), 1, delta=1e-13)  # partition of unity, p + 1 terms
                # design_matrix at the knots too (right limits, last span at the end).
                dm = BSpline.design_matrix(np.array([0.0, 0.5, 1.0]), np.array(knots), p).toarray()
                r = self.basis(kind="bspline", degree=p, knots=knots, t=[0.0, 0.5, 1.0])
                self.assert_close(r["values"], dm.tolist(), 1e-12)

    def test_lagrange(self):
        x = [0, 0.5, 1.5, 2, 3.25]
        ts = [0, 0.3, 1.5, 2.9, 3.25, -0.5, 4]
        r = self.basis(kind="lagrange", params=x, t=ts, derivatives=5)
        for j in range(6):
            table = r["values"] if j == 0 else r["derivatives"][j - 1]
            for f in range(len(x)):
                a = lagrange_poly(x, f)
                for _ in range(j):
                    a = poly_deriv(a)
                want = [float(poly_eval(a, F(t))) for t in ts]
                got = [row[f] for row in table]
                # Derivatives of degree-4 polynomials with node gaps of 0.5: values up to ~1e2;
                # the barycentric formulas lose a few digits per order (n^2 / spread).
                self.assert_close(got, want, 1e-11, f"l_{f} order {j}")
        for row in r["values"]:
            self.assertAlmostEqual(sum(row), 1, delta=1e-13)  # partition of unity
        self.assertEqual(r["values"][2], [0, 0, 1, 0, 0])  # at a node: exactly the indicator
        self.assertNotIn("matrix", r)

    def test_no_derivatives_key_without_k(self):
        r = self.basis(kind="hermite", t=[0.5])
        self.assertNotIn("derivatives", r)
        self.assertEqual(set(r), {"values", "matrix", "constraint", "basis_matrix"})
        r = self.basis(kind="bernstein", degree=2, t=[])
        self.assertEqual(r, {"values": []})

    def test_bad_input(self):
        self.bad("basis", {"kind": "bezier", "t": [0]}, "kind", contains="unknown")
        self.bad("basis", {"t": [0]}, "kind", contains="missing")
        self.bad("basis", {"kind": "hermite"}, "t", contains="missing")
        self.bad("basis", {"kind": "bernstein", "t": [0]}, "degree", contains="missing")
        self.bad("basis", {"kind": "bernstein", "degree": -1, "t": [0]}, "degree", contains=">= 0")
        self.bad("basis", {"kind": "bspline", "degree": 2, "t": [0]}, "knots", contains="missing")
        self.bad("basis", {"kind": "bspline", "knots": [0, 0, 1, 1], "t": [0]}, "degree", contains="missing")
        self.bad("basis", {"kind": "bspline", "degree": 1, "knots": [0, 0, 2, 1, 1], "t": [0]}, "knots[3]",
                 contains="non-decreasing")
        # p + 1 = 2 copies are allowed (a break); the first copy past them is named
        self.bad("basis", {"kind": "bspline", "degree": 1, "knots": [0, 0.5, 0.5, 0.5, 1], "t": [0]}, "knots[3]",
                 contains="repeated")
        self.bad("basis", {"kind": "bspline", "degree": 2, "knots": [0, 0, 1], "t": [0]}, "knots", contains="at least")
        self.bad("basis", {"kind": "bspline", "degree": 0, "knots": [1, 0], "t": [0]}, "knots[1]", contains="non-decreasing")
        self.bad("basis", {"kind": "lagrange", "t": [0]}, "params", contains="missing")
        self.bad("basis", {"kind": "lagrange", "params": [0, 1, 0], "t": [0]}, "params[2]", contains="distinct")
        self.bad("basis", {"kind": "lagrange", "params": [], "t": [0]}, "params")
        self.bad("basis", {"kind": "cardinal", "t": [0]}, "tension", contains="missing")
        self.bad("basis", {"kind": "cardinal", "tension": 1.5, "t": [0]}, "tension", contains="[0, 1]")
        self.bad("basis", {"kind": "cardinal", "tension": -0.1, "t": [0]}, "tension", contains="[0, 1]")
        # A field of another kind is refused, not ignored.
        self.bad("basis", {"kind": "hermite", "tension": 0.5, "t": [0]}, "tension", contains="another kind")
        self.bad("basis", {"kind": "uniform_bspline", "degree": 3, "t": [0]}, "degree", contains="another kind")
        # Far outside the nodes the values overflow: refused naming the parameter (the
        # Lagrange basis on 0, 1, 2 grows like t^2 / 2: 5e599 at t = 1e300).
        self.bad("basis", {"kind": "lagrange", "params": [0, 1, 2], "t": [0.5, 1e300]}, "t[1]", contains="not representable")
        self.bad("basis", {"kind": "hermite", "t": [1e200]}, "t[0]", contains="not representable")
        self.bad("basis", {"kind": "bernstein", "degree": 3, "knots": [0, 1], "t": [0]}, "knots", contains="another kind")
        self.bad("basis", {"kind": "catmull_rom", "params": [0, 1], "t": [0]}, "params", contains="another kind")
        self.bad("basis", {"kind": "hermite", "t": [0], "derivatives": -1}, "derivatives", contains=">= 0")
        self.bad("basis", {"kind": "hermite", "t": [0], "derivatives": 1.5}, "derivatives")
        self.bad("basis", {"kind": "hermite", "t": 0.5}, "t")
        self.bad("basis", {"kind": "hermite", "t": ["a"]}, "t[0]")
        self.bad("basis", where="request", text='{"kind": "hermite", "t": [NaN]}', contains="malformed JSON")
        self.bad("basis", {"kind": "hermite", "t": [0], "bogus": 1}, "bogus", contains="unknown field")
        self.bad("basis", {"kind": "bernstein", "degree": 100000, "t": [0.5] * 200}, "t", contains="limit")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
