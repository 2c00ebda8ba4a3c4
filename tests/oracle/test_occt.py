#!/usr/bin/python3
"""B-spline and NURBS operations of the `casteljau` command line against OpenCASCADE's
Geom_BSplineCurve at test time (tests/oracle/occt_bspline.cpp, which links no casteljau
code): evaluation with first and second derivatives, knot insertion, degree elevation,
split (OCCT's Segment) and knot removal, on random clamped curves of degrees 1..5 in
dimensions 1..3, polynomial and rational.

Knot insertion, elevation and segmentation have unique results (the same curve in the
refined space), so knots must agree exactly and control points to rounding. NURBS weights
are compared up to one common factor (a rational curve's weights are defined up to
scale). Removal is compared where both libraries' tolerances agree by construction: a knot
that was inserted (removable to rounding) and a knot of a random curve (not removable at
1e-9).

Surfaces: the surface form of eval (points and partial derivatives to order 2) against
Geom_BSplineSurface evaluated through GeomAdaptor_Surface, random B-spline and NURBS
surfaces.

Usage: test_occt.py PATH_TO_CASTELJAU PATH_TO_OCCT_ORACLE [unittest options]
"""
import json
import math
import os
import random
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import test_cli  # noqa: E402
from test_cli import run  # noqa: E402

ORACLE = None  # set from argv


class Oracle:
    """One OCCT oracle process, answering one request per line."""

    def __init__(self, exe):
        self.p = subprocess.Popen([exe], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

    def ask(self, request):
        self.p.stdin.write(json.dumps(request) + "\n")
        self.p.stdin.flush()
        out = json.loads(self.p.stdout.readline())
        if "error" in out:
            raise AssertionError(f"oracle: {out['error']} for {request}")
        return out

    def close(self):
        self.p.stdin.close()
        self.p.wait()


def random_curve(rng, p, dim, rational):
    """A clamped curve on [0, 1] with n in p+1..p+8 control points, interior knots random,
    one of them repeated when the degree allows."""
    n = rng.randint(p + 1, p + 8)
    inner = sorted(round(rng.uniform(0.02, 0.98), 6) for _ in range(n - p - 1))
    if p >= 2 and len(inner) >= 2:
        inner[1] = inner[0]
    runs = {x: inner.count(x) for x in inner}
    if any(c > p for c in runs.values()):
        return random_curve(rng, p, dim, rational)
    U = [0.0] * (p + 1) + inner + [1.0] * (p + 1)
    P = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]
    c = {"degree": p, "knots": U, "points": P}
    if rational:
        c["weights"] = [rng.uniform(0.3, 3) for _ in range(n)]
    return c


def as_json_curve(c):
    out = {"type": "nurbs" if "weights" in c else "bspline", "degree": c["degree"], "knots": c["knots"],
           "points": c["points"]}
    if "weights" in c:
        out["weights"] = c["weights"]
    return out


def scale_of(c):
    return max(1.0, max(abs(x) for p in c["points"] for x in p))


class OcctTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.oracle = Oracle(ORACLE)

    @classmethod
    def tearDownClass(cls):
        cls.oracle.close()

    def ok(self, command, request):
        rc, out, err = run(command, request)
        self.assertEqual(rc, 0, f"{command}: {err} for {json.dumps(request)[:300]}")
        return json.loads(out)

    def assert_same_curve(self, ours, theirs, what):
        """Same degree, same knots (exactly: both insert the same values), control points to
        rounding, weights up to a common factor."""
        self.assertEqual(ours["degree"], theirs["degree"], what)
        self.assertEqual(len(ours["knots"]), len(theirs["knots"]), what)
        for a, b in zip(ours["knots"], theirs["knots"]):
            self.assertLessEqual(abs(a - b), 1e-15 * max(1, abs(b)), f"{what}: knots {ours['knots']} vs {theirs['knots']}")
        self.assertEqual(len(ours["points"]), len(theirs["points"]), what)
        tol = 1e-12 * scale_of(theirs)
        for i, (p, q) in enumerate(zip(ours["points"], theirs["points"])):
            for a, b in zip(p, q):
                self.assertLessEqual(abs(a - b), tol, f"{what}: point {i}: {p} vs {q}")
        if "weights" in theirs:
            w0, v0 = ours["weights"][0], theirs["weights"][0]
            for a, b in zip(ours["weights"], theirs["weights"]):
                self.assertLessEqual(abs(a / w0 - b / v0), 1e-12 * max(1, b / v0), f"{what}: weights")

    def test_eval_and_derivatives(self):
        rng = random.Random(20261130)
        for trial in range(60):
            p, dim, rational = rng.randint(1, 5), rng.randint(1, 3), trial % 2 == 1
            c = random_curve(rng, p, dim, rational)
            ts = [0.0, 1.0] + sorted(set(c["knots"])) + [rng.uniform(0, 1) for _ in range(10)]
            ref = self.oracle.ask(dict(c, op="eval", eval=ts))["eval"]
            got = self.ok("eval", {"curve": as_json_curve(c), "t": ts, "derivatives": 2})
            for j, t in enumerate(ts):
                # OCCT answers with the left piece at an interior knot for derivatives; the
                # contract asks for the right one: compare derivatives only off the knots.
                at_knot = t in c["knots"] and 0 < t < 1
                orders = [got["points"][j]] + ([] if at_knot else [got["derivatives"][0][j], got["derivatives"][1][j]])
                for k, (a, b) in enumerate(zip(orders, ref[j])):
                    # Derivatives of order k grow like (n / span)^k: relative to the reference's size.
                    tol = 1e-11 * max(scale_of(c), max(abs(x) for x in b))
                    for x, y in zip(a, b):
                        self.assertLessEqual(abs(x - y), tol, f"trial {trial} t={t} order {k}: {a} vs {b}")

    def test_insert_knot(self):
        rng = random.Random(7)
        for trial in range(60):
            p, dim, rational = rng.randint(1, 5), rng.randint(1, 3), trial % 2 == 1
            c = random_curve(rng, p, dim, rational)
            interior = [x for x in c["knots"] if 0 < x < 1]
            u = rng.choice(interior) if interior and trial % 3 == 0 else round(rng.uniform(0.01, 0.99), 5)
            have = c["knots"].count(u)
            if have >= p:
                continue
            times = rng.randint(1, p - have)
            ref = self.oracle.ask(dict(c, op="insert_knot", knot=u, times=times))
            got = self.ok("insert_knot", {"curve": as_json_curve(c), "knot": u, "times": times})["curve"]
            self.assert_same_curve(got, ref, f"trial {trial}: insert {u} x{times} into {c}")

    def test_elevate(self):
        rng = random.Random(11)
        for trial in range(40):
            p, dim, rational = rng.randint(1, 4), rng.randint(1, 3), trial % 2 == 1
            c = random_curve(rng, p, dim, rational)
            times = rng.randint(1, 3)
            ref = self.oracle.ask(dict(c, op="elevate", times=times))
            got = self.ok("elevate", {"curve": as_json_curve(c), "times": times})["curve"]
            self.assert_same_curve(got, ref, f"trial {trial}: elevate {c} by {times}")

    def test_split_is_occt_segment(self):
        rng = random.Random(13)
        for trial in range(40):
            p, dim, rational = rng.randint(1, 5), rng.randint(1, 3), trial % 2 == 1
            c = random_curve(rng, p, dim, rational)
            u = round(rng.uniform(0.05, 0.95), 5)
            left = self.oracle.ask(dict(c, op="segment", **{"from": 0.0, "to": u}))
            right = self.oracle.ask(dict(c, op="segment", **{"from": u, "to": 1.0}))
            got = self.ok("split", {"curve": as_json_curve(c), "t": u})["curves"]
            self.assert_same_curve(got[0], left, f"trial {trial}: left half at {u}")
            self.assert_same_curve(got[1], right, f"trial {trial}: right half at {u}")

    def test_remove_knot(self):
        rng = random.Random(17)
        for trial in range(40):
            p, dim, rational = rng.randint(2, 5), rng.randint(1, 3), trial % 2 == 1
            c = random_curve(rng, p, dim, rational)
            u = round(rng.uniform(0.05, 0.95), 5)
            if u in c["knots"]:
                continue
            # Inserted twice (p >= 2), then removed: both come back to the original curve.
            inserted = self.oracle.ask(dict(c, op="insert_knot", knot=u, times=2))
            if "weights" in c:
                inserted["weights"] = inserted["weights"]
            req = dict(inserted, op="remove_knot", knot=u, times=2, tolerance=1e-9)
            ref = self.oracle.ask(req)
            got = self.ok("remove_knot", {"curve": as_json_curve(inserted), "knot": u, "times": 2, "tolerance": 1e-9})
            self.assertEqual(ref["removed"], 2, f"trial {trial}: OCCT")
            self.assertEqual(got["removed"], 2, f"trial {trial}")
            self.assert_same_curve(got["curve"], ref, f"trial {trial}: remove {u} x2")
            # A knot of a random curve is not removable at 1e-9 (its neighbours' points are
            # random): neither library removes it.
            interior = sorted(set(x for x in c["knots"] if 0 < x < 1))
            if interior:
                k = interior[-1]
                ref = self.oracle.ask(dict(c, op="remove_knot", knot=k, times=1, tolerance=1e-9))
                got = self.ok("remove_knot", {"curve": as_json_curve(c), "knot": k, "times": 1, "tolerance": 1e-9})
                self.assertEqual((got["removed"], ref["removed"]), (0, 0), f"trial {trial}: knot {k} of {c}")


