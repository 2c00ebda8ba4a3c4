#!/usr/bin/python3
"""Black-box tests of the `cubic_spline` and `hermite` curve types against independent
oracles at test time: scipy.interpolate (Debian's python3-scipy 1.10) CubicSpline for every
boundary (named and general bc_type tuples), CubicHermiteSpline for given tangents and the
simple tangent rules (tangents computed here from their formulas), PchipInterpolator and
Akima1DInterpolator; mpmath (an exact solve of the spline system at 50 digits) where the
spacing ratio is 1e6. Points and derivatives of orders 1..3 at the params, inside and
extrapolated, n = 2, 3, 4 and more, uneven spacing, d = 1 and 2. Also parametrizations,
closed curves, affine invariance, Kochanek-Bartels properties and the contract's errors.

Usage: test_interp_spline.py PATH_TO_CASTELJAU [unittest options]
"""
import json
import math
import os
import random
import sys
import unittest

import mpmath
import numpy as np
from scipy.interpolate import Akima1DInterpolator, CubicHermiteSpline, CubicSpline, PchipInterpolator

import test_cli
from test_cli import CliTest, run

# Agreement with scipy: 1e-12 relative to the largest value of that derivative order over
# the compared parameters (both sides evaluate the same cubics, one by Horner in the power
# form, one in the Hermite form, after solving the same well-conditioned systems).
REL = 1e-12


def evaluate(curve, ts, k=3):
    """Points and derivatives 1..k of the curve at ts, from the program."""
    rc, out, err = run("eval", {"curve": curve, "t": list(ts), "derivatives": k})
    assert rc == 0, err
    r = json.loads(out)
    return [np.array(r["points"])] + [np.array(d) for d in r.get("derivatives", [])]


def sample_params(rng, x):
    lo, hi = x[0], x[-1]
    return sorted(list(x) + [rng.uniform(lo, hi) for _ in range(15)] + [lo - 0.2 * (hi - lo), hi + 0.2 * (hi - lo)])


def random_data(rng, n, dim, uneven=True):
    if uneven:
        x = np.cumsum([0.0] + [rng.uniform(0.05, 2.0) for _ in range(n - 1)]) - rng.uniform(-2, 2)
    else:
        x = np.arange(float(n))
    y = np.array([[rng.uniform(-3, 3) for _ in range(dim)] for _ in range(n)])
    return x, y


