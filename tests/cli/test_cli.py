#!/usr/bin/python3
"""Black-box tests of the `casteljau` command line program (docs/cli.md).

Usage: test_cli.py PATH_TO_CASTELJAU [unittest options]

Expected values come from closed forms and a small de Casteljau written here, never from
the program under test. Standard library only.
"""
import atexit
import json
import math
import os
import select
import subprocess
import sys
import tempfile
import time
import unittest

BINARY = None  # set from argv in __main__
# Seconds one program run may take, times CASTELJAU_TIMEOUT_SCALE (the sanitizer build at -O0
# sets 5: tests/cli/CMakeLists.txt).
TIMEOUT = 30 * float(os.environ.get("CASTELJAU_TIMEOUT_SCALE", "1"))

# Tolerances. EXACT: dyadic inputs whose de Casteljau steps (halving, sums of small
# integers) are exact in double. TIGHT: a few ulps of O(1) coordinates after a handful of
# operations (de Casteljau error is O(n eps max|P|) [Farin02, 3.1]).
TIGHT = 1e-14


def run(command, request=None, args=(), text=None):
    """Runs `casteljau command args...` with the request (a dict, dumped) or raw text on
    stdin. Returns (exit status, stdout, stderr)."""
    argv = [BINARY] + ([command] if command else []) + list(args)
    data = text if text is not None else (json.dumps(request) if request is not None else "")
    if isinstance(data, str):
        data = data.encode()
    p = subprocess.run(argv, input=data, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=TIMEOUT)
    return p.returncode, p.stdout.decode(), p.stderr.decode()



def run_jsonl(command, requests):
    """Runs `casteljau command --jsonl` once on the requests (dicts), one per line, for
    tests that check many independent responses (one process instead of one per request).
    Returns (exit status, the parsed response lines, stderr)."""
    text = "".join(json.dumps(r) + "\n" for r in requests)
    rc, out, err = run(command, args=["--jsonl"], text=text)
    return rc, [json.loads(line) for line in out.splitlines()], err

