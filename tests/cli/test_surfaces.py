#!/usr/bin/python3
"""Black-box tests of the surfaces (issue 19): surface JSON, the surface forms of eval,
split, elevate, insert_knot, to_bezier, isocurve, project, intersect, and the `surface`
constructions.

Oracles, all independent of the program:
- a tensor-product evaluator written here (Cox-de Boor by its recursive definition, the
  rational quotient), in numpy floats and in mpmath at 40 digits; partial derivatives by
  mpmath.diff of the mpmath evaluator (numerical differentiation at high precision);
- closed forms: the sphere, torus, cylinder and cone of `revolve` (distances, Gaussian
  and mean curvatures), the hyperbolic paraboloid's curvatures, rotations by Rodrigues'
  formula, extrusion and ruled surfaces from de Casteljau written here;
- numpy.linalg.lstsq for the least-squares fit, on design matrices built here;
- project: closed forms (sphere, torus, cylinder, plane, a parabolic trough's two tied
  minimisers) and, on random surfaces, dense sampling refined by scipy.optimize on the
  evaluator here (the answer must not be worse); intersect: closed forms (rays through
  and tangent to a sphere, a line on a plane), points checked on both by the evaluators
  here, crossings counted by sign changes on a graph surface;
- properties: splitting, elevation, knot insertion and the Bézier patches leave the
  surface unchanged; interpolation passes through its data.
- curvatures of random surfaces of the four types: partials from the exact derivatives of
  the basis and the quotient rule in mpmath at 40 digits, then the contract's formulas
  (SurfaceCurvatureOracleTest);
- seeded random properties of every type (SurfacePropertyTest): partition of unity, affine
  invariance, knot insertion, degree elevation and split on dense grids, through the program
  and the evaluator here; each check shown to fail when one control point moves by 1e-9.

Usage: test_surfaces.py PATH_TO_CASTELJAU [unittest options]
"""
import json
import math
import os
import random
import sys
import unittest

import mpmath
import numpy as np

import test_cli
from test_cli import CliTest, de_casteljau

# Evaluations are sums of convex combinations of O(1) data: a few dozen eps.
TIGHT = 1e-13


def basis(U, p, i, t):
    """N_{i,p}(t) by the Cox-de Boor recursion (0/0 = 0), right-continuous, the last
    non-empty span closed at the domain's end."""
    n = len(U) - p - 1
    if p == 0:
        if U[i] <= t < U[i + 1]:
            return 1
        # the domain's end belongs to the last non-empty span
        if t == U[n] and U[i] < U[i + 1] == U[n]:
            return 1
        return 0
    a = 0 if U[i + p] == U[i] else (t - U[i]) / (U[i + p] - U[i]) * basis(U, p - 1, i, t)
    b = 0 if U[i + p + 1] == U[i + 1] else (U[i + p + 1] - t) / (U[i + p + 1] - U[i + 1]) * basis(U, p - 1, i + 1, t)
    return a + b


def knots_of(s):
    """(p, q, U, V) of a surface object (Bézier kinds: clamped on [0, 1])."""
    P = s["points"]
    if s["type"] in ("bezier_surface", "rational_bezier_surface"):
        n, m = len(P) - 1, len(P[0]) - 1
        return n, m, [0] * (n + 1) + [1] * (n + 1), [0] * (m + 1) + [1] * (m + 1)
    return s["degree"][0], s["degree"][1], s["knots"][0], s["knots"][1]


def evaluate(s, u, v, num=float):
    """S(u, v) of a surface object, by the definition: sum N_i(u) N_j(v) w_ij P_ij / sum
    N_i(u) N_j(v) w_ij, in the number type num (float or mpmath.mpf)."""
    p, q, U, V = knots_of(s)
    U = [num(x) for x in U]
    V = [num(x) for x in V]
    u, v = num(u), num(v)
    P = s["points"]
    W = s.get("weights")
    d = len(P[0][0])
    acc = [num(0)] * d
    den = num(0)
    for i in range(len(P)):
        bu = basis(U, p, i, u)
        if bu == 0:
            continue
        for j in range(len(P[0])):
            b = bu * basis(V, q, j, v)
            if b == 0:
                continue
            w = num(W[i][j]) if W else num(1)
            den += b * w
            for k in range(d):
                acc[k] += b * w * num(P[i][j][k])
    return [a / den for a in acc]


def partial_mp(s, u, v, a, b):
    """d^(a+b) S / du^a dv^b by mpmath.diff of the 40-digit evaluator (u, v away from knots)."""
    with mpmath.workdps(40):
        d = len(s["points"][0][0])
        return [float(mpmath.diff(lambda x, y, k=k: evaluate(s, x, y, mpmath.mpf)[k], (mpmath.mpf(u), mpmath.mpf(v)), (a, b)))
                for k in range(d)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def random_nurbs(rng, p=3, q=2, rows=5, cols=4, dim=3):
    U = [0] * (p + 1) + sorted(rng.uniform(0.1, 0.9) for _ in range(rows - p - 1)) + [1] * (p + 1)
    V = [0] * (q + 1) + sorted(rng.uniform(0.1, 0.9) for _ in range(cols - q - 1)) + [1] * (q + 1)
    P = [[[rng.uniform(-2, 2) for _ in range(dim)] for _ in range(cols)] for _ in range(rows)]
    W = [[rng.uniform(0.5, 2) for _ in range(cols)] for _ in range(rows)]
    return {"type": "nurbs_surface", "degree": [p, q], "knots": [U, V], "points": P, "weights": W}


def grid(n=5):
    return [(i / n, j / n) for i in range(n + 1) for j in range(n + 1)]


HALF = math.sqrt(0.5)


def semicircle(r):
    """The profile of a sphere of radius r about z: (0,0,-r) to (0,0,r) through (r,0,0)."""
    return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
            "points": [[0, 0, -r], [r, 0, -r], [r, 0, 0], [r, 0, r], [0, 0, r]], "weights": [1, HALF, 1, HALF, 1]}


Z_AXIS = {"point": [0, 0, 0], "direction": [0, 0, 1]}


