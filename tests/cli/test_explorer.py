#!/usr/bin/python3
"""The explorer page in a real browser: headless Debian chromium driven by chromedriver
(python3-selenium). For each view: load it, drag a control point with real pointer events,
and check that the drawn curve and the numbers shown are the server's answer for the moved
point (asked here, independently of the page), with no console error. Screenshots go to
the current directory (the build folder's tests/cli).

Usage: test_explorer.py PATH_TO_CASTELJAU [unittest options]
Skips (exit status 77) only when chromium or chromedriver is not installed.
"""
import json
import math
import os
import shutil
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_serve  # noqa: E402  (the server fixture)

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
SKIP = 77  # ctest's SKIP_RETURN_CODE for this test
FONTS = "/usr/share/fonts/truetype/dejavu"


def fmt(x):
    """The page's number format (JavaScript's toFixed(4))."""
    return f"{x:.4f}"


def fmt_point(p):
    return "(" + ", ".join(fmt(x) for x in p) + ")"


class ExplorerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service

        # The fonts the import view's text outlines read (glyph is served with --font-dir).
        cls.fonts = FONTS if os.path.exists(os.path.join(FONTS, "DejaVuSans.ttf")) else None
        cls.server = test_serve.Server(*(["--font-dir", cls.fonts] if cls.fonts else []))
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1000,800",
                    # Less background work: nothing here needs them.
                    "--disable-extensions", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                    "--no-first-run", "--disable-default-apps", "--mute-audio"):
            options.add_argument(arg)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        cls.driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
        cls.driver.set_script_timeout(20)
        cls.base = f"http://{cls.server.host}:{cls.server.port}/"

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        cls.server.stop()

    def settle(self):
        """Waits (in the page, without polling) until no request is in flight and the
        answers are drawn."""
        self.driver.execute_async_script("const done = arguments[arguments.length - 1]; window.explorerIdle().then(() => done(true));")

    def api(self, command, request):
        status, _, body = self.server.post(command, request)
        self.assertEqual(status, 200, body)
        return json.loads(body)

    def handles(self, view):
        from selenium.webdriver.common.by import By
        return self.driver.find_elements(By.CSS_SELECTOR, f"#{view}-canvas circle.handle")

    # Reading the page: one WebDriver command each (a command costs 50-200 ms on the loaded
    # machine; reading attributes element by element made most of the test's time).

    def attrs(self, selector, name):
        """The attribute `name` of every element that the CSS selector matches."""
        return self.driver.execute_script(
            "return Array.from(document.querySelectorAll(arguments[0]), (e) => e.getAttribute(arguments[1]))", selector, name)

    def attr(self, selector, name):
        values = self.attrs(selector, name)
        self.assertEqual(len(values), 1, selector)
        return values[0]

    def element(self, selector):
        return self.driver.find_element("css selector", selector)

    def points(self, view):
        return [json.loads(v) for v in self.attrs(f"#{view}-canvas circle.handle", "data-point")]

    def drag(self, element, dx, dy, steps=4, step_ms=16):
        """Mouse drag by (dx, dy) CSS pixels in steps (pointerdown, pointermoves, pointerup),
        a move every step_ms (16 ms: a 60 Hz pointer)."""
        from selenium.webdriver.common.action_chains import ActionChains
        chain = ActionChains(self.driver, duration=step_ms).click_and_hold(element)
        for _ in range(steps):
            chain = chain.move_by_offset(dx / steps, dy / steps)
        chain.release().perform()
        # The page redraws its handles when the server answers: an element found before
        # that is stale (the Hermite view's tangent tip was, in a run at load 8).
        self.settle()

    def touch_drag(self, element, dx, dy):
        """The same with a touch pointer."""
        from selenium.webdriver.common.actions import interaction
        from selenium.webdriver.common.actions.action_builder import ActionBuilder
        from selenium.webdriver.common.actions.pointer_input import PointerInput
        actions = ActionBuilder(self.driver, mouse=PointerInput(interaction.POINTER_TOUCH, "finger"), duration=16)
        rect = element.rect
        x, y = rect["x"] + rect["width"] / 2, rect["y"] + rect["height"] / 2
        actions.pointer_action.move_to_location(int(x), int(y)).pointer_down()
        for k in range(1, 6):
            actions.pointer_action.move_to_location(int(x + dx * k / 5), int(y + dy * k / 5))
        actions.pointer_action.pointer_up()
        actions.perform()
        self.settle()

    def data_points(self, view):
        """{index: point} of every control point drawn in a view (handles and dependent
        points)."""
        return {int(i): json.loads(p) for i, p in self.driver.execute_script(
            "return Array.from(document.querySelectorAll(arguments[0]), (e) => [e.dataset.index, e.dataset.point])",
            f"#{view}-canvas [data-point]")}

    def curve_points(self, element_id):
        return json.loads(self.attr("#" + element_id, "data-points"))

    def text(self, element_id):
        return self.driver.execute_script("return document.getElementById(arguments[0]).innerText.trim()", element_id)

    def no_console_errors(self):
        errors = [e for e in self.driver.get_log("browser") if e["level"] == "SEVERE"]
        self.assertEqual(errors, [])

    def test_bezier_view(self):
        self.driver.get(self.base + "#bezier")
        self.settle()
        before = self.points("bz")
        self.assertEqual(len(before), 5)  # opens on a real example
        self.drag(self.handles("bz")[1], 60, 40)
        self.settle()
        after = self.points("bz")
        # The dragged point moved right and down (world y is up), the others stayed.
        self.assertGreater(after[1][0], before[1][0] + 0.3)
        self.assertLess(after[1][1], before[1][1] - 0.2)
        self.assertEqual([p for i, p in enumerate(after) if i != 1], [p for i, p in enumerate(before) if i != 1])
        # The drawn curve is the server's answer for the moved points (sampled as the page
        # does: 161 parameters i / 160), exactly.
        curve = {"type": "bezier", "points": after}
        ts = [i / 160 for i in range(161)]
        self.assertEqual(self.curve_points("bz-curve"), self.api("eval", {"curve": curve, "t": ts})["points"])
        # The numbers shown at t = 0.4.
        at = self.api("eval", {"curve": curve, "t": [0.4], "derivatives": 1, "curvature": True})
        self.assertEqual(self.text("bz-point"), fmt_point(at["points"][0]))
        self.assertEqual(self.text("bz-tangent"), fmt_point(at["derivatives"][0][0]))
        self.assertEqual(self.text("bz-curvature"), fmt(at["curvature"][0]))
        self.assertEqual(self.text("bz-length"), fmt(self.api("length", {"curve": curve})["length"]))
        basis = self.api("basis", {"kind": "bernstein", "degree": 4, "t": [0.4]})["values"][0]
        self.assertEqual(self.text("bz-bernstein"), ", ".join(fmt(v) for v in basis))
        # The construction's levels: degree 4 draws levels 1..3 (4, 3, 2 points).
        levels = self.driver.find_elements("css selector", "#bz-canvas path.level")
        self.assertEqual(len(levels), 3)
        # A touch drag moves a point too.
        self.touch_drag(self.handles("bz")[3], -40, 30)
        self.settle()
        touched = self.points("bz")
        self.assertLess(touched[3][0], after[3][0] - 0.2)
        curve = {"type": "bezier", "points": touched}
        self.assertEqual(self.curve_points("bz-curve"), self.api("eval", {"curve": curve, "t": ts})["points"])
        # The hodograph: the server's first derivatives at the same parameters.
        self.driver.find_element("id", "bz-hodograph").click()
        self.settle()
        self.assertEqual(self.curve_points("bz-hodograph-curve"), self.api("eval", {"curve": curve, "t": ts, "derivatives": 1})["derivatives"][0])
        # The portion over [0.4, 0.8] (t and s), whose control points are the blossom's values
        # b(a..a b..b): against the blossom written here (1e-12: the server's two splits
        # round differently from the blossom's n levels of affine combinations).
        self.driver.find_element("id", "bz-portion").click()
        self.settle()
        portion = self.curve_points("bz-portion-polygon")
        n = len(touched) - 1
        for i, p in enumerate(portion):
            q = blossom(touched, [0.4] * (n - i) + [0.8] * i)
            for k in range(2):
                self.assertAlmostEqual(p[k], q[k], delta=1e-12)
        self.driver.save_screenshot("explorer-bezier.png")
        self.driver.find_element("id", "bz-hodograph").click()
        self.driver.find_element("id", "bz-portion").click()
        self.settle()
        self.no_console_errors()

    def test_bspline_view(self):
        from selenium.webdriver.common.keys import Keys
        self.show_view("bspline")
        before = self.points("bs")
        self.drag(self.handles("bs")[3], -30, -50)
        self.settle()
        after = self.points("bs")
        self.assertLess(after[3][0], before[3][0] - 0.2)
        self.assertGreater(after[3][1], before[3][1] + 0.3)
        knots = [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1]  # the page's clamped uniform knots for 7 points, degree 3
        ts = [0 + (1 - 0) * i / 240 for i in range(241)]
        curve = {"type": "bspline", "degree": 3, "knots": knots, "points": after}
        self.assertEqual(self.curve_points("bs-curve"), self.api("eval", {"curve": curve, "t": ts})["points"])
        self.assertEqual(self.text("bs-point"), fmt_point(self.api("eval", {"curve": curve, "t": [0.5]})["points"][0]))
        # De Boor's construction at u = 0.5 (a knot of multiplicity 1: levels 0..2), against
        # the construction written here. 1e-12: a few ulps of coordinates of size 5 through
        # two levels of affine combinations, computed in another order by the server.
        levels = {int(k): json.loads(v) for k, v in zip(self.attrs("#bs-canvas path.level", "data-level"),
                                                          self.attrs("#bs-canvas path.level", "data-points"))}
        expected = de_boor(after, knots, 3, 0.5)
        self.assertEqual(sorted(levels), list(range(len(expected))))
        for r, level in enumerate(expected):
            self.assertEqual(len(levels[r]), len(level), r)
            for p, q in zip(levels[r], level):
                for a, b in zip(p, q):
                    self.assertAlmostEqual(a, b, delta=1e-12)
        self.assertEqual(len(expected[-1]), 1)  # the last level is C(u)
        # A weight changed by its slider (keyboard: real input events) makes it a NURBS.
        slider = self.driver.find_element("id", "bs-weight-3")
        slider.send_keys(Keys.PAGE_UP)
        self.settle()
        weight = float(slider.get_attribute("value"))
        self.assertGreater(weight, 1)
        weights = [1, 1, 1, weight, 1, 1, 1]
        curve = {"type": "nurbs", "degree": 3, "knots": knots, "points": after, "weights": weights}
        self.assertEqual(self.curve_points("bs-curve"), self.api("eval", {"curve": curve, "t": ts})["points"])
        self.assertTrue(self.text("bs-type").startswith("NURBS"))
        # The exact circle: every drawn point at the radius from the centre (the server's
        # NURBS; 1e-12: a few ulps of coordinates of size 5 through the rational evaluation).
        self.driver.find_element("id", "bs-circle").click()
        self.settle()
        for x, y in self.curve_points("bs-curve"):
            self.assertAlmostEqual(((x - 4.5) ** 2 + (y - 2.5) ** 2) ** 0.5, 2, delta=1e-12)
        self.assertEqual(self.text("bs-radius"), fmt(2))
        self.driver.save_screenshot("explorer-bspline.png")
        self.no_console_errors()

    def show_view(self, name):
        """Switches to a view by its nav link (a real click) and waits for its drawing."""
        if not self.driver.current_url.startswith(self.base):
            self.driver.get(self.base)
        self.driver.find_element("css selector", f'nav a[data-view="{name}"]').click()
        # In the page: once the view is shown (after the hash change), until it is drawn.
        self.driver.execute_async_script("""
            const done = arguments[arguments.length - 1], view = document.getElementById(arguments[0]);
            const wait = () => (view.hidden ? requestAnimationFrame(wait) : window.explorerIdle().then(() => done(true)));
            wait();""", "view-" + name)

    def test_interpolation_view(self):
        self.show_view("interpolation")
        before = self.points("ip")
        self.assertEqual(len(before), 9)  # Runge's bump
        self.drag(self.handles("ip")[4], 0, 60, steps=4)
        self.settle()
        after = self.points("ip")
        self.assertLess(after[4][1], before[4][1] - 0.5)
        # Two of the curves shown by default, as the server flattens them for the moved
        # points (the page's tolerance, 0.002), and the lengths shown.
        curves = {
            "lagrange_uniform": {"type": "lagrange", "params": list(range(9)), "points": after},
            "spline_natural": {"type": "cubic_spline", "parametrization": "chord", "boundary": "natural", "points": after},
        }
        for key, curve in curves.items():
            self.assertEqual(self.curve_points("ip-curve-" + key), self.api("flatten", {"curve": curve, "tolerance": 0.002})["points"], key)
            self.assertEqual(self.text("ip-length-" + key), fmt(self.api("length", {"curve": curve})["length"]), key)
        # The other end conditions, side by side (their boxes ticked by the page's own inputs).
        self.driver.execute_script("for (const k of ['not_a_knot', 'clamped', 'periodic']) document.getElementById('ip-spline_' + k).click()")
        self.settle()
        spline = {"type": "cubic_spline", "parametrization": "chord"}
        for key, curve in (("spline_not_a_knot", dict(spline, boundary="not-a-knot", points=after)),
                           ("spline_clamped", dict(spline, boundary="clamped", start_derivative=[1, 0], end_derivative=[1, 0], points=after)),
                           ("spline_periodic", dict(spline, boundary="periodic", points=after + [after[0]]))):
            self.assertEqual(self.curve_points("ip-curve-" + key), self.api("flatten", {"curve": curve, "tolerance": 0.002})["points"], key)
        self.driver.save_screenshot("explorer-interpolation.png")
        self.no_console_errors()

    def test_queries_view(self):
        self.show_view("queries")
        handles = self.handles("qr")
        self.drag(handles[1], 20, 30, steps=4)
        self.settle()
        pts = self.points("qr")
        a, b = pts[:4], pts[4:]
        self.assertNotEqual(a[1], [2.2, 4.8])
        A, B = {"type": "bezier", "points": a}, {"type": "bezier", "points": b}
        inter = self.api("intersect", {"curves": [A, B]})["intersections"]
        marks = json.loads(self.attr("#qr-intersections", "data-points"))
        self.assertEqual(marks, [x["point"] for x in inter])
        self.assertGreater(len(marks), 0)  # the example's curves cross
        self.assertEqual(self.text("qr-intersections-text"), "; ".join(
            x["kind"] + " at t = (" + ", ".join(fmt(v) for v in x["t"]) + ")" for x in inter))
        box = json.loads(self.attr("#qr-bounds-box", "data-box"))
        self.assertEqual(box, self.api("bounds", {"curve": A}))
        self.assertEqual(self.text("qr-length"), fmt(self.api("length", {"curve": A})["length"]))
        # Segment counts at the page's tolerance 10^-1.5 (a count does not hinge on the last
        # bit of the tolerance as the page's Math.pow computes it).
        for method in ("optimal", "subdivision", "uniform"):
            n = len(self.api("flatten", {"curve": A, "tolerance": 10 ** -1.5, "method": method})["points"]) - 1
            self.assertEqual(self.text("qr-count-" + method), str(n), method)
        # The features of A marked where the server's features and eval put them.
        features = self.api("features", {"curve": A})
        ts = features["inflections"] + features["cusps"] + features["extrema"][0] + features["extrema"][1]
        marks = json.loads(self.attr("#qr-features-marks", "data-marks"))
        self.assertEqual([m["t"] for m in marks], ts)
        self.assertEqual([m["point"] for m in marks], self.api("eval", {"curve": A, "t": ts})["points"] if ts else [])
        # B made a piece of A (split twice by the server): the overlap drawn and stated.
        self.driver.find_element("id", "qr-piece").click()
        self.settle()
        b = self.points("qr")[4:]
        inter = self.api("intersect", {"curves": [A, {"type": "bezier", "points": b}]})
        self.assertEqual(len(inter["overlaps"]), 1)
        self.assertEqual(len(self.attrs("#qr-canvas path.overlap", "data-overlap")), 1)
        self.assertEqual(self.text("qr-overlaps"), "A on [" + ", ".join(fmt(x) for x in inter["overlaps"][0]["a"]) + "]")
        self.driver.save_screenshot("explorer-queries.png")
        self.no_console_errors()

    def test_subdivision_view(self):
        self.show_view("subdivision")
        before = self.points("sd")
        self.drag(self.handles("sd")[2], -50, 30, steps=4)
        self.settle()
        after = self.points("sd")
        self.assertLess(after[2][0], before[2][0] - 0.3)
        # The page opens on Chaikin, 2 steps, closed: the drawn step and the limit curve are
        # the server's (the limit: the B-spline `subdivide` answers, sampled at 401
        # parameters as the page does).
        request = {"points": after, "scheme": "chaikin", "iterations": 2, "closed": True}
        self.assertEqual(self.curve_points("sd-step"), self.api("subdivide", request)["points"])
        limit = self.api("subdivide", dict(request, iterations=7))["limit"]
        p, n = limit["degree"], len(limit["points"])
        a, b = limit["knots"][p], limit["knots"][n]
        ts = [a + ((b - a) * i) / 400 for i in range(401)]
        self.assertEqual(self.curve_points("sd-limit-curve"), self.api("eval", {"curve": limit, "t": ts})["points"])
        self.assertEqual(self.text("sd-count"), str(len(self.api("subdivide", request)["points"])))
        self.driver.save_screenshot("explorer-subdivision.png")
        self.no_console_errors()

    def test_composite_view(self):
        from selenium.webdriver.support.ui import Select
        self.show_view("composite")
        Select(self.driver.find_element("id", "cp-joint-0")).select_by_visible_text("C2")
        Select(self.driver.find_element("id", "cp-joint-1")).select_by_visible_text("G1")
        self.settle()
        handle = self.element("#cp-canvas circle.handle[data-index='1']")
        before = self.data_points("cp")
        self.drag(handle, 30, -25)
        self.settle()
        pts = self.data_points("cp")
        self.assertEqual(sorted(pts), list(range(10)))
        self.assertGreater(pts[1][0], before[1][0] + 0.2)
        P = [pts[i] for i in range(10)]
        # The continuity asked, from the cubic end derivatives 3 (P3 - P2), 6 (P3 - 2 P2 + P1)
        # written here: C2 at P3 (C1: P4 = 2 P3 - P2; C2: P5 = P1 + 4 (P3 - P2)), and G1 at
        # P6 (P7 - P6 along P6 - P5). 1e-12: the same few operations, possibly reordered.
        for k in range(2):
            self.assertAlmostEqual(P[4][k], P[3][k] + (P[3][k] - P[2][k]), delta=1e-12)
            self.assertAlmostEqual(P[5][k], P[1][k] + 4 * (P[3][k] - P[2][k]), delta=1e-12)
        a = [P[6][k] - P[5][k] for k in range(2)]
        b = [P[7][k] - P[6][k] for k in range(2)]
        self.assertAlmostEqual(a[0] * b[1] - a[1] * b[0], 0, delta=1e-12)
        self.assertGreater(a[0] * b[0] + a[1] * b[1], 0)
        # The drawn curve and comb: the server's eval of the path for these points.
        path = {"type": "path", "segments": [{"type": "bezier", "points": P[3 * i:3 * i + 4]} for i in range(3)]}
        ts = [(3 * i) / 240 for i in range(241)]
        answer = self.api("eval", {"curve": path, "t": ts, "derivatives": 1, "curvature": True})
        self.assertEqual(self.curve_points("cp-curve"), answer["points"])
        self.assertEqual(json.loads(self.attr("#cp-comb-envelope", "data-curvature")), answer["curvature"])
        # What each joint reaches, shown; and the curvatures on both sides.
        self.assertEqual(self.text("cp-joint-0-reached"), "C2")
        self.assertEqual(self.text("cp-joint-1-reached"), "G1")
        for j in range(2):
            left = self.api("eval", {"curve": path["segments"][j], "t": [1], "curvature": True})["curvature"][0]
            right = self.api("eval", {"curve": path["segments"][j + 1], "t": [0], "curvature": True})["curvature"][0]
            self.assertEqual(self.text(f"cp-joint-{j}-curvature"), fmt(left) + " | " + fmt(right))
        self.driver.save_screenshot("explorer-composite.png")
        self.no_console_errors()

    def test_hermite_view(self):
        self.show_view("hermite")
        self.drag(self.handles("hm")[3], 0, -30)
        tip = self.element("#hm-canvas circle.tangent-handle[data-index='2']")
        self.drag(tip, 25, -20)
        self.settle()
        pts = self.points("hm")
        tangents = [json.loads(v) for v in self.attrs("#hm-canvas circle.tangent-handle", "data-tangent")]
        self.assertNotEqual(tangents[2], [1, 1.5])
        params = [p[0] for p in pts]  # the page opens on "the points' x"
        curves = {
            "explicit": {"type": "hermite", "params": params, "points": pts, "tangents": tangents},
            "catmull_rom": {"type": "hermite", "params": params, "points": pts, "tangent_rule": "catmull_rom"},
            "monotone": {"type": "hermite", "params": params, "points": pts, "tangent_rule": "monotone"},
            "akima": {"type": "hermite", "params": params, "points": pts, "tangent_rule": "akima"},
        }
        for key, curve in curves.items():
            drawn = self.curve_points("hm-curve-" + key)
            self.assertEqual(drawn, self.api("flatten", {"curve": curve, "tolerance": 0.002})["points"], key)
            box = self.api("bounds", {"curve": curve})
            self.assertEqual(self.text("hm-range-" + key), "[" + fmt(box["min"][1]) + ", " + fmt(box["max"][1]) + "]", key)
        # PCHIP does not overshoot: its drawn points stay within the data's y range (1e-12:
        # rounding of the cubic pieces' values).
        ys = [p[1] for p in pts]
        for x, y in self.curve_points("hm-curve-monotone"):
            self.assertGreaterEqual(y, min(ys) - 1e-12)
            self.assertLessEqual(y, max(ys) + 1e-12)
        self.driver.save_screenshot("explorer-hermite.png")
        self.no_console_errors()

    def test_catmull_view(self):
        self.show_view("catmull")
        # On the opening example the uniform curve loops and the centripetal one does not.
        self.assertTrue(self.text("cr-count-0").startswith("3 self-intersections"))
        self.assertTrue(self.text("cr-count-05").startswith("0 self-intersections"))
        self.drag(self.handles("cr")[4], -20, 25)
        self.settle()
        pts = self.points("cr")
        for alpha, key in ((0, "0"), (0.5, "05"), (1, "1")):
            curve = {"type": "catmull_rom", "alpha": alpha, "ends": "reflect", "points": pts}
            self.assertEqual(self.curve_points("cr-curve-" + key), self.api("flatten", {"curve": curve, "tolerance": 0.002})["points"], key)
            inter = self.api("intersect", {"curves": [curve]})["intersections"]
            cusps = self.api("features", {"curve": curve})["cusps"]
            self.assertEqual(json.loads(self.attr("#cr-marks-" + key, "data-intersections")), [x["point"] for x in inter], key)
            self.assertEqual(len(json.loads(self.attr("#cr-marks-" + key, "data-cusps"))), len(cusps), key)
            n, m = len(inter), len(cusps)
            self.assertEqual(self.text("cr-count-" + key), f"{n} self-intersection{'' if n == 1 else 's'}, {m} cusp{'' if m == 1 else 's'}")
        self.driver.save_screenshot("explorer-catmull.png")
        self.no_console_errors()

    def imported(self, text):
        """import_svg's subpaths for text (an SVG document or path data), asked here."""
        request = {"svg": text} if text.lstrip().startswith("<") else {"d": text}
        return [s for p in self.api("import_svg", request)["paths"] for s in p["subpaths"]]

    def check_import_drawing(self, subpaths):
        tolerance = float(self.attr("#im-canvas", "data-tolerance"))
        for k, curve in enumerate(subpaths):
            self.assertEqual(self.curve_points(f"im-curve-{k}"), self.api("flatten", {"curve": curve, "tolerance": tolerance})["points"], k)
        self.assertEqual(len(self.attrs("#im-canvas path.curve", "id")), len(subpaths))

    def test_import_view(self):
        self.show_view("import")
        # The opening example, as the server reads it.
        example = self.driver.execute_script("return document.getElementById('im-text').value")
        self.check_import_drawing(self.imported(example))
        self.assertEqual(self.text("im-shapes"), "#heart: 1 subpath, #box: 1 subpath, #wave: 1 subpath")
        # Path data pasted, then imported.
        d = "M 10 10 C 30 60 70 -20 90 30 Q 100 60 60 70 A 25 15 30 0 1 10 10 Z"
        box = self.driver.find_element("id", "im-text")
        box.clear()
        box.send_keys(d)
        self.driver.find_element("id", "im-import").click()
        self.settle()
        subpaths = self.imported(d)
        self.check_import_drawing(subpaths)
        self.assertEqual(self.text("im-pieces"), "0 lines, 1 quadratics, 1 cubics, 2 arc pieces (rational quadratics)")
        # Drag the cubic's first inner control point: the drawn curve is the server's for the
        # moved point.
        cubic_inner = "#im-canvas circle.handle[data-subpath='0'][data-segment='0'][data-index='1']"
        handle = self.element(cubic_inner)
        old = json.loads(self.attr(cubic_inner, "data-point"))
        self.drag(handle, 30, 20)
        self.settle()
        new = json.loads(self.attr(cubic_inner, "data-point"))
        self.assertGreater(new[0], old[0])
        self.assertGreater(new[1], old[1])  # y down, as in SVG
        subpaths[0]["segments"][0]["points"][1] = new
        self.check_import_drawing(subpaths)
        # Exported as SVG (to_svg_path) and read back: the same pieces' end points (1e-9 of
        # the drawing's size 100: to_svg_path writes round-trip digits; arcs go through
        # their radii and angles).
        self.driver.find_element("id", "im-export-svg").click()
        self.settle()
        back = self.imported(self.text("im-export"))
        self.assertEqual(len(back), 1)
        ends = lambda c: [s["points"][-1] for s in c["segments"]]
        self.assertEqual(len(ends(back[0])), len(ends(subpaths[0])))
        for p, q in zip(ends(back[0]), ends(subpaths[0])):
            self.assertAlmostEqual(p[0], q[0], delta=1e-7)
            self.assertAlmostEqual(p[1], q[1], delta=1e-7)
        # A file chosen (as a drop would give it).
        path = os.path.abspath("explorer-import.svg")
        document = '<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(5 5) rotate(30)"><circle id="c" cx="20" cy="0" r="8"/></g><text>x</text></svg>'
        with open(path, "w") as f:
            f.write(document)
        self.driver.find_element("id", "im-file").send_keys(path)
        self.settle()
        self.check_import_drawing(self.imported(document))
        self.assertEqual(self.text("im-shapes"), "#c: 1 subpath")
        self.assertEqual(self.text("im-skipped"), "text")
        self.driver.save_screenshot("explorer-import.png")
        self.no_console_errors()

    # Session 13's views: one drag each, the drawing against the server's answers asked here.

    def test_affine_view(self):
        self.show_view("affine")
        self.drag(self.handles("af")[1], 30, 40)
        pts = self.points("af")
        self.assertNotEqual(pts[1], [1.6, 4.6])
        # The map from the sliders' values, written here (rotation of scale and shear, then
        # moved by (5.6, 0.4)); the page's mapped control points are its image (1e-12).
        v = {k: float(self.attr("#af-" + k, "value")) for k in ("angle", "sx", "sy", "shear")}
        a = math.radians(v["angle"])
        c, s = math.cos(a), math.sin(a)
        M = [[c * v["sx"], c * v["shear"] * v["sy"] - s * v["sy"]], [s * v["sx"], s * v["shear"] * v["sy"] + c * v["sy"]]]
        mapped = [json.loads(x) for x in self.attrs("#af-canvas rect[data-mapped]", "data-point")]
        for p, q in zip(pts, mapped):
            for k in range(2):
                self.assertAlmostEqual(M[k][0] * p[0] + M[k][1] * p[1] + (5.6, 0.4)[k], q[k], delta=1e-12)
        ts = [i / 160 for i in range(161)]
        image = self.api("eval", {"curve": {"type": "bezier", "points": mapped}, "t": ts})["points"]
        self.assertEqual(self.curve_points("af-image"), image)
        # Affine invariance, as the page shows it: the mapped samples on the image curve.
        self.assertLess(float(self.text("af-error")), 1e-12)
        self.driver.save_screenshot("explorer-affine.png")
        self.no_console_errors()

    def test_reduce_view(self):
        self.show_view("reduce")
        self.drag(self.handles("rd")[3], -20, -30)
        pts = self.points("rd")
        curve = {"type": "bezier", "points": pts}
        ts = [i / 160 for i in range(161)]
        self.assertEqual(self.curve_points("rd-curve"), self.api("eval", {"curve": curve, "t": ts})["points"])
        reduced = self.api("reduce", {"curve": curve, "times": 3, "tolerance": 1e6})  # degree 7 to 4, the page's default
        self.assertEqual(self.curve_points("rd-polygon"), reduced["curve"]["points"])
        self.assertEqual(self.curve_points("rd-reduced"), self.api("eval", {"curve": reduced["curve"], "t": ts})["points"])
        self.assertEqual(self.text("rd-error"), fmt(reduced["max_error"]))
        self.driver.save_screenshot("explorer-reduce.png")
        self.no_console_errors()

    def test_pieces_view(self):
        self.show_view("pieces")
        joint = self.element("#pc-canvas circle.handle[data-segment='0'][data-index='3']")
        self.drag(joint, 20, -20)
        drawn = {(int(s), int(i)): json.loads(p) for s, i, p in self.driver.execute_script(
            "return Array.from(document.querySelectorAll('#pc-canvas circle.handle'), (e) => [e.dataset.segment, e.dataset.index, e.dataset.point])")}
        self.assertEqual(drawn[(0, 3)], drawn[(1, 0)])  # the joint moved both segments
        self.assertNotEqual(drawn[(0, 3)], [4.0, 2.8])
        segs = [{"type": "polyline", "points": [drawn[(0, i)] for i in range(4)]},
                {"type": "bezier", "points": [drawn[(1, i)] for i in range(4)]},
                {"type": "rational_bezier", "points": [drawn[(2, i)] for i in range(3)], "weights": [1, 0.5 ** 0.5, 1]}]
        path = {"type": "path", "segments": segs, "breaks": [0, 1.5, 3, 4]}
        bz = self.api("to_bezier", {"curve": path})["curve"]
        self.assertEqual(len(self.attrs("#pc-canvas path[data-piece]", "data-piece")), len(bz["segments"]))
        self.assertEqual(self.text("pc-breaks"), ", ".join(fmt(b) for b in bz["breaks"]))
        ts = [i / 40 for i in range(41)]
        for i, seg in enumerate(bz["segments"]):
            self.assertEqual(json.loads(self.attr(f"#pc-canvas path[data-piece='{i}']", "data-points")),
                             self.api("eval", {"curve": seg, "t": ts})["points"], i)
        self.assertEqual(json.loads(self.attr("#pc-bounds", "data-box")), self.api("bounds", {"curve": path}))
        self.driver.save_screenshot("explorer-pieces.png")
        self.no_console_errors()

    def test_fit_view(self):
        self.show_view("fit")
        self.drag(self.handles("ft")[5], 0, -40)
        pts = self.points("ft")
        fit = self.api("fit", {"points": pts, "degree": 3, "control_points": 7})  # the page's defaults
        self.assertEqual(json.loads(self.attr("#ft-curve", "data-curve")), fit["curve"])
        ts = [i / 240 for i in range(241)]
        self.assertEqual(self.curve_points("ft-curve"), self.api("eval", {"curve": fit["curve"], "t": ts})["points"])
        self.assertEqual(self.text("ft-error"), fmt(fit["max_error"]))
        self.driver.save_screenshot("explorer-fit.png")
        self.no_console_errors()

    def test_frames_view(self):
        self.show_view("frames")
        self.drag(self.handles("fr")[1], 25, 20)
        pts = self.points("fr")
        self.assertNotEqual(pts[1], [3.2, 3.4, 1.2])
        self.assertEqual(len(pts[1]), 3)
        curve = {"type": "bezier", "points": pts}
        at = [i / 24 for i in range(25)]
        for key, method in (("frenet", "frenet"), ("rmf", "rotation_minimizing")):
            normals = self.api("frames", {"curve": curve, "t": at, "method": method})["normals"]
            self.assertEqual(json.loads(self.attr("#fr-normals-" + key, "data-normals")), normals, key)
        self.driver.save_screenshot("explorer-frames.png")
        self.no_console_errors()

    def test_surface_view(self):
        from selenium.webdriver.support.ui import Select
        self.show_view("surface")
        self.drag(self.element("#sf-canvas circle.handle[data-curve='1'][data-index='1']"), 15, -25)
        grid = {(int(c), int(i)): json.loads(p) for c, i, p in self.driver.execute_script(
            "return Array.from(document.querySelectorAll('#sf-canvas circle.handle'), (e) => [e.dataset.curve, e.dataset.index, e.dataset.point])")}
        patch = {"type": "bezier_surface", "points": [[grid[(i, j)] for j in range(4)] for i in range(4)]}
        self.assertNotEqual(grid[(1, 1)], [1, 1, 1.6])
        uv = json.loads(self.attr("#sf-isocurves", "data-uv"))
        self.assertEqual(json.loads(self.attr("#sf-isocurves", "data-points")), self.api("eval", {"surface": patch, "uv": uv})["points"])
        self.assertEqual(self.text("sf-area"), fmt(self.api("area", {"surface": patch})["area"]))
        # The surface of revolution, meshed: the server's construction and tessellation.
        Select(self.driver.find_element("id", "sf-mode")).select_by_value("revolve")
        self.driver.find_element("id", "sf-mesh").click()
        self.settle()
        profile = [json.loads(p) for p in self.attrs("#sf-canvas circle.handle", "data-point")]
        s = self.api("surface", {"construct": "revolve", "curve": {"type": "bezier", "points": profile},
                                 "axis": {"point": [0, 0, 0], "direction": [0, 0, 1]}})["surface"]
        uv = json.loads(self.attr("#sf-isocurves", "data-uv"))
        self.assertEqual(json.loads(self.attr("#sf-isocurves", "data-points")), self.api("eval", {"surface": s, "uv": uv})["points"])
        tess = self.api("tessellate", {"surface": s, "tolerance": 10 ** -1.5})
        self.assertTrue(self.text("sf-triangles").startswith(f"{len(tess['triangles'])} within"))
        self.driver.save_screenshot("explorer-surface.png")
        self.no_console_errors()

    def test_knot_removal_and_glyphs(self):
        # Knot removal in the B-spline view: u = 0.5 inserted once more (multiplicity 2),
        # then the knot nearest u removed twice within 1e-9 (the page's default): the curve
        # drawn is the server's answer for that request, asked here.
        self.show_view("bspline")
        self.driver.find_element("id", "bs-reset").click()
        self.settle()
        self.driver.find_element("id", "bs-insert").click()
        self.settle()
        self.driver.find_element("id", "bs-remove").click()
        self.settle()
        knots = [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1]
        start = {"type": "bspline", "degree": 3, "knots": knots, "points": [[0.3, 0.6], [1.2, 4.0], [3.2, 4.8], [4.6, 1.0], [6.3, 0.8], [7.4, 4.5], [9.0, 3.0]]}
        inserted = self.api("insert_knot", {"curve": start, "knot": 0.5})["curve"]
        self.assertEqual(json.loads(self.attr("#bs-removed", "data-request")), {"knot": 0.5, "times": 2, "tolerance": 1e-9})
        removed = self.api("remove_knot", {"curve": inserted, "knot": 0.5, "times": 2, "tolerance": 1e-9})
        self.assertEqual(removed["removed"], 1)  # the copy inserted; the original knot stays
        ts = [i / 240 for i in range(241)]
        self.assertEqual(self.curve_points("bs-curve"), self.api("eval", {"curve": removed["curve"], "t": ts})["points"])
        self.assertTrue(self.text("bs-removed").startswith("u = 0.5000: 1 of 2 copies removed"))
        # Text outlines in the import view (glyph, from the server's font folder).
        if self.fonts:
            self.show_view("import")
            self.driver.find_element("id", "im-glyph").click()
            self.settle()
            answer = self.api("glyph", {"font": "DejaVuSans.ttf", "text": "Curves", "size": 100})
            contours = [c for g in answer["glyphs"] if g["curve"] for c in g["curve"]["segments"]]
            self.check_import_drawing(contours)
            self.assertTrue(self.text("im-shapes").startswith("#C: 1 subpath, #u: 1 subpath"))
            self.driver.save_screenshot("explorer-glyphs.png")
        self.no_console_errors()

    def test_view_from_address(self):
        # The gallery links to views by address (http://127.0.0.1:8080/#VIEW): a page
        # opened there shows that view alone; an unknown name shows the first view.
        for fragment, shown in (("catmull", "catmull"), ("no-such-view", "bezier")):
            self.driver.get("about:blank")
            self.driver.get(self.base + "#" + fragment)
            self.settle()
            visible = self.driver.execute_script(
                "return Array.from(document.querySelectorAll('section.view'), (v) => [v.id, v.hidden])")
            self.assertEqual([v for v, hidden in visible if not hidden], ["view-" + shown])
        self.no_console_errors()

    # A drag at exactly 60 Hz, in the page: one pointermove per animation frame (chromedriver
    # paces its moves at 25-30 a second on the loaded machine, too slow to show the redraw
    # rate). The page's handlers take these events as they take the pointer's.
    DRAG_60HZ = """
        const done = arguments[arguments.length - 1], frames = arguments[0];
        const svg = document.getElementById('bz-canvas'), h = svg.querySelector('circle.handle[data-index="2"]');
        const box = h.getBoundingClientRect();
        let x = box.x + box.width / 2, y = box.y + box.height / 2;
        const event = (type) => new PointerEvent(type, {pointerId: 1, bubbles: true, clientX: x, clientY: y,
            pointerType: 'mouse', isPrimary: true, buttons: type === 'pointerup' ? 0 : 1});
        const start = [window.explorerLatencies().length, window.explorerRoundTrips().length, window.explorerPhases().length];
        h.dispatchEvent(event('pointerdown'));
        let k = 0, redraws = 0, last = document.getElementById('bz-curve').getAttribute('d');
        const t0 = performance.now();
        const step = () => {
          const d = document.getElementById('bz-curve').getAttribute('d');
          if (d !== last) { redraws++; last = d; }
          if (k++ < frames) {
            x += 2; y += 1;
            svg.dispatchEvent(event('pointermove'));
            requestAnimationFrame(step);
          } else {
            const span = performance.now() - t0;
            svg.dispatchEvent(event('pointerup'));
            window.explorerIdle().then(() => done([redraws, span, window.explorerLatencies().slice(start[0]),
                window.explorerRoundTrips().slice(start[1]), window.explorerPhases().slice(start[2])]));
          }
        };
        requestAnimationFrame(step);"""

    def test_update_latency(self):
        # Drags in the de Casteljau view, a move every frame for 60 frames, on the example
        # (degree 4) and on degree 10, the highest the issue asks to redraw at 60 frames per
        # second. Updates are coalesced: a move arriving while one is computed is merged
        # into the next, so the redraw rate is the frames' rate while an update takes less
        # than a frame.
        self.show_view("bezier")
        figures = {}
        for degree in (4, 10):
            # Points added by their button, all at once (the updates coalesce), then one wait.
            self.driver.execute_script("for (let i = 0; i < arguments[0]; i++) document.getElementById('bz-add').click()",
                                       degree + 1 - len(self.handles("bz")))
            self.settle()
            self.assertEqual(self.text("bz-degree"), str(degree))
            redraws, span, latencies, trips, phases = self.driver.execute_async_script(self.DRAG_60HZ, 60)
            self.assertGreater(len(latencies), 3)
            med = lambda xs: sorted(xs)[len(xs) // 2]
            median = med(latencies)
            figures[degree] = median
            where = ", ".join(f"{k} {med([p[k] for p in phases]):.1f}" for k in ("server", "parse", "draw", "frame"))
            print(f"\nexplorer drag, a move per frame (de Casteljau view, degree {degree}): {redraws} redraws in 60 frames "
                  f"({span:.0f} ms: {60000 / span:.0f} frames and {1000 * redraws / span:.0f} redraws per second); "
                  f"update latency median {median:.1f} ms, "
                  f"max {max(latencies):.1f} ms; medians of its parts: {where} ms (frame: the next frame's "
                  f"style, layout and paint, after the update); answer {med([p['bytes'] for p in phases])} bytes",
                  file=sys.stderr)
        # 500 ms: generous (medians of 9-30 ms measured on the loaded 2-core machine): catches
        # a return to queued or unbatched requests, or an update whose cost explodes with the
        # degree, without flaking on a busy machine.
        for degree, median in figures.items():
            self.assertLess(median, 500, f"degree {degree}")
        # Back to the example, for the tests after this one.
        self.driver.execute_script("for (let i = 0; i < 6; i++) document.getElementById('bz-remove').click()")
        self.settle()


def blossom(points, args):
    """The blossom of the Bézier curve on points at args (one per degree): de Casteljau's
    construction with level k at args[k] (written here)."""
    level = [list(p) for p in points]
    for u in args:
        level = [[(1 - u) * a + u * b for a, b in zip(level[i], level[i + 1])] for i in range(len(level) - 1)]
    return level[0]


def de_boor(points, knots, p, u):
    """De Boor's construction at u (written here, the NURBS Book's algorithm A3.1 with the
    multiplicity s of u): the levels 0 .. p - s, level r the points d_i^r, i = k-p+r .. k-s."""
    n = len(points)
    k = max(i for i in range(p, n) if knots[i] <= u)
    s = knots.count(u)
    levels = [[list(points[i]) for i in range(k - p, k - s + 1)]]
    for r in range(1, p - s + 1):
        prev, first = levels[-1], k - p + r - 1
        level = []
        for i in range(k - p + r, k - s + 1):
            a = (u - knots[i]) / (knots[i + p - r + 1] - knots[i])
            level.append([(1 - a) * x + a * y for x, y in zip(prev[i - 1 - first], prev[i - first])])
        levels.append(level)
    return levels


if __name__ == "__main__":
    test_serve.BINARY = sys.argv.pop(1)
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        print(f"SKIP: chromium ({CHROMIUM}) or chromedriver ({CHROMEDRIVER}) is not installed "
              "(scripts/install-deps.sh installs both)")
        sys.exit(SKIP)
    unittest.main()