class ScipyAgreement(CliTest):
    def agree(self, curve, ts, oracle, what, k=3, rel=REL, got=None):
        """oracle(ts, nu) -> array (len(ts), dim); compares orders 0..k (got: the
        program's evaluation, when already made)."""
        got = evaluate(curve, ts, k) if got is None else got
        x = np.array(curve.get("params", [0, 1]), dtype=float)
        length = x[-1] - x[0]
        for nu in range(k + 1):
            ref = np.asarray(oracle(np.array(ts), nu), dtype=float).reshape(got[nu].shape)
            scale = max(np.max(np.abs(ref)), np.max(np.abs(got[0])) / length ** nu, 1e-300)
            worst = np.max(np.abs(got[nu] - ref)) / scale
            self.assertLessEqual(worst, rel, f"{what}: order {nu}, relative error {worst:.3g}")

    def test_cubic_spline_every_boundary(self):
        rng = random.Random(61)
        pending = []  # (curve, ts, oracle, what)
        for n in (2, 3, 4, 5, 8, 13):
            for dim in (1, 2):
                for uneven in (True, False):
                    x, y = random_data(rng, n, dim, uneven)
                    ts = sample_params(rng, x)
                    v = lambda: [rng.uniform(-2, 2) for _ in range(dim)]
                    cases = [("natural", {}, "natural"), ("not-a-knot", {}, "not-a-knot")]
                    a, b = v(), v()
                    cases.append(("clamped", {"start_derivative": a, "end_derivative": b}, ((1, np.array(a)), (1, np.array(b)))))
                    for oa, ob in ((1, 2), (2, 1), (2, 2), (1, 1)):
                        a, b = v(), v()
                        cases.append(({"start": {"order": oa, "value": a}, "end": {"order": ob, "value": b}}, {},
                                      ((oa, np.array(a)), (ob, np.array(b)))))
                    for boundary, extra, bc in cases:
                        curve = dict({"type": "cubic_spline", "params": list(x), "points": y.tolist(), "boundary": boundary}, **extra)
                        s = CubicSpline(x, y, bc_type=bc)
                        pending.append((curve, ts, lambda t, nu, s=s: s(t, nu, extrapolate=True), f"n={n} d={dim} {boundary}"))
                    # Periodic: the last point repeats the first.
                    yp = y.copy()
                    yp[-1] = yp[0]
                    curve = {"type": "cubic_spline", "params": list(x), "points": yp.tolist(), "boundary": "periodic"}
                    # scipy extrapolates a periodic spline periodically (and so answers at the
                    # last param from the first piece); the contract extends the end pieces.
                    # Column by column: scipy 1.10's 3-point periodic shortcut sums the slopes of
                    # all columns of a 2-D y into one (its C^2 conditions then fail); per column
                    # it is the exact solution of the cyclic system.
                    cols = [CubicSpline(x, yp[:, j], bc_type="periodic", extrapolate=True) for j in range(dim)]
                    pending.append((curve, ts, lambda t, nu, cols=cols: np.stack([c(t, nu, extrapolate=True) for c in cols], axis=1),
                                    f"n={n} d={dim} periodic"))
        # The program's evaluations in one --jsonl process (only the responses are checked).
        rc, answers, err = test_cli.run_jsonl("eval", [{"curve": c, "t": list(ts), "derivatives": 3} for c, ts, _, _ in pending])
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual(len(answers), len(pending))
        for (curve, ts, oracle, what), r in zip(pending, answers):
            got = [np.array(r["points"])] + [np.array(d) for d in r["derivatives"]]
            self.agree(curve, ts, oracle, what, got=got)

    def test_default_boundary_is_natural(self):
        x, y = [0, 1, 2.5, 3], [0, 1, 0, 2]
        s = CubicSpline(x, y, bc_type="natural")
        self.agree({"type": "cubic_spline", "params": x, "points": [[v] for v in y]}, [0.5, 2, 4], lambda t, nu: s(t, nu), "default")

    def test_small_n_as_scipy(self):
        # not-a-knot through 2 points is the line, through 3 the parabola; periodic 2 equal points: constant.
        got = evaluate({"type": "cubic_spline", "params": [0, 2], "points": [[1], [5]], "boundary": "not-a-knot"}, [-1, 0.5, 3])
        np.testing.assert_allclose(got[0].ravel(), [-1, 2, 7], rtol=1e-15)
        np.testing.assert_array_equal(got[2].ravel(), [0, 0, 0])
        got = evaluate({"type": "cubic_spline", "params": [0, 1, 3], "points": [[0], [1], [9]], "boundary": "not-a-knot"}, [2, -1])
        np.testing.assert_allclose(got[0].ravel(), [4, 1], rtol=1e-14)  # the parabola x^2
        np.testing.assert_allclose(got[2].ravel(), [2, 2], rtol=1e-13)
        np.testing.assert_allclose(got[3].ravel(), [0, 0], atol=1e-13)
        got = evaluate({"type": "cubic_spline", "params": [0, 1], "points": [[3, 1], [3, 1]], "boundary": "periodic"}, [0.3, 7])
        np.testing.assert_array_equal(got[0], [[3, 1], [3, 1]])
        np.testing.assert_array_equal(got[1], [[0, 0], [0, 0]])

    def test_hermite_given_tangents(self):
        rng = random.Random(62)
        for n in (2, 3, 4, 9):
            for dim in (1, 3):
                x, y = random_data(rng, n, dim)
                m = np.array([[rng.uniform(-4, 4) for _ in range(dim)] for _ in range(n)])
                s = CubicHermiteSpline(x, y, m)
                curve = {"type": "hermite", "params": list(x), "points": y.tolist(), "tangents": m.tolist()}
                self.agree(curve, sample_params(rng, x), lambda t, nu: s(t, nu), f"hermite n={n} d={dim}")

    def rule_tangents(self, rule, x, y, **kw):
        """Tangents of the simple rules, from their formulas (docs/cli.md), written here."""
        n = len(x)
        d = [(y[i + 1] - y[i]) / (x[i + 1] - x[i]) for i in range(n - 1)]
        if rule == "finite_difference":
            return np.array([d[0]] + [(d[i - 1] + d[i]) / 2 for i in range(1, n - 1)] + [d[-1]])
        c = kw.get("tension", 0.0)
        return (1 - c) * np.array([d[0]] + [(y[i + 1] - y[i - 1]) / (x[i + 1] - x[i - 1]) for i in range(1, n - 1)] + [d[-1]])

    def test_simple_tangent_rules(self):
        rng = random.Random(63)
        for n in (2, 3, 6):
            x, y = random_data(rng, n, 2)
            ts = sample_params(rng, x)
            for rule, extra in (("finite_difference", {}), ("catmull_rom", {}), ("cardinal", {"tension": 0.3}),
                                ("cardinal", {"tension": 1})):
                m = self.rule_tangents(rule, x, y, **extra)
                s = CubicHermiteSpline(x, y, m)
                curve = dict({"type": "hermite", "params": list(x), "points": y.tolist(), "tangent_rule": rule}, **extra)
                self.agree(curve, ts, lambda t, nu: s(t, nu), f"{rule} {extra} n={n}")
            # Kochanek-Bartels with zero parameters is the finite-difference rule.
            m = self.rule_tangents("finite_difference", x, y)
            s = CubicHermiteSpline(x, y, m)
            self.agree({"type": "hermite", "params": list(x), "points": y.tolist(), "tangent_rule": "kochanek_bartels"}, ts,
                       lambda t, nu: s(t, nu), f"kochanek_bartels zero n={n}")

    def test_monotone_is_pchip(self):
        rng = random.Random(64)
        datasets = [([0, 1], [[0], [2]]), ([0, 1, 3], [[0], [2], [2.5]]), ([0, 0.5, 3, 3.2], [[1], [0], [0], [4]]),
                    ([0, 1, 2, 3, 4, 5], [[0], [0], [1], [1], [0], [-3]]), ([0, 1, 2], [[0], [5], [0]])]
        for _ in range(12):
            x, y = random_data(rng, rng.randint(2, 12), 1)
            datasets.append((list(x), y.tolist()))
        x, y = random_data(rng, 7, 3)
        datasets.append((list(x), y.tolist()))
        for x, y in datasets:
            s = PchipInterpolator(np.array(x, dtype=float), np.array(y, dtype=float))
            curve = {"type": "hermite", "params": x, "points": y, "tangent_rule": "monotone"}
            self.agree(curve, sample_params(rng, np.array(x, dtype=float)), lambda t, nu: s(t, nu, extrapolate=True), f"pchip {x} {y}")

    def test_akima(self):
        rng = random.Random(65)
        # Flat runs give equal (zero) weights: the fill value (m_i + m_(i+3)) / 2.
        datasets = [([0, 1, 2], [[0], [1], [3]]), ([0, 1, 2, 3, 4, 5, 6], [[0], [0], [0], [1], [1], [1], [2]]),
                    ([0, 1, 2, 3, 4, 5], [[0], [1], [2], [3], [2], [1]]), ([0, 0.1, 3, 3.5], [[1], [0], [0], [4]])]
        for _ in range(12):
            x, y = random_data(rng, rng.randint(3, 12), 1)
            datasets.append((list(x), y.tolist()))
        for x, y in datasets:
            xa = np.array(x, dtype=float)
            s = Akima1DInterpolator(xa, np.array(y, dtype=float))
            curve = {"type": "hermite", "params": x, "points": y, "tangent_rule": "akima"}
            self.agree(curve, sample_params(rng, xa), lambda t, nu: s(t, nu, extrapolate=True), f"akima {x} {y}")
        # Per coordinate in 2-D: each column as its own 1-D Akima interpolant.
        x, y = random_data(rng, 8, 2)
        cols = [Akima1DInterpolator(x, y[:, j]) for j in range(2)]
        self.agree({"type": "hermite", "params": list(x), "points": y.tolist(), "tangent_rule": "akima"}, sample_params(rng, x),
                   lambda t, nu: np.stack([c(t, nu, extrapolate=True) for c in cols], axis=1), "akima 2-D")

    def test_parametrizations(self):
        P = [[0, 0], [1, 0], [1, 2], [4, 6], [4.5, 6]]
        for rule in ("uniform", "chord", "centripetal"):
            u = [0.0]
            for a, b in zip(P, P[1:]):
                dist = math.hypot(b[0] - a[0], b[1] - a[1])
                u.append(u[-1] + {"uniform": 1.0, "chord": dist, "centripetal": math.sqrt(dist)}[rule])
            s = CubicSpline(u, P, bc_type="natural")
            curve = {"type": "cubic_spline", "parametrization": rule, "points": P}
            ts = [u[0] + (u[-1] - u[0]) * i / 20 for i in range(21)]
            got = evaluate(curve, ts, 2)
            for nu in range(3):
                np.testing.assert_allclose(got[nu], s(ts, nu), rtol=1e-12, atol=1e-12 * np.max(np.abs(s(ts, nu))))
            m = PchipInterpolator(u, P)
            got = evaluate({"type": "hermite", "parametrization": rule, "points": P, "tangent_rule": "monotone"}, ts, 1)
            np.testing.assert_allclose(got[0], m(ts), rtol=1e-12, atol=1e-12)
        # A closed curve: periodic on chord parameters, C^2 where the ends meet.
        C = [[1, 0], [0, 1], [-1, 0], [0, -1.5], [1, 0]]
        curve = {"type": "cubic_spline", "parametrization": "chord", "points": C, "boundary": "periodic"}
        rc, out, _ = run("eval", {"curve": curve, "t": [0], "derivatives": 2})
        d0 = json.loads(out)["derivatives"]
        dom_end = sum(math.dist(a, b) for a, b in zip(C, C[1:]))
        rc, out, _ = run("eval", {"curve": curve, "t": [dom_end], "derivatives": 2})
        d1 = json.loads(out)["derivatives"]
        for k in range(2):
            np.testing.assert_allclose(d0[k], d1[k], rtol=1e-12, atol=1e-12)

    def test_affine_invariance(self):
        rng = random.Random(66)
        P = np.array([[rng.uniform(-2, 2), rng.uniform(-2, 2)] for _ in range(7)])
        A = np.array([[1.5, 0.7], [-0.3, 0.4]])  # a shear and scale, not a similarity
        b = np.array([3.0, -1.0])
        Q = P @ A.T + b
        u = sorted(rng.uniform(0, 5) for _ in range(7))
        ts = [u[0] + (u[-1] - u[0]) * i / 30 for i in range(31)]
        for extra in ({"type": "cubic_spline", "params": u}, {"type": "cubic_spline", "params": u, "boundary": "not-a-knot"},
                      {"type": "cubic_spline", "parametrization": "uniform"},
                      {"type": "hermite", "params": u, "tangent_rule": "catmull_rom"},
                      {"type": "hermite", "params": u, "tangent_rule": "kochanek_bartels", "tension": 0.2, "continuity": 0.5, "bias": -0.3}):
            tts = ts if "params" in extra else [6 * i / 30 for i in range(31)]
            a = evaluate(dict(extra, points=P.tolist()), tts, 0)[0]
            c = evaluate(dict(extra, points=Q.tolist()), tts, 0)[0]
            np.testing.assert_allclose(c, a @ A.T + b, rtol=0, atol=1e-12 * np.max(np.abs(c)), err_msg=str(extra))
        # Chord parameters commute with a similarity (rotation and scale s: parameters times s),
        # not with the shear above.
        ang, sc = 0.7, 2.5
        S = sc * np.array([[math.cos(ang), -math.sin(ang)], [math.sin(ang), math.cos(ang)]])
        R = P @ S.T + b
        chord = {"type": "cubic_spline", "parametrization": "chord"}
        length = sum(np.linalg.norm(P[i + 1] - P[i]) for i in range(6))
        ts = [length * i / 30 for i in range(31)]
        a = evaluate(dict(chord, points=P.tolist()), ts, 0)[0]
        c = evaluate(dict(chord, points=R.tolist()), [sc * t for t in ts], 0)[0]
        np.testing.assert_allclose(c, a @ S.T + b, rtol=0, atol=1e-12 * np.max(np.abs(c)))
        c = evaluate(dict(chord, points=Q.tolist()), ts, 0)[0]
        self.assertGreater(np.max(np.abs(c - (a @ A.T + b))), 1e-3)