class SurfaceEvalTest(CliTest):
    def test_points_and_partials_of_a_nurbs_surface(self):
        rng = random.Random(19)
        s = random_nurbs(rng)
        uv = [(0.13, 0.21), (0.47, 0.66), (0.88, 0.37)]
        r = self.ok("eval", {"surface": s, "uv": [list(x) for x in uv], "derivatives": 2})
        self.assertEqual(list(r["partials"]), ["u", "v", "uu", "uv", "vv"])
        for k, (u, v) in enumerate(uv):
            self.assert_close(r["points"][k], evaluate(s, u, v), TIGHT)
            for name in r["partials"]:
                a, b = name.count("u"), name.count("v")
                # Rational second derivatives: the quotient rule on O(10) values; 1e-11
                # relative covers its rounding (mpmath.diff's own error is far below).
                self.assert_close(r["partials"][name][k], partial_mp(s, u, v, a, b), 1e-11, name)

    def test_grid_and_scattered_pairs_agree(self):
        # eval evaluates a uv list that is a grid (u outer) row by row; the same pairs in
        # another order go pair by pair: the same values exactly, and the evaluator's here.
        rng = random.Random(29)
        for s in (random_nurbs(rng), dict(random_nurbs(rng, p=2, q=3, rows=6, cols=5), weights=None)):
            if s["weights"] is None:
                del s["weights"]
                s["type"] = "bspline_surface"
            us, vs = [0, 0.3, 0.5, s["knots"][0][4], 1], [0, 0.25, 0.6, 1]
            uv = [[u, v] for u in us for v in vs]
            grid_pts = self.ok("eval", {"surface": s, "uv": uv})["points"]
            back = self.ok("eval", {"surface": s, "uv": uv[::-1]})["points"][::-1]
            self.assertEqual(grid_pts, back)
            for k, (u, v) in enumerate(uv):
                self.assert_close(grid_pts[k], evaluate(s, u, v), TIGHT)

    def test_every_dimension_and_bezier_kinds(self):
        for dim in (1, 2, 4):
            P = [[[i + j + k * 0.5 for k in range(dim)] for j in range(3)] for i in range(2)]
            P[1][1][0] = 7
            s = {"type": "bezier_surface", "points": P}
            r = self.ok("eval", {"surface": s, "uv": [[0.3, 0.8]]})
            # Tensor de Casteljau: along v in each row, then along u.
            want = de_casteljau([de_casteljau(row, 0.8) for row in P], 0.3)
            self.assert_close(r["points"][0], want, TIGHT)
        s = {"type": "rational_bezier_surface", "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]], "weights": [[1, 2], [3, 4]]}
        r = self.ok("eval", {"surface": s, "uv": [[0.25, 0.5]]})
        self.assert_close(r["points"][0], evaluate(s, 0.25, 0.5), TIGHT)

    def test_small_nurbs_surface_in_exact_rational_arithmetic(self):
        # A NURBS surface with dyadic data, degree (2, 1), an interior knot in u, evaluated
        # at dyadic (u, v) in fractions.Fraction: Cox-de Boor and its derivative formula, the
        # quotient rule, all exact; the program's points and first partials to a few ulps.
        from fractions import Fraction as Q

        U, V, p, q = [0, 0, 0, Q(1, 2), 1, 1, 1], [0, 0, 1, 1], 2, 1
        P = [[[0, 0, 0], [0, 1, Q(1, 4)]], [[Q(1, 2), 0, 1], [Q(1, 2), 1, Q(3, 2)]], [[1, 0, Q(1, 2)], [1, 1, 0]],
             [[Q(3, 2), 0, Q(-1, 4)], [Q(3, 2), 1, 1]]]
        W = [[1, 2], [Q(1, 2), 1], [3, Q(3, 4)], [1, Q(5, 4)]]

        def basis(T, deg, t):
            """N_{i,deg}(t) and their derivatives, exactly (t inside the domain, right-continuous)."""
            n = len(T) - deg - 1
            N = [[Q(1) if T[i] <= t < T[i + 1] or (t == T[-1] and T[i] < T[i + 1] == T[-1]) else Q(0)
                  for i in range(len(T) - 1)]]
            for d in range(1, deg + 1):
                prev = N[-1]
                N.append([(Q(t - T[i]) / (T[i + d] - T[i]) * prev[i] if T[i + d] != T[i] else 0) +
                          (Q(T[i + d + 1] - t) / (T[i + d + 1] - T[i + 1]) * prev[i + 1] if T[i + d + 1] != T[i + 1] else 0)
                          for i in range(len(T) - d - 1)])
            low = N[deg - 1]
            dN = [(deg * low[i] / (T[i + deg] - T[i]) if T[i + deg] != T[i] else 0) -
                  (deg * low[i + 1] / (T[i + deg + 1] - T[i + 1]) if T[i + deg + 1] != T[i + 1] else 0) for i in range(n)]
            return N[deg][:n], dN

        s = {"type": "nurbs_surface", "degree": [p, q], "knots": [[float(x) for x in U], [float(x) for x in V]],
             "points": [[[float(c) for c in x] for x in row] for row in P], "weights": [[float(w) for w in row] for row in W]}
        uv = [(Q(1, 8), Q(3, 4)), (Q(1, 2), Q(1, 2)), (Q(13, 16), Q(1, 16)), (Q(1), Q(1))]
        r = self.ok("eval", {"surface": s, "uv": [[float(u), float(v)] for u, v in uv], "derivatives": 1})
        for k, (u, v) in enumerate(uv):
            (Nu, dNu), (Nv, dNv) = basis(U, p, u), basis(V, q, v)
            def blend(a, b):
                A = [sum(a[i] * b[j] * W[i][j] * P[i][j][c] for i in range(len(P)) for j in range(2)) for c in range(3)]
                w = sum(a[i] * b[j] * W[i][j] for i in range(len(P)) for j in range(2))
                return A, w
            (A, w), (Au, wu), (Av, wv) = blend(Nu, Nv), blend(dNu, Nv), blend(Nu, dNv)
            S = [x / w for x in A]
            want = {"points": S, "u": [(Au[c] - wu * S[c]) / w for c in range(3)], "v": [(Av[c] - wv * S[c]) / w for c in range(3)]}
            got = {"points": r["points"][k], "u": r["partials"]["u"][k], "v": r["partials"]["v"][k]}
            for key in want:
                for c in range(3):
                    self.assertAlmostEqual(got[key][c], float(want[key][c]), delta=1e-14 * (1 + abs(float(want[key][c]))),
                                           msg=f"{key} at {(u, v)}")

    def test_hyperbolic_paraboloid_curvature(self):
        # (u, v, uv): K = -1 / (1 + u^2 + v^2)^2, H = -uv / (1 + u^2 + v^2)^(3/2), n ~ (-v, -u, 1).
        s = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}
        uv = [[0.2, 0.7], [1, 1], [0, 0.5]]
        r = self.ok("eval", {"surface": s, "uv": uv, "normal": True, "curvature": True})
        for k, (u, v) in enumerate(uv):
            q = 1 + u * u + v * v
            self.assertAlmostEqual(r["gaussian"][k], -1 / q ** 2, delta=1e-14)
            self.assertAlmostEqual(r["mean"][k], -u * v / q ** 1.5, delta=1e-14)
            k1, k2 = r["principal"][k]
            self.assertGreaterEqual(k1, k2)
            self.assertAlmostEqual(k1 + k2, 2 * r["mean"][k], delta=1e-14)
            self.assert_close(r["normals"][k], [-v / math.sqrt(q), -u / math.sqrt(q), 1 / math.sqrt(q)], 1e-15)

    def test_sphere_from_revolve(self):
        r = 2.5
        s = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        self.assertEqual(s["type"], "nurbs_surface")
        self.assertEqual(s["degree"], [2, 2])
        uv = [[u, v] for u in (0, 0.1, 0.3, 0.5, 0.9, 1) for v in (0, 0.7, 2.0, 3.5, 2 * math.pi)]
        e = self.ok("eval", {"surface": s, "uv": uv, "normal": True, "curvature": True})
        for k, (u, v) in enumerate(uv):
            x = e["points"][k]
            self.assertAlmostEqual(norm(x), r, delta=4e-16 * r)  # a few roundings of the rational arcs
            self.assert_close(x, evaluate(s, u, v), TIGHT)
            if u in (0, 1):
                # The poles: S_v = 0, the normal is undefined (null, not NaN).
                self.assertIsNone(e["normals"][k])
                self.assertIsNone(e["gaussian"][k])
                continue
            n = e["normals"][k]
            outward = dot(n, x) / r
            self.assertAlmostEqual(abs(outward), 1, delta=1e-14)
            self.assertAlmostEqual(e["gaussian"][k], 1 / r ** 2, delta=1e-13)
            # The contract's sign: H = +1/r when S_u x S_v points inward, -1/r outward.
            self.assertAlmostEqual(e["mean"][k], -outward / r, delta=1e-13)
        # u along the profile from the south pole, v turning counter-clockwise about +z:
        # S_u points up, S_v along the parallel, S_u x S_v inward.
        self.assertLess(dot(e["normals"][uv.index([0.3, 0.7])], e["points"][uv.index([0.3, 0.7])]), 0)

    def test_torus_cylinder_cone_from_revolve(self):
        R, a = 3.0, 1.0
        circle = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                  "points": [[R + a, 0, 0], [R + a, 0, a], [R, 0, a], [R - a, 0, a], [R - a, 0, 0], [R - a, 0, -a],
                             [R, 0, -a], [R + a, 0, -a], [R + a, 0, 0]],
                  "weights": [1, HALF, 1, HALF, 1, HALF, 1, HALF, 1]}
        torus = self.ok("surface", {"construct": "revolve", "curve": circle, "axis": Z_AXIS})["surface"]
        uv = [[u, v] for u in (0.05, 0.3, 0.6, 0.8) for v in (0.4, 4)]
        e = self.ok("eval", {"surface": torus, "uv": uv, "curvature": True})
        for k in range(len(uv)):
            x, y, z = e["points"][k]
            rho = math.hypot(x, y)
            self.assertAlmostEqual((rho - R) ** 2 + z * z, a * a, delta=1e-14)
            # K = cos(phi) / (a (R + a cos phi)) with cos(phi) = (rho - R) / a, |H| = (2 rho - R) / (2 a rho).
            self.assertAlmostEqual(e["gaussian"][k], (rho - R) / (a * a * rho), delta=1e-13)
            self.assertAlmostEqual(abs(e["mean"][k]), (2 * rho - R) / (2 * a * rho), delta=1e-13)
        line = {"type": "bezier", "points": [[2, 0, 0], [2, 0, 5]]}
        cyl = self.ok("surface", {"construct": "revolve", "curve": line, "axis": Z_AXIS, "angle": 2})["surface"]
        e = self.ok("eval", {"surface": cyl, "uv": [[0.5, 1.0], [0.2, 2.0]], "curvature": True})
        for k in range(2):
            self.assertAlmostEqual(math.hypot(*e["points"][k][:2]), 2, delta=1e-15)
            self.assertAlmostEqual(e["gaussian"][k], 0, delta=1e-14)
            self.assertAlmostEqual(abs(e["mean"][k]), 0.25, delta=1e-14)
        cone = {"type": "bezier", "points": [[0, 0, 1], [1, 0, 0]]}  # apex on the axis, half-angle 45 degrees
        s = self.ok("surface", {"construct": "revolve", "curve": cone, "axis": Z_AXIS})["surface"]
        e = self.ok("eval", {"surface": s, "uv": [[0.5, 1.0], [0.25, 5.0], [0, 3]], "curvature": True})
        for k, t in enumerate((0.5, 0.25)):
            x = e["points"][k]
            self.assertAlmostEqual(math.hypot(x[0], x[1]), t, delta=1e-15)
            self.assertAlmostEqual(x[2], 1 - t, delta=1e-15)
            self.assertAlmostEqual(e["gaussian"][k], 0, delta=1e-13)
            # H of a cone: (1/2) cos(half-angle) / rho.
            self.assertAlmostEqual(abs(e["mean"][k]), HALF / (2 * t), delta=1e-13)
        self.assertIsNone(e["gaussian"][2])  # the apex

    def test_revolve_keeps_axis_distance_about_an_oblique_axis(self):
        rng = random.Random(5)
        profile = {"type": "bezier", "points": [[rng.uniform(-1, 1) for _ in range(3)] for _ in range(4)]}
        O = [0.5, -1, 2]
        d = [1, 2, 2]  # |d| = 3
        angle = 2.5
        s = self.ok("surface", {"construct": "revolve", "curve": profile, "axis": {"point": O, "direction": d}, "angle": angle})["surface"]
        dn = [x / 3 for x in d]
        us = [0, 0.2, 0.5, 0.9, 1]
        c = self.ok("eval", {"curve": profile, "t": us})["points"]
        for v in (0, 0.3, 1.1, 2.2, angle):
            e = self.ok("eval", {"surface": s, "uv": [[u, v] for u in us]})
            for k in range(len(us)):
                X, Y = [a - b for a, b in zip(c[k], O)], [a - b for a, b in zip(e["points"][k], O)]
                h0, h1 = dot(X, dn), dot(Y, dn)
                r0 = norm([x - h0 * y for x, y in zip(X, dn)])
                r1 = norm([x - h1 * y for x, y in zip(Y, dn)])
                scale = max(1, norm(X))
                self.assertAlmostEqual(h0, h1, delta=1e-14 * scale)
                self.assertAlmostEqual(r0, r1, delta=1e-14 * scale)
            if v == angle:
                # The end is the profile rotated by the angle (Rodrigues' formula).
                for k in range(len(us)):
                    X = [a - b for a, b in zip(c[k], O)]
                    cs, sn = math.cos(angle), math.sin(angle)
                    kx = cross(dn, X)
                    kd = dot(dn, X)
                    rot = [X[i] * cs + kx[i] * sn + dn[i] * kd * (1 - cs) + O[i] for i in range(3)]
                    self.assert_close(e["points"][k], rot, 1e-14)


