#!/usr/bin/python3
"""Black-box tests of `tessellate` and the surface form of `render` (issue 19).

The guarantee is checked independently, both ways, on meshes of a few thousand triangles:
- mesh -> surface: every triangle sampled at barycentric points (vertices, edges and the
  inside); each sample's distance to the exact surface by closed forms (sphere, torus,
  cylinder) or, for general B-spline / NURBS surfaces, by a vectorised Cox-de Boor
  evaluator written here: the distance to S at the sample's interpolated (u, v) is an
  upper bound of the true distance, improved by scipy's minimize where it is not already
  well inside the tolerance (any surface point gives an upper bound, so a pass is proof);
- surface -> mesh: the surface sampled densely (closed forms or the evaluator), each
  sample's distance to the mesh by exact point-triangle distances over the triangles near
  it (candidates from a scipy cKDTree of a dense sampling of the mesh: again an upper
  bound of the true distance);
- no cracks: every edge used by one triangle only lies on the domain's boundary, and on a
  closed surface's seam it has a twin on the other side with the same end points; no edge
  is used by more than two triangles, no triangle has zero area;
- orientation: each triangle's normal agrees with S_u x S_v (finite differences of the
  evaluator written here, or its sign on a closed form found once the same way);
- normals: unit, finite; at a sphere's poles the limit normal (never null there);
- OBJ and STL read back into the same mesh; bad input refused.

Usage: test_surface_mesh.py PATH_TO_CASTELJAU [unittest options]
"""
import json
import math
import os
import random
import sys
import unittest
import xml.etree.ElementTree as ET

import numpy as np
from scipy.optimize import minimize
from scipy.spatial import cKDTree

import test_cli
from test_cli import CliTest

HALF = math.sqrt(0.5)
Z_AXIS = {"point": [0, 0, 0], "direction": [0, 0, 1]}


def semicircle(r):
    return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
            "points": [[0, 0, -r], [r, 0, -r], [r, 0, 0], [r, 0, r], [0, 0, r]], "weights": [1, HALF, 1, HALF, 1]}


def circle_xz(R, a):
    """The circle of radius a about (R, 0, 0) in the xz plane (a torus' profile)."""
    return {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
            "points": [[R + a, 0, 0], [R + a, 0, a], [R, 0, a], [R - a, 0, a], [R - a, 0, 0], [R - a, 0, -a],
                       [R, 0, -a], [R + a, 0, -a], [R + a, 0, 0]],
            "weights": [1, HALF, 1, HALF, 1, HALF, 1, HALF, 1]}


# ---------------------------------------------------------------------------------------
# An independent evaluator: Cox-de Boor on arrays of parameters.

def knots_of(s):
    P = s["points"]
    if s["type"] in ("bezier_surface", "rational_bezier_surface"):
        n, m = len(P) - 1, len(P[0]) - 1
        return n, m, [0.0] * (n + 1) + [1.0] * (n + 1), [0.0] * (m + 1) + [1.0] * (m + 1)
    return s["degree"][0], s["degree"][1], [float(x) for x in s["knots"][0]], [float(x) for x in s["knots"][1]]


def basis_matrix(U, p, t):
    """N[k, i] = N_{i,p}(t_k) by the Cox-de Boor recursion (0/0 = 0), right-continuous,
    the domain's end in the last non-empty span; t clamped to the domain."""
    U = np.asarray(U, float)
    n = len(U) - p - 1
    t = np.clip(np.asarray(t, float), U[p], U[n])
    N = np.zeros((len(t), len(U) - 1))
    for i in range(len(U) - 1):
        if U[i] < U[i + 1]:
            N[:, i] = (U[i] <= t) & (t < U[i + 1])
    last = max(i for i in range(len(U) - 1) if U[i] < U[i + 1] and U[i + 1] <= U[n])
    N[t == U[n], :] = 0
    N[t == U[n], last] = 1
    for d in range(1, p + 1):
        M = np.zeros((len(t), len(U) - 1 - d))
        for i in range(len(U) - 1 - d):
            if U[i + d] > U[i]:
                M[:, i] += (t - U[i]) / (U[i + d] - U[i]) * N[:, i]
            if U[i + d + 1] > U[i + 1]:
                M[:, i] += (U[i + d + 1] - t) / (U[i + d + 1] - U[i + 1]) * N[:, i + 1]
        N = M
    return N[:, :n]