class ExtremeScales(CliTest):
    """Issue 15: params and coordinates from 1e-300 to 1e300 and near the largest double.
    The oracle is scipy at unit scale, scaled: C_ab(a x) = b C(x), derivatives of order k
    times b / a^k (Python floats; the scaling is a few ulps)."""

    DATA_X = [0.0, 1.0, 2.5, 3.0, 4.5]
    DATA_Y = [[0.0, 1.0], [1.0, -1.0], [0.0, 2.0], [2.0, 0.5], [1.0, 1.0]]

    def compare(self, curve, a, b, spline, what):
        xs = [0.25, 1.7, 2.9, 4.0]
        r = self.ok("eval", {"curve": curve, "t": [a * x for x in xs], "derivatives": 1})
        ref = spline(np.array(xs))
        dref = spline(np.array(xs), 1)
        for got, want in zip(r["points"], ref):
            for g, w in zip(got, want):
                self.assertLessEqual(abs(g - b * w), 1e-13 * b * 3, f"{what}: {got} vs {b * want}")
        if math.isfinite(b / a) and b / a > 1e-300:
            for got, want in zip(r["derivatives"][0], dref):
                for g, w in zip(got, want):
                    self.assertLessEqual(abs(g - b / a * w), 1e-12 * b / a * 10, f"{what} derivative")

    def test_boundaries_and_rules_at_every_scale(self):
        x, y = np.array(self.DATA_X), np.array(self.DATA_Y)
        scales = [(1e300, 1e300), (1e-300, 1e-300), (1e300, 1.0), (1e-300, 1.0), (1.0, 1e300), (1.0, 1e-300), (1e154, 1e154),
                  (3e307, 1.0), (1e-160, 1e-160)]
        for a, b in scales:
            params, points = [a * v for v in x], [[b * c for c in p] for p in y]
            for boundary, bc in (("natural", "natural"), ("not-a-knot", "not-a-knot")):
                curve = {"type": "cubic_spline", "params": params, "points": points, "boundary": boundary}
                self.compare(curve, a, b, CubicSpline(x, y, bc_type=bc), f"{boundary} a={a} b={b}")
            for rule in ("monotone", "akima", "catmull_rom"):
                curve = {"type": "hermite", "params": params, "points": points, "tangent_rule": rule}
                if rule == "monotone":
                    ref = PchipInterpolator(x, y)
                elif rule == "akima":
                    ref = Akima1DInterpolator(x, y)
                else:
                    m = np.array([(y[1] - y[0]) / (x[1] - x[0])] + [(y[i + 1] - y[i - 1]) / (x[i + 1] - x[i - 1]) for i in range(1, 4)]
                                 + [(y[4] - y[3]) / (x[4] - x[3])])
                    ref = CubicHermiteSpline(x, y, m)
                self.compare(curve, a, b, ref, f"{rule} a={a} b={b}")

    def test_domain_longer_than_the_largest_double(self):
        # Was "error: internal: solve_tridiagonal: zero pivot" (exit 1).
        curve = {"type": "cubic_spline", "params": [-1e308, 0, 1e308, 1.5e308], "points": [[0], [1], [0], [2]]}
        self.bad("eval", {"curve": curve, "t": [0]}, "curve.params", contains="longer than the largest double")
        # 0, 1e308, 1.7e308: the domain is a double, 2 (h0 + h1) is not; natural spline by
        # hand: M1 = 3 (d1 - d0) / (h0 + h1), S(x) = (1 - M1 / 6) x + M1 x^3 / 6 on [0, 1].
        r = self.ok("eval", {"curve": {"type": "cubic_spline", "params": [0, 1e308, 1.7e308], "points": [[0], [1], [0]]},
                             "t": [0.5e308]})
        M1 = 3 * (-1 / 0.7 - 1) / 1.7
        self.assertAlmostEqual(r["points"][0][0], (1 - M1 / 6) * 0.5 + M1 * 0.125 / 6, delta=1e-15)

    def test_coordinates_whose_differences_overflow(self):
        # +-1e308 alternating: the natural spline through (0, -1), (1, 1), (2, -1), (3, 1),
        # scaled (scipy at unit scale); differences of the points overflow, the curve does not.
        x = np.array([0.0, 1, 2, 3])
        s = CubicSpline(x, [-1.0, 1, -1, 1], bc_type="natural")
        curve = {"type": "cubic_spline", "params": [1e300 * v for v in x], "points": [[-1e308], [1e308], [-1e308], [1e308]]}
        ts = [0.5, 1.5, 2.25]
        r = self.ok("eval", {"curve": curve, "t": [1e300 * t for t in ts]})
        for got, want in zip(r["points"], s(np.array(ts))):
            self.assertLessEqual(abs(got[0] - 1e308 * want), 1e-15 * 1e308 * 3)
        # A slope that overflows is refused naming points (not tangents, which were not given).
        self.bad("eval", {"curve": {"type": "cubic_spline", "params": [0, 1e-300, 2e-300], "points": [[0], [1e300], [0]]}, "t": [0]},
                 "curve.points", contains="overflow")