class ConstructionTest(CliTest):
    def test_extrude_and_ruled(self):
        C = [[0, 0, 0], [1, 2, 0], [3, -1, 1], [4, 0, 0]]
        vec = [0.5, 0, 2]
        s = self.ok("surface", {"construct": "extrude", "curve": {"type": "bezier", "points": C}, "vector": vec})["surface"]
        self.assertEqual(s["type"], "bspline_surface")
        for u, v in grid(4):
            want = [x + v * y for x, y in zip(de_casteljau(C, u), vec)]
            self.assert_close(evaluate(s, u, v), want, TIGHT)
        # ruled between a quadratic Bézier on [0, 1] and a cubic B-spline on [2, 4] with an
        # interior knot: the second is mapped onto [0, 1], then (1 - v) a(u) + v b(u).
        A = [[0, 0, 0], [1, 1, 0], [2, 0, 0]]
        B = {"type": "bspline", "degree": 3, "knots": [2, 2, 2, 2, 3, 4, 4, 4, 4],
             "points": [[0, 0, 1], [0.5, 1, 1], [1, 2, 1.5], [1.5, 0, 1], [2, 0, 1]]}
        s = self.ok("surface", {"construct": "ruled", "curves": [{"type": "bezier", "points": A}, B]})["surface"]
        uu = [0, 0.1, 0.5, 0.77, 1]
        b = self.ok("eval", {"curve": B, "t": [2 + 2 * u for u in uu]})["points"]
        for k, u in enumerate(uu):
            for v in (0, 0.4, 1):
                want = [(1 - v) * x + v * y for x, y in zip(de_casteljau(A, u), b[k])]
                self.assert_close(evaluate(s, u, v), want, TIGHT)

    def test_degree_zero_curves_are_refused(self):
        # surfaces.md: a surface's degrees are >= 1; piecewise constant curves would give
        # degree 0 along u. One degree-0 curve beside a degree-1 one is raised to 1: fine.
        step = {"type": "bspline", "degree": 0, "knots": [0, 1, 2], "points": [[0, 0, 0], [1, 1, 0]]}
        dot = {"type": "bezier", "points": [[1, 2, 3]]}
        for req, field in (({"construct": "extrude", "curve": step, "vector": [0, 0, 1]}, "curve"),
                           ({"construct": "extrude", "curve": dot, "vector": [0, 0, 1]}, "curve"),
                           ({"construct": "revolve", "curve": step, "axis": {"point": [0, 0, 0], "direction": [0, 0, 1]}}, "curve"),
                           ({"construct": "ruled", "curves": [step, step]}, "curves"),
                           ({"construct": "loft", "curves": [dot, {"type": "bezier", "points": [[2, 2, 3]]}]}, "curves")):
            self.bad("surface", req, field, contains="degree 0")
        line = {"type": "bezier", "points": [[0, 0, 1], [2, 0, 1]]}
        self.assertEqual(self.ok("surface", {"construct": "ruled", "curves": [dot, line]})["surface"]["degree"][0], 1)

    def test_loft_passes_through_its_curves(self):
        curves = [[[0, 0, z], [1, z * z, z], [2, 1, z], [3, 0, z]] for z in (0, 1, 2.5, 3)]
        objs = [{"type": "bezier", "points": c} for c in curves]
        s = self.ok("surface", {"construct": "loft", "curves": objs})["surface"]
        self.assertEqual(s["degree"], [3, 3])
        # Default params: the average distance between corresponding control points of
        # consecutive curves, accumulated and normalised.
        steps = [sum(math.dist(a, b) for a, b in zip(curves[k], curves[k - 1])) / 4 for k in range(1, 4)]
        t = [0, steps[0], steps[0] + steps[1], sum(steps)]
        t = [x / t[-1] for x in t]
        for k, c in enumerate(curves):
            for u in (0, 0.3, 0.8, 1):
                self.assert_close(evaluate(s, u, t[k]), de_casteljau(c, u), 1e-12)  # one dense solve: 1e-12
        s = self.ok("surface", {"construct": "loft", "curves": objs, "degree": 1, "params": [0, 1, 2, 5]})["surface"]
        for k, c in enumerate(curves):
            self.assert_close(evaluate(s, 0.6, [0, 1, 2, 5][k]), de_casteljau(c, 0.6), 1e-12)

    def test_coons(self):
        # Boundaries: c0 (v = 0) and c1 (v = 1) in u, d0 (u = 0) and d1 (u = 1) in v.
        c0 = [[0, 0, 0], [1, 0, 1], [2, 0, 0]]
        c1 = [[0, 2, 0], [0.7, 2, -1], [1.4, 2, 0.5], [2, 2, 0]]
        d0 = [[0, 0, 0], [0, 1, 2], [0, 2, 0]]
        d1 = [[2, 0, 0], [2, 2, 0]]
        objs = [{"type": "bezier", "points": c} for c in (c0, c1, d0, d1)]
        s = self.ok("surface", {"construct": "coons", "curves": objs})["surface"]
        for t in (0, 0.25, 0.6, 1):
            self.assert_close(evaluate(s, t, 0), de_casteljau(c0, t), TIGHT)
            self.assert_close(evaluate(s, t, 1), de_casteljau(c1, t), TIGHT)
            self.assert_close(evaluate(s, 0, t), de_casteljau(d0, t), TIGHT)
            self.assert_close(evaluate(s, 1, t), de_casteljau(d1, t), TIGHT)
        # Inside: ruled in v + ruled in u - bilinear, from the boundaries written here.
        for u, v in [(0.3, 0.4), (0.8, 0.1)]:
            rv = [(1 - v) * a + v * b for a, b in zip(de_casteljau(c0, u), de_casteljau(c1, u))]
            ru = [(1 - u) * a + u * b for a, b in zip(de_casteljau(d0, v), de_casteljau(d1, v))]
            bl = [(1 - u) * (1 - v) * p00 + (1 - u) * v * p01 + u * (1 - v) * p10 + u * v * p11
                  for p00, p01, p10, p11 in zip(c0[0], c1[0], c0[-1], c1[-1])]
            self.assert_close(evaluate(s, u, v), [a + b - c for a, b, c in zip(rv, ru, bl)], TIGHT)
        objs[3] = {"type": "bezier", "points": [[2, 0, 0], [2, 2, 0.001]]}
        self.bad("surface", {"construct": "coons", "curves": objs}, where="curves[3]", contains="the corners do not meet")

    def test_ruled_and_coons_of_rational_curves(self):
        # Exact NURBS forms (the weight function is the product of the curves'): checked
        # against the blends computed here from the curves (rational de Casteljau of
        # test_cli.py, the Cox-de Boor quotient for the NURBS curve).
        def nurbs_point(c, t):
            U, p, P, W = c["knots"], c["degree"], c["points"], c["weights"]
            N = [basis(U, p, i, t) * W[i] for i in range(len(P))]
            return [sum(n * x[k] for n, x in zip(N, P)) / sum(N) for k in range(len(P[0]))]

        a = {"type": "rational_bezier", "points": [[0, 0, 0], [1, 2, 0], [2, 0, 1]], "weights": [1, 3, 0.5]}
        b = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.4, 1, 1, 1], "points": [[0, 0, 2], [0.5, 1, 2], [1.5, -1, 3], [2, 0, 2]],
             "weights": [1, 0.5, 2, 1]}
        s = self.ok("surface", {"construct": "ruled", "curves": [a, b]})["surface"]
        self.assertEqual(s["type"], "nurbs_surface")
        for u in (0, 0.2, 0.4, 0.77, 1):
            A, B = test_cli.rational_point(a["points"], a["weights"], u), nurbs_point(b, u)
            for v in (0, 0.3, 1):
                self.assert_close(evaluate(s, u, v), [(1 - v) * x + v * y for x, y in zip(A, B)], TIGHT)
        # Coons: a quarter circle and a rational arc of other weights in u, a Bézier and a
        # rational Bézier in v.
        c0 = {"type": "rational_bezier", "points": [[1, 0, 0], [1, 1, 0], [0, 1, 0]], "weights": [1, HALF, 1]}
        c1 = {"type": "rational_bezier", "points": [[1, 0, 2], [1, 1, 2.5], [0, 1, 2]], "weights": [1, 0.3, 1]}
        d0 = {"type": "bezier", "points": [[1, 0, 0], [1.5, 0, 1], [1, 0, 2]]}
        d1 = {"type": "rational_bezier", "points": [[0, 1, 0], [0, 1.2, 1], [0, 1, 2]], "weights": [1, 2, 1]}
        s = self.ok("surface", {"construct": "coons", "curves": [c0, c1, d0, d1]})["surface"]
        self.assertEqual(s["type"], "nurbs_surface")
        rp = lambda c, t: test_cli.rational_point(c["points"], c["weights"], t) if "weights" in c else de_casteljau(c["points"], t)
        P00, P01, P10, P11 = c0["points"][0], c1["points"][0], c0["points"][-1], c1["points"][-1]
        for u in (0, 0.3, 0.5, 1):
            for v in (0, 0.4, 0.9, 1):
                rv = [(1 - v) * x + v * y for x, y in zip(rp(c0, u), rp(c1, u))]
                ru = [(1 - u) * x + u * y for x, y in zip(rp(d0, v), rp(d1, v))]
                bl = [(1 - u) * (1 - v) * w + (1 - u) * v * x + u * (1 - v) * y + u * v * z for w, x, y, z in zip(P00, P01, P10, P11)]
                self.assert_close(evaluate(s, u, v), [x + y - z for x, y, z in zip(rv, ru, bl)], TIGHT)

    def test_interpolate_and_fit(self):
        rng = random.Random(7)
        rows, cols = 6, 5
        Q = [[[i + rng.uniform(-0.2, 0.2), j + rng.uniform(-0.2, 0.2), math.sin(i) * math.cos(j)] for j in range(cols)]
             for i in range(rows)]
        s = self.ok("surface", {"construct": "interpolate", "points": Q})["surface"]
        self.assertEqual(s["degree"], [3, 3])

        def params(G):
            # chord lengths per line, normalised, averaged over the lines [PT97, A9.3]
            t = [0.0] * len(G)
            for j in range(len(G[0])):
                d = [math.dist(G[i][j], G[i - 1][j]) for i in range(1, len(G))]
                acc = 0
                for i in range(1, len(G)):
                    acc += d[i - 1]
                    t[i] += acc / sum(d)
            return [x / len(G[0]) for x in t]

        tu = params(Q)
        tv = params([list(c) for c in zip(*Q)])
        for i in range(rows):
            for j in range(cols):
                self.assert_close(evaluate(s, tu[i], tv[j]), Q[i][j], 1e-12)  # two dense solves: 1e-12
        r = self.ok("surface", {"construct": "fit", "points": Q, "degree": [2, 2], "control_points": [4, 4]})
        f = r["surface"]
        U, V = f["knots"]
        # The least-squares oracle: min |(N_u x N_v) c - q| over the whole grid, by lstsq.
        Nu = np.array([[basis(U, 2, i, t) for i in range(4)] for t in tu], dtype=float)
        Nv = np.array([[basis(V, 2, j, t) for j in range(4)] for t in tv], dtype=float)
        A = np.kron(Nu, Nv)
        q = np.array([Q[i][j] for i in range(rows) for j in range(cols)])
        c, *_ = np.linalg.lstsq(A, q, rcond=None)
        got = np.array([x for row in f["points"] for x in row])
        self.assertLess(np.abs(got - c).max(), 1e-10)  # two QR solves against one: conditioning ~1e2
        err = max(math.dist(evaluate(f, tu[i], tv[j]), Q[i][j]) for i in range(rows) for j in range(cols))
        self.assertAlmostEqual(r["max_error"], err, delta=1e-12)


    def test_interpolate_at_huge_coordinates(self):
        # Grid parameters at 1e200 (squared distances overflow): the shared chord and
        # centripetal steps (curves/parametrization.hpp) measure without overflow. Oracle:
        # Python's math.dist (overflow-safe) for the parameters, and the surface must pass
        # through the grid there. Scaling by 2^664 (even: the centripetal square root
        # scales by 2^332) changes nothing but the scale, exactly.
        rng = random.Random(11)
        rows, cols = 5, 4
        Q = [[[i + rng.uniform(-0.2, 0.2), j + rng.uniform(-0.2, 0.2), math.sin(i) * math.cos(j)] for j in range(cols)]
             for i in range(rows)]
        for rule, step in (("chord", lambda d: d), ("centripetal", math.sqrt)):
            def params(G):
                t = [0.0] * len(G)
                for j in range(len(G[0])):
                    d = [step(math.dist(G[i][j], G[i - 1][j])) for i in range(1, len(G))]
                    for i in range(1, len(G)):
                        t[i] += sum(d[:i]) / sum(d)
                return [x / len(G[0]) for x in t]
            big = [[[1e200 * x for x in p] for p in row] for row in Q]
            s = self.ok("surface", {"construct": "interpolate", "points": big, "parametrization": rule})["surface"]
            tu, tv = params(big), params([list(c) for c in zip(*big)])
            for i in range(rows):
                for j in range(cols):
                    got = evaluate(s, tu[i], tv[j])
                    self.assertLess(max(abs(a - b) for a, b in zip(got, big[i][j])), 1e-12 * 1e200, (rule, i, j))
            unit = self.ok("surface", {"construct": "interpolate", "points": Q, "parametrization": rule})["surface"]
            two = [[[math.ldexp(x, 664) for x in p] for p in row] for row in Q]
            s2 = self.ok("surface", {"construct": "interpolate", "points": two, "parametrization": rule})["surface"]
            self.assertEqual(s2["knots"], unit["knots"])
            self.assertEqual(s2["points"], [[[math.ldexp(x, 664) for x in p] for p in row] for row in unit["points"]])

