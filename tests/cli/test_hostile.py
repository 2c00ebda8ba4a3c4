#!/usr/bin/python3
"""Hostile input to the `casteljau` command line program (issue 5, section 5): NUL bytes,
empty arguments, huge strings and numbers, deep nesting, extreme curves and styling.
Every answer is either a correct response or a clean error (exit status 2, nothing on
stdout, one short stderr line `error: <where>: <what>`); never a wrong or runaway answer,
NaN / null in the output, a crash or a hang.

Usage: test_hostile.py PATH_TO_CASTELJAU [unittest options]. Standard library only.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli  # noqa: E402  (the shared runner and assertions)
from test_cli import CliTest, bezier, run  # noqa: E402

CUBIC = [[0, 0], [1, 3], [3, 3], [4, 0]]
GOOD = json.dumps({"curve": bezier([[1, 2]]), "t": [0]})

# The longest error line any of these inputs may give (bytes): the messages quote at most
# 64 characters of user text, and paths are cut to about 256 bytes; 1000 leaves room for
# the message around them while being far below the megabytes echoed before.
MAX_ERROR_LINE = 1000


def svg_path_points(svg):
    """The coordinates of every path command of the first <path> of an SVG, in order."""
    d = re.search(r'<path d="([^"]*)"', svg).group(1)
    nums = [float(x) for x in re.findall(r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?", d)]
    return list(zip(nums[0::2], nums[1::2]))


def chebyshev_bezier(n):
    """Control points (i/n, b_i) of the graph of T_n(2t - 1) on [0, 1], exact: the
    Bernstein coefficients b_i of a polynomial bounded by 1 on [0, 1] grow like 2^n /
    poly(n) (8e11 at n = 40), so the control points lie far outside the curve."""
    T = [[Fraction(1)], [Fraction(0), Fraction(1)]]
    for _ in range(2, n + 1):
        a = [Fraction(0)] + [2 * c for c in T[-1]]
        b = T[-2] + [Fraction(0)] * (len(a) - len(T[-2]))
        T.append([x - y for x, y in zip(a, b)])
    power = [Fraction(0)] * (n + 1)  # sum c_k (2t - 1)^k in powers of t
    for k, ck in enumerate(T[n]):
        for j in range(k + 1):
            power[j] += ck * math.comb(k, j) * 2 ** j * (-1) ** (k - j)
    # Power to Bernstein: b_i = sum_{j <= i} C(i, j) / C(n, j) a_j [Farin02, 5.3].
    bern = [sum(Fraction(math.comb(i, j), math.comb(n, j)) * power[j] for j in range(i + 1)) for i in range(n + 1)]
    return [[i / n, float(b)] for i, b in enumerate(bern)]


class HostileTest(CliTest):
    def bad(self, *args, **kwargs):
        err = super().bad(*args, **kwargs)
        self.assertLess(len(err.encode()), MAX_ERROR_LINE, err[:300])
        return err

    def bad_any(self, command, request=None, text=None, args=()):
        """The error contract, whatever the place: status 2, nothing on stdout, one short
        line `error: <where>: <what>`. Returns the line."""
        rc, out, err = run(command, request, args, text)
        self.assertEqual((rc, out), (2, ""), err[:300])
        self.assertEqual(err.count("\n"), 1, err[:300])
        self.assertTrue(err.endswith("\n") and re.match(r"error: [^ ]+: \S", err), err[:300])
        self.assertLess(len(err.encode()), MAX_ERROR_LINE, err[:300])
        return err


class NulBytesTest(HostileTest):
    """Defect 1: nlohmann's lexer takes a NUL for the end of the input."""

    def test_bytes_after_a_nul_are_an_error(self):
        err = self.bad("eval", where="request", text=GOOD.encode() + b"\0garbage", contains="NUL")
        self.assertIn(f"column {len(GOOD) + 1}", err)  # the position of the NUL
        self.bad("eval", where="request", text=GOOD.encode() + b"\0", contains="NUL")
        self.bad("eval", where="request", text=GOOD.encode() + b"\n \0", contains="line 2, column 2")
        self.bad("eval", where="request", text=b"\0" + GOOD.encode(), contains="column 1")
        # Inside a string a NUL must be escaped; the escaped form is an ordinary character.
        self.bad("eval", where="request", text=b'{"curve": "a\0b"}', contains="NUL")
        self.bad("eval", where="curve", text=b'{"curve": "a\\u0000b", "t": [0]}', contains="object")

    def test_an_error_before_the_nul_is_reported_as_such(self):
        self.bad("eval", where="request", text=b'{x \0', contains="column 2")
        self.bad("eval", where="t[0]", text=b'{"t": [1e999]}\0', contains="overflows")

    def test_whitespace_after_the_value_is_fine(self):
        rc, out, err = run("eval", text=GOOD + " \n\t\r\n ")
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual(json.loads(out), {"points": [[1, 2]]})

    def test_jsonl_lines_with_a_nul_are_error_lines(self):
        text = GOOD.encode() + b"\n" + GOOD.encode() + b"\0garbage\n" + GOOD.encode() + b" \0\n" + GOOD.encode() + b"\n"
        rc, out, err = run("eval", args=["--jsonl"], text=text)
        self.assertEqual(rc, 2)
        lines = [json.loads(l) for l in out.splitlines()]
        self.assertEqual(len(lines), 4)
        self.assertEqual(lines[0], {"points": [[1, 2]]})
        self.assertEqual(lines[3], {"points": [[1, 2]]})
        for line in lines[1:3]:
            self.assertTrue(line["error"].startswith("request: malformed JSON"), line)
            self.assertIn("NUL", line["error"])
        self.assertTrue(err.startswith("error: lines 2, 3: 2 of 4"), err)