class KochanekBartels(CliTest):
    def test_continuity_minus_one_is_the_polyline(self):
        P = [[0, 0], [1, 2], [3, 2.5], [4, 0]]
        curve = {"type": "hermite", "parametrization": "uniform", "points": P, "tangent_rule": "kochanek_bartels", "continuity": -1}
        ts = [i / 10 for i in range(31)]
        got = evaluate(curve, ts, 0)[0]
        for t, p in zip(ts, got):
            i = min(int(t), 2)
            a, b = np.array(P[i]), np.array(P[i + 1])
            # On the chord from P_i to P_(i+1) (the tangents are the chord itself).
            self.assertLess(abs(np.cross(b - a, p - a)), 1e-12, t)

    def test_tension_one_gives_zero_tangents(self):
        P = [[0, 0], [1, 2], [3, 2.5]]
        for rule, extra in (("kochanek_bartels", {"tension": 1}), ("cardinal", {"tension": 1})):
            curve = dict({"type": "hermite", "params": [0, 1, 3], "points": P, "tangent_rule": rule}, **extra)
            got = evaluate(curve, [0, 1, 3], 1)[1]
            np.testing.assert_array_equal(got, np.zeros((3, 2)))

    def test_one_sided_tangents(self):
        # With continuity c, the incoming and outgoing derivatives at an interior point differ:
        # (1 - t)/2 ((1 + b)(1 -+ c) d_prev + (1 - b)(1 +- c) d_next), as [KB84] gives them.
        P, u = [[0.0], [2.0], [3.0]], [0, 1, 3]
        t, c, b = 0.2, 0.4, -0.3
        curve = {"type": "hermite", "params": u, "points": P, "tangent_rule": "kochanek_bartels", "tension": t, "continuity": c, "bias": b}
        dp, dn = 2.0, 0.5
        out = (1 - t) / 2 * ((1 + b) * (1 + c) * dp + (1 - b) * (1 - c) * dn)
        inc = (1 - t) / 2 * ((1 + b) * (1 - c) * dp + (1 - b) * (1 + c) * dn)
        right = evaluate(curve, [1], 1)[1][0][0]      # the right piece answers at a param
        left = evaluate(curve, [1 - 1e-9], 1)[1][0][0]
        self.assertAlmostEqual(right, out, delta=1e-13)
        self.assertAlmostEqual(left, inc, delta=1e-7)
        # The curve JSON of to_bezier keeps the corner: the pieces' inner control points.
        rc, o, _ = run("to_bezier", {"curve": curve})
        segs = json.loads(o)["curve"]["segments"]
        self.assertAlmostEqual(segs[0]["points"][2][0], 2 - inc / 3, delta=1e-14)
        self.assertAlmostEqual(segs[1]["points"][1][0], 2 + 2 * out / 3, delta=1e-14)