class SurfaceOpsTest(CliTest):
    def check_same(self, a, b, uvs, tol=TIGHT):
        for u, v in uvs:
            self.assert_close(evaluate(b, u, v), evaluate(a, u, v), tol, f"at {u}, {v}")

    def test_split_elevate_insert_to_bezier_isocurve(self):
        rng = random.Random(3)
        s = random_nurbs(rng)
        uvs = grid(5)
        halves = self.ok("split", {"surface": s, "direction": "v", "t": 0.45})["surfaces"]
        self.assertEqual(halves[0]["knots"][1][-1], 0.45)
        self.check_same(s, halves[0], [(u, v) for u, v in uvs if v <= 0.45])
        self.check_same(s, halves[1], [(u, v) for u, v in uvs if v >= 0.45])
        e = self.ok("elevate", {"surface": s, "direction": "u", "times": 2})["surface"]
        self.assertEqual(e["degree"], [5, 2])
        self.check_same(s, e, uvs)
        k = self.ok("insert_knot", {"surface": s, "direction": "u", "knot": 0.3, "times": 2})["surface"]
        self.assertEqual(sum(1 for x in k["knots"][0] if x == 0.3), 2)
        self.check_same(s, k, uvs)
        b = self.ok("to_bezier", {"surface": s})
        ub, vb = b["breaks"]
        self.assertEqual(ub, sorted(set(s["knots"][0])))
        self.assertEqual(vb, sorted(set(s["knots"][1])))
        for i in range(len(ub) - 1):
            for j in range(len(vb) - 1):
                patch = b["patches"][i][j]
                self.assertEqual(patch["type"], "rational_bezier_surface")
                for x, y in [(0, 0), (0.3, 0.9), (1, 1)]:
                    u, v = ub[i] + x * (ub[i + 1] - ub[i]), vb[j] + y * (vb[j + 1] - vb[j])
                    self.assert_close(evaluate(patch, x, y), evaluate(s, u, v), TIGHT)
        c = self.ok("isocurve", {"surface": s, "direction": "u", "value": 0.6})["curve"]
        self.assertEqual(c["type"], "nurbs")
        ts = [0, 0.2, 0.5, 0.9, 1]
        got = self.ok("eval", {"curve": c, "t": ts})["points"]
        for t, g in zip(ts, got):
            self.assert_close(g, evaluate(s, 0.6, t), TIGHT)
        # Bézier: split halves on [0, 1], the isocurve a Bézier curve.
        bz = {"type": "bezier_surface", "points": [[[0, 0], [0, 1], [1, 2]], [[2, 0], [2, 1], [3, 3]]]}
        h = self.ok("split", {"surface": bz, "direction": "u", "t": 0.25})["surfaces"]
        self.assert_close(evaluate(h[1], 0.5, 0.3), evaluate(bz, 0.625, 0.3), TIGHT)
        c = self.ok("isocurve", {"surface": bz, "direction": "v", "value": 0.3})["curve"]
        self.assertEqual(c["type"], "bezier")
        self.assert_close(de_casteljau(c["points"], 0.7), evaluate(bz, 0.7, 0.3), TIGHT)

    def test_round_trip_and_errors(self):
        s = random_nurbs(random.Random(11))
        e = self.ok("elevate", {"surface": s, "direction": "u", "times": 1})
        self.assertEqual(self.ok("to_bezier", {"surface": {"type": "bezier_surface", "points": [[[0.1, 0.7]]]}})["patches"][0][0],
                         {"type": "bezier_surface", "points": [[[0.1, 0.7]]]})
        self.assertIn("surface", e)
        ragged = {"type": "bezier_surface", "points": [[[0, 0], [1, 0], [2, 0], [3, 0]], [[0, 1], [1, 1], [2, 1], [3, 1]],
                                                       [[0, 2], [1, 2], [2, 2]]]}
        err = self.bad("eval", {"surface": ragged, "uv": [[0, 0]]}, where="surface.points[2]")
        self.assertIn("row 2 has 3 points, row 0 has 4", err)
        bad_knots = dict(s, knots=[s["knots"][0], [0, 0, 0, 0.7, 0.5, 1, 1, 1]][:2])
        bad_knots["knots"][1] = [0, 0, 0, 0.7, 0.5, 1, 1]
        self.bad("eval", {"surface": bad_knots, "uv": [[0, 0]]}, where="surface.knots[1][4]",
                 contains="knots must be non-decreasing (0.5 after 0.7)")
        self.bad("eval", {"surface": dict(s, weights=s["weights"][:4]), "uv": [[0, 0]]}, where="surface.weights")
        self.bad("eval", {"surface": s, "uv": [[0, 0], [1]]}, where="uv[1]")
        self.bad("surface", {"construct": "sweep"}, where="construct", contains="unknown construction 'sweep' (extrude, ruled,")
        self.bad("surface", {"construct": "extrude", "curve": {"type": "bezier", "points": [[0, 0], [1, 0]]}, "vector": [0, 1],
                             "angle": 1}, where="angle", contains="unknown field")
        flat = {"type": "bezier_surface", "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]}
        self.bad("eval", {"surface": flat, "uv": [[0, 0]], "normal": True}, where="normal", contains="3-D")
        self.bad("insert_knot", {"surface": flat, "direction": "u", "knot": 0.5}, where="surface", contains="bspline_surface")
        self.bad("split", {"surface": s, "direction": "w", "t": 0.5}, where="direction")
        self.bad("eval", {"surface": dict(s, type="torus_surface"), "uv": [[0, 0]]}, where="surface.type")
        # --jsonl: curve and surface requests of one command, one response line each.
        rc, out, err = test_cli.run("eval", args=["--jsonl"], text=json.dumps({"curve": {"type": "bezier", "points": [[0], [2]]}, "t": [0.5]})
                                    + "\n" + json.dumps({"surface": {"type": "bezier_surface", "points": [[[0], [2]]]}, "uv": [[0.5, 0.5]]}) + "\n")
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual([json.loads(l) for l in out.splitlines()], [{"points": [[1]]}, {"points": [[1]]}])
        # A request may not hold both.
        self.bad("eval", {"surface": flat, "curve": {"type": "bezier", "points": [[0]]}, "uv": [[0, 0]]}, where="curve")


class SurfaceQueryTest(CliTest):
    def test_area_closed_forms(self):
        r, R, a = 1.5, 3.0, 1.0
        sphere = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        # Quadrature to 1e-10 relative (the contract's target).
        self.assertAlmostEqual(self.ok("area", {"surface": sphere})["area"] / (4 * math.pi * r * r), 1, delta=1e-10)
        line = {"type": "bezier", "points": [[2, 0, 0], [2, 0, 5]]}
        cyl = self.ok("surface", {"construct": "revolve", "curve": line, "axis": Z_AXIS, "angle": 2})["surface"]
        self.assertAlmostEqual(self.ok("area", {"surface": cyl})["area"] / (2 * 2 * 5), 1, delta=1e-10)
        cone = self.ok("surface", {"construct": "revolve", "curve": {"type": "bezier", "points": [[0, 0, 1], [1, 0, 0]]},
                                   "axis": Z_AXIS})["surface"]
        self.assertAlmostEqual(self.ok("area", {"surface": cone})["area"] / (math.pi * math.sqrt(2)), 1, delta=1e-10)
        # z = xy over the unit square: the integral of sqrt(1 + x^2 + y^2), by mpmath.quad.
        hp = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}
        want = float(mpmath.quad(lambda x, y: mpmath.sqrt(1 + x * x + y * y), [0, 1], [0, 1]))
        self.assertAlmostEqual(self.ok("area", {"surface": hp})["area"] / want, 1, delta=1e-10)

    def test_bounds(self):
        r = 1.5
        # A sphere about an oblique axis through its centre C: the profile is the half
        # circle from C - r d to C + r d through C + r e (e = z, perpendicular to d).
        C, d, e = [1, 2, 3], [HALF, HALF, 0], [0, 0, 1]
        pt = lambda a, b: [C[i] + r * (a * d[i] + b * e[i]) for i in range(3)]
        profile = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
                   "points": [pt(-1, 0), pt(-1, 1), pt(0, 1), pt(1, 1), pt(1, 0)], "weights": [1, HALF, 1, HALF, 1]}
        sphere = self.ok("surface", {"construct": "revolve", "curve": profile, "axis": {"point": C, "direction": [1, 1, 0]}})["surface"]
        b = self.ok("bounds", {"surface": sphere})
        diag = 2 * r * math.sqrt(3)
        for k, c in enumerate((1, 2, 3)):
            # Containing (up to the rounding of the data: the profile's points C + r d are
            # rounded, so the surface itself may fall short of c +- r by an ulp or two of
            # the coordinates), and each side within 1e-9 of the diagonal (the contract).
            ulps = 8 * 2.0 ** -52 * (abs(c) + r)
            self.assertLessEqual(b["min"][k], c - r + ulps)
            self.assertGreaterEqual(b["min"][k], c - r - 1e-9 * diag)
            self.assertGreaterEqual(b["max"][k], c + r - ulps)
            self.assertLessEqual(b["max"][k], c + r + 1e-9 * diag)
        # A random NURBS surface: the true extremes by dense sampling refined with a local
        # optimiser on the evaluator written here (scipy.optimize, bounded).
        from scipy.optimize import minimize
        s = random_nurbs(random.Random(23))
        b = self.ok("bounds", {"surface": s})
        pts = {(u, v): evaluate(s, u, v) for u, v in grid(20)}
        for k in range(3):
            for sign, key in ((1, "min"), (-1, "max")):
                u0, v0 = min(pts, key=lambda x: sign * pts[x][k])
                res = minimize(lambda x: sign * evaluate(s, min(max(x[0], 0), 1), min(max(x[1], 0), 1))[k], [u0, v0],
                               bounds=[(0, 1), (0, 1)], method="L-BFGS-B", options={"ftol": 1e-15, "gtol": 1e-12})
                extreme = sign * res.fun
                lo, hi = [min(p[i] for p in pts.values()) for i in range(3)], [max(p[i] for p in pts.values()) for i in range(3)]
                size = math.dist(lo, hi)
                # Containing: beyond every point found; tight: within 1e-9 of the size from
                # the optimiser's extreme (itself a point of the surface, so never beyond
                # the true extreme).
                self.assertLessEqual(sign * b[key][k], sign * extreme + 1e-15 * size)
                self.assertGreaterEqual(sign * b[key][k], sign * extreme - 1e-9 * size)