class Evaluator:
    def __init__(self, s):
        self.p, self.q, self.U, self.V = knots_of(s)
        P = np.asarray(s["points"], float)
        W = np.asarray(s["weights"], float) if "weights" in s else np.ones(P.shape[:2])
        self.H = np.concatenate([P * W[:, :, None], W[:, :, None]], axis=2)
        self.domain = (self.U[self.p], self.U[len(self.U) - self.p - 1], self.V[self.q], self.V[len(self.V) - self.q - 1])

    def __call__(self, u, v):
        """S at the pairs (u[k], v[k])."""
        Nu, Nv = basis_matrix(self.U, self.p, np.atleast_1d(u)), basis_matrix(self.V, self.q, np.atleast_1d(v))
        h = np.einsum("ki,kj,ijc->kc", Nu, Nv, self.H)
        return h[:, :-1] / h[:, -1:]

    def grid(self, us, vs):
        Nu, Nv = basis_matrix(self.U, self.p, us), basis_matrix(self.V, self.q, vs)
        h = np.einsum("ai,bj,ijc->abc", Nu, Nv, self.H)
        return h[:, :, :-1] / h[:, :, -1:]

    def normal(self, u, v):
        """S_u x S_v by central differences (inside the domain, away from its edges)."""
        u0, u1, v0, v1 = self.domain
        e = 1e-6 * max(u1 - u0, v1 - v0)
        Su = (self(u + e, v) - self(u - e, v)) / (2 * e)
        Sv = (self(u, v + e) - self(u, v - e)) / (2 * e)
        return np.cross(Su, Sv)


# ---------------------------------------------------------------------------------------
# Geometry on arrays.

def point_triangle_distance(P, A, B, C):
    """Distances from points P[k] to triangles (A[k], B[k], C[k]) (Ericson, Real-Time
    Collision Detection 5.1.5: the closest point by Voronoi regions), vectorised."""
    ab, ac, ap = B - A, C - A, P - A
    d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
    bp = P - B
    d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
    cp = P - C
    d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    out = np.empty_like(P)
    done = np.zeros(len(P), bool)

    def put(mask, value):
        m = mask & ~done
        out[m] = value[m]
        done[m] = True

    put((d1 <= 0) & (d2 <= 0), A)
    put((d3 >= 0) & (d4 <= d3), B)
    with np.errstate(divide="ignore", invalid="ignore"):
        put((vc <= 0) & (d1 >= 0) & (d3 <= 0), A + (d1 / (d1 - d3))[:, None] * ab)
        put((d6 >= 0) & (d5 <= d6), C)
        put((vb <= 0) & (d2 >= 0) & (d6 <= 0), A + (d2 / (d2 - d6))[:, None] * ac)
        put((va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0), B + ((d4 - d3) / ((d4 - d3) + (d5 - d6)))[:, None] * (C - B))
        den = va + vb + vc
        v, w = vb / den, vc / den
        put(np.ones(len(P), bool), A + v[:, None] * ab + w[:, None] * ac)
    return np.linalg.norm(P - out, axis=1)


def barycentric_samples(k):
    """Barycentric points of a triangle: every (i, j, k - i - j) / k."""
    return np.array([(i / k, j / k, 1 - (i + j) / k) for i in range(k + 1) for j in range(k + 1 - i)])