class Session:
    """One `casteljau COMMAND --jsonl` process kept open for many requests: a request line
    in, its response line out (the program flushes each). The feature scripts send their
    valid requests through sessions (CliTest.ok): a process start is about 11 ms of CPU and
    the scripts make thousands of requests. The answers are the same bytes as a process per
    request gives (both print apps/cli/request.cpp's answer()); the contract of a single
    request (exit status, stderr) is tested by test_cli.py and by every `bad` call, which
    keep a process each."""

    def __init__(self, command):
        self.command = command
        self.errors = tempfile.TemporaryFile()
        self.process = subprocess.Popen([BINARY, command, "--jsonl"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=self.errors)
        self.pending = b""

    def ask(self, request):
        """The response line to one request (a dict), or raises AssertionError with what
        went wrong (the process ended, wrote to stderr, or took longer than TIMEOUT s)."""
        timeout = TIMEOUT
        self.process.stdin.write(json.dumps(request).encode() + b"\n")
        self.process.stdin.flush()
        deadline = time.monotonic() + timeout
        fd = self.process.stdout.fileno()
        while b"\n" not in self.pending:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                raise AssertionError(f"{self.command} --jsonl: no response within {timeout} s")
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                raise AssertionError(f"{self.command} --jsonl ended (status {self.process.wait()})")
            self.pending += chunk
        line, self.pending = self.pending.split(b"\n", 1)
        if os.fstat(self.errors.fileno()).st_size:
            self.errors.seek(0)
            raise AssertionError(f"{self.command} --jsonl wrote to stderr: {self.errors.read().decode()!r}")
        return line.decode() + "\n"

    def close(self):
        self.process.stdin.close()
        self.process.wait()
        self.process.stdout.close()
        self.errors.close()


SESSIONS = {}  # command -> Session, for CliTest.ok; test_cli.py's own tests start a process each
USE_SESSIONS = True
NO_SESSION = ("render", "surface_mesh")  # responses that are not JSON outside --jsonl


@atexit.register
def _close_sessions():
    for s in SESSIONS.values():
        s.close()


def answer(command, request):
    """The response line of a valid request through the command's session."""
    s = SESSIONS.get(command)
    if s is None:
        s = SESSIONS[command] = Session(command)
    return s.ask(request)


# ---------------------------------------------------------------------------------------
# Reference geometry, written independently of the library.

# The curve commands of docs/cli.md (`surface`, `isocurve`, `tessellate` and `serve` are
# tested in files of their own).
CONTRACT_COMMANDS = ("eval", "split", "elevate", "insert_knot", "remove_knot", "subdivide", "to_bezier",
                     "bounds", "length", "param_at_length", "features", "distance", "area", "project",
                     "intersect", "flatten", "fit", "render", "solve", "refine", "to_bspline", "reduce", "basis", "frames", "offset",
                     "to_quadratic", "import_svg", "to_svg_path", "glyph")


def supported_commands():
    """The commands `casteljau --help` lists without "(not supported yet)"."""
    rc, out, _ = run(None, args=["--help"])
    assert rc == 0
    found = []
    for c in CONTRACT_COMMANDS:
        line = next(l for l in out.splitlines() if l.startswith(f"  {c} "))
        if "not supported yet" not in line:
            found.append(c)
    return found


def lerp(a, b, t):
    return [(1 - t) * x + t * y for x, y in zip(a, b)]


def de_casteljau(P, t):
    pts = [list(p) for p in P]
    while len(pts) > 1:
        pts = [lerp(pts[i], pts[i + 1], t) for i in range(len(pts) - 1)]
    return pts[0]


def rational_point(P, w, t):
    """R(t) = sum w_i B_i P_i / sum w_i B_i with Bernstein polynomials written out."""
    n = len(P) - 1
    B = [math.comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]
    den = sum(wi * bi for wi, bi in zip(w, B))
    return [sum(w[i] * B[i] * P[i][k] for i in range(n + 1)) / den for k in range(len(P[0]))]


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def dist_to_segment(p, a, b):
    ab = [y - x for x, y in zip(a, b)]
    ap = [y - x for x, y in zip(a, p)]
    l2 = sum(x * x for x in ab)
    s = 0.0 if l2 == 0 else max(0.0, min(1.0, sum(x * y for x, y in zip(ap, ab)) / l2))
    return dist(p, [x + s * y for x, y in zip(a, ab)])


def dist_to_polyline(p, poly):
    return min(dist_to_segment(p, poly[i], poly[i + 1]) for i in range(len(poly) - 1))


CUBIC = [[0, 0], [1, 3], [3, 3], [4, 0]]
QUARTER_CIRCLE = {"type": "rational_bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, math.sqrt(2) / 2, 1]}


def bezier(points, **extra):
    return dict({"type": "bezier", "points": points}, **extra)


class CliTest(unittest.TestCase):
    def ok(self, command, request, args=()):
        if USE_SESSIONS and not args and command not in NO_SESSION:
            out = answer(command, request)
            response = json.loads(out)
            if isinstance(response, dict) and list(response) == ["error"]:
                # --jsonl's error line: the request's own process gives the message.
                rc, _, err = run(command, request)
                self.fail(f"{command}: status {rc}: {err or response['error']}")
            return response
        rc, out, err = run(command, request, args)
        self.assertEqual(rc, 0, err)
        self.assertEqual(err, "")
        self.assertTrue(out.endswith("\n"))
        self.assertEqual(out.count("\n"), 1, "one response line")
        return json.loads(out)

    def ok_jsonl(self, command, requests):
        """The responses to independent requests, through one --jsonl process (run_jsonl):
        every line answered, none with an error, nothing on stderr."""
        rc, answers, err = run_jsonl(command, requests)
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual(len(answers), len(requests))
        for a in answers:
            self.assertNotIn("error", a)
        return answers

    def bad(self, command, request=None, where="", text=None, args=(), contains=None, status=2):
        """Asserts the error contract: status 2, nothing on stdout, one stderr line
        `error: <where>: <what>`."""
        rc, out, err = run(command, request, args, text)
        self.assertEqual(rc, status, f"stdout={out!r} stderr={err!r}")
        self.assertEqual(out, "", "bad input must not produce output")
        self.assertTrue(err.endswith("\n"), repr(err))
        self.assertEqual(err.count("\n"), 1, f"exactly one stderr line: {err!r}")
        self.assertTrue(err.startswith(f"error: {where}: "), f"expected where {where!r}: {err!r}")
        self.assertGreater(len(err), len(f"error: {where}: ") + 3, "the message says what is wrong")
        if contains:
            self.assertIn(contains, err)
        return err

    def assert_close(self, got, want, tol, msg=None):
        self.assertEqual(len(got), len(want), msg)
        for g, w in zip(got, want):
            if isinstance(w, (list, tuple)):
                self.assert_close(g, w, tol, msg)
            else:
                self.assertLessEqual(abs(g - w), tol * max(1.0, abs(w)), f"{got} vs {want} {msg or ''}")


# ---------------------------------------------------------------------------------------

class EvalTest(CliTest):
    def test_pole_of_a_rational_curve_names_the_parameter(self):
        # Weights 1 and 3: W(t) = 1 + 2t vanishes at t = -1/2 (outside the domain, where
        # extrapolation is allowed): the second parameter is at fault, not the curve.
        curve = {"type": "rational_bezier", "points": [[0, 0], [1, 0]], "weights": [1, 3]}
        self.bad("eval", {"curve": curve, "t": [0, -0.5]}, where="t[1]", contains="pole")
        self.bad("eval", {"curve": curve, "t": [-0.5], "derivatives": 1}, where="t[0]", contains="pole")

    def test_cubic_midpoint_closed_form(self):
        # P(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8: exact for small integers.
        r = self.ok("eval", {"curve": bezier(CUBIC), "t": [0.5]})
        want = [(CUBIC[0][k] + 3 * CUBIC[1][k] + 3 * CUBIC[2][k] + CUBIC[3][k]) / 8 for k in range(2)]
        self.assertEqual(r["points"], [want])
        self.assertNotIn("derivatives", r)

    def test_cubic_bernstein_form(self):
        ts = [0, 0.1, 0.25, 1 / 3, 0.9, 1]
        r = self.ok("eval", {"curve": bezier(CUBIC), "t": ts})
        for t, p in zip(ts, r["points"]):
            s = 1 - t
            want = [s ** 3 * CUBIC[0][k] + 3 * s * s * t * CUBIC[1][k] + 3 * s * t * t * CUBIC[2][k] + t ** 3 * CUBIC[3][k]
                    for k in range(2)]
            self.assert_close(p, want, TIGHT)
        self.assertEqual(r["points"][0], CUBIC[0])  # end points are interpolated exactly
        self.assertEqual(r["points"][-1], CUBIC[-1])

    def test_quadratic_derivatives(self):
        P = [[0, 0], [2, 4], [6, 2]]
        ts = [0, 0.25, 0.5, 1]
        r = self.ok("eval", {"curve": bezier(P), "t": ts, "derivatives": 3})
        self.assertEqual(len(r["derivatives"]), 3)
        for j, t in enumerate(ts):
            # P' = 2((1-t)(P1-P0) + t(P2-P1)), P'' = 2(P2 - 2P1 + P0), P''' = 0.
            d1 = [2 * ((1 - t) * (P[1][k] - P[0][k]) + t * (P[2][k] - P[1][k])) for k in range(2)]
            d2 = [2 * (P[2][k] - 2 * P[1][k] + P[0][k]) for k in range(2)]
            self.assert_close(r["derivatives"][0][j], d1, TIGHT)
            self.assert_close(r["derivatives"][1][j], d2, TIGHT)
            self.assertEqual(r["derivatives"][2][j], [0, 0])

    def test_derivatives_zero_and_integral_float(self):
        r = self.ok("eval", {"curve": bezier(CUBIC), "t": [0.5], "derivatives": 0})
        self.assertNotIn("derivatives", r)
        r = self.ok("eval", {"curve": bezier(CUBIC), "t": [0], "derivatives": 1.0})
        self.assertEqual(r["derivatives"], [[[3, 9]]])  # 3 (P1 - P0)

    def test_empty_t(self):
        self.assertEqual(self.ok("eval", {"curve": bezier(CUBIC), "t": []}), {"points": []})

    def test_dimensions_1_to_4(self):
        for d in range(1, 5):
            P = [[float(i + k) for k in range(d)] for i in range(3)]
            r = self.ok("eval", {"curve": bezier(P, dim=d, degree=2), "t": [0.5]})
            self.assertEqual(r["points"], [de_casteljau(P, 0.5)])

    def test_extrapolation(self):
        r = self.ok("eval", {"curve": bezier(CUBIC), "t": [-1, 2]})
        for p, t in zip(r["points"], [-1, 2]):
            self.assert_close(p, de_casteljau(CUBIC, t), 1e-13)

    def test_quarter_circle(self):
        ts = [i / 16 for i in range(17)]
        r = self.ok("eval", {"curve": QUARTER_CIRCLE, "t": ts, "derivatives": 1})
        for t, p, d in zip(ts, r["points"], r["derivatives"][0]):
            # On the unit circle; 1e-15: a few ulps of 1.
            self.assertLessEqual(abs(math.hypot(p[0], p[1]) - 1), 1e-15, (t, p))
            self.assert_close(p, rational_point(QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"], t), TIGHT)
            # The tangent is perpendicular to the radius.
            self.assertLessEqual(abs(p[0] * d[0] + p[1] * d[1]), 1e-14 * math.hypot(*d))
        # R'(0) = n w1/w0 (P1 - P0) = 2 (sqrt(2)/2) (0, 1) [Farin02, 13.3].
        self.assert_close(r["derivatives"][0][0], [0, math.sqrt(2)], TIGHT)

    def test_number_formats(self):
        rc, out, _ = run("eval", text='{"curve": {"type": "bezier", "points": [[0.1, 0.3333333333333333]]}, "t": [0]}')
        self.assertEqual(rc, 0)
        self.assertIn("0.1", out)
        self.assertNotIn("0.10000000000000001", out)  # shortest round-trip form
        p = json.loads(out)["points"][0]
        self.assertEqual(p[0], 0.1)
        self.assertEqual(p[1], 1 / 3)  # round-trips exactly
        # Integers, exponents and negative zero are numbers too.
        rc, out, err = run("eval", text='{"curve": {"type": "bezier", "points": [[1, -0.0, 2E2, 5e-1]]}, "t": [1]}')
        self.assertEqual(rc, 0, err)
        self.assertEqual(json.loads(out)["points"], [[1, 0, 200, 0.5]])


class PathTest(CliTest):
    # Segment 0 on [0, 2]: a line; segment 1 on [2, 5]: a quadratic that does not start
    # where segment 0 ends, so that the piece chosen at the break shows.
    SEG0 = [[0, 0], [2, 0]]
    SEG1 = [[10, 10], [11, 13], [13, 10]]
    PATH = {"type": "path", "segments": [bezier(SEG0), bezier(SEG1)], "breaks": [0, 2, 5]}

    def test_eval_at_break_and_outside(self):
        ts = [1, 2, 3.5, -1, 6]
        r = self.ok("eval", {"curve": self.PATH, "t": ts, "derivatives": 1})
        # At the interior break the right segment answers (docs/cli.md: segment i on [ti, ti+1]).
        self.assertEqual(r["points"][1], self.SEG1[0])
        self.assert_close(r["points"][0], de_casteljau(self.SEG0, 0.5), TIGHT)
        self.assert_close(r["points"][2], de_casteljau(self.SEG1, 0.5), TIGHT)
        # Outside the domain the first / last piece is extrapolated.
        self.assert_close(r["points"][3], de_casteljau(self.SEG0, -0.5), TIGHT)
        self.assert_close(r["points"][4], de_casteljau(self.SEG1, 4 / 3), TIGHT)
        # Chain rule: d/du = (d/dt) / h, h = 3 for segment 1: 2 (P1 - P0) / 3 at the break.
        self.assert_close(r["derivatives"][0][1], [2 * (11 - 10) / 3, 2 * (13 - 10) / 3], TIGHT)
        self.assert_close(r["derivatives"][0][0], [2 / 2, 0], TIGHT)

    def test_default_breaks_and_rational_segment(self):
        path = {"type": "path", "segments": [bezier(self.SEG0), QUARTER_CIRCLE], "dim": 2}
        r = self.ok("eval", {"curve": path, "t": [0.5, 1.5]})
        self.assert_close(r["points"][0], [1, 0], TIGHT)
        self.assert_close(r["points"][1], rational_point(QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"], 0.5), TIGHT)


class SplitElevateTest(CliTest):
    def test_split_cubic_half(self):
        r = self.ok("split", {"curve": bezier(CUBIC), "t": 0.5})
        P = CUBIC
        # Subdivision matrix at 1/2 [Farin02, 4.6]: rows (1), (1,1)/2, (1,2,1)/4, (1,3,3,1)/8.
        rows = [[1, 0, 0, 0], [1, 1, 0, 0], [1, 2, 1, 0], [1, 3, 3, 1]]
        left = [[sum(c * P[j][k] for j, c in enumerate(row)) / sum(row) for k in range(2)] for row in rows]
        right = [[sum(c * P[3 - j][k] for j, c in enumerate(row)) / sum(row) for k in range(2)] for row in rows][::-1]
        self.assertEqual(r["curves"], [bezier(left), bezier(right)])  # exact: dyadic arithmetic

    def test_split_rational_stays_on_circle(self):
        r = self.ok("split", {"curve": QUARTER_CIRCLE, "t": 0.25})
        left, right = r["curves"]
        self.assertEqual(left["type"], "rational_bezier")
        self.assert_close(left["points"][-1], rational_point(QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"], 0.25), TIGHT)
        for half in (left, right):
            for t in (0.3, 0.7):
                p = rational_point(half["points"], half["weights"], t)
                self.assertLessEqual(abs(math.hypot(*p) - 1), 1e-15)

    def test_split_ends(self):
        r = self.ok("split", {"curve": bezier([[1], [2]]), "t": 0})
        self.assertEqual(r["curves"][0]["points"], [[1], [1]])
        self.assertEqual(r["curves"][1]["points"], [[1], [2]])

    def test_elevate_quadratic_forrest(self):
        P = [[0, 0], [3, 6], [9, 3]]
        r = self.ok("elevate", {"curve": bezier(P), "times": 1})
        # Forrest: Q_i = i/(n+1) P_{i-1} + (1 - i/(n+1)) P_i, n = 2.
        Q = [P[0], [(P[0][k] + 2 * P[1][k]) / 3 for k in range(2)], [(2 * P[1][k] + P[2][k]) / 3 for k in range(2)], P[2]]
        self.assertEqual(r["curve"]["type"], "bezier")
        self.assert_close(r["curve"]["points"], Q, TIGHT)

    def test_elevate_twice_and_rational(self):
        r = self.ok("elevate", {"curve": bezier([[0], [4]]), "times": 3})
        self.assert_close(r["curve"]["points"], [[0], [1], [2], [3], [4]], TIGHT)  # a line stays uniform
        r = self.ok("elevate", {"curve": QUARTER_CIRCLE, "times": 2})
        c = r["curve"]
        self.assertEqual((c["type"], len(c["points"]), len(c["weights"])), ("rational_bezier", 5, 5))
        for t in (0, 0.2, 0.5, 0.8, 1):
            self.assert_close(rational_point(c["points"], c["weights"], t),
                              rational_point(QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"], t), TIGHT)


class BoundsTest(CliTest):
    def test_cubic_interior_extremum(self):
        P = [[0, 0], [1, 4], [2, -2], [5, 1]]
        r = self.ok("bounds", {"curve": bezier(P)})
        # y'(t)/3 = a (1-t)^2 + 2 b t(1-t) + c t^2 with a, b, c the y differences: solve
        # (a - 2b + c) t^2 + 2 (b - a) t + a = 0 in (0, 1).
        a, b, c = (P[i + 1][1] - P[i][1] for i in range(3))
        A, B, C = a - 2 * b + c, 2 * (b - a), a
        disc = math.sqrt(B * B - 4 * A * C)
        roots = [t for t in ((-B - disc) / (2 * A), (-B + disc) / (2 * A)) if 0 < t < 1]
        self.assertEqual(len(roots), 2)
        ys = [P[0][1], P[3][1]] + [de_casteljau(P, t)[1] for t in roots]
        # x has differences 1, 1, 3 > 0: monotonic, so its extremes are the end points.
        self.assert_close(r["min"], [0, min(ys)], 1e-13)
        self.assert_close(r["max"], [5, max(ys)], 1e-13)
        self.assertLess(r["max"][1], 4)  # tight, not the control box

    def test_quarter_circle(self):
        r = self.ok("bounds", {"curve": QUARTER_CIRCLE})
        self.assert_close(r["min"], [0, 0], 1e-15)
        self.assert_close(r["max"], [1, 1], 1e-15)

    def test_path_union(self):
        path = {"type": "path", "segments": [bezier([[0, 0], [1, 1]]), bezier([[1, 1], [2, 3], [3, 1]])]}
        r = self.ok("bounds", {"curve": path})
        self.assert_close(r["min"], [0, 0], TIGHT)
        self.assert_close(r["max"], [3, 2], TIGHT)  # y of the quadratic at t = 1/2: (1 + 2*3 + 1)/4


class ToBezierTest(CliTest):
    def test_shapes(self):
        r = self.ok("to_bezier", {"curve": bezier(CUBIC)})
        self.assertEqual(r, {"curve": {"type": "path", "segments": [bezier(CUBIC)], "breaks": [0, 1]}})
        r = self.ok("to_bezier", {"curve": QUARTER_CIRCLE})
        self.assertEqual(r["curve"]["segments"], [QUARTER_CIRCLE])
        self.assertEqual(r["curve"]["breaks"], [0, 1])
        path = {"type": "path", "segments": [bezier([[0], [1]]), bezier([[1], [5], [2]])], "breaks": [-1, 0.5, 4]}
        self.assertEqual(self.ok("to_bezier", {"curve": path})["curve"], path)
        path.pop("breaks")
        self.assertEqual(self.ok("to_bezier", {"curve": path})["curve"]["breaks"], [0, 1, 2])


class FlattenTest(CliTest):
    def check_polyline(self, point_at, poly, tol, start, end):
        """The polyline runs from start to end, and 1000 samples of the curve lie within tol
        of it (sampling bounds the distance from below; 1e-12 allows for rounding). Returns
        the samples."""
        self.assert_close(poly[0], start, TIGHT)
        self.assert_close(poly[-1], end, TIGHT)
        samples = [point_at(i / 1000) for i in range(1001)]
        self.assertLessEqual(max(dist_to_polyline(p, poly) for p in samples), tol + 1e-12)
        return samples

    def test_cubic(self):
        for tol in (0.1, 0.01, 0.001):
            poly = self.ok("flatten", {"curve": bezier(CUBIC), "tolerance": tol})["points"]
            samples = self.check_polyline(lambda t: de_casteljau(CUBIC, t), poly, tol, CUBIC[0], CUBIC[-1])
            # Every vertex lies on the curve: within the sample spacing (|P'| <= 9, so
            # consecutive samples are at most 0.009 apart) of a sample.
            for v in poly:
                self.assertLessEqual(min(dist(v, p) for p in samples), 0.0045 + 1e-12)

    def test_quarter_circle_and_path(self):
        P, w = QUARTER_CIRCLE["points"], QUARTER_CIRCLE["weights"]
        poly = self.ok("flatten", {"curve": QUARTER_CIRCLE, "tolerance": 1e-3})["points"]
        self.check_polyline(lambda t: rational_point(P, w, t), poly, 1e-3, [1, 0], [0, 1])
        path = {"type": "path", "segments": [bezier([[0, 0], [1, 0]]), bezier([[1, 0], [2, 1], [3, 0]])]}
        poly = self.ok("flatten", {"curve": path, "tolerance": 0.01})["points"]
        self.assertEqual(poly[:2], [[0, 0], [1, 0]])  # the joint vertex is written once
        self.check_polyline(lambda t: de_casteljau([[1, 0], [2, 1], [3, 0]], t), poly, 0.01, [0, 0], [3, 0])


class RenderTest(CliTest):
    def test_svg_document(self):
        for req in ({"curve": bezier(CUBIC)},
                    {"curves": [bezier(CUBIC), QUARTER_CIRCLE], "width": 200, "height": 100, "padding": 0,
                     "background": "none", "stroke": "#ff0000", "stroke_width": 1.5, "control_polygon": False,
                     "axes": True, "tolerance": 0},
                    {"curve": bezier([[0], [1], [0.5]])}):
            rc, out, err = run("render", req)
            self.assertEqual((rc, err), (0, ""))
            self.assertTrue(out.startswith("<svg") or out.startswith("<?xml"), out[:80])

    def test_jsonl_render_answers_svg_objects(self):
        rc, out, err = run("render", args=["--jsonl"], text=json.dumps({"curve": bezier(CUBIC)}) + "\n")
        self.assertEqual((rc, err), (0, ""))
        svg = json.loads(out)["svg"]
        self.assertTrue(svg.startswith("<svg") or svg.startswith("<?xml"))


class JsonlTest(CliTest):
    def test_good_and_bad_lines(self):
        lines = [
            json.dumps({"curve": bezier(CUBIC), "t": [0.5]}),
            '{"curve": ',
            json.dumps({"curve": bezier(CUBIC), "t": [1], "weight": 1}),
            "",
            json.dumps({"curve": bezier([[2]]), "t": [0]}) + "\r",
        ]
        rc, out, err = run("eval", args=["--jsonl"], text="\n".join(lines) + "\n")
        self.assertEqual(rc, 2)
        responses = [json.loads(l) for l in out.splitlines()]
        self.assertEqual(len(responses), len(lines))
        self.assertEqual(responses[0], {"points": [[2, 2.25]]})  # (0+3+9+4)/8, (0+9+9+0)/8
        self.assertTrue(responses[1]["error"].startswith("request: malformed JSON"))
        self.assertTrue(responses[2]["error"].startswith("weight: unknown field"))
        self.assertTrue(responses[3]["error"].startswith("request: "))
        self.assertEqual(responses[4], {"points": [[2]]})
        self.assertEqual(err.count("\n"), 1)
        self.assertTrue(err.startswith("error: lines 2, 3, 4: 3 of 5"), err)

    def test_all_good_and_option_positions(self):
        text = "".join(json.dumps({"curve": bezier([[i]]), "t": [0]}) + "\n" for i in range(3))
        for args, cmd in ((["--jsonl"], "eval"), (["--jsonl", "-"], "eval")):
            rc, out, err = run(cmd, args=args, text=text)
            self.assertEqual((rc, err), (0, ""))
            self.assertEqual([json.loads(l)["points"] for l in out.splitlines()], [[[0]], [[1]], [[2]]])
        p = subprocess.run([BINARY, "--jsonl", "eval"], input=text.encode(), capture_output=True, timeout=30)
        self.assertEqual(p.returncode, 0)
        self.assertEqual(len(p.stdout.splitlines()), 3)
        # No trailing newline on the last line; empty input answers nothing.
        rc, out, err = run("eval", args=["--jsonl"], text=text.rstrip("\n"))
        self.assertEqual((rc, len(out.splitlines())), (0, 3))
        self.assertEqual(run("eval", args=["--jsonl"], text=""), (0, "", ""))


class IoTest(CliTest):
    def test_file_argument(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "req.json")
            with open(path, "w") as f:
                json.dump({"curve": bezier([[1, 2]]), "t": [0.5]}, f)
            self.assertEqual(self.ok("eval", None, args=[path]), {"points": [[1, 2]]})
            missing = os.path.join(d, "nope.json")
            self.bad("eval", where=missing, args=[missing], text="", contains="No such file")

    def test_stdin_dash(self):
        self.assertEqual(self.ok("eval", {"curve": bezier([[3]]), "t": [0]}, args=["-"]), {"points": [[3]]})

    def test_help_and_version(self):
        rc, out, err = run(None, args=["--help"])
        self.assertEqual((rc, err), (0, ""))
        for c in CONTRACT_COMMANDS:
            self.assertRegex(out, rf"\n  {c} +\S")  # listed with a description
        rc, out, _ = run(None, args=["--version"])
        self.assertEqual(rc, 0)
        self.assertRegex(out, r"^casteljau \d+\.\d+\.\d+\n$")

    def test_help_examples_match_program_output_self_consistency(self):
        # A consistency check, not a reference check: the expected response is the one the
        # help text prints, which was itself written from the program's output. It catches
        # help texts that went stale; the values are checked against closed forms and
        # oracles in the other tests.
        for c in supported_commands():
            rc, out, err = run(c, args=["--help"])
            self.assertEqual((rc, err), (0, ""))
            self.assertIn("Request:", out)
            self.assertIn("Example:", out)
            lines = out.splitlines()
            i = next(i for i, l in enumerate(lines) if l.strip().startswith("echo '"))
            request = lines[i].strip()[len("echo '"):lines[i].strip().index("' |")]
            if c != "render":
                got = json.loads(run(c, text=request)[1])
                self.assertEqual(got, json.loads(lines[i + 1]), c)

    def test_usage_errors(self):
        self.bad(None, where="command", text="")
        self.bad("frobnicate", where="command", text="{}", contains="unknown command")
        for c in set(CONTRACT_COMMANDS) - set(supported_commands()):
            self.bad(c, where="command", text="{}", contains="not supported yet")
        self.bad("eval", where="arguments", args=["--bogus"], text="{}")
        self.bad("eval", where="arguments", args=["a", "b"], text="{}")


class BadInputTest(CliTest):
    def eval_bad(self, curve, where, t=(0.5,), contains=None, **extra):
        req = dict({"curve": curve, "t": list(t)}, **extra)
        return self.bad("eval", req, where, contains=contains)

    def test_request_level(self):
        self.bad("eval", where="request", text='{"curve": {', contains="malformed JSON")
        self.bad("eval", where="request", text="", contains="malformed JSON")
        self.bad("eval", where="request", text='{"t": [NaN]}', contains="malformed JSON")
        self.bad("eval", where="request", text='{"t": [1]} {"t": [2]}', contains="malformed JSON")
        self.bad("eval", where="request", text="[1, 2]", contains="object")
        self.bad("eval", where="request", text='"eval"', contains="object")
        self.bad("eval", where="request", text=b'{"t": "\xff"}', contains="malformed JSON")
        self.bad("eval", {"t": [0]}, "curve", contains="missing")
        self.bad("eval", {"curve": bezier(CUBIC), "t": [0], "tt": 1}, "tt", contains="unknown field")
        self.bad("eval", where="t", text='{"curve": {"type": "bezier", "points": [[0]]}, "t": [0], "t": [1]}',
                 contains="duplicate")
        self.bad("eval", where="curve.points[1].a",
                 text='{"curve": {"type": "bezier", "points": [[0], {"a": 1, "a": 2}]}, "t": [0]}', contains="duplicate")
        # Deep nesting is refused without exhausting the stack (the parser keeps no recursion).
        self.bad("eval", where="curve", text='{"curve": ' + "[" * 100000 + "]" * 100000 + ', "t": [0]}')
        self.bad("eval", where="deep", text='{"curve": {"type": "bezier", "points": [[0]]}, "t": [0], "deep": '
                 + '{"a": ' * 100000 + "1" + "}" * 100000 + "}", contains="unknown field")
        # A field name with a newline stays on one stderr line.
        self.bad("eval", {"curve": bezier(CUBIC), "t": [0], "a\nb": 1}, "a\\nb")

    def test_curve_type(self):
        self.eval_bad({"points": CUBIC}, "curve.type", contains="missing")
        self.eval_bad(bezier(CUBIC, type=3), "curve.type", contains="string")
        self.eval_bad(bezier(CUBIC, type="bezzier"), "curve.type", contains="unknown curve type")
        # The contract's types not served yet say so; the served ones (tested in their own
        # files) read a bezier's fields as theirs or reject them, never as "unknown".
        for ty in ("lagrange", "cubic_spline", "hermite", "catmull_rom"):
            rc, out, err = run("eval", {"curve": bezier(CUBIC, type=ty), "t": [0.5]})
            self.assertIn(rc, (0, 2), err)
            self.assertNotIn("unknown curve type", err)
            if "not supported yet" in err:
                self.assertTrue(err.startswith("error: curve.type: "), err)
                self.assertIn(f"'{ty}'", err)
        self.eval_bad([1, 2], "curve", contains="object")

    def test_fields(self):
        self.eval_bad({"type": "bezier"}, "curve.points", contains="missing")
        self.eval_bad({"type": "rational_bezier", "points": CUBIC}, "curve.weights", contains="missing")
        self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weight": [1, 1, 1, 1]}, "curve.weight",
                      contains="unknown field")
        self.eval_bad(bezier(CUBIC, weights=[1, 1, 1, 1]), "curve.weights", contains="unknown field")
        self.eval_bad({"type": "path"}, "curve.segments", contains="missing")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC)], "degree": 3}, "curve.degree", contains="unknown field")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC, knots=[1])]}, "curve.segments[0].knots",
                      contains="unknown field")

    def test_json_types(self):
        self.eval_bad(bezier("abc"), "curve.points", contains="array")
        self.eval_bad(bezier([[0, 0], 5]), "curve.points[1]", contains="array")
        self.eval_bad(bezier([[0, 0], [1, "2"]]), "curve.points[1][1]", contains="number")
        self.eval_bad(bezier([[0, 0], [1, True]]), "curve.points[1][1]", contains="boolean")
        self.eval_bad(bezier([[0, 0], [1, None]]), "curve.points[1][1]", contains="null")
        self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weights": "1"}, "curve.weights", contains="array")
        self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weights": [1, 1, False, 1]}, "curve.weights[2]")
        self.eval_bad({"type": "path", "segments": {}}, "curve.segments", contains="array")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC)], "breaks": 1}, "curve.breaks", contains="array")
        self.eval_bad({"type": "path", "segments": [7]}, "curve.segments[0]", contains="object")
        self.eval_bad(bezier(CUBIC, dim="2"), "curve.dim", contains="integer")
        self.eval_bad(bezier(CUBIC, degree=3.5), "curve.degree", contains="integer")

    def test_counts_and_dimensions(self):
        self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weights": [1, 1]}, "curve.weights", contains="4 points")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC)], "breaks": [0, 1, 2]}, "curve.breaks")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC), bezier(CUBIC)], "breaks": [0, 2, 1]}, "curve.breaks[2]")
        self.eval_bad(bezier([[0, 0], [1, 1], [2, 2, 2]]), "curve.points[2]", contains="3 coordinates")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC), bezier([[1, 2, 3]])]}, "curve.segments[1]",
                      contains="dimension")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC), bezier([[1, 2], [1, 2, 3]])]},
                      "curve.segments[1].points[1]")
        self.eval_bad(bezier(CUBIC, dim=3), "curve.dim", contains="3")
        self.eval_bad({"type": "path", "segments": [bezier(CUBIC)], "dim": 1}, "curve.dim")
        self.eval_bad(bezier(CUBIC, degree=2), "curve.degree", contains="degree 3")
        self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weights": [1] * 4, "degree": 4}, "curve.degree")
        self.eval_bad(bezier([[1, 2, 3, 4, 5]]), "curve.points[0]", contains="1..4")
        self.eval_bad(bezier([[1, 2, 3, 4, 5]], dim=5), "curve.dim", contains="1..4")
        self.eval_bad(bezier([]), "curve.points", contains="at least one")
        self.eval_bad(bezier([[]]), "curve.points[0]", contains="at least one coordinate")
        self.eval_bad({"type": "path", "segments": []}, "curve.segments", contains="at least one")
        # A path segment may be any curve object, a path included (spliced in).
        r = self.ok("eval", {"curve": {"type": "path", "segments": [{"type": "path", "segments": [bezier(CUBIC)]}]},
                             "t": [0.5]})
        self.assertEqual(r["points"], [de_casteljau(CUBIC, 0.5)])

    def test_numbers(self):
        text = '{"curve": {"type": "bezier", "points": [[0, 0], [1, 1], [2, 1e999]]}, "t": [0]}'
        self.bad("eval", where="curve.points[2][1]", text=text, contains="1e999")
        text = '{"curve": {"type": "bezier", "points": [[0, 0]]}, "t": [0, -1e999]}'
        self.bad("eval", where="t[1]", text=text)
        text = '{"curve": {"type": "path", "segments": [{"type": "bezier", "points": [[0]]}], "breaks": [0, 1E400]}, "t": [0]}'
        self.bad("eval", where="curve.breaks[1]", text=text)
        for w in (0, -1):
            self.eval_bad({"type": "rational_bezier", "points": CUBIC, "weights": [1, w, 1, 1]}, "curve.weights[1]",
                          contains="> 0")

    def test_eval_fields(self):
        self.bad("eval", {"curve": bezier(CUBIC)}, "t", contains="missing")
        self.bad("eval", {"curve": bezier(CUBIC), "t": 0.5}, "t", contains="array")
        self.bad("eval", {"curve": bezier(CUBIC), "t": [0, 1, 0.5, "x"]}, "t[3]", contains="number")
        for k in (-1, 1.5, True, "2", 10 ** 30):
            self.bad("eval", {"curve": bezier(CUBIC), "t": [0], "derivatives": k}, "derivatives")
        # A result that overflows is refused, not written as null.
        self.bad("eval", {"curve": bezier(CUBIC), "t": [0, 1e200]}, "t[1]", contains="not representable")

    def test_split(self):
        self.bad("split", {"curve": bezier(CUBIC)}, "t", contains="missing")
        self.bad("split", {"curve": bezier(CUBIC), "t": [0.5]}, "t", contains="number")
        for t in (-0.1, 1.5):
            self.bad("split", {"curve": bezier(CUBIC), "t": t}, "t", contains="[0, 1]")
        self.bad("split", {"curve": QUARTER_CIRCLE, "t": 2}, "t")
        self.bad("split", {"curve": {"type": "path", "segments": [bezier(CUBIC)]}, "t": 0.5}, "curve.type")
        self.bad("split", {"curve": bezier(CUBIC), "t": 0.5, "times": 1}, "times", contains="unknown field")

    def test_elevate(self):
        self.bad("elevate", {"curve": bezier(CUBIC)}, "times", contains="missing")
        for r in (0, -2, 1.5, "1", None):
            self.bad("elevate", {"curve": bezier(CUBIC), "times": r}, "times")
        self.bad("elevate", {"curve": bezier(CUBIC), "times": 100000}, "times")
        self.bad("elevate", {"curve": {"type": "path", "segments": [bezier(CUBIC)]}, "times": 1}, "curve.type",
                 contains="path")

    def test_flatten(self):
        self.bad("flatten", {"curve": bezier(CUBIC)}, "tolerance", contains="missing")
        for tol in (0, -1, "0.1", [0.1]):
            self.bad("flatten", {"curve": bezier(CUBIC), "tolerance": tol}, "tolerance")
        self.bad("flatten", {"curve": bezier(CUBIC), "tolerance": 1e-300}, "tolerance")

    def test_bounds_and_to_bezier(self):
        self.bad("bounds", {"curve": bezier(CUBIC), "t": [0]}, "t", contains="unknown field")
        self.bad("bounds", {}, "curve", contains="missing")
        self.bad("to_bezier", {"curve": bezier([[0], ["x"]])}, "curve.points[1][0]")

    def test_render(self):
        c = bezier(CUBIC)
        for field, value in (("width", 0), ("height", -1), ("stroke_width", 0), ("padding", -1), ("tolerance", -1),
                             ("width", "640"), ("control_polygon", "yes"), ("axes", 1), ("background", 3),
                             ("stroke", 'red" onload="x'), ("stroke", "")):
            self.bad("render", {"curve": c, field: value}, field)
        self.bad("render", {"curve": c, "colour": "red"}, "colour", contains="unknown field")
        self.bad("render", {"curve": c, "curves": [c]}, "curves")
        self.bad("render", {"curves": []}, "curves")
        self.bad("render", {}, "curve", contains="missing")
        self.bad("render", {"curves": [c, bezier([[0, 1], "x"])]}, "curves[1].points[1]")
        self.bad("render", {"curve": {"type": "hermit"}}, "curve.type", contains="unknown curve type")
        # The renderer draws 1D and 2D curves; the refused curve is named as in the request.
        c3 = bezier([[0, 0, 0], [1, 1, 1]])
        self.bad("render", {"curve": c3}, "curve")
        self.bad("render", {"curves": [c3]}, "curves[0]")
        self.bad("render", {"curves": [c, c3]}, "curves[1]")


if __name__ == "__main__":
    BINARY = os.path.abspath(sys.argv.pop(1))
    USE_SESSIONS = False  # the contract of one request: a process each
    unittest.main(verbosity=1)