class FileArgumentTest(HostileTest):
    """Defect 2: an empty FILE read stdin."""

    def test_empty_file_name_is_an_error(self):
        err = self.bad("eval", where="arguments", args=[""], text=GOOD)
        self.assertIn("FILE", err)
        self.bad("eval", where="arguments", args=["--jsonl", ""], text=GOOD + "\n")
        self.bad("render", where="arguments", args=["", "--jsonl"], text=GOOD + "\n")

    def test_dash_and_no_argument_read_stdin(self):
        for args in ([], ["-"], ["--jsonl"], ["-", "--jsonl"]):
            rc, out, err = run("eval", args=args, text=GOOD + "\n")
            self.assertEqual((rc, err), (0, ""), args)
            self.assertEqual(json.loads(out), {"points": [[1, 2]]})

    def test_long_file_name_is_cut_in_the_message(self):
        with tempfile.TemporaryDirectory() as d:
            name = os.path.join(d, *["x" * 200] * 200)  # 40 kB, beyond PATH_MAX
            rc, out, err = run("eval", args=[name], text="")
            self.assertEqual((rc, out), (2, ""))
            self.assertEqual(err.count("\n"), 1)
            self.assertLess(len(err), MAX_ERROR_LINE)
            self.assertTrue(err.startswith("error: " + d), err[:100])


