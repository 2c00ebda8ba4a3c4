#!/usr/bin/python3
"""Black-box tests of `frames`: rotation-minimizing (double reflection) and Frenet frames of
a space curve.

Oracle: the exact rotation-minimizing frame of the circular helix (r cos t, r sin t, h t):
relative to its Frenet frame (N = (-cos t, -sin t, 0), B = T x N) the RMF normal is N
turned about T by the angle -tau s(t), tau = h / (r^2 + h^2) the torsion and
s = sqrt(r^2 + h^2) t the arc length (r' = -(tau) ... from N' = -kappa T + tau B: a normal
cos(phi) N + sin(phi) B moves along T only when phi' = -tau). The helix is given to the
program as a `lagrange` curve through 16 Chebyshev points of it on [0, pi] (half a turn;
the program takes Lagrange curves up to degree 15): the interpolation error of cos and
sin there is about 2 (pi / 4)^16 / 16! = 2e-15 (the Chebyshev remainder bound), so it is the
helix to rounding (its derivatives to about n^2 times that). Invariants: unit, orthogonal
vectors, binormal = tangent x normal.

Usage: test_frames.py PATH_TO_CASTELJAU [unittest options]
"""
import math
import os
import sys
import unittest

import numpy as np

import test_cli
from test_cli import CliTest

R, H = 1.0, 0.5
TAU = H / (R * R + H * H)
SPEED = math.sqrt(R * R + H * H)
T_END = math.pi


def helix_curve(n=16):
    # Chebyshev points of the second kind on [0, 2 pi].
    ts = [T_END / 2 * (1 - math.cos(math.pi * j / (n - 1))) for j in range(n)]
    return {"type": "lagrange", "params": ts, "points": [[R * math.cos(t), R * math.sin(t), H * t] for t in ts]}


def helix_frenet(t):
    tan = np.array([-R * math.sin(t), R * math.cos(t), H]) / SPEED
    nor = np.array([-math.cos(t), -math.sin(t), 0.0])
    return tan, nor, np.cross(tan, nor)


def helix_rmf_normal(t):
    _, n, b = helix_frenet(t)
    phi = -TAU * SPEED * t
    return math.cos(phi) * n + math.sin(phi) * b