def basis_matrix(U, p, n, ts):
    """The matrix of N_i(t) (rows: the ts, columns: i < n), by the Cox-de Boor evaluator above."""
    return np.array([[float(basis(U, p, i, t)) for i in range(n)] for t in ts])


def dense_points(s, ts_u, ts_v):
    """S on the grid ts_u x ts_v, by the tensor product of the basis matrices written here
    (the rational quotient for NURBS): an array (len(ts_u), len(ts_v), d)."""
    p, q, U, V = knots_of(s)
    P = np.array(s["points"], dtype=float)
    W = np.array(s["weights"], dtype=float) if "weights" in s else np.ones(P.shape[:2])
    A, B = basis_matrix(U, p, P.shape[0], ts_u), basis_matrix(V, q, P.shape[1], ts_v)
    num = np.einsum("ai,bj,ijk->abk", A, B, P * W[:, :, None])
    return num / np.einsum("ai,bj,ij->ab", A, B, W)[:, :, None]


def brute_force_distance(s, x, n=40):
    """The least distance from x to s by dense sampling (n + 1)^2, then scipy's bounded
    L-BFGS-B from the three best samples on the evaluator written here (never below the
    true minimum: every value is a point of the surface)."""
    from scipy.optimize import minimize
    p, q, U, V = knots_of(s)
    a, b, c, d = U[p], U[-p - 1], V[q], V[-q - 1]
    tu, tv = np.linspace(a, b, n + 1), np.linspace(c, d, n + 1)
    D = np.linalg.norm(dense_points(s, tu, tv) - np.array(x), axis=2)
    best = float(D.min())
    for k in np.argsort(D, axis=None)[:3]:
        i, j = divmod(int(k), n + 1)
        f = lambda y: math.dist(evaluate(s, min(max(y[0], a), b), min(max(y[1], c), d)), x)
        res = minimize(f, [tu[i], tv[j]], bounds=[(a, b), (c, d)], method="L-BFGS-B", options={"ftol": 1e-15, "gtol": 1e-12})
        best = min(best, float(res.fun))
    return best


def torus_profile(R, a):
    """The circle of radius a about (R, 0, 0) in the xz-plane, four quarter arcs."""
    return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
            "points": [[R + a, 0, 0], [R + a, 0, a], [R, 0, a], [R - a, 0, a], [R - a, 0, 0], [R - a, 0, -a],
                       [R, 0, -a], [R + a, 0, -a], [R + a, 0, 0]],
            "weights": [1, HALF, 1, HALF, 1, HALF, 1, HALF, 1]}


SQUARE = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]}  # z = 0, x = u, y = v


class SurfaceProjectTest(CliTest):
    def check_answer(self, s, x, r):
        """The reported point is S(uv) (evaluator written here) and distance its distance."""
        self.assert_close(r["point"], evaluate(s, *r["uv"]), 1e-13)  # evaluations: a few dozen eps
        self.assertAlmostEqual(r["distance"], math.dist(r["point"], x), delta=1e-14 * max(1, r["distance"]))

    def test_sphere_torus_cylinder_plane_closed_forms(self):
        r = 2.5
        sphere = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        rng = random.Random(7)
        for _ in range(6):
            x = [rng.uniform(-6, 6) for _ in range(3)]
            got = self.ok("project", {"surface": sphere, "point": x})
            self.check_answer(sphere, x, got)
            # | |x| - r | and the radial point; the distance is a global minimum to its
            # rounding (a few eps of r), the point to sqrt of that (a flat minimum).
            self.assertAlmostEqual(got["distance"], abs(norm(x) - r), delta=1e-14 * r)
            self.assert_close(got["point"], [r * c / norm(x) for c in x], 1e-7)
            self.assertNotIn("all_uv", got)
        # The centre: every point ties, a whole region of minimisers (no all_uv).
        got = self.ok("project", {"surface": sphere, "point": [0, 0, 0]})
        self.assertAlmostEqual(got["distance"], r, delta=1e-14 * r)
        self.assertNotIn("all_uv", got)
        self.check_answer(sphere, [0, 0, 0], got)
        # A torus and a point on its axis: the minimum is attained on a circle (no all_uv):
        # sqrt(R^2 + h^2) - a.
        R, a = 3.0, 1.0
        torus = self.ok("surface", {"construct": "revolve", "curve": torus_profile(R, a), "axis": Z_AXIS})["surface"]
        for h in (0.0, 0.4, -2.0):
            got = self.ok("project", {"surface": torus, "point": [0, 0, h]})
            self.assertAlmostEqual(got["distance"], math.hypot(R, h) - a, delta=1e-14 * R)
            self.assertNotIn("all_uv", got)
            self.check_answer(torus, [0, 0, h], got)
        # A point off the axis: the nearest point of the tube circle in its half-plane.
        x = [4.0, 1.5, 0.7]
        got = self.ok("project", {"surface": torus, "point": x})
        rho = math.hypot(x[0], x[1])
        self.assertAlmostEqual(got["distance"], math.hypot(rho - R, x[2]) - a, delta=1e-14 * R)
        self.assertNotIn("all_uv", got)
        # A cylinder of radius 2 over 2 radians, height 5: inside its angle and height the
        # radial distance, beyond its angle the distance to its end line.
        cyl = self.ok("surface", {"construct": "revolve", "curve": {"type": "bezier", "points": [[2, 0, 0], [2, 0, 5]]},
                                  "axis": Z_AXIS, "angle": 2})["surface"]
        for x, want in (([3 * math.cos(1), 3 * math.sin(1), 2], 1.0), ([0.5 * math.cos(0.3), 0.5 * math.sin(0.3), 4], 1.5),
                        ([1, -1, 1], math.dist([1, -1], [2, 0]))):
            got = self.ok("project", {"surface": cyl, "point": x})
            self.assertAlmostEqual(got["distance"], want, delta=1e-14 * 5)
            self.check_answer(cyl, x, got)
        # The unit square in z = 0: above it the height, beyond an edge the edge's distance,
        # beyond a corner the corner's.
        for x, uv, want in (([0.3, 0.6, 2], [0.3, 0.6], 2), ([1.5, 0.25, -1], [1, 0.25], math.hypot(0.5, 1)),
                            ([-1, -2, 0], [0, 0], math.hypot(1, 2)), ([0.5, 0.5, 0], [0.5, 0.5], 0)):
            got = self.ok("project", {"surface": SQUARE, "point": x})
            self.assertAlmostEqual(got["distance"], want, delta=1e-15)
            self.assert_close(got["uv"], uv, 1e-7)  # a global minimum to the distance's rounding: uv to its square root

    def test_two_isolated_minimisers_tie(self):
        # The parabolic trough z = (u - 1/2)^2 (x = u/..., y = v): from (1/2, 1/2, h) beyond its
        # focal point, d^2 = s^2 + (h - s^2)^2 (s = u - 1/2) is least at s^2 = h - 1/2:
        # h = 0.5625 gives u = 0.25 and 0.75, v = 0.5, d^2 = 0.0625 + 0.25.
        trough = {"type": "bezier_surface", "points": [[[0, 0, 0.25], [0, 1, 0.25]], [[0.5, 0, -0.25], [0.5, 1, -0.25]],
                                                       [[1, 0, 0.25], [1, 1, 0.25]]]}
        got = self.ok("project", {"surface": trough, "point": [0.5, 0.5, 0.5625]})
        self.assertAlmostEqual(got["distance"], math.sqrt(0.3125), delta=1e-15)
        self.assertEqual(len(got["all_uv"]), 2)
        self.assert_close(got["all_uv"], [[0.25, 0.5], [0.75, 0.5]], 1e-7)  # flat minima: the square root of eps
        self.assertEqual(got["uv"], got["all_uv"][0])
        # Off the symmetry plane the tie is broken: one minimiser, the nearer side.
        got = self.ok("project", {"surface": trough, "point": [0.55, 0.5, 0.5625]})
        self.assertNotIn("all_uv", got)
        self.assertGreater(got["uv"][0], 0.5)

    def test_random_surfaces_against_brute_force(self):
        # The answer is never worse than dense sampling refined by scipy (1e-12 relative:
        # the tie tolerance), and is a point of the surface at the distance reported.
        rng = random.Random(1919)
        for k in range(4):
            s = random_nurbs(rng, p=rng.choice([2, 3]), q=rng.choice([1, 2, 3]), rows=5, cols=5)
            if k % 2:
                del s["weights"]
                s["type"] = "bspline_surface"
            for _ in range(2):
                x = [rng.uniform(-3, 3) for _ in range(3)]
                got = self.ok("project", {"surface": s, "point": x})
                self.check_answer(s, x, got)
                self.assertLessEqual(got["distance"], brute_force_distance(s, x) * (1 + 1e-12) + 1e-14)

    def test_other_dimensions_and_bad_input(self):
        # 2-D: a bilinear square patch in the plane covers the point (distance 0).
        s2 = {"type": "bezier_surface", "points": [[[0, 0], [0, 2]], [[2, 0], [2, 2]]]}
        got = self.ok("project", {"surface": s2, "point": [0.5, 1.5]})
        self.assertEqual(got["distance"], 0)
        self.assert_close(got["uv"], [0.25, 0.75], 1e-15)
        self.bad("project", {"surface": SQUARE, "point": [1, 2]}, where="point", contains="3 coordinates")
        self.bad("project", {"surface": SQUARE}, where="point", contains="missing")
        self.bad("project", {"surface": SQUARE, "point": [0, 0, "x"]}, where="point[2]")
        self.bad("project", {"surface": SQUARE, "point": [0, 0, 0], "farthest": True}, where="farthest", contains="unknown field")
        # Past the work limit: refused at once, naming the surface.
        n = 36
        big = {"type": "bspline_surface", "degree": [30, 30],
               "knots": [[0] * 31 + [k / 6 for k in range(1, 6)] + [1] * 31] * 2,
               "points": [[[i, j, (i * j) % 7] for j in range(n)] for i in range(n)]}
        self.bad("project", {"surface": big, "point": [0, 0, 0]}, where="surface", contains="limit")


def line(a, b):
    return {"type": "bezier", "points": [a, b]}