class CatmullRomUniform(CliTest):
    def test_uniform_catmull_rom_tangents(self):
        # On uniform params the rule gives f'(j) = (p[j+1] - p[j-1]) / 2 at interior points
        # (the uniform Catmull-Rom curve of the contract on the interior intervals).
        P = [[0, 0], [1, 3], [4, 4], [6, 0], [7, 1]]
        curve = {"type": "hermite", "parametrization": "uniform", "points": P, "tangent_rule": "catmull_rom"}
        got = evaluate(curve, [1, 2, 3], 1)[1]
        for j, g in zip((1, 2, 3), got):
            np.testing.assert_array_equal(g, (np.array(P[j + 1]) - np.array(P[j - 1])) / 2)


def mp_spline(x, y, bc, ts, k):
    """The spline's order-k derivative at ts, solved and evaluated exactly (mpmath, 50
    digits) from the system of C^2 conditions with natural or not-a-knot ends, written
    independently of the program as a dense system."""
    mpmath.mp.dps = 50
    X = [mpmath.mpf(v) for v in x]
    Y = [mpmath.mpf(v) for v in y]
    n = len(X)
    h = [X[i + 1] - X[i] for i in range(n - 1)]
    d = [(Y[i + 1] - Y[i]) / h[i] for i in range(n - 1)]
    A = mpmath.zeros(n, n)
    r = mpmath.zeros(n, 1)
    for i in range(1, n - 1):
        A[i, i - 1], A[i, i], A[i, i + 1] = h[i], 2 * (h[i - 1] + h[i]), h[i - 1]
        r[i] = 3 * (h[i] * d[i - 1] + h[i - 1] * d[i])
    if bc == "natural":  # C''(x0) = 0 = C''(xn)
        A[0, 0], A[0, 1], r[0] = 2, 1, 3 * d[0]
        A[n - 1, n - 2], A[n - 1, n - 1], r[n - 1] = 1, 2, 3 * d[-1]
    else:  # not-a-knot: third derivative continuous at x1 and x(n-2)
        # c3 of piece i is (s_i + s_(i+1) - 2 d_i) / h_i^2; equal for pieces 0 and 1.
        A[0, 0], A[0, 1], A[0, 2] = 1 / h[0] ** 2, 1 / h[0] ** 2 - 1 / h[1] ** 2, -1 / h[1] ** 2
        r[0] = 2 * d[0] / h[0] ** 2 - 2 * d[1] / h[1] ** 2
        A[n - 1, n - 3], A[n - 1, n - 2] = 1 / h[-2] ** 2, 1 / h[-2] ** 2 - 1 / h[-1] ** 2
        A[n - 1, n - 1] = -1 / h[-1] ** 2
        r[n - 1] = 2 * d[-2] / h[-2] ** 2 - 2 * d[-1] / h[-1] ** 2
    s = mpmath.lu_solve(A, r)
    out = []
    for t in ts:
        T = mpmath.mpf(t)
        i = max(0, min(n - 2, max(j for j in range(n) if X[j] <= T) if T >= X[0] else 0))
        dx = T - X[i]
        c3 = (s[i] + s[i + 1] - 2 * d[i]) / h[i] ** 2
        c2 = (3 * d[i] - 2 * s[i] - s[i + 1]) / h[i]
        coef = [Y[i], s[i], c2, c3]
        val = sum(coef[j] * mpmath.ff(j, k) * dx ** (j - k) for j in range(k, 4))
        out.append(float(val))
    return np.array(out)