def random_knots(rng, p, n):
    """A clamped knot vector on [0, 1] for n points of degree p, one interior knot repeated
    when the degree allows."""
    inner = sorted(round(rng.uniform(0.02, 0.98), 6) for _ in range(n - p - 1))
    if p >= 2 and len(inner) >= 2:
        inner[1] = inner[0]
    if any(inner.count(x) > p for x in inner):
        return random_knots(rng, p, n)
    return [0.0] * (p + 1) + inner + [1.0] * (p + 1)


class OcctSurfaceTest(unittest.TestCase):
    """Surface evaluation (the surface form of eval, derivatives to order 2) against OCCT's
    Geom_BSplineSurface through GeomAdaptor_Surface (D2 and D0), random B-spline and NURBS
    surfaces of degrees 1..4 in each direction."""

    @classmethod
    def setUpClass(cls):
        cls.oracle = Oracle(ORACLE)

    @classmethod
    def tearDownClass(cls):
        cls.oracle.close()

    def test_values_and_partials(self):
        rng = random.Random(20261202)
        names = ["u", "v", "uu", "uv", "vv"]
        for trial in range(24):
            p, q, rational = rng.randint(1, 4), rng.randint(1, 4), trial % 2 == 1
            rows, cols = rng.randint(p + 1, p + 5), rng.randint(q + 1, q + 5)
            U, V = random_knots(rng, p, rows), random_knots(rng, q, cols)
            P = [[[rng.uniform(-5, 5) for _ in range(3)] for _ in range(cols)] for _ in range(rows)]
            s = {"type": "bspline_surface", "degree": [p, q], "knots": [U, V], "points": P}
            if rational:
                s["type"] = "nurbs_surface"
                s["weights"] = [[rng.uniform(0.3, 3) for _ in range(cols)] for _ in range(rows)]
            uv = [[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]] + [[rng.uniform(0, 1), rng.uniform(0, 1)] for _ in range(12)]
            uv += [[x, rng.uniform(0, 1)] for x in sorted(set(U)) if 0 < x < 1]
            req = {"op": "surface_eval", "degree": [p, q], "knots": [U, V], "points": P, "uv": uv}
            if rational:
                req["weights"] = s["weights"]
            ref = self.oracle.ask(req)
            rc, out, err = run("eval", {"surface": s, "uv": uv, "derivatives": 2})
            self.assertEqual(rc, 0, err)
            got = json.loads(out)
            scale = max(1.0, max(abs(x) for row in P for pt in row for x in pt))
            for j, (u, v) in enumerate(uv):
                self.assert_close(got["points"][j], ref["eval"][j][0], 1e-12 * scale, f"trial {trial} S({u}, {v})")
                self.assert_close(got["points"][j], ref["d0"][j], 1e-12 * scale, f"trial {trial} D0({u}, {v})")
                # OCCT's derivatives at an interior knot come from one side, the contract's
                # from the right piece: derivatives are compared off the knots only.
                if (0 < u < 1 and u in U) or (0 < v < 1 and v in V):
                    continue
                for k, name in enumerate(names):
                    b = ref["eval"][j][k + 1]
                    # Derivatives of order k grow like (degree / span)^k: relative to the
                    # reference's own size, a few hundred eps of it.
                    tol = 1e-11 * max(scale, max(abs(x) for x in b))
                    self.assert_close(got["partials"][name][j], b, tol, f"trial {trial} S_{name}({u}, {v})")

    def assert_close(self, a, b, tol, what):
        for x, y in zip(a, b):
            self.assertLessEqual(abs(x - y), tol, f"{what}: {a} vs {b}")


if __name__ == "__main__":
    test_cli.BINARY = sys.argv.pop(1)
    ORACLE = sys.argv.pop(1)
    unittest.main()