class SurfaceIntersectTest(CliTest):
    def check_hits(self, s, c, r, tol=1e-9):
        """Each point is on both: C(t) by de Casteljau written here, S(uv) by the evaluator
        (to the intersection's tolerance, 1e-9 of the size)."""
        for h in r["intersections"]:
            self.assert_close(h["point"], de_casteljau(c["points"], h["t"]), 1e-14)
            self.assert_close(h["point"], evaluate(s, *h["uv"]), tol)
        ts = [h["t"] for h in r["intersections"]]
        self.assertEqual(ts, sorted(ts))

    def test_rays_and_a_sphere(self):
        r = 2.0
        sphere = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        # A ray (x from -5 to 5 at y0, z0): crossings where x^2 = r^2 - y0^2 - z0^2.
        for y0, z0 in ((0.3, 0.2), (0, 0), (1.1, -1.2)):
            c = line([-5, y0, z0], [5, y0, z0])
            got = self.ok("intersect", {"surface": sphere, "curve": c})
            xs = math.sqrt(r * r - y0 * y0 - z0 * z0)
            self.assertEqual([h["kind"] for h in got["intersections"]], ["crossing", "crossing"])
            self.assert_close([h["t"] for h in got["intersections"]], [(5 - xs) / 10, (5 + xs) / 10], 1e-12)
            self.assertEqual(got["overlaps"], [])
            self.check_hits(sphere, c, got)
        # Along the axis through both poles (where the normal is only a limit).
        c = line([0, 0, -4], [0, 0, 4])
        got = self.ok("intersect", {"surface": sphere, "curve": c})
        self.assertEqual([h["kind"] for h in got["intersections"]], ["crossing", "crossing"])
        self.assert_close([h["t"] for h in got["intersections"]], [0.25, 0.75], 1e-12)
        # Tangent: a line at distance r from the centre touches once, at x = 0 (a double
        # root: t to the square root of the rounding).
        z0 = math.sqrt(r * r - 0.36)
        for c in (line([-5, r, 0], [5, r, 0]), line([-5, 0.6, z0], [5, 0.6, z0])):
            got = self.ok("intersect", {"surface": sphere, "curve": c})
            self.assertEqual([h["kind"] for h in got["intersections"]], ["tangent"], got)
            self.assertAlmostEqual(got["intersections"][0]["t"], 0.5, delta=1e-7)
            self.check_hits(sphere, c, got)
        # Missing it by 1e-6: nothing.
        got = self.ok("intersect", {"surface": sphere, "curve": line([-5, r + 1e-6, 0], [5, r + 1e-6, 0])})
        self.assertEqual(got["intersections"], [])

    def test_lines_and_a_torus(self):
        R, a = 3.0, 1.0
        torus = self.ok("surface", {"construct": "revolve", "curve": torus_profile(R, a), "axis": Z_AXIS})["surface"]
        # Random segments: the real roots in [0, 1] of the torus's quartic
        # (|x|^2 + R^2 - a^2)^2 - 4 R^2 (x^2 + y^2) along them (numpy's polynomial roots).
        rng = random.Random(31)
        Poly = np.polynomial.Polynomial
        for _ in range(6):
            P0, P1 = [rng.uniform(-5, 5) for _ in range(3)], [rng.uniform(-5, 5) for _ in range(3)]
            X = [Poly([P0[i], P1[i] - P0[i]]) for i in range(3)]
            f = (X[0] ** 2 + X[1] ** 2 + X[2] ** 2 + R * R - a * a) ** 2 - 4 * R * R * (X[0] ** 2 + X[1] ** 2)
            want = sorted(r.real for r in f.roots() if abs(r.imag) < 1e-9 and 0 <= r.real <= 1)
            got = self.ok("intersect", {"surface": torus, "curve": line(P0, P1)})
            # Simple roots of a quartic with O(10) coefficients: numpy's to about 1e-12.
            self.assert_close([h["t"] for h in got["intersections"]], want, 1e-10)
        # Horizontal lines at the top (z = a) touch it where they cross the top circle
        # (two tangent points), and along the top circle's tangent at (0, 3, 1) the contact
        # is of order 4 (z = a - x^4 / 72 + ...): one tangent point, t to the 4th root of
        # the rounding.
        got = self.ok("intersect", {"surface": torus, "curve": line([-5, 2, 1], [5, 2, 1])})
        self.assertEqual([h["kind"] for h in got["intersections"]], ["tangent", "tangent"])
        self.assert_close([h["t"] for h in got["intersections"]], [0.5 - math.sqrt(5) / 10, 0.5 + math.sqrt(5) / 10], 1e-7)
        got = self.ok("intersect", {"surface": torus, "curve": line([-5, 3, 1], [5, 3, 1])})
        self.assertEqual([h["kind"] for h in got["intersections"]], ["tangent"])
        self.assertAlmostEqual(got["intersections"][0]["t"], 0.5, delta=1e-3)
        self.assertEqual(got["overlaps"], [])

    def test_overlaps(self):
        # A line in the plane of the square: on it from x = 0 to x = 1 (t = 0.2 .. 0.6).
        c = line([-0.5, 0.5, 0], [2, 0.5, 0])
        got = self.ok("intersect", {"surface": SQUARE, "curve": c})
        self.assertEqual(got["intersections"], [])
        self.assertEqual(len(got["overlaps"]), 1)
        self.assert_close(got["overlaps"][0]["t"], [0.2, 0.6], 1e-12)
        # Inside the square throughout.
        got = self.ok("intersect", {"surface": SQUARE, "curve": line([0.1, 0.2, 0], [0.8, 0.9, 0])})
        self.assertEqual(got["overlaps"], [{"t": [0, 1]}])
        # An isocurve of a random NURBS surface lies on it over its whole domain.
        rng = random.Random(3)
        s = random_nurbs(rng)
        iso = self.ok("isocurve", {"surface": s, "direction": "u", "value": 0.37})["curve"]
        got = self.ok("intersect", {"surface": s, "curve": iso})
        self.assertEqual(got["intersections"], [])
        self.assertEqual(len(got["overlaps"]), 1)
        self.assert_close(got["overlaps"][0]["t"], [0, 1], 1e-12)
        # A circle of a sphere (its equator, a rational curve) lies on it.
        r = 1.5
        sphere = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        eq = {"type": "circle", "center": [0, 0], "radius": r}
        eq3 = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
               "points": [[r, 0, 0], [r, r, 0], [0, r, 0], [-r, r, 0], [-r, 0, 0], [-r, -r, 0], [0, -r, 0], [r, -r, 0], [r, 0, 0]],
               "weights": [1, HALF, 1, HALF, 1, HALF, 1, HALF, 1]}
        got = self.ok("intersect", {"surface": sphere, "curve": eq3})
        self.assertEqual(got["intersections"], [])
        self.assertEqual(len(got["overlaps"]), 1)
        self.assert_close(got["overlaps"][0]["t"], [0, 1], 1e-12)

    def test_random_graph_surfaces_against_sign_changes(self):
        # S(u, v) = (u, v, h(u, v)), a random bicubic height; a random segment crosses it
        # where z(t) - h(x(t), y(t)) changes sign (counted on 2000 samples, tangencies
        # avoided by the random data): every crossing is found, each on both.
        rng = random.Random(11)
        for _ in range(4):
            s = {"type": "bezier_surface", "points": [[[i / 3, j / 3, rng.uniform(-1, 1)] for j in range(4)] for i in range(4)]}
            a = [rng.uniform(0, 0.3), rng.uniform(0, 0.3), rng.uniform(-1, 1)]
            b = [rng.uniform(0.7, 1), rng.uniform(0.7, 1), rng.uniform(-1, 1)]
            c = {"type": "bezier", "points": [a, [rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(-2, 2)], b]}
            ts = np.linspace(0, 1, 2001)
            pts = [de_casteljau(c["points"], t) for t in ts]
            g = [p[2] - evaluate(s, p[0], p[1])[2] for p in pts]
            changes = sum(1 for k in range(len(g) - 1) if (g[k] < 0) != (g[k + 1] < 0))
            got = self.ok("intersect", {"surface": s, "curve": c})
            self.assertEqual(len(got["intersections"]), changes, got)
            self.assertTrue(all(h["kind"] == "crossing" for h in got["intersections"]))
            self.check_hits(s, c, got)

    def test_bad_input(self):
        self.bad("intersect", {"surface": SQUARE, "curve": line([0, 0], [1, 1])}, where="curve", contains="3-D")
        s2 = {"type": "bezier_surface", "points": [[[0, 0], [0, 2]], [[2, 0], [2, 2]]]}
        self.bad("intersect", {"surface": s2, "curve": line([0, 0, 0], [1, 1, 1])}, where="surface", contains="3-D")
        self.bad("intersect", {"surface": SQUARE}, where="curve", contains="missing")
        # A line 1e-11 above the plane, all along it: within the tolerances at every leaf
        # without lying on it; refused after 5000 candidate points rather than running on.
        self.bad("intersect", {"surface": SQUARE, "curve": line([-0.5, 0.5, 1e-11], [2, 0.5, 1e-11])}, where="surface",
                 contains="did not settle")
        self.bad("intersect", {"surface": SQUARE, "curves": [line([0, 0, 0], [1, 1, 1])]}, where="curves", contains="unknown field")


class SurfaceListingTest(CliTest):
    def test_help_and_listing_show_the_surface_forms(self):
        rc, out, err = test_cli.run("eval", args=["--help"])
        self.assertEqual((rc, err), (0, ""))
        form = out.split("Surface form", 1)[1]
        for field in ("surface", "uv", "derivatives", "normal", "curvature"):
            self.assertRegex(form, rf"\n  {field} +\S")
        # GET /api lists the surface forms beside the commands (the server of test_serve.py).
        import test_serve
        test_serve.BINARY = test_cli.BINARY
        server = test_serve.Server()
        try:
            status, _, body = server.request("GET", "/api")
            self.assertEqual(status, 200)
            forms = {c["name"]: c for c in json.loads(body)["surface_forms"]}
            self.assertEqual(set(forms), {"eval", "split", "elevate", "insert_knot", "to_bezier", "bounds", "area", "project", "intersect"})
            self.assertEqual([f["name"] for f in forms["eval"]["fields"]], ["surface", "uv", "derivatives", "normal", "curvature"])
            self.assertEqual([(f["name"], f["type"]) for f in forms["intersect"]["fields"]], [("surface", "surface"), ("curve", "curve")])
            status, _, body = server.post("project", {"surface": SQUARE, "point": [0.25, 0.5, 2]})
            self.assertEqual((status, json.loads(body)["distance"]), (200, 2.0))
        finally:
            server.stop()
        # Each surface form's example answers as printed (a consistency check, as above).
        for c in ("eval", "split", "elevate", "insert_knot", "to_bezier", "bounds", "area", "project", "intersect"):
            rc, out, err = test_cli.run(c, args=["--help"])
            lines = out.split("Example (surface form):", 1)[1].splitlines()
            i = next(i for i, l in enumerate(lines) if l.strip().startswith("echo '"))
            request = lines[i].strip()[len("echo '"):lines[i].strip().index("' |")]
            self.assertEqual(json.loads(test_cli.run(c, text=request)[1]), json.loads(lines[i + 1]), c)


