#!/usr/bin/python3
"""Black-box tests of the curve types served through the registry: `polyline` in every
command, paths whose segments are any curve object (nested paths included), the
piecewise queries (bounds, flatten, to_bezier) respecting each curve's domain, and the
limits every command applies the same way.

Usage: test_registry.py PATH_TO_CASTELJAU [unittest options]

Expected values come from closed forms and small independent computations here.
"""
import json
import os
import sys
import unittest

import test_cli
from test_cli import CliTest, bezier, de_casteljau, dist, dist_to_polyline, run

TIGHT = test_cli.TIGHT

ZIGZAG = [[0, 0], [2, 0], [2, 4], [5, 4]]


def polyline(points, **extra):
    return dict({"type": "polyline", "points": points}, **extra)


def polyline_point(P, u):
    """The polyline through P at parameter u (point i at i), extending the end segments."""
    i = min(max(int(u // 1), 0), len(P) - 2)
    s = u - i
    return [a + s * (b - a) for a, b in zip(P[i], P[i + 1])]


class PolylineTest(CliTest):
    def test_eval(self):
        ts = [0, 0.25, 1, 1.5, 2, 2.75, 3, -1, 4.5]
        r = self.ok("eval", {"curve": polyline(ZIGZAG), "t": ts, "derivatives": 2})
        self.assert_close(r["points"], [polyline_point(ZIGZAG, t) for t in ts], TIGHT)
        # First derivative: the segment's difference; the right segment at a vertex, the
        # last one at the end of the domain and beyond it, the first one before it.
        seg = [[b - a for a, b in zip(ZIGZAG[i], ZIGZAG[i + 1])] for i in range(3)]
        want = [seg[0], seg[0], seg[1], seg[1], seg[2], seg[2], seg[2], seg[0], seg[2]]
        self.assertEqual(r["derivatives"][0], want)
        self.assertEqual(r["derivatives"][1], [[0, 0]] * len(ts))

    def test_one_dimensional_and_four_dimensional(self):
        r = self.ok("eval", {"curve": polyline([[1], [3], [-1]]), "t": [0.5, 1.5]})
        self.assertEqual(r["points"], [[2], [1]])
        P4 = [[0, 0, 0, 0], [1, 2, 3, 4]]
        r = self.ok("eval", {"curve": polyline(P4, dim=4), "t": [0.5]})
        self.assertEqual(r["points"], [[0.5, 1, 1.5, 2]])

    def test_bounds_is_the_box_of_the_points(self):
        r = self.ok("bounds", {"curve": polyline([[0, 0], [3, -1], [1, 5], [2, 2]])})
        self.assertEqual(r, {"min": [0, -1], "max": [3, 5]})

    def test_to_bezier(self):
        r = self.ok("to_bezier", {"curve": polyline(ZIGZAG)})
        c = r["curve"]
        self.assertEqual(c["type"], "path")
        self.assertEqual(c["breaks"], [0, 1, 2, 3])
        self.assertEqual([s["points"] for s in c["segments"]], [ZIGZAG[i:i + 2] for i in range(3)])
        self.assertTrue(all(s["type"] == "bezier" for s in c["segments"]))

    def test_flatten_is_the_polyline(self):
        r = self.ok("flatten", {"curve": polyline(ZIGZAG), "tolerance": 0.01})
        self.assertEqual(r["points"], ZIGZAG)

    def test_render(self):
        for c in (polyline(ZIGZAG), polyline([[0], [1], [-1]])):
            rc, out, err = run("render", {"curve": c})
            self.assertEqual(rc, 0, err)
            self.assertTrue(out.startswith("<svg"))
            self.assertIn("<path", out)
            self.assertNotIn("nan", out.lower())

    def test_split_and_elevate_refuse_politely(self):
        self.bad("split", {"curve": polyline(ZIGZAG), "t": 1}, "curve.type", contains="polyline")
        self.bad("elevate", {"curve": polyline(ZIGZAG), "times": 1}, "curve.type", contains="polyline")

    def test_bad_polylines(self):
        self.bad("eval", {"curve": polyline([[0, 0]]), "t": [0]}, "curve.points", contains="at least 2")
        self.bad("eval", {"curve": polyline([]), "t": [0]}, "curve.points")
        self.bad("eval", {"curve": polyline(ZIGZAG, weights=[1, 1, 1, 1]), "t": [0]}, "curve.weights",
                 contains="unknown field")
        self.bad("eval", {"curve": polyline(ZIGZAG, degree=1), "t": [0]}, "curve.degree", contains="unknown field")
        self.bad("eval", {"curve": polyline([[0, 0], [1]]), "t": [0]}, "curve.points[1]")
        self.bad("eval", {"curve": polyline([[0, 0], [1, 1]], dim=3), "t": [0]}, "curve.dim")
        self.bad("eval", {"curve": polyline(ZIGZAG), "t": [1e308]}, "t[0]")


class PathSegmentsTest(CliTest):
    # A cubic on [0, 1], a polyline (own domain [0, 2]) on [1, 5], a nested path on [5, 6].
    PATH = {"type": "path", "breaks": [0, 1, 5, 6], "segments": [
        bezier([[0, 0], [0, 1], [1, 1], [1, 0]]),
        polyline([[1, 0], [2, 0], [2, -2]]),
        {"type": "path", "segments": [polyline([[2, -2], [3, -2]]), bezier([[3, -2], [4, -1], [5, -2]])],
         "breaks": [-1, 0, 1]}]}

    def reference(self, u):
        if u < 1:
            return de_casteljau([[0, 0], [0, 1], [1, 1], [1, 0]], u)
        if u < 5:
            return polyline_point([[1, 0], [2, 0], [2, -2]], (u - 1) / 2)
        s = (u - 5) * 2 - 1  # the nested path's own parameter in [-1, 1]
        if s < 0:
            return polyline_point([[2, -2], [3, -2]], s + 1)
        return de_casteljau([[3, -2], [4, -1], [5, -2]], s)

    def test_eval_maps_each_segment_domain(self):
        ts = [0, 0.3, 1, 2, 3, 4.5, 5, 5.25, 5.5, 5.8, 6]
        r = self.ok("eval", {"curve": self.PATH, "t": ts, "derivatives": 1})
        self.assert_close(r["points"], [self.reference(t) for t in ts], TIGHT)
        # The polyline's own [0, 2] is stretched onto [1, 5]: derivatives halve.
        self.assertEqual(r["derivatives"][0][3], [0.5, 0])
        self.assertEqual(r["derivatives"][0][4], [0, -1])
        # The nested polyline's own [0, 1] on [5, 5.5]: derivative doubled.
        self.assertEqual(r["derivatives"][0][7], [2, 0])

    def test_to_bezier_keeps_the_parametrisation(self):
        c = self.ok("to_bezier", {"curve": self.PATH})["curve"]
        self.assertEqual(c["breaks"], [0, 1, 3, 5, 5.5, 6])
        ts = [0.2, 1.5, 3.5, 5.2, 5.9]
        r = self.ok("eval", {"curve": c, "t": ts})
        self.assert_close(r["points"], [self.reference(t) for t in ts], TIGHT)

    def test_bounds(self):
        r = self.ok("bounds", {"curve": self.PATH})
        # x: 0 .. 5; y: the cubic's peak 3/4 at t = 1/2 and -2 on the polyline; the final
        # quadratic's y = -2 + 2 t (1 - t) stays above -2.
        self.assert_close(r["min"], [0, -2], TIGHT)
        self.assert_close(r["max"], [5, 0.75], TIGHT)

    def test_flatten_within_tolerance(self):
        tol = 0.01
        r = self.ok("flatten", {"curve": self.PATH, "tolerance": tol})
        poly = r["points"]
        self.assertEqual(poly[0], [0, 0])
        self.assertEqual(poly[-1], [5, -2])
        for k in range(601):
            u = 6 * k / 600
            self.assertLessEqual(dist_to_polyline(self.reference(u), poly), tol * (1 + 1e-9), f"u={u}")

    def test_gap_wider_than_the_tolerance_is_refused(self):
        gap = {"type": "path", "segments": [polyline([[0, 0], [1, 0]]), bezier([[1, 0.5], [2, 0]])]}
        self.bad("flatten", {"curve": gap, "tolerance": 0.1}, "curve", contains="not connected")
        r = self.ok("flatten", {"curve": gap, "tolerance": 0.5})
        self.assertEqual(r["points"], [[0, 0], [1, 0], [1, 0.5], [2, 0]])
        # The renderer draws it (a separate subpath), it does not refuse it.
        rc, out, err = run("render", {"curve": gap})
        self.assertEqual(rc, 0, err)

    def test_segment_errors_name_their_place(self):
        bad = {"type": "path", "segments": [polyline([[0, 0], [1, 0]]), polyline([[1], [2]])]}
        self.bad("bounds", {"curve": bad}, "curve.segments[1]", contains="dimension")
        bad = {"type": "path", "segments": [polyline([[0, 0], [1, 0]]),
                                            {"type": "path", "segments": [polyline([[0, 0], ["x", 0]])]}]}
        self.bad("bounds", {"curve": bad}, "curve.segments[1].segments[0].points[1][0]")
        deep = bezier([[0]])
        for _ in range(40):
            deep = {"type": "path", "segments": [deep]}
        rc, out, err = run("bounds", {"curve": deep})
        self.assertEqual((rc, out), (2, ""))
        # The long field path is shortened in the middle; its end names the place.
        self.assertTrue(err.startswith("error: curve.segments[0].segments[0]"), err)
        self.assertTrue(err.endswith("segments[0].segments: paths nest more than 32 levels deep\n"), err)


class LimitsTest(CliTest):
    def test_input_degree_cap_is_the_same_in_every_command(self):
        P = [[i % 7, (i * i) % 5] for i in range(1002)]  # degree 1001
        for command, extra in (("eval", {"t": [0.5]}), ("bounds", {}), ("flatten", {"tolerance": 0.1}),
                               ("render", {}), ("to_bezier", {}), ("elevate", {"times": 1}), ("split", {"t": 0.5})):
            self.bad(command, dict({"curve": bezier(P)}, **extra), "curve.points", contains="highest supported degree 1000")
        # Degree 1000 itself is accepted.
        r = self.ok("eval", {"curve": bezier(P[:1001]), "t": [0]})
        self.assertEqual(r["points"], [P[0]])

    def test_elevate_cap(self):
        self.bad("elevate", {"curve": bezier([[0], [1]]), "times": 1000}, "times", contains="1000")
        r = self.ok("elevate", {"curve": bezier([[0], [1]]), "times": 999})
        self.assertEqual(len(r["curve"]["points"]), 1001)


# One valid curve object of every type of docs/cli.md's "Curve objects" table.
SAMPLES = {
    "bezier": bezier([[0, 0], [1, 2], [2, 0]]),
    "rational_bezier": {"type": "rational_bezier", "points": [[0, 0], [1, 2], [2, 0]], "weights": [1, 2, 1]},
    "bspline": {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "points": [[0, 0], [1, 2], [2, 0], [3, 1]]},
    "nurbs": {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "points": [[0, 0], [1, 2], [2, 0], [3, 1]],
              "weights": [1, 2, 1, 1]},
    "polyline": polyline([[0, 0], [1, 1], [2, 0]]),
    "cubic_spline": {"type": "cubic_spline", "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]},
    "hermite": {"type": "hermite", "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]], "tangent_rule": "catmull_rom"},
    "path": {"type": "path", "segments": [bezier([[0, 0], [1, 2], [2, 0]])]},
    "lagrange": {"type": "lagrange", "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]},
    "catmull_rom": {"type": "catmull_rom", "points": [[0, 0], [1, 1], [2, 0], [3, 1]]},
}


class CapabilityTest(CliTest):
    """A command that needs a member some curve types lack (split, elevate, reduce, the
    knot operations) names in its refusal exactly the types it works on: found here by running
    it on every type, not from a list."""

    def capability(self, command, extra):
        works, refused = set(), {}
        for name, curve in SAMPLES.items():
            rc, out, err = run(command, dict({"curve": curve}, **extra))
            if err.startswith("error: curve.type: "):
                refused[name] = err
            else:
                works.add(name)  # answered, or refused for another reason (a parameter)
        self.assertTrue(works and refused, command)
        for name, err in refused.items():
            prefix = f"error: curve.type: {command} needs a "
            self.assertTrue(err.startswith(prefix), err)
            listed = err[len(prefix):err.index(" curve, got a ")]
            *head, last = listed.split(" or ")
            names = (head[0].split(", ") if head else []) + [last]
            self.assertEqual(set(names), works, err)
            self.assertTrue(err.rstrip().split(" (")[0].endswith(f"got a {name}"), err)
        return works

    def test_split(self):
        self.assertEqual(self.capability("split", {"t": 1}), {"bezier", "rational_bezier", "bspline", "nurbs"})

    def test_elevate(self):
        self.capability("elevate", {"times": 1})

    def test_reduce(self):
        # The registry's degree_reduction: a Bézier by least squares, a B-spline or NURBS by
        # its reduce_degree member (samples of degree 1 or 2, a tolerance they all meet).
        self.assertEqual(self.capability("reduce", {"tolerance": 100}), {"bezier", "bspline", "nurbs"})

    def test_knot_operations(self):
        self.assertEqual(self.capability("insert_knot", {"knot": 0.5}), {"bspline", "nurbs"})
        self.assertEqual(self.capability("remove_knot", {"knot": 1}), {"bspline", "nurbs"})


class MessageTest(CliTest):
    def test_one_time_is_singular(self):
        # Degree 0: a knot at most once (p + 1; degree 1 now allows an interior knot twice).
        c = {"type": "bspline", "degree": 0, "knots": [0, 1, 1, 2], "points": [[0], [1], [2]]}
        err = self.bad("eval", {"curve": c, "t": [0]}, "curve.knots[2]", contains="at most once (p + 1) for degree 0")
        self.assertNotIn("1 times", err)

    def test_help_names_every_curve_type(self):
        rc, out, err = run(None, args=["--help"])
        self.assertEqual(rc, 0)
        first = out.splitlines()[0]
        for name in SAMPLES:
            self.assertIn(name, first)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