class LongEchoTest(HostileTest):
    """Defect 3: messages echoed unbounded input (a 1 MB key gave a 2 MB line)."""

    MB = 1 << 20

    def test_long_key(self):
        key = "a" * self.MB
        err = self.bad("eval", {"curve": bezier(CUBIC), "t": [0], key: 1}, where="a" * 64 + "\u2026",
                       contains=f"unknown field '{'a' * 64}\u2026' ({self.MB} bytes)")
        self.assertNotIn("a" * 65, err)

    def test_long_key_in_jsonl(self):
        rc, out, err = run("eval", args=["--jsonl"], text=json.dumps({"curve": bezier(CUBIC), "b" * self.MB: 1}) + "\n")
        self.assertEqual(rc, 2)
        self.assertLess(len(out), MAX_ERROR_LINE)
        self.assertIn(f"({self.MB} bytes)", json.loads(out)["error"])

    def test_long_type_name_and_segment_type(self):
        self.bad("eval", {"curve": bezier(CUBIC, type="q" * self.MB), "t": [0]}, where="curve.type",
                 contains=f"({self.MB} bytes)")
        self.bad("eval", {"curve": {"type": "path", "segments": [bezier(CUBIC, type="\u00e9" * self.MB)]}, "t": [0]},
                 where="curve.segments[0].type", contains=f"'{chr(0xe9) * 64}\u2026' ({2 * self.MB} bytes)")

    def test_long_duplicate_key_and_deep_paths(self):
        k = "k" * self.MB
        self.bad("eval", where="k" * 64 + "\u2026", text='{"%s": 1, "%s": 2}' % (k, k), contains="duplicate")
        # 100000 levels: the path keeps its start and its end.
        deep = '{"a": ' * 100000 + '{"b": 1, "b": 2}' + "}" * 100000
        err = self.bad_any("eval", text=deep)
        self.assertTrue(err.startswith("error: a.a.a."), err)
        self.assertIn("\u2026", err)
        self.assertIn(".a.b: duplicate field 'b'", err)
        err = self.bad_any("eval", text="[" * 100000 + "1e999" + "]" * 100000)
        self.assertTrue(err.startswith("error: [0][0][0]"), err)
        self.assertIn("[0]: number overflows a double: '1e999'", err)

    def test_long_tokens_of_malformed_json(self):
        digits = "1" * self.MB
        self.bad("eval", where="t[0]", text='{"t": [%se999]}' % digits, contains=f"'{'1' * 64}\u2026' ({self.MB + 4} bytes)")
        # An unescaped control character at the end of a long string: the end is kept.
        err = self.bad("eval", where="request", text='{"t": "%s\x01"}' % ("s" * self.MB), contains="last read: '\u2026")
        self.assertIn("<U+0001>'", err)
        self.bad("eval", where="request", text="[" + "tru" * self.MB, contains="malformed JSON")

    def test_long_command_line_text(self):
        # 100000 bytes: one argument may have at most 128 kB (MAX_ARG_STRLEN).
        self.bad("x" * 100000, where="command", text="", contains="unknown command 'xxx")
        self.bad("eval", where="arguments", args=["a", "y" * 100000], text="")
        self.bad("eval", where="arguments", args=["--" + "z" * 100000], text="")

    def test_long_colour(self):
        for field in ("stroke", "background"):
            self.bad("render", {"curve": bezier(CUBIC), field: "r" * self.MB}, where=field)


class BigIntegerTest(HostileTest):
    """Defect 4: integers beyond 64 bits arrive as the nearest double, whose digits differ."""

    def check(self, field, token, request_text):
        err = self.bad("eval" if field == "derivatives" else "elevate", where=field, text=request_text % token,
                       contains="out of range")
        written = token.lstrip("-")
        # Either the number as written, or none: never another number's digits.
        numbers = re.findall(r"\d{10,}", err.split("got", 1)[1])
        for n in numbers:
            self.assertIn(n, ["2147483647", "2147483648", written.split(".")[0]], err)
        return err

    def test_integers_beyond_int64(self):
        eval_req = '{"curve": {"type": "bezier", "points": [[0]]}, "t": [0], "derivatives": %s}'
        err = self.check("derivatives", "-9223372036854775809", eval_req)
        self.assertNotIn("9223372036854775808", err)
        self.assertIn("below -2147483648", err)
        err = self.check("derivatives", "18446744073709551616", eval_req)
        self.assertNotIn("18446744073709551615", err)
        self.check("derivatives", "123456789012345678901234567890", eval_req)
        self.check("times", "-99999999999999999999", '{"curve": {"type": "bezier", "points": [[0]]}, "times": %s}')
        # Representable values are echoed exactly.
        err = self.check("derivatives", "-9223372036854775808", eval_req)
        self.assertIn("-9223372036854775808", err)
        self.assertIn("18446744073709551615", self.check("derivatives", "18446744073709551615", eval_req))
        self.assertIn("above 2147483647", self.check("derivatives", "4294967296.0", eval_req))

    def test_curve_integer_fields(self):
        for field in ("dim", "degree"):
            err = self.bad("eval", where=f"curve.{field}",
                           text='{"curve": {"type": "bezier", "points": [[0]], "%s": -9223372036854775809}, "t": [0]}' % field)
            self.assertNotIn("9223372036854775808", err)