class SurfaceHelpTest(CliTest):
    def test_help_examples_match_program_output_self_consistency(self):
        # A consistency check of the help texts (as test_cli.py's for the curve commands):
        # the printed response is the program's own; the values are checked above.
        for c in ("surface", "isocurve"):
            rc, out, err = test_cli.run(c, args=["--help"])
            self.assertEqual((rc, err), (0, ""))
            lines = out.splitlines()
            i = next(i for i, l in enumerate(lines) if l.strip().startswith("echo '"))
            request = lines[i].strip()[len("echo '"):lines[i].strip().index("' |")]
            self.assertEqual(json.loads(test_cli.run(c, text=request)[1]), json.loads(lines[i + 1]), c)


# ---------------------------------------------------------------------------------------
# Session 13: an mpmath oracle for the curvatures of random surfaces (issue 19, item 23)
# and seeded property checks on random surfaces of every type (item 24).

KINDS = ("bezier_surface", "rational_bezier_surface", "bspline_surface", "nurbs_surface")


def random_knots(rng, p, n, a, b):
    """A clamped knot vector on [a, b] for n control points of degree p: random interior
    knots, now and then one of multiplicity 2..p."""
    inner, left = [], n - p - 1
    while left > 0:
        m = rng.randint(2, min(p, left)) if p > 1 and left > 1 and rng.random() < 0.3 else 1
        inner += [rng.uniform(a + 0.05 * (b - a), b - 0.05 * (b - a))] * m
        left -= m
    return [a] * (p + 1) + sorted(inner) + [b] * (p + 1)


def random_surface(rng, kind, dim=3, max_degree=4):
    """A random surface of the kind: degrees 1..max_degree, B-spline domains anywhere in
    [-2, 4], points in [-2, 2]^dim, weights in [0.3, 3]."""
    p, q = rng.randint(1, max_degree), rng.randint(1, max_degree)
    s = {"type": kind}
    if kind in ("bezier_surface", "rational_bezier_surface"):
        rows, cols = p + 1, q + 1
    else:
        rows, cols = p + 1 + rng.randint(0, 3), q + 1 + rng.randint(0, 3)
        a, c = rng.uniform(-2, 1), rng.uniform(-2, 1)
        s["degree"] = [p, q]
        s["knots"] = [random_knots(rng, p, rows, a, a + rng.uniform(0.5, 3)),
                      random_knots(rng, q, cols, c, c + rng.uniform(0.5, 3))]
    s["points"] = [[[rng.uniform(-2, 2) for _ in range(dim)] for _ in range(cols)] for _ in range(rows)]
    if kind in ("rational_bezier_surface", "nurbs_surface"):
        s["weights"] = [[rng.uniform(0.3, 3) for _ in range(cols)] for _ in range(rows)]
    return s


def domain(s):
    p, q, U, V = knots_of(s)
    return U[p], U[len(U) - p - 1], V[q], V[len(V) - q - 1]


def basis_derivative(T, p, i, t, k):
    """d^k/dt^k N_{i,p}(t) by differentiating the Cox-de Boor recursion k times:
    p (N^(k-1)_{i,p-1} / (T[i+p] - T[i]) - N^(k-1)_{i+1,p-1} / (T[i+p+1] - T[i+1])), 0/0 = 0."""
    if k == 0:
        return basis(T, p, i, t)
    if p == 0:
        return 0
    a = 0 if T[i + p] == T[i] else basis_derivative(T, p - 1, i, t, k - 1) / (T[i + p] - T[i])
    b = 0 if T[i + p + 1] == T[i + 1] else basis_derivative(T, p - 1, i + 1, t, k - 1) / (T[i + p + 1] - T[i + 1])
    return p * (a - b)


def fundamental_forms_mp(s, u, v, dps=40):
    """The partials of S up to order 2 (the exact derivatives of the basis above and the
    quotient rule on A / W), the unit normal, E, F, G, L, M, N and the curvatures K, H,
    k1 >= k2 by the contract's formulas, all in mpmath at dps digits (u, v off the knots).
    Also `sine`: |S_u x S_v| / (|S_u| |S_v|)."""
    with mpmath.workdps(dps):
        mpf = mpmath.mpf
        p, q, U, V = knots_of(s)
        U, V, u, v = [mpf(x) for x in U], [mpf(x) for x in V], mpf(u), mpf(v)
        rows, cols, d = len(s["points"]), len(s["points"][0]), len(s["points"][0][0])
        P = [[[mpf(x) for x in pt] for pt in row] for row in s["points"]]
        W = [[mpf(w) for w in row] for row in s.get("weights", [[1] * cols] * rows)]
        # Off the knots N_i^(k) is nonzero only where N_i is.
        nu, nv = [basis(U, p, i, u) for i in range(rows)], [basis(V, q, j, v) for j in range(cols)]
        Nu = [nu] + [[basis_derivative(U, p, i, u, k) if nu[i] else 0 for i in range(rows)] for k in (1, 2)]
        Nv = [nv] + [[basis_derivative(V, q, j, v, k) if nv[j] else 0 for j in range(cols)] for k in (1, 2)]

        def blend(a, b):
            """sum N_i^(a)(u) N_j^(b)(v) w_ij (P_ij, 1): the homogeneous partial (A, W)."""
            h = [mpf(0)] * (d + 1)
            for i in (i for i in range(rows) if Nu[a][i]):
                for j in (j for j in range(cols) if Nv[b][j]):
                    c = Nu[a][i] * Nv[b][j] * W[i][j]
                    for k in range(d):
                        h[k] += c * P[i][j][k]
                    h[d] += c
            return h[:d], h[d]

        (A, w), (Au, wu), (Av, wv) = blend(0, 0), blend(1, 0), blend(0, 1)
        (Auu, wuu), (Auv, wuv), (Avv, wvv) = blend(2, 0), blend(1, 1), blend(0, 2)
        S = [x / w for x in A]
        Su = [(Au[k] - wu * S[k]) / w for k in range(d)]
        Sv = [(Av[k] - wv * S[k]) / w for k in range(d)]
        Suu = [(Auu[k] - 2 * wu * Su[k] - wuu * S[k]) / w for k in range(d)]
        Suv = [(Auv[k] - wu * Sv[k] - wv * Su[k] - wuv * S[k]) / w for k in range(d)]
        Svv = [(Avv[k] - 2 * wv * Sv[k] - wvv * S[k]) / w for k in range(d)]
        out = {"points": S, "u": Su, "v": Sv, "uu": Suu, "uv": Suv, "vv": Svv}
        if d != 3:
            return out
        dp = lambda a, b: sum(x * y for x, y in zip(a, b))
        X = cross(Su, Sv)
        length = mpmath.sqrt(dp(X, X))
        out["sine"] = length / mpmath.sqrt(dp(Su, Su) * dp(Sv, Sv))
        n = [x / length for x in X]
        E, F, G = dp(Su, Su), dp(Su, Sv), dp(Sv, Sv)
        L, M, N = dp(Suu, n), dp(Suv, n), dp(Svv, n)
        K = (L * N - M * M) / (E * G - F * F)
        H = (E * N - 2 * F * M + G * L) / (2 * (E * G - F * F))
        root = mpmath.sqrt(max(H * H - K, 0))
        out.update(E=E, G=G, normal=n, gaussian=K, mean=H, principal=[H + root, H - root], root=root)
        return out