def angle(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return math.atan2(np.linalg.norm(np.cross(a, b)), float(np.dot(a, b)))


class FramesTest(CliTest):
    def frames(self, **req):
        return self.ok("frames", req)

    def check_orthonormal(self, r, tol):
        for t, n, b in zip(r["tangents"], r["normals"], r["binormals"]):
            if n is None:
                self.assertIsNone(b)
                continue
            for v in (t, n, b):
                self.assertAlmostEqual(np.linalg.norm(v), 1, delta=tol)
            self.assertAlmostEqual(float(np.dot(t, n)), 0, delta=tol)
            self.assert_close(b, np.cross(t, n).tolist(), tol)

    def test_helix_rmf(self):
        # The program marches on its own grid (the fourth order of one double-reflection
        # step per interval is measured on rotation_minimizing_normals in
        # tests/unit/basis_rmf_test.cpp): every sampling gets the exact frame to the stated
        # accuracy (docs/cli.md: 1e-10 rad per piece).
        errors = []
        for n in [1, 4, 16, 128]:
            ts = [T_END * i / n for i in range(n + 1)]
            r = self.frames(curve=helix_curve(), t=ts)
            self.check_orthonormal(r, 1e-13)  # normalised each step: rounding only
            for t, tan in zip(ts, r["tangents"]):
                self.assertLess(angle(tan, helix_frenet(t)[0]), 1e-11)  # the interpolant's derivative error
            err = max(angle(nv, helix_rmf_normal(t)) for t, nv in zip(ts, r["normals"]))
            errors.append(err)
        print(f"\nhelix r=1 h=0.5 on [0, pi], RMF normal max angle error (rad) asked at 1/4/16/128 steps: "
              + ", ".join(f"{e:.3e}" for e in errors), file=sys.stderr)
        for e in errors:
            self.assertLess(e, 1e-10)

    def test_independent_of_sampling(self):
        # The frame at a parameter must not depend on which other parameters are asked: the
        # program marches on an internal grid. Oracle: the RMF ODE integrated by scipy. A
        # normal U (unit, normal to T = C'/|C'|) is rotation-minimizing when U' is parallel
        # to T, U' = -(U . T') T; as U . T = 0, U . T' = U . C'' / |C'|, so
        # dU/dt = -(U . C'') C' / |C'|^2.
        from scipy.integrate import solve_ivp
        p = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]], float)
        curve = {"type": "bezier", "points": p.tolist()}

        def rhs(t, u):
            d1 = 3 * ((1 - t) ** 2 * (p[1] - p[0]) + 2 * t * (1 - t) * (p[2] - p[1]) + t * t * (p[3] - p[2]))
            d2 = 6 * ((1 - t) * (p[2] - 2 * p[1] + p[0]) + t * (p[3] - 2 * p[2] + p[1]))
            return -np.dot(u, d2) * d1 / np.dot(d1, d1)

        # Frenet normal at 0: C'(0) along x, C''(0) along y.
        sol = solve_ivp(rhs, (0, 1), [0.0, 1.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-14)
        exact = sol.y[:, -1] / np.linalg.norm(sol.y[:, -1])
        alone = self.frames(curve=curve, t=[0, 1])["normals"][-1]
        many = self.frames(curve=curve, t=[i / 1000 for i in range(1001)])["normals"][-1]
        print(f"\ncubic [0, 1]: RMF normal at t = 1 vs the ODE: {angle(alone, exact):.2e} rad (t = [0, 1]), "
              f"{angle(many, exact):.2e} rad (1001 samples)", file=sys.stderr)
        self.assertLess(angle(alone, exact), 1e-8)
        self.assertLess(angle(many, exact), 1e-8)
        self.assertLess(angle(alone, many), 1e-8)
        # Across the breaks of a 20-piece cubic B-spline (scipy's BSpline for the oracle's
        # derivatives): asked at the ends alone, and among 401 samples.
        from scipy.interpolate import BSpline
        n = 20
        pts = np.array([[math.cos(0.3 * i), math.sin(0.3 * i), 0.1 * i] for i in range(n + 3)])
        knots = [0.0] * 3 + [float(i) for i in range(n + 1)] + [float(n)] * 3
        spline = BSpline(np.array(knots), pts, 3)
        d1, d2 = spline.derivative(1), spline.derivative(2)
        curve = {"type": "bspline", "degree": 3, "knots": knots, "points": pts.tolist()}
        alone = self.frames(curve=curve, t=[0, n])["normals"]
        many = self.frames(curve=curve, t=[n * i / 400 for i in range(401)])["normals"][-1]
        sol = solve_ivp(lambda t, u: -np.dot(u, d2(t)) * d1(t) / np.dot(d1(t), d1(t)), (0, n), alone[0],
                        method="DOP853", rtol=1e-13, atol=1e-14, max_step=0.5)
        exact = sol.y[:, -1] / np.linalg.norm(sol.y[:, -1])
        print(f"20-piece B-spline: at t = 20 vs the ODE: {angle(alone[-1], exact):.2e} rad (t = [0, 20]), "
              f"{angle(many, exact):.2e} rad (401 samples)", file=sys.stderr)
        self.assertLess(angle(alone[-1], exact), 1e-8)
        self.assertLess(angle(many, exact), 1e-8)
        # The helix's exact RMF, asked at the end alone.
        r = self.frames(curve=helix_curve(), t=[0, T_END])
        self.assertLess(angle(r["normals"][-1], helix_rmf_normal(T_END)), 1e-8)

    def test_helix_initial_normal(self):
        # Starting from the binormal instead of the normal: the whole frame turns by 90 degrees.
        ts = [T_END * i / 256 for i in range(257)]
        tan0, _, b0 = helix_frenet(0)
        r = self.frames(curve=helix_curve(), t=ts, initial_normal=(3 * b0 + 2 * tan0).tolist())  # projected, normalised
        self.assert_close(r["normals"][0], b0.tolist(), 1e-12)
        for t, nv in zip(ts, r["normals"]):
            want = np.cross(helix_frenet(t)[0], helix_rmf_normal(t))  # T x r: r turned by 90 degrees
            self.assertLess(angle(nv, want), 1e-10)  # the stated accuracy

    def test_helix_frenet(self):
        ts = [0, 0.3, 1, 2.5, 3, T_END]
        r = self.frames(curve=helix_curve(), t=ts, method="frenet")
        for t, tan, nv, bv in zip(ts, r["tangents"], r["normals"], r["binormals"]):
            want = helix_frenet(t)
            # the interpolant's first and second derivatives, about 1e-12 of the helix's
            self.assert_close(tan, want[0].tolist(), 1e-11)
            self.assert_close(nv, want[1].tolist(), 1e-10)
            self.assert_close(bv, want[2].tolist(), 1e-10)

    def test_straight_line(self):
        line = {"type": "bezier", "points": [[0, 0, 0], [1, 1, 1]]}
        r = self.frames(curve=line, t=[0, 0.5, 1], method="frenet")
        self.assertEqual(r["normals"], [None, None, None])
        self.assertEqual(r["binormals"], [None, None, None])
        s = 1 / math.sqrt(3)
        self.assert_close(r["tangents"], [[s, s, s]] * 3, 1e-15)
        self.bad("frames", {"curve": line, "t": [0, 1]}, "initial_normal", contains="Frenet normal")
        r = self.frames(curve=line, t=[0, 0.5, 1], initial_normal=[0, 0, 5])
        want = np.array([0, 0, 1]) - np.array([1, 1, 1]) / 3
        want = (want / np.linalg.norm(want)).tolist()
        self.assert_close(r["normals"], [want] * 3, 1e-15)  # constant along a line
        self.check_orthonormal(r, 1e-15)

    def test_empty_t(self):
        r = self.frames(curve=helix_curve(), t=[])
        self.assertEqual(r, {"tangents": [], "normals": [], "binormals": []})

    def test_bad_input(self):
        helix = helix_curve()
        self.bad("frames", {"curve": {"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]}, "t": [0]}, "curve", contains="3-D")
        self.bad("frames", {"curve": helix, "t": [0, 1, 1]}, "t[2]", contains="increasing")
        self.bad("frames", {"curve": helix, "t": [1, 0]}, "t[1]", contains="increasing")
        self.bad("frames", {"curve": helix, "t": [0], "method": "bishop"}, "method", contains="unknown")
        self.bad("frames", {"curve": helix, "t": [0], "initial_normal": [1, 0]}, "initial_normal", contains="3")
        tan0 = helix_frenet(0)[0]
        self.bad("frames", {"curve": helix, "t": [0], "initial_normal": (2 * tan0).tolist()}, "initial_normal",
                 contains="parallel")
        self.bad("frames", {"curve": helix, "t": [0], "initial_normal": [0, 0, 0]}, "initial_normal")
        self.bad("frames", {"curve": helix, "t": [0], "method": "frenet", "initial_normal": [1, 0, 0]}, "initial_normal")
        self.bad("frames", {"curve": helix}, "t", contains="missing")
        self.bad("frames", {"t": [0]}, "curve", contains="missing")
        stop = {"type": "bezier", "points": [[0, 0, 0], [0, 0, 0], [1, 1, 0], [1, 1, 1]]}
        self.bad("frames", {"curve": stop, "t": [0, 1]}, "t[0]", contains="velocity")

    def test_frenet_null_where_the_velocity_vanishes(self):
        # The contract: Frenet frames are null where undefined. At t = 0 (P0 = P1) the
        # velocity is zero: no tangent, normal or binormal; the other parameters keep
        # theirs. Tangents by hand: C'(t) = 3 sum B2_i(t) (P[i+1] - P[i]), differences 0,
        # (1, 1, 0), (0, -1, 1): at 1/2 (0.5, 0.25, 0.25), at 1 (0, -1, 1).
        stop = {"type": "bezier", "points": [[0, 0, 0], [0, 0, 0], [1, 1, 0], [1, 0, 1]]}
        r = self.frames(curve=stop, t=[0, 0.5, 1], method="frenet")
        self.assertEqual([r["tangents"][0], r["normals"][0], r["binormals"][0]], [None, None, None])
        self.assert_close(r["tangents"][1], (np.array([2, 1, 1]) / math.sqrt(6)).tolist(), 1e-15)
        self.assert_close(r["tangents"][2], [0, -1 / math.sqrt(2), 1 / math.sqrt(2)], 1e-15)
        for k in (1, 2):
            self.assertIsNotNone(r["normals"][k])
            self.assertAlmostEqual(float(np.dot(r["normals"][k], r["tangents"][k])), 0, delta=1e-15)
            self.assert_close(r["binormals"][k], np.cross(r["tangents"][k], r["normals"][k]).tolist(), 1e-15)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