class SpacingRatio1e6(CliTest):
    def test_against_mpmath(self):
        xs = [[0, 1e-6, 1, 2, 2 + 1e-6, 3], [0, 1, 1 + 1e-6, 1 + 2e-6, 2, 3e6 + 2], [0, 1e-6, 2e-6, 1, 1 + 1e-6, 2]]
        rng = random.Random(67)
        for x in xs:
            y = [rng.uniform(-1, 1) for _ in x]
            ts = sorted(x + [rng.uniform(x[0], x[-1]) for _ in range(10)] + [a + 0.3 * (b - a) for a, b in zip(x, x[1:])])
            for bc in ("natural", "not-a-knot"):
                curve = {"type": "cubic_spline", "params": x, "points": [[v] for v in y], "boundary": bc}
                got = evaluate(curve, ts, 1)
                sp = CubicSpline(x, y, bc_type=bc)
                for k in range(2):
                    exact = mp_spline(x, y, bc, ts, k)
                    scale = np.max(np.abs(exact))
                    ours = np.max(np.abs(got[k].ravel() - exact)) / scale
                    theirs = np.max(np.abs(sp(ts, k) - exact)) / scale
                    # Ours within 2e-9 of the exact spline, relative to the largest value of the
                    # order: the data's rounding (eps) is amplified by up to the spacing ratio
                    # (not-a-knot extends a cubic from a 1e-6 interval over a unit one):
                    # 2.2e-16 * 1e6 = 2.2e-10, with a factor 10 of margin. Measured: ours and
                    # scipy's errors agree (set VERBOSE=1 to print them).
                    self.assertLessEqual(ours, 2e-9, f"{x} {bc} order {k}: ours {ours:.2g}, scipy {theirs:.2g}")
                    if os.environ.get("VERBOSE"):
                        print(f"{bc} order {k}: ours {ours:.2g} scipy {theirs:.2g}")