class SurfaceCurvatureOracleTest(CliTest):
    """Normals and curvatures of random surfaces of the four types against
    fundamental_forms_mp (an evaluator whose partials are exact, at 40 digits)."""

    def test_the_oracle_on_closed_forms(self):
        # The oracle itself: the hyperbolic paraboloid (u, v, uv) and a sphere of revolve
        # (K = 1/r^2, H = +1/r where S_u x S_v points inward: the contract's sign).
        hp = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}
        for u, v in ((0.2, 0.7), (0.9, 0.1)):
            o, q = fundamental_forms_mp(hp, u, v), 1 + u * u + v * v
            self.assertAlmostEqual(float(o["gaussian"]), -1 / q ** 2, delta=1e-15)
            self.assertAlmostEqual(float(o["mean"]), -u * v / q ** 1.5, delta=1e-15)
        r = 2.5
        sphere = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        for u, v in ((0.3, 0.7), (0.61, 4.1)):
            o = fundamental_forms_mp(sphere, u, v)
            self.assertAlmostEqual(float(o["gaussian"]), 1 / r ** 2, delta=1e-15)
            inward = -float(dot(o["normal"], o["points"])) / r
            self.assertAlmostEqual(inward, 1, delta=1e-15)
            self.assertAlmostEqual(float(o["mean"]), 1 / r, delta=1e-15)
            self.assert_close([float(x) for x in o["principal"]], [1 / r, 1 / r], 1e-7)  # a double root: sqrt of the rounding

    def compare(self, s, uv, got, oracle=None):
        """The program's response (derivatives 2, normal, curvature) against the oracle (the
        list of fundamental_forms_mp at uv, computed when not given). Returns how many points
        had their curvatures compared."""
        scale = max(1.0, max(abs(x) for row in s["points"] for p in row for x in p))
        oracle = oracle or [fundamental_forms_mp(s, u, v) for u, v in uv]
        compared = 0
        for k, ((u, v), o) in enumerate(zip(uv, oracle)):
            for key in ("u", "v", "uu", "uv", "vv"):
                # Partials: the rational quotient rule in double on O(10) values, relative to
                # the largest partial of that order (a few hundred eps; 1e-12).
                size = max(1.0, max(abs(float(x)) for x in o[key]))
                self.assert_close(got["partials"][key][k], [float(x) for x in o[key]], 1e-12 * size, f"S_{key} at {(u, v)}")
            self.assert_close(got["points"][k], [float(x) for x in o["points"]], 1e-14 * scale)
            if o["sine"] < 1e-2:
                continue  # nearly singular: the normal is ill-conditioned (rare in the random data)
            self.assert_close(got["normals"][k], [float(x) for x in o["normal"]], 1e-11 / float(o["sine"]), f"normal at {(u, v)}")
            # Curvatures: rounding in the partials (relative eps) moves them by about eps
            # times c = (largest second partial) / (smaller of E, G) (1 / length), K by
            # eps c^2, and the principal ones also by eps c^2 / (2 sqrt(H^2 - K)).
            second = max(norm([float(x) for x in o[key]]) for key in ("uu", "uv", "vv"))
            c = second / min(float(o["E"]), float(o["G"])) + 1e-300
            tol = 1e-12 / float(o["sine"])
            self.assertLessEqual(abs(got["gaussian"][k] - float(o["gaussian"])), tol * c * c, f"K at {(u, v)}")
            self.assertLessEqual(abs(got["mean"][k] - float(o["mean"])), tol * c, f"H at {(u, v)}")
            k1, k2 = got["principal"][k]
            self.assertGreaterEqual(k1, k2)
            ptol = tol * c * (1 + c / max(float(o["root"]), 1e-300))
            self.assertLessEqual(abs(k1 - float(o["principal"][0])), ptol, f"k1 at {(u, v)}")
            self.assertLessEqual(abs(k2 - float(o["principal"][1])), ptol, f"k2 at {(u, v)}")
            compared += 1
        return compared

    def test_random_surfaces_of_every_type(self):
        rng = random.Random(2319)
        compared = 0
        for case in range(24):
            s = random_surface(rng, KINDS[case % 4])
            a, b, c, d = domain(s)
            uv = [[rng.uniform(a, b), rng.uniform(c, d)] for _ in range(5)]
            got = self.ok("eval", {"surface": s, "uv": uv, "derivatives": 2, "normal": True, "curvature": True})
            oracle = [fundamental_forms_mp(s, u, v) for u, v in uv]
            compared += self.compare(s, uv, got, oracle)
            if case < 4:
                # Able to fail: the oracle on the surface with one control point moved by 1e-9.
                moved = json.loads(json.dumps(s))
                moved["points"][len(moved["points"]) // 2][len(moved["points"][0]) // 2][2] += 1e-9
                self.assertRaises(AssertionError, self.compare, moved, uv, got)
                # and the program's curvatures, each in turn made 1e-8 relative larger where
                # it is largest.
                for key, part in (("gaussian", None), ("mean", None), ("principal", 0), ("principal", 1)):
                    values = [abs(x if part is None else x[part]) if x is not None else 0 for x in got[key]]
                    k = values.index(max(values))
                    wrong = json.loads(json.dumps(got))
                    if part is None:
                        wrong[key][k] *= 1 + 1e-8
                    else:
                        wrong[key][k][part] *= 1 + 1e-8
                    self.assertRaises(AssertionError, self.compare, s, uv, wrong, oracle)
        self.assertGreaterEqual(compared, 100)  # of 120 points: only the nearly singular skipped


def dense_params(s, rng, n=6):
    """Parameters for a dense check in each direction: n + 1 equally spaced over the domain,
    every interior knot and one random value."""
    a, b, c, d = domain(s)
    p, q, U, V = knots_of(s)
    us = sorted({a, b} | {a + (b - a) * k / n for k in range(1, n)} | {x for x in U if a < x < b} | {rng.uniform(a, b)})
    vs = sorted({c, d} | {c + (d - c) * k / n for k in range(1, n)} | {x for x in V if c < x < d} | {rng.uniform(c, d)})
    return us, vs


def moved(s, by=1e-9):
    """A copy of s with the middle control point's first coordinate moved by `by` (times the
    net's size): what each property check must notice."""
    t = json.loads(json.dumps(s))
    size = max(1.0, max(abs(x) for row in s["points"] for p in row for x in p))
    t["points"][len(t["points"]) // 2][len(t["points"][0]) // 2][0] += by * size
    return t


class SurfacePropertyTest(CliTest):
    """Invariants on seeded random surfaces of the four types (dimensions 1..4, degrees 1..4,
    repeated knots): each result is compared on a dense grid (equally spaced, every knot, a
    random value) with the original, both evaluated by the program, and is also evaluated by
    the tensor-product evaluator written here (dense_points). Each property's check is shown
    to fail on its first case when one control point of the result moves by 1e-9 of the net's
    size."""

    CASES = 16

    def grid_eval(self, s, us, vs):
        """The program's S on us x vs (u outer), an array (len(us), len(vs), d)."""
        pts = self.ok("eval", {"surface": s, "uv": [[u, v] for u in us for v in vs]})["points"]
        return np.array(pts).reshape(len(us), len(vs), -1)

    def assert_same(self, want, s, us, vs, scale, tol=1e-13):
        """s on us x vs, by the program and by the evaluator here, equals want (to tol times
        the net's size: a few dozen eps of convex combinations)."""
        for how, got in (("program", self.grid_eval(s, us, vs)), ("here", dense_points(s, us, vs))):
            err = float(np.abs(got - want).max())
            self.assertLessEqual(err, tol * scale, f"{how}: {err:.3g} on {s['type']}")

    def random_cases(self, seed, kinds=KINDS):
        rng = random.Random(seed)
        for case in range(self.CASES):
            s = random_surface(rng, kinds[case % len(kinds)], dim=rng.randint(1, 4))
            scale = max(1.0, max(abs(x) for row in s["points"] for p in row for x in p))
            us, vs = dense_params(s, rng)
            before = self.grid_eval(s, us, vs)
            # The program's evaluation against the evaluator here, before any operation.
            self.assertLessEqual(float(np.abs(before - dense_points(s, us, vs)).max()), 1e-13 * scale)
            yield case, rng, s, scale, us, vs, before

    def test_partition_of_unity(self):
        # Every control point the same c (random weights and knots): S = c and its first
        # partials 0 everywhere, as the (rational) basis sums to 1.
        for case, rng, s, scale, us, vs, _ in self.random_cases(2401):
            cpt = [rng.uniform(-3, 3) for _ in range(len(s["points"][0][0]))]
            s["points"] = [[list(cpt) for _ in row] for row in s["points"]]

            def check(t):
                r = self.ok("eval", {"surface": t, "uv": [[u, v] for u in us for v in vs], "derivatives": 1})
                self.assertLessEqual(float(np.abs(np.array(r["points"]) - cpt).max()), 1e-14 * max(1, max(map(abs, cpt))))
                # The partials: sums of N_i' c, the N_i' of size p / (shortest span).
                p, q, U, V = knots_of(t)
                span = min(y - x for x, y in zip(U + V, U[1:] + V[1:]) if y > x and x >= min(U[0], V[0]))
                self.assertLessEqual(float(np.abs(np.array(r["partials"]["u"] + r["partials"]["v"])).max()),
                                     1e-13 * max(1, max(map(abs, cpt))) * 4 / span)

            check(s)
            if case == 0:
                self.assertRaises(AssertionError, check, moved(s))

    def test_affine_invariance(self):
        # S of the net mapped by x -> M x + b (weights kept) is M S + b.
        for case, rng, s, scale, us, vs, before in self.random_cases(2402):
            d = len(s["points"][0][0])
            M = np.array([[rng.uniform(-2, 2) for _ in range(d)] for _ in range(d)])
            b = np.array([rng.uniform(-3, 3) for _ in range(d)])
            image = dict(s, points=[[list(M @ np.array(p) + b) for p in row] for row in s["points"]])
            want = before @ M.T + b
            mscale = float(np.abs(M).sum(axis=1).max()) * scale + float(np.abs(b).max())
            self.assert_same(want, image, us, vs, mscale)
            if case == 0:
                self.assertRaises(AssertionError, self.assert_same, want, moved(image), us, vs, mscale)

    def test_knot_insertion(self):
        # A random value or an existing knot, 1..(p - multiplicity) times, in u or v: the
        # knot vector gains exactly those copies and the surface does not change.
        for case, rng, s, scale, us, vs, before in self.random_cases(2403, KINDS[2:]):
            k = rng.randrange(2)
            deg, T = s["degree"][k], s["knots"][k]
            a, b = T[deg], T[len(T) - deg - 1]
            inner = [x for x in T if a < x < b and T.count(x) < deg]
            knot = rng.choice(inner) if inner and rng.random() < 0.4 else rng.uniform(a, b)
            times = rng.randint(1, deg - T.count(knot))
            r = self.ok("insert_knot", {"surface": s, "direction": "uv"[k], "knot": knot, "times": times})["surface"]
            self.assertEqual(r["type"], s["type"])
            self.assertEqual(r["degree"], s["degree"])
            self.assertEqual(r["knots"][k], sorted(T + [knot] * times))
            self.assertEqual(r["knots"][1 - k], s["knots"][1 - k])
            self.assert_same(before, r, us, vs, scale)
            if case == 0:
                self.assertRaises(AssertionError, self.assert_same, before, moved(r), us, vs, scale)

    def test_degree_elevation(self):
        # 1 or 2 times in u or v: the degree rises by that, every distinct knot gains that
        # multiplicity (B-spline kinds), the surface does not change.
        for case, rng, s, scale, us, vs, before in self.random_cases(2404):
            k, times = rng.randrange(2), rng.randint(1, 2)
            r = self.ok("elevate", {"surface": s, "direction": "uv"[k], "times": times})["surface"]
            self.assertEqual(r["type"], s["type"])
            p, q, U, V = knots_of(s)
            if "degree" in s:
                self.assertEqual(r["degree"][k], s["degree"][k] + times)
                T = s["knots"][k]
                self.assertEqual(r["knots"][k], sorted(T + sorted(set(T)) * times))
                self.assertEqual(r["knots"][1 - k], s["knots"][1 - k])
            else:
                self.assertEqual((len(r["points"]), len(r["points"][0])), (p + 1 + times * (1 - k), q + 1 + times * k))
            self.assert_same(before, r, us, vs, scale)
            if case == 0:
                self.assertRaises(AssertionError, self.assert_same, before, moved(r), us, vs, scale)

    def test_split(self):
        # At a random value or an interior knot, in u or v: the halves trace the two parts
        # (Bézier halves reparametrised onto [0, 1], B-spline halves on [a, t] and [t, b]).
        for case, rng, s, scale, us, vs, _ in self.random_cases(2405):
            k = rng.randrange(2)
            a, b, c, d = domain(s)
            lo, hi = (a, b) if k == 0 else (c, d)
            p, q, U, V = knots_of(s)
            inner = sorted({x for x in (U, V)[k] if lo < x < hi})
            t = rng.choice(inner) if inner and rng.random() < 0.4 else rng.uniform(lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo))
            halves = self.ok("split", {"surface": s, "direction": "uv"[k], "t": t})["surfaces"]
            for h, (x0, x1) in zip(halves, ((lo, t), (t, hi))):
                self.assertEqual(h["type"], s["type"])
                hu, hv = dense_params(h, rng)
                ha, hb, hc, hd = domain(h)
                if "degree" in s:
                    self.assertEqual(((ha, hb), (hc, hd))[k], (x0, x1))
                    self.assertEqual(((ha, hb), (hc, hd))[1 - k], ((a, b), (c, d))[1 - k])
                    ou, ov = hu, hv
                else:
                    self.assertEqual((ha, hb, hc, hd), (0, 1, 0, 1))
                    mapped = [x0 + (x1 - x0) * x for x in (hu, hv)[k]]
                    ou, ov = (mapped, hv) if k == 0 else (hu, mapped)
                want = self.grid_eval(s, ou, ov)
                self.assert_same(want, h, hu, hv, scale)
                if case == 0:
                    self.assertRaises(AssertionError, self.assert_same, want, moved(h), hu, hv, scale)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main()