class MeshCase:
    """A tessellation response as arrays."""

    def __init__(self, r):
        self.X = np.asarray(r["vertices"], float)
        self.UV = np.asarray(r["uv"], float)
        self.T = np.asarray(r["triangles"], int).reshape(-1, 3)
        self.normals = r["normals"]

    def samples(self, k):
        """Sample points of every triangle, their triangle, their interpolated (u, v)."""
        B = barycentric_samples(k)
        pts = np.einsum("sb,tbc->tsc", B, self.X[self.T]).reshape(-1, self.X.shape[1])
        uv = np.einsum("sb,tbc->tsc", B, self.UV[self.T]).reshape(-1, 2)
        tri = np.repeat(np.arange(len(self.T)), len(B))
        return pts, tri, uv

    def containing_triangles(self, q, bins=64):
        """For each (u, v) of q, a triangle whose (u, v) triangle holds it (-1: none), found
        through a grid of buckets of the triangles' (u, v) boxes."""
        UVt = self.UV[self.T]
        lo, hi = self.UV.min(axis=0), self.UV.max(axis=0)
        scale = bins / np.maximum(hi - lo, 1e-300)

        def cell(x):
            return np.clip(((x - lo) * scale).astype(int), 0, bins - 1)

        a, b = cell(UVt.min(axis=1)), cell(UVt.max(axis=1))
        tri, key = [], []
        for t in range(len(self.T)):
            for i in range(a[t, 0], b[t, 0] + 1):
                for j in range(a[t, 1], b[t, 1] + 1):
                    tri.append(t)
                    key.append(i * bins + j)
        tri, key = np.asarray(tri), np.asarray(key)
        order = np.argsort(key, kind="stable")
        tri, key = tri[order], key[order]
        start = np.searchsorted(key, np.arange(bins * bins))
        end = np.searchsorted(key, np.arange(bins * bins), side="right")
        qc = cell(q)
        qk = qc[:, 0] * bins + qc[:, 1]
        n = end[qk] - start[qk]
        qi = np.repeat(np.arange(len(q)), n)
        ti = tri[np.repeat(start[qk], n) + np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)]
        A, E1, E2 = UVt[ti, 0], UVt[ti, 1] - UVt[ti, 0], UVt[ti, 2] - UVt[ti, 0]
        det = E1[:, 0] * E2[:, 1] - E1[:, 1] * E2[:, 0]
        P = q[qi] - A
        with np.errstate(divide="ignore", invalid="ignore"):
            l1 = (P[:, 0] * E2[:, 1] - P[:, 1] * E2[:, 0]) / det
            l2 = (E1[:, 0] * P[:, 1] - E1[:, 1] * P[:, 0]) / det
        inside = (det != 0) & (l1 >= -1e-9) & (l2 >= -1e-9) & (l1 + l2 <= 1 + 1e-9)
        out = np.full(len(q), -1)
        out[qi[inside][::-1]] = ti[inside][::-1]
        return out

    def distance_to_mesh(self, Q, k=4, candidates=12, uv=None):
        """An upper bound of each point's distance to the mesh (exact distances to the
        triangles of its nearest mesh samples; with uv, the points' (u, v), also to the
        triangle whose (u, v) triangle holds it: long thin triangles of the mesh may have
        no sample near the point)."""
        pts, tri, _ = self.samples(k)
        _, idx = cKDTree(pts).query(Q, k=candidates)
        best = np.full(len(Q), np.inf)
        for c in range(candidates):
            t = self.T[tri[idx[:, c]]]
            d = point_triangle_distance(Q, self.X[t[:, 0]], self.X[t[:, 1]], self.X[t[:, 2]])
            best = np.minimum(best, d)
        if uv is not None:
            hold = self.containing_triangles(uv)
            ok = hold >= 0
            t = self.T[hold[ok]]
            best[ok] = np.minimum(best[ok], point_triangle_distance(Q[ok], self.X[t[:, 0]], self.X[t[:, 1]], self.X[t[:, 2]]))
        return best


