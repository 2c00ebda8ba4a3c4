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
import os
import shutil
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_serve  # noqa: E402  (the server fixture)

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
SKIP = 77  # ctest's SKIP_RETURN_CODE for this test


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

        cls.server = test_serve.Server()
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

    def points(self, view):
        return [json.loads(h.get_attribute("data-point")) for h in self.handles(view)]

    def drag(self, element, dx, dy, steps=4):
        """Mouse drag by (dx, dy) CSS pixels in steps (pointerdown, pointermoves, pointerup)."""
        from selenium.webdriver.common.action_chains import ActionChains
        chain = ActionChains(self.driver).click_and_hold(element)
        for _ in range(steps):
            chain = chain.move_by_offset(dx / steps, dy / steps)
        chain.release().perform()

    def touch_drag(self, element, dx, dy):
        """The same with a touch pointer."""
        from selenium.webdriver.common.actions import interaction
        from selenium.webdriver.common.actions.action_builder import ActionBuilder
        from selenium.webdriver.common.actions.pointer_input import PointerInput
        actions = ActionBuilder(self.driver, mouse=PointerInput(interaction.POINTER_TOUCH, "finger"))
        rect = element.rect
        x, y = rect["x"] + rect["width"] / 2, rect["y"] + rect["height"] / 2
        actions.pointer_action.move_to_location(int(x), int(y)).pointer_down()
        for k in range(1, 6):
            actions.pointer_action.move_to_location(int(x + dx * k / 5), int(y + dy * k / 5))
        actions.pointer_action.pointer_up()
        actions.perform()

    def curve_points(self, element_id):
        return json.loads(self.driver.find_element("id", element_id).get_attribute("data-points"))

    def text(self, element_id):
        return self.driver.find_element("id", element_id).text

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
        self.driver.save_screenshot("explorer-bezier.png")
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
        from selenium.webdriver.support.ui import WebDriverWait
        if not self.driver.current_url.startswith(self.base):
            self.driver.get(self.base)
        self.driver.find_element("css selector", f'nav a[data-view="{name}"]').click()
        WebDriverWait(self.driver, 10, poll_frequency=0.05).until(
            lambda d: d.find_element("id", "view-" + name).get_attribute("hidden") is None)
        self.settle()

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
        marks = json.loads(self.driver.find_element("id", "qr-intersections").get_attribute("data-points"))
        self.assertEqual(marks, [x["point"] for x in inter])
        self.assertGreater(len(marks), 0)  # the example's curves cross
        self.assertEqual(self.text("qr-intersections-text"), "; ".join(
            x["kind"] + " at t = (" + ", ".join(fmt(v) for v in x["t"]) + ")" for x in inter))
        box = json.loads(self.driver.find_element("id", "qr-bounds-box").get_attribute("data-box"))
        self.assertEqual(box, self.api("bounds", {"curve": A}))
        self.assertEqual(self.text("qr-length"), fmt(self.api("length", {"curve": A})["length"]))
        # Segment counts at the page's tolerance 10^-1.5 (a count does not hinge on the last
        # bit of the tolerance as the page's Math.pow computes it).
        for method in ("optimal", "subdivision", "uniform"):
            n = len(self.api("flatten", {"curve": A, "tolerance": 10 ** -1.5, "method": method})["points"]) - 1
            self.assertEqual(self.text("qr-count-" + method), str(n), method)
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


if __name__ == "__main__":
    test_serve.BINARY = sys.argv.pop(1)
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        print(f"SKIP: chromium ({CHROMIUM}) or chromedriver ({CHROMEDRIVER}) is not installed "
              "(scripts/install-deps.sh installs both)")
        sys.exit(SKIP)
    unittest.main()