class RenderExtentTest(HostileTest):
    """Defect 5: extents that overflow, and small curves far from the origin, drew a dot."""

    def render_points(self, request):
        rc, out, err = run("render", request)
        self.assertEqual((rc, err), (0, ""))
        self.assertIsNone(re.search(r"(?i)nan|inf", out))
        return svg_path_points(out)

    def assert_spans(self, pts, width, height, padding=24):
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        # The view is the tight box fitted into the page less padding, keeping the aspect:
        # the curve spans at least half of the smaller side, and stays on the page.
        inner = min(width, height) - 2 * padding
        self.assertGreater(max(xs) - min(xs), inner / 2, pts)
        self.assertGreater(max(ys) - min(ys), inner / 4, pts)
        for x, y in [pts[0], pts[-1]]:
            self.assertTrue(-1e-9 <= x <= width + 1e-9 and -1e-9 <= y <= height + 1e-9, pts)

    def test_extent_beyond_double(self):
        c = bezier([[-1e308, 0], [0, 1e308], [1e308, 0]])
        for extra in ({}, {"control_polygon": False}, {"axes": True}):
            pts = self.render_points(dict({"curve": c}, **extra))
            self.assert_spans(pts, 640, 480)
            self.assertAlmostEqual(pts[0][1], pts[-1][1])  # symmetric: both ends at one height
        # A path whose domain is longer than the largest double is refused: parameters are
        # mapped through break lengths (eval at t = 0 used to answer 0 instead of 0.5).
        path = {"type": "path", "segments": [bezier([[0], [1]])], "breaks": [-1e308, 1e308]}
        self.bad("render", {"curve": path}, "curve.breaks", contains="longer than the largest double")
        self.bad("eval", {"curve": path, "t": [0]}, "curve.breaks", contains="longer than the largest double")
        path["breaks"] = [-0.8e308, 0.8e308]
        r = json.loads(run("eval", {"curve": path, "t": [0]})[1])
        self.assertEqual(r["points"], [[0.5]])
        pts = self.render_points({"curve": path})
        self.assertAlmostEqual(pts[-1][0] - pts[0][0], 592, delta=1e-3)  # 640 - 2 * 24
        c = bezier([[-1.7976931348623157e308, -1.7976931348623157e308], [1.7976931348623157e308, 1.7976931348623157e308]])
        pts = self.render_points({"curve": c, "axes": True, "padding": 200})
        self.assertGreater(pts[-1][0] - pts[0][0], 70)

    def test_small_curve_far_from_the_origin(self):
        # 4 units at 1e13 (ulp 0.002): 2000 ulps across, plenty of resolution.
        e = 1e13
        c = bezier([[e, e], [e + 2, e + 4], [e + 4, e]])
        for extra in ({}, {"control_polygon": False}):
            self.assert_spans(self.render_points(dict({"curve": c}, **extra)), 640, 480)
        # Far along x only: was drawn off the page (x flat, the y extent set the scale).
        self.assert_spans(self.render_points({"curve": bezier([[e, 0], [e + 2, 4], [e + 4, 0]])}), 640, 480)

    def test_graph_far_from_the_origin(self):
        # A 1D curve is drawn as its graph y(t), stretched to the page: y spans 1e13..1e13 + 4.
        pts = self.render_points({"curve": bezier([[1e13], [1e13 + 8], [1e13]])})
        self.assertGreater(max(p[1] for p in pts) - min(p[1] for p in pts), 200)