class TessellateTest(CliTest):
    def mesh(self, surface, tol, **extra):
        return MeshCase(self.ok("tessellate", dict({"surface": surface, "tolerance": tol}, **extra)))

    def check_topology(self, m, domain, closed_u=False, closed_v=False):
        """Edges: at most two triangles each; an edge of one triangle lies on the domain's
        boundary, and on a closed direction's seam it has a twin with the same points."""
        T = m.T
        size = np.ptp(m.X, axis=0).max()
        # No zero-area (sliver at a pole) triangles, no repeated vertex.
        area2 = np.linalg.norm(np.cross(m.X[T[:, 1]] - m.X[T[:, 0]], m.X[T[:, 2]] - m.X[T[:, 0]]), axis=1)
        self.assertGreater(area2.min(), 1e-12 * size * size)
        count = {}
        for t in T:
            for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                key = (min(a, b), max(a, b))
                count[key] = count.get(key, 0) + 1
        self.assertLessEqual(max(count.values()), 2, "an edge shared by more than two triangles")
        u0, u1, v0, v1 = domain
        eps = 1e-12 * max(u1 - u0, v1 - v0)

        def on_boundary(k):
            u, v = m.UV[k]
            return min(abs(u - u0), abs(u - u1), abs(v - v0), abs(v - v1)) <= eps

        boundary = [e for e, c in count.items() if c == 1]
        for a, b in boundary:
            self.assertTrue(on_boundary(a) and on_boundary(b), f"a crack: edge {a}-{b} at uv {m.UV[a]}, {m.UV[b]}")
        if closed_u or closed_v:
            key = lambda e: tuple(sorted(tuple(np.round(m.X[k] / (1e-9 * size)).astype(np.int64)) for k in e))
            seen = {}
            for e in boundary:
                seen.setdefault(key(e), []).append(e)
            for e in boundary:
                ua, va = m.UV[e[0]]
                ub, vb = m.UV[e[1]]
                on_u_end = closed_u and (abs(ua - ub) <= eps) and min(abs(ua - u0), abs(ua - u1)) <= eps
                on_v_end = closed_v and (abs(va - vb) <= eps) and min(abs(va - v0), abs(va - v1)) <= eps
                if on_u_end or on_v_end or (closed_u and closed_v):
                    self.assertEqual(len(seen[key(e)]), 2, f"the seam edge {e} has no twin")

    def check_orientation(self, m, normal_at):
        """Each triangle's normal agrees with S_u x S_v at a point inside it."""
        T = m.T
        tn = np.cross(m.X[T[:, 1]] - m.X[T[:, 0]], m.X[T[:, 2]] - m.X[T[:, 0]])
        c = (m.X[T[:, 0]] + m.X[T[:, 1]] + m.X[T[:, 2]]) / 3
        n = normal_at(T, c)
        cos = np.einsum("ij,ij->i", tn, n) / (np.linalg.norm(tn, axis=1) * np.linalg.norm(n, axis=1))
        # Triangles of a mesh within a small tolerance are nearly tangent: 0.5 leaves room
        # for the coarse ones at a pole, and a flipped one has cos near -1.
        self.assertGreater(cos.min(), 0.5)

    def check_normals(self, m, cd=3):
        self.assertEqual(len(m.normals), len(m.X))
        for n in m.normals:
            self.assertIsNotNone(n)
            self.assertAlmostEqual(math.hypot(*n), 1, delta=1e-12)

    # -----------------------------------------------------------------------------------
    # Closed forms

    @staticmethod
    def smallest_angles(m, breaks):
        """The smallest angle (degrees) of each triangle with a vertex on a patch side:
        breaks(uv) gives (u, v) scaled so that the sides are at integers."""
        E = [m.X[m.T[:, (k + 1) % 3]] - m.X[m.T[:, k]] for k in range(3)]
        cosines = [-(E[k] * E[k - 1]).sum(1) / np.linalg.norm(E[k], axis=1) / np.linalg.norm(E[k - 1], axis=1) for k in range(3)]
        smallest = np.degrees(np.arccos(np.clip(np.stack(cosines, 1), -1, 1))).min(1)
        su, sv = breaks(m.UV)
        side = (np.abs(su - np.round(su)) < 1e-9) | (np.abs(sv - np.round(sv)) < 1e-9)
        return smallest[side[m.T].any(axis=1)]

    def test_sphere(self):
        r = 2.0
        s = self.ok("surface", {"construct": "revolve", "curve": semicircle(r), "axis": Z_AXIS})["surface"]
        ev = Evaluator(s)
        # Which way S_u x S_v points (inward or outward), found once from the evaluator.
        sign = np.sign(np.dot(ev.normal(0.3, 1.0)[0], ev(0.3, 1.0)[0]))
        for tol in (1e-2, 2e-3):
            m = self.mesh(s, tol)
            self.assertLess(len(m.T), 40000)
            pts, _, _ = m.samples(6)
            # Sphere: the distance of a point to it is | |p| - r |.
            dev = np.abs(np.linalg.norm(pts, axis=1) - r)
            self.assertLessEqual(dev.max(), tol)
            # Not over-refined: the deviation reaches a good part of the tolerance.
            self.assertGreater(dev.max(), 0.2 * tol)
            # Surface -> mesh: dense points of the exact sphere (including the poles).
            th, ph = np.meshgrid(np.linspace(0, math.pi, 121), np.linspace(0, 2 * math.pi, 241))
            Q = r * np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)], axis=-1).reshape(-1, 3)
            self.assertLessEqual(m.distance_to_mesh(Q).max(), tol)
            self.check_topology(m, ev.domain, closed_u=False, closed_v=True)
            self.check_orientation(m, lambda T, c: sign * c)
            self.check_normals(m)
            # The normals are the sphere's (the poles' limit normals too), on the side of S_u x S_v.
            N = np.asarray(m.normals)
            self.assertLess(np.abs(N - sign * m.X / r).max(), 1e-9)
            poles = np.abs(np.abs(m.X[:, 2]) - r) < 1e-12
            self.assertEqual(poles.sum(), 2, "each pole is one vertex")
            # No slivers at the poles: the triangles with a vertex within r / 4 of the axis
            # have no angle below 6 degrees (angles of the mesh's own vertices; one patch
            # count down to the pole gave 3 degrees at 2e-3, 1 degree at r / 10^4).
            E = [m.X[m.T[:, (k + 1) % 3]] - m.X[m.T[:, k]] for k in range(3)]
            cosines = [-(E[k] * E[k - 1]).sum(1) / np.linalg.norm(E[k], axis=1) / np.linalg.norm(E[k - 1], axis=1) for k in range(3)]
            smallest = np.degrees(np.arccos(np.clip(np.stack(cosines, 1), -1, 1))).min(1)
            near = (np.linalg.norm(m.X[:, :2], axis=1)[m.T] < r / 4).any(axis=1)
            self.assertGreaterEqual(smallest[near].min(), 6.0)

    def test_torus_and_cylinder(self):
        R, a = 3.0, 1.0
        s = self.ok("surface", {"construct": "revolve", "curve": circle_xz(R, a), "axis": Z_AXIS})["surface"]
        ev = Evaluator(s)
        tol = 4e-3
        m = self.mesh(s, tol)
        self.assertLess(len(m.T), 40000)

        def torus_distance(P):
            rho = np.hypot(P[:, 0], P[:, 1])
            return np.abs(np.hypot(rho - R, P[:, 2]) - a)

        def outward(P):
            rho = np.hypot(P[:, 0], P[:, 1])
            core = np.stack([P[:, 0] / rho * R, P[:, 1] / rho * R, np.zeros(len(P))], axis=1)
            return P - core

        pts, _, _ = m.samples(6)
        dev = torus_distance(pts)
        self.assertLessEqual(dev.max(), tol)
        self.assertGreater(dev.max(), 0.2 * tol)
        th, ph = np.meshgrid(np.linspace(0, 2 * math.pi, 181), np.linspace(0, 2 * math.pi, 361))
        Q = np.stack([(R + a * np.cos(th)) * np.cos(ph), (R + a * np.cos(th)) * np.sin(ph), a * np.sin(th)], axis=-1).reshape(-1, 3)
        self.assertLessEqual(m.distance_to_mesh(Q).max(), tol)
        self.check_topology(m, ev.domain, closed_u=True, closed_v=True)
        x = ev(0.3, 1.0)
        sign = np.sign(np.dot(ev.normal(0.3, 1.0)[0], outward(x)[0]))
        self.check_orientation(m, lambda T, c: sign * outward(c))
        self.check_normals(m)
        N = np.asarray(m.normals)
        o = outward(m.X)
        self.assertLess(np.abs(N - sign * o / np.linalg.norm(o, axis=1)[:, None]).max(), 1e-9)
        # No needles along patch sides (u a multiple of 1/4, v of pi/2): the outer and inner
        # patches take different counts along their shared sides, and counts whose steps
        # nearly coincide there (a union of i / n1 and k / n2 nodes) gave 1.9 degrees here.
        self.assertGreaterEqual(self.smallest_angles(m, lambda uv: (uv[:, 0] * 4, uv[:, 1] / (math.pi / 2))).min(), 10.0)
        # Cylinder of radius 2, height 5, three quarters of a turn: flat along its axis.
        line = {"type": "bezier", "points": [[2, 0, 0], [2, 0, 5]]}
        cyl = self.ok("surface", {"construct": "revolve", "curve": line, "axis": Z_AXIS, "angle": 4.71238898038469})["surface"]
        ev = Evaluator(cyl)
        tol = 1e-3
        m = self.mesh(cyl, tol)
        # Straight along the axis: few steps in u (the bound on the homogeneous form sees
        # the weights' variation in v through the mixed difference, so not one).
        self.assertLessEqual(len(np.unique(np.round(m.X[:, 2], 9))), 8)
        pts, _, _ = m.samples(6)
        self.assertLessEqual(np.abs(np.hypot(pts[:, 0], pts[:, 1]) - 2).max(), tol)
        zz, ph = np.meshgrid(np.linspace(0, 5, 11), np.linspace(0, 4.71238898038469, 400))
        Q = np.stack([2 * np.cos(ph), 2 * np.sin(ph), zz], axis=-1).reshape(-1, 3)
        self.assertLessEqual(m.distance_to_mesh(Q).max(), tol)
        self.check_topology(m, ev.domain)
        self.check_orientation(m, lambda T, c: ev.normal(np.full(len(T), 0.5), np.mean(m.UV[T][:, :, 1], axis=1)))

    # -----------------------------------------------------------------------------------
    # General surfaces against the evaluator written here

    def check_general(self, s, tol, max_triangles=30000):
        ev = Evaluator(s)
        m = self.mesh(s, tol)
        self.assertLess(len(m.T), max_triangles)
        u0, u1, v0, v1 = ev.domain
        # Vertices on the surface at their (u, v).
        self.assertLess(np.abs(ev(m.UV[:, 0], m.UV[:, 1]) - m.X).max(), 1e-12 * np.ptp(m.X, axis=0).max())
        # Mesh -> surface: the distance to S at the interpolated (u, v) bounds the true
        # distance from above; where it is over the tolerance, a few vectorised
        # Gauss-Newton steps towards the foot point (finite-difference Jacobian, clamped
        # to the domain) improve it, and scipy's minimize any that remain.
        pts, _, uv = m.samples(5)
        d = np.linalg.norm(ev(uv[:, 0], uv[:, 1]) - pts, axis=1)
        far = np.nonzero(d > tol)[0]
        if len(far):
            x, q = uv[far].copy(), pts[far]
            e = 1e-7 * max(u1 - u0, v1 - v0)
            for _ in range(6):
                S = ev(x[:, 0], x[:, 1])
                J = np.stack([(ev(x[:, 0] + e, x[:, 1]) - S) / e, (ev(x[:, 0], x[:, 1] + e) - S) / e], axis=2)
                step = np.linalg.solve(np.einsum("kci,kcj->kij", J, J) + 1e-300, np.einsum("kci,kc->ki", J, q - S))
                x = np.clip(x + step, [u0, v0], [u1, v1])
                d[far] = np.minimum(d[far], np.linalg.norm(ev(x[:, 0], x[:, 1]) - q, axis=1))
        for k in np.nonzero(d > tol)[0]:
            res = minimize(lambda x: float(np.sum((ev(x[0], x[1])[0] - pts[k]) ** 2)), uv[k], method="L-BFGS-B",
                           bounds=[(u0, u1), (v0, v1)], options={"ftol": 1e-16, "gtol": 1e-14})
            d[k] = min(d[k], math.sqrt(res.fun))
        self.assertLessEqual(d.max(), tol)
        self.assertGreater(d.max(), 0.05 * tol)  # a mesh, not a needlessly fine one
        # Surface -> mesh: a dense grid of surface points plus random ones.
        rng = np.random.default_rng(7)
        gu, gv = np.linspace(u0, u1, 90), np.linspace(v0, v1, 90)
        G = ev.grid(gu, gv).reshape(-1, 3)
        ru, rv = rng.uniform(u0, u1, 3000), rng.uniform(v0, v1, 3000)
        Rn = ev(ru, rv)
        GU, GV = np.meshgrid(gu, gv, indexing="ij")
        uv = np.concatenate([np.stack([GU.ravel(), GV.ravel()], axis=1), np.stack([ru, rv], axis=1)])
        self.assertLessEqual(m.distance_to_mesh(np.concatenate([G, Rn]), uv=uv).max(), tol)
        self.check_topology(m, ev.domain)
        # Orientation: S_u x S_v at the triangle's centre in (u, v) (no degenerate edges here).
        self.check_orientation(m, lambda T, c: ev.normal(m.UV[T][:, :, 0].mean(axis=1), m.UV[T][:, :, 1].mean(axis=1)))
        self.check_normals(m)
        return m

    def test_bicubic_bezier_bspline_and_nurbs(self):
        rng = random.Random(3)
        bez = {"type": "bezier_surface",
               "points": [[[i, j, rng.uniform(-1, 1)] for j in range(4)] for i in range(4)]}
        self.check_general(bez, 5e-3)
        # A bicubic B-spline with interior knots (several patches: shared edges).
        P = [[[i * 0.5, j * 0.5, math.sin(i) * math.cos(j) * 0.7] for j in range(6)] for i in range(7)]
        bsp = {"type": "bspline_surface", "degree": [3, 3], "knots": [[0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1], [0, 0, 0, 0, 0.4, 0.6, 1, 1, 1, 1]],
               "points": P}
        m = self.check_general(bsp, 2e-3)
        # The knot lines are grid lines of the mesh (patch edges split alike on both sides).
        us = set(np.round(m.UV[:, 0], 12))
        for k in (0.2, 0.5, 0.7):
            self.assertIn(k, us)
        # A NURBS surface with uneven weights.
        P = [[[i, j, rng.uniform(-0.5, 0.5)] for j in range(5)] for i in range(5)]
        W = [[rng.uniform(0.5, 2) for _ in range(5)] for _ in range(5)]
        nurbs = {"type": "nurbs_surface", "degree": [2, 3], "knots": [[0, 0, 0, 0.4, 0.6, 1, 1, 1], [0, 0, 0, 0, 0.5, 1, 1, 1, 1]],
                 "points": P, "weights": W}
        self.check_general(nurbs, 5e-3)

    def test_adaptive_flat_parts_get_few_triangles(self):
        # A plane: two triangles; a surface flat in v gets one step in v.
        plane = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 2, 0], [0, 4, 0]], [[3, 0, 0], [3, 2, 0], [3, 4, 0]]]}
        self.assertEqual(len(self.mesh(plane, 1e-6).T), 2)
        ridge = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 2], [1, 1, 2]], [[2, 0, 0], [2, 1, 0]]]}
        m = self.mesh(ridge, 1e-3)
        self.assertEqual(len(np.unique(m.UV[:, 1])), 2)
        self.assertGreater(len(np.unique(m.UV[:, 0])), 10)

    # -----------------------------------------------------------------------------------
    # Formats and errors

    def test_obj_and_stl_read_back(self):
        s = self.ok("surface", {"construct": "revolve", "curve": semicircle(1), "axis": Z_AXIS})["surface"]
        req = {"surface": s, "tolerance": 0.02}
        m = MeshCase(self.ok("tessellate", req))
        rc, out, err = test_cli.run("tessellate", dict(req, format="obj"))
        self.assertEqual((rc, err), (0, ""))
        V, F = [], []
        for line in out.splitlines():
            f = line.split()
            if f and f[0] == "v":
                V.append([float(x) for x in f[1:]])
            elif f and f[0] == "f":
                F.append([int(x.split("/")[0]) - 1 for x in f[1:]])
        self.assertEqual(np.asarray(V).tolist(), m.X.tolist())
        self.assertEqual(F, m.T.tolist())
        rc, out, err = test_cli.run("tessellate", dict(req, format="stl"))
        self.assertEqual((rc, err), (0, ""))
        lines = [l.split() for l in out.splitlines()]
        self.assertEqual(lines[0], ["solid", "casteljau"])
        self.assertEqual(lines[-1], ["endsolid", "casteljau"])
        verts = [[float(x) for x in l[1:]] for l in lines if l[0] == "vertex"]
        normals = [[float(x) for x in l[2:]] for l in lines if l[0] == "facet"]
        self.assertEqual(len(normals), len(m.T))
        self.assertEqual(verts, m.X[m.T.reshape(-1)].tolist())
        for k, n in enumerate(normals):
            t = m.X[m.T[k]]
            c = np.cross(t[1] - t[0], t[2] - t[0])
            self.assertLess(np.abs(np.asarray(n) - c / np.linalg.norm(c)).max(), 1e-12)
        # --jsonl: the text as a JSON string.
        a = self.ok_jsonl("tessellate", [dict(req, format="obj")])
        self.assertTrue(a[0]["obj"].startswith("# casteljau"))

    def test_bad_input(self):
        s = self.ok("surface", {"construct": "revolve", "curve": semicircle(2), "axis": Z_AXIS})["surface"]
        self.bad("tessellate", {"surface": s, "tolerance": 0}, where="tolerance")
        self.bad("tessellate", {"surface": s, "tolerance": -1}, where="tolerance")
        self.bad("tessellate", {"surface": s, "tolerance": "small"}, where="tolerance")
        self.bad("tessellate", {"surface": s}, where="tolerance", contains="missing")
        self.bad("tessellate", {"surface": s, "tolerance": 0.1, "format": "ply"}, where="format", contains="ply")
        # Over 10^7 triangles: refused at once (estimated before any work).
        import time
        t0 = time.monotonic()
        self.bad("tessellate", {"surface": s, "tolerance": 1e-9}, where="tolerance", contains="10^7")
        self.assertLess(time.monotonic() - t0, 5)
        s4 = {"type": "bezier_surface", "points": [[[0, 0, 0, 0], [0, 1, 0, 0]], [[1, 0, 0, 1], [1, 1, 1, 0]]]}
        self.bad("tessellate", {"surface": s4, "tolerance": 0.1, "format": "stl"}, where="format")
        self.bad("tessellate", {"surface": {"type": "bezier_surface", "points": [[[0, 0, 0]], [[1, 0]]]}, "tolerance": 0.1},
                 where="surface.points[1][0]")
        # Degree 0 in u or v: a curve (constant along that direction), refused.
        line = {"type": "bezier_surface", "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]]]}
        self.bad("tessellate", {"surface": line, "tolerance": 0.01}, where="surface", contains="degree 0 in u")
        seg = {"type": "bezier_surface", "points": [[[0, 0, 0]], [[1, 1, 1]]]}
        self.bad("tessellate", {"surface": seg, "tolerance": 0.01}, where="surface", contains="degree 0 in v")
        # Other dimensions tessellate in JSON (no normals there).
        r = self.ok("tessellate", {"surface": s4, "tolerance": 0.1})
        self.assertEqual(len(r["vertices"][0]), 4)
        self.assertTrue(all(n is None for n in r["normals"]))

    def test_help_example_matches_program_output_self_consistency(self):
        rc, out, err = test_cli.run("tessellate", args=["--help"])
        self.assertEqual((rc, err), (0, ""))
        lines = out.splitlines()
        i = next(i for i, l in enumerate(lines) if l.strip().startswith("echo '"))
        request = lines[i].strip()[len("echo '"):lines[i].strip().index("' |")]
        self.assertEqual(json.loads(test_cli.run("tessellate", text=request)[1]), json.loads(lines[i + 1]))


class RenderSurfaceTest(CliTest):
    def svg(self, request):
        rc, out, err = test_cli.run("render", request)
        self.assertEqual((rc, err), (0, ""))
        return ET.fromstring(out)

    def test_render(self):
        ns = "{http://www.w3.org/2000/svg}"
        s = self.ok("surface", {"construct": "revolve", "curve": circle_xz(3, 1), "axis": Z_AXIS})["surface"]
        root = self.svg({"surface": s, "view": {"azimuth": 40, "elevation": 30}})
        polys = root.findall(f".//{ns}polygon")
        self.assertGreater(len(polys), 100)
        self.assertEqual(root.findall(f".//{ns}line"), [])
        # Shaded: several fill colours.
        self.assertGreater(len({p.get("fill") for p in polys}), 10)
        bez = {"type": "bezier_surface", "points": [[[i, j, (i - 1.5) * (j - 1.5) / 2] for j in range(4)] for i in range(4)]}
        curve = {"type": "bezier", "points": [[0, 0, 2], [3, 3, 2]]}
        root = self.svg({"surfaces": [s, bez], "curves": [curve], "isocurves": 4, "control_net": True})
        lines = root.findall(f".//{ns}line")
        # Nets: 2 x 4 x 3 segments of the bicubic patch, the torus' net, isocurves, the curve.
        self.assertGreater(len(lines), 2 * 4 * 3 + 8 * 64)
        self.assertGreaterEqual(len(root.findall(f".//{ns}circle")), 16)
        # Painter's order: seen from above (elevation 90), the top of the torus (z = 1)
        # is drawn after its bottom (z = -1).
        sphere_like = self.ok("tessellate", {"surface": s, "tolerance": 0.05})
        self.assertTrue(sphere_like["triangles"])
        self.bad("render", {"surface": s, "view": {"azimuth": 0, "elevation": 120}}, where="view.elevation")
        self.bad("render", {"surface": s, "view": {"tilt": 3}}, where="tilt")
        self.bad("render", {"surface": s, "surfaces": [s]}, where="surfaces")
        self.bad("render", {"surfaces": [s, {"type": "bezier_surface"}]}, where="surfaces[1].points")
        self.bad("render", {"surface": s, "isocurves": -1}, where="isocurves")
        self.bad("render", {"surface": {"type": "bezier_surface", "points": [[[0], [1]]]}}, where="surface")


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main()