class Errors(CliTest):
    def bad_curve(self, curve, where, contains=None):
        return self.bad("eval", {"curve": curve, "t": [0.5]}, where, contains=contains)

    def test_errors(self):
        P = [[0], [1], [0]]
        h = lambda **kw: dict({"type": "hermite", "params": [0, 1, 2], "points": P, "tangents": [[1], [0], [1]]}, **kw)
        s = lambda **kw: dict({"type": "cubic_spline", "params": [0, 1, 2], "points": P}, **kw)
        self.ok("eval", {"curve": h(), "t": [0.5]})
        self.ok("eval", {"curve": s(), "t": [0.5]})
        self.bad_curve(h(tangents=[[1], [0]]), "curve.tangents", "one tangent per param")
        self.bad_curve(h(tangents=[[1], [0], [1, 2]]), "curve.tangents[2]", "coordinates")
        self.bad_curve(h(tangent_rule="akima"), "curve.tangent_rule", "not both")
        self.bad_curve({"type": "hermite", "params": [0, 1, 2], "points": P}, "curve.tangents", "missing")
        self.bad_curve(h(tension=0.5), "curve.tension", "belongs to tangent_rule")
        rule = lambda r, **kw: dict({"type": "hermite", "params": [0, 1, 2], "points": P, "tangent_rule": r}, **kw)
        self.bad_curve(rule("monotone", tension=0.5), "curve.tension", "belongs to tangent_rule")
        self.bad_curve(rule("cardinal", bias=0.5), "curve.bias", "'kochanek_bartels'")
        self.bad_curve(rule("cardinal", tension=1.5), "curve.tension", "[0, 1]")
        self.bad_curve(rule("kochanek_bartels", continuity=-2), "curve.continuity", "[-1, 1]")
        self.bad_curve(rule("spline"), "curve.tangent_rule", "'akima'")
        self.bad_curve(dict(rule("akima"), params=[0, 1], points=[[0], [1]]), "curve.points", "at least 3")
        self.bad_curve(h(params=[0, 2, 1]), "curve.params[2]", "strictly increasing")
        self.bad_curve(h(params=[0, 1, 1]), "curve.params[2]", "strictly increasing")
        self.bad_curve(s(params=[0, 0, 1]), "curve.params[1]", "strictly increasing")
        self.bad_curve(s(params=[0, 1]), "curve.points", "one point per param")
        self.bad_curve(h(params=[0, 1, "x"]), "curve.params[2]")
        self.bad("eval", text='{"curve": {"type": "cubic_spline", "params": [0, 1, NaN], "points": [[0], [1], [0]]}, "t": [0]}',
                 where="request", contains="malformed")
        self.bad("eval", where="curve.params[2]",
                 text='{"curve": {"type": "cubic_spline", "params": [0, 1, 1e400], "points": [[0], [1], [0]]}, "t": [0]}')
        self.bad_curve(s(parametrization="chord"), "curve.parametrization", "not both")
        self.bad_curve({"type": "cubic_spline", "points": P}, "curve.params", "missing")
        self.bad_curve({"type": "cubic_spline", "points": [[0, 0], [1, 1], [1, 1]], "parametrization": "chord"}, "curve.points[2]",
                       "distinct")
        self.bad_curve({"type": "hermite", "points": [[0, 0], [0, 0]], "parametrization": "centripetal", "tangent_rule": "catmull_rom"},
                       "curve.points[1]", "distinct")
        self.ok("eval", {"curve": {"type": "cubic_spline", "points": [[0, 0], [1, 1], [1, 1]], "parametrization": "uniform"}, "t": [1]})
        self.bad_curve({"type": "cubic_spline", "points": P, "parametrization": "arc"}, "curve.parametrization", "'centripetal'")
        self.bad_curve(s(boundary="periodic", points=[[0], [1], [1e-300]]), "curve.points[2]", "equal points[0]")
        self.bad_curve(s(boundary="free"), "curve.boundary", "'not-a-knot'")
        self.bad_curve(s(boundary=3), "curve.boundary", "string or an object")
        self.bad_curve(s(start_derivative=[1]), "curve.start_derivative", "belongs to boundary 'clamped'")
        self.bad_curve(s(boundary="not-a-knot", end_derivative=[1]), "curve.end_derivative", "'not-a-knot'")
        self.bad_curve(s(boundary="clamped", start_derivative=[1]), "curve.end_derivative", "missing")
        self.bad_curve(s(boundary="clamped", start_derivative=[1, 2], end_derivative=[0]), "curve.start_derivative", "coordinates")
        self.bad_curve(s(boundary={"start": {"order": 3, "value": [0]}, "end": {"order": 1, "value": [0]}}), "curve.boundary.start.order",
                       "1 or 2")
        self.bad_curve(s(boundary={"start": {"order": 1, "value": [0]}}), "curve.boundary.end", "missing")
        self.bad_curve(s(boundary={"start": {"order": 1, "value": [0]}, "end": {"order": 1, "value": [0], "x": 1}}),
                       "curve.boundary.end.x", "unknown field")
        self.bad_curve(s(boundary={"start": {"order": 1, "value": [0]}, "end": {"order": 1, "value": ["a"]}}),
                       "curve.boundary.end.value[0]")
        self.bad_curve(s(tangents=[[0]] * 3), "curve.tangents", "unknown field")
        self.bad_curve(s(boundary={"start": {"order": 1, "value": [0]}, "end": {"order": 1, "value": [0]}, "middle": 1}),
                       "curve.boundary.middle", "unknown field")
        self.bad_curve({"type": "cubic_spline", "params": [0], "points": [[0]]}, "curve.points", "at least 2")
        self.bad_curve(s(dim=2), "curve.dim")
        self.bad("eval", {"curve": s(), "t": [float("inf")]} if False else {"curve": s(), "t": ["x"]}, "t[0]")

    def test_extrapolation_overflow_is_an_error(self):
        c = {"type": "cubic_spline", "params": [0, 1, 2], "points": [[0], [1e300], [0]]}
        self.bad("eval", {"curve": c, "t": [1e200]}, "t[0]")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