class RenderStyleTest(HostileTest):
    """Item 6: styling numbers that overflow, or make the document without bound."""

    def test_page_size_limits(self):
        c = bezier(CUBIC)
        for field in ("width", "height"):
            for v in (1e308, 1e20, 1e6 + 1):
                self.bad("render", {"curve": c, field: v}, where=field, contains="<= 1000000")
            self.bad("render", {"curve": c, field: 0.5, "padding": 0}, where=field, contains=">= 1 ")
        rc, out, _ = run("render", {"curve": c, "width": 1, "height": 1, "padding": 0, "axes": True})
        self.assertEqual(rc, 0)

    def test_padding_leaving_no_room(self):
        c = bezier(CUBIC)
        for p in (1e308, 240, 239.75, 1.7976931348623157e308):
            self.bad("render", {"curve": c, "padding": p}, where="padding", contains="no room")
        rc, out, _ = run("render", {"curve": c, "padding": 239.5, "axes": True})  # 1 px left
        self.assertEqual(rc, 0)
        self.assertIsNone(re.search(r"(?i)nan|inf", out))

    def test_huge_stroke_width_and_tolerance(self):
        quintic = bezier([[0, 0], [1, 3], [2, -1], [3, 3], [4, -1], [5, 0]])
        for extra in ({"stroke_width": 1e308}, {"tolerance": 1e308}, {"tolerance": 5e-324}, {"width": 1e6, "height": 3, "padding": 0}):
            rc, out, err = run("render", dict({"curve": quintic, "axes": True}, **extra))
            self.assertEqual((rc, err), (0, ""), extra)
            self.assertIsNone(re.search(r"(?i)nan|inf", out), extra)
            self.assertLess(len(out), 10 ** 7, extra)

    def test_curve_that_cannot_be_drawn_is_named(self):
        # Control points up to 8e11 times the curve's size: within 0.25 px of the page is
        # below their resolution once mapped. A bad request about that curve, not a bug.
        cheb = bezier(chebyshev_bezier(40))
        self.bad("render", {"curve": cheb, "control_polygon": False}, where="curve", contains="cannot be drawn")
        self.bad("render", {"curves": [bezier(CUBIC), cheb], "control_polygon": False}, where="curves[1]",
                 contains="cannot be drawn")
        rc, out, err = run("render", {"curve": bezier(chebyshev_bezier(12)), "control_polygon": False})
        self.assertEqual((rc, err), (0, ""))


class ExtremeCurvesTest(HostileTest):
    """Item 6: every command on curves at the limits of double answers finite numbers or
    refuses cleanly (the contract of bad())."""

    def test_commands_on_extreme_curves(self):
        big = 1.7976931348623157e308
        curves = [
            bezier([[big, -big], [-big, big], [big, big], [-big, -big]]),
            bezier([[1e308], [-1e308], [1e308]]),
            {"type": "rational_bezier", "points": [[1e308, 0], [0, 1e308], [-1e308, 0]], "weights": [1e-300, 1e300, 1e-300]},
            {"type": "path", "segments": [bezier([[0, 0], [1, 1]])] * 3, "breaks": [0, 5e-324, 1e-323, 1.5e-323]},
            {"type": "path", "segments": [bezier([[1e308], [-1e308]])], "breaks": [-1e308, 1e308]},
        ]
        requests = []
        for c in curves:
            requests += [("eval", {"curve": c, "t": [0, 0.5, 1, -1e308, 1e308, 5e-324], "derivatives": 3}),
                         ("bounds", {"curve": c}), ("to_bezier", {"curve": c}), ("flatten", {"curve": c, "tolerance": 1e300}),
                         ("split", {"curve": c, "t": 0.5}), ("elevate", {"curve": c, "times": 3}),
                         ("render", {"curve": c, "axes": True}), ("render", {"curve": c, "control_polygon": False, "axes": True})]
        for command, req in requests:
            with self.subTest(command=command, curve=json.dumps(req["curve"])[:80]):
                rc, out, err = run(command, req)
                self.assertIn(rc, (0, 2), err)
                if rc == 2:
                    self.bad_any(command, req)
                elif command == "render":
                    self.assertIsNone(re.search(r"(?i)nan|inf", out))
                else:
                    self.assertNotIn("null", out)
                    json.loads(out)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
