#!/usr/bin/python3
"""Black-box tests of `import_svg`: the response's shape and errors, and the imported
curves checked against an independent reading of the same drawings.

Oracle for real drawings: librsvg (`rsvg-convert`, Debian librsvg2-bin) renders the
original document; the test writes a second document from the imported curves alone (one
<path> per element: its bezier segments as L/Q/C with every digit, its rational arcs
evaluated here from their definition as dense polylines, Z for closed subpaths) in the same
page frame (the original root's width, height and viewBox), and librsvg renders that too.
Both are drawn as plain black fills (an author style sheet with !important forces fill,
nonzero rule, no stroke, opacity, clip, mask or filter on the original), so the pixels
differ only where the geometry does. The drawings: a document written here that uses every
element and transform kind, and a sample of the Adwaita icon theme's scalable icons (real
files made by Inkscape and svgo: compact relative path data, arcs, transforms).

Usage: test_import_svg.py PATH_TO_CASTELJAU [unittest options]
"""
import glob
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET
import zlib

import numpy as np

import test_cli
from test_cli import CliTest

SVG_NS = "http://www.w3.org/2000/svg"
ICONS = "/usr/share/icons/Adwaita/scalable"

# The style that turns any drawing into its black fill silhouette.
SILHOUETTE = ("* { fill: #000 !important; fill-opacity: 1 !important; fill-rule: nonzero !important; "
              "stroke: none !important; opacity: 1 !important; clip-path: none !important; "
              "mask: none !important; filter: none !important; marker: none !important; display: inline !important; "
              "visibility: visible !important } "
              # What import_svg skips (text, images, references) is not drawn either.
              "text, image, use, switch, foreignObject { display: none !important }")

# A document with every element kind, nested transforms of all six functions, a nested
# svg viewport, rounded rects with auto radii, arcs with every flag pair and radii scaled up.
DRAWING = """<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64" viewBox="0 0 64 64">
  <g transform="translate(32 32) rotate(30) scale(1.2 0.8)">
    <rect x="-20" y="-14" width="24" height="18" rx="5" ry="3"/>
    <circle cx="12" cy="10" r="7"/>
  </g>
  <ellipse cx="40" cy="12" rx="12" ry="6" transform="skewX(20)"/>
  <rect x="50" y="24" width="12" height="10" rx="9" transform="skewY(-15) rotate(10 56 29)"/>
  <path d="M4 60a8 5 30 1 1 12-6l4 0q2-6 6 0t6 0s3-4 6 0c1 2 3 2 4 0z"/>
  <path d="M6 40 A4 4 0 0 0 14 40 A4 4 0 1 1 22 40 a4 4 0 0 1 8 0 a 4 4 0 1 0 8 0 z"/>
  <path d="M40 40 A 1 1 0 0 1 50 40 Z M52 50 H60 V56 h-4 v2 Z"/>
  <polygon points="40,62 48,44 56,62 52,54 44,54"/>
  <polyline points="2,2 10,4 6,10"/>
  <line x1="0" y1="0" x2="10" y2="10"/>
  <svg x="2" y="20" width="12" height="12" viewBox="0 0 10 10"><circle cx="5" cy="5" r="4"/></svg>
  <g transform="matrix(0.9 0.1 -0.2 1.1 20 20)"><path d="M0 0h6v6h-6z M1 1v4h4v-4z"/></g>
</svg>
"""


def read_png_alpha(path):
    """The alpha channel of an 8-bit RGBA PNG (what rsvg-convert writes) as a float array
    in [0, 1]: chunks, zlib, the five scanline filters (PNG specification, section 9)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour == 6 and interlace == 0, (depth, colour, interlace)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride, bpp = width * 4, 4
    out = np.zeros((height, stride), dtype=np.int64)
    prev = np.zeros(stride, dtype=np.int64)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)], dtype=np.uint8).astype(np.int64)
        if f == 0:
            cur = line
        elif f == 2:
            cur = (line + prev) % 256
        else:
            cur = np.zeros(stride, dtype=np.int64)
            for x in range(stride):
                a = cur[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                if f == 1:
                    pred = a
                elif f == 3:
                    pred = (a + b) // 2
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[x] = (line[x] + pred) % 256
        out[y] = cur
        prev = cur
    return out.reshape(height, width, 4)[:, :, 3] / 255.0


def read_text(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def rational_point(seg, t):
    """A bezier or rational_bezier segment at t, from the Bernstein definition."""
    P = seg["points"]
    n = len(P) - 1
    w = seg.get("weights", [1.0] * (n + 1))
    x = y = s = 0.0
    for i in range(n + 1):
        b = math.comb(n, i) * t ** i * (1 - t) ** (n - i) * w[i]
        x += b * P[i][0]
        y += b * P[i][1]
        s += b
    return x / s, y / s


def path_data(shape):
    """Path data for one imported element: L/Q/C exactly (repr keeps every digit), rational
    pieces as 256-point polylines (a quarter of an ellipse of radius r px then deviates by
    at most r (1 - cos(pi / 1024)) = 5e-6 r px)."""
    out = []
    for curve, closed in zip(shape["subpaths"], shape["closed"]):
        segs = curve["segments"]
        out.append("M %r %r" % tuple(segs[0]["points"][0]))
        for s in segs:
            P = s["points"]
            if s["type"] == "rational_bezier":
                for k in range(1, 257):
                    out.append("L %r %r" % rational_point(s, k / 256))
            else:
                letter = {2: "L", 3: "Q", 4: "C"}[len(P)]
                out.append(letter + " " + " ".join("%r %r" % tuple(p) for p in P[1:]))
        if closed:
            out.append("Z")
    return " ".join(out)


class PixelTest(CliTest):
    """The pixel comparison against librsvg (no tests of its own)."""

    # -----------------------------------------------------------------------------------
    # Pixels against librsvg

    def silhouettes(self, documents, size):
        """For each document (text): the alpha of librsvg's rendering of the original and of
        the document rebuilt from the imported curves, size x size px."""
        requests = "".join(json.dumps({"svg": d}) + "\n" for d in documents)
        rc, out, err = test_cli.run("import_svg", text=requests, args=("--jsonl",))
        self.assertEqual(rc, 0, err)
        responses = [json.loads(line) for line in out.splitlines()]
        self.assertEqual(len(responses), len(documents))
        ET.register_namespace("", SVG_NS)
        pairs = []
        with tempfile.TemporaryDirectory() as tmp:
            for k, (doc, resp) in enumerate(zip(documents, responses)):
                self.assertNotIn("error", resp, resp)
                root = ET.fromstring(doc)
                style = ET.Element("{%s}style" % SVG_NS)
                style.text = SILHOUETTE
                root.insert(0, style)
                frame = " ".join('%s="%s"' % (a, root.get(a)) for a in ("width", "height", "viewBox") if root.get(a))
                rebuilt = '<svg xmlns="%s" %s>\n' % (SVG_NS, frame) + "".join(
                    '<path fill="#000" d="%s"/>\n' % path_data(p) for p in resp["paths"] if p["subpaths"]) + "</svg>\n"
                images = []
                for name, text in (("original", ET.tostring(root, encoding="unicode")), ("rebuilt", rebuilt)):
                    src, png = os.path.join(tmp, "%d-%s.svg" % (k, name)), os.path.join(tmp, "%d-%s.png" % (k, name))
                    with open(src, "w") as f:
                        f.write(text)
                    subprocess.run(["rsvg-convert", "-w", str(size), "-h", str(size), "-o", png, src], check=True)
                    images.append(read_png_alpha(png))
                pairs.append((images[0], images[1], resp))
        return pairs

    def check_pixels(self, names, documents, size):
        worst_max = worst_local = 0.0
        for name, (a, b, resp) in zip(names, self.silhouettes(documents, size)):
            d = a - b
            # The signed difference averaged over each 3 x 3 window (zero padded): how much
            # more area one drawing covers than the other there, in units of 9 px^2.
            p = np.pad(d, 1)
            local = sum(p[i:i + d.shape[0], j:j + d.shape[1]] for i in range(3) for j in range(3)) / 9
            with self.subTest(drawing=name):
                self.assertGreater(a.sum(), 0.01 * size * size, "the drawing draws something")
                # Thresholds: librsvg (cairo) flattens curves within 0.1 px, and the rebuilt
                # document describes the same edges differently (arcs as polylines,
                # transforms applied to the control points), so an edge pixel's coverage
                # may differ by about a tenth (measured: at most 0.12 per pixel), while the
                # area covered near it hardly changes: these differences cancel in a 3 x 3
                # window (measured: at most 0.035, on the gallery's circles of radius 0.6 px).
                # A wrong control point, arc or transform moves whole edges: an edge moved
                # by 0.15 px along a window changes its area by 3 x 0.15 / 9 = 0.05, a
                # pixel crossed by the moved edge by up to 1 (every point moved by 0.05
                # user units, 0.2 to 0.4 px here, fails). Max 0.25 per pixel, 0.05 per
                # window.
                self.assertLessEqual(np.abs(d).max(), 0.25)
                self.assertLessEqual(np.abs(local).max(), 0.05)
            worst_max = max(worst_max, np.abs(d).max())
            worst_local = max(worst_local, np.abs(local).max())
        print("\n%d drawings at %d px: largest pixel difference %.4f, largest 3 x 3 window difference %.4f"
              % (len(names), size, worst_max, worst_local), file=sys.stderr)


class ImportSvgTest(PixelTest):
    def import_svg(self, **req):
        return self.ok("import_svg", req)

    # -----------------------------------------------------------------------------------
    # Shape of the response and errors

    def test_path_data_alone(self):
        r = self.import_svg(d="M0 0 h1 v1 z m2 0 l1 1")
        self.assertEqual(r["skipped"], [])
        self.assertEqual(len(r["paths"]), 1)
        p = r["paths"][0]
        self.assertIsNone(p["id"])
        self.assertEqual(p["closed"], [True, False])
        first = p["subpaths"][0]
        self.assertEqual(first["type"], "path")
        self.assertEqual([s["points"] for s in first["segments"]],
                         [[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, 1], [0, 0]]])
        # A relative m after z starts from the closed subpath's start.
        self.assertEqual(p["subpaths"][1]["segments"][0]["points"], [[2, 0], [3, 1]])

    def test_arc_is_exact_rational_quadratic(self):
        # A half circle of radius 1 about the origin from (1, 0) to (-1, 0), sweep 1
        # (positive angles): two quarters through (0, 1); weights cos(45 degrees).
        r = self.import_svg(d="M1 0 A1 1 0 0 1 -1 0")
        segs = r["paths"][0]["subpaths"][0]["segments"]
        self.assertEqual([s["type"] for s in segs], ["rational_bezier"] * 2)
        for s in segs:
            self.assertAlmostEqual(s["weights"][1], math.sqrt(0.5), places=15)
            for k in range(9):
                x, y = rational_point(s, k / 8)
                self.assertAlmostEqual(math.hypot(x, y), 1, places=14)  # on the circle
                self.assertGreaterEqual(y, -1e-15)  # the upper half
        self.assertEqual(segs[0]["points"][0], [1, 0])
        self.assertEqual(segs[1]["points"][2], [-1, 0])
        # The curves are curve JSON the other commands take: the length of the half circle.
        length = self.ok("length", {"curve": r["paths"][0]["subpaths"][0]})["length"]
        self.assertAlmostEqual(length, math.pi, places=9)

    def test_document_ids_skipped_and_order(self):
        svg = ('<svg xmlns="http://www.w3.org/2000/svg"><text id="t">x</text><g id="g" transform="translate(1 2)">'
               '<circle id="c" r="1"/><line x1="0" y1="0" x2="1" y2="0"/></g><use href="#c"/><image id="i"/></svg>')
        r = self.import_svg(svg=svg)
        self.assertEqual([p["id"] for p in r["paths"]], ["c", None])
        self.assertEqual(r["skipped"], [{"element": "text", "id": "t"}, {"element": "use", "id": None},
                                        {"element": "image", "id": "i"}])
        self.assertEqual(r["paths"][1]["subpaths"][0]["segments"][0]["points"], [[1, 2], [2, 2]])
        self.assertEqual(r["paths"][0]["closed"], [True])

    def test_help_example_is_the_program_output(self):
        # A consistency check of the help text (as test_cli.py's for the other commands).
        rc, out, err = test_cli.run("import_svg", args=["--help"])
        self.assertEqual((rc, err), (0, ""))
        lines = out.splitlines()
        i = next(i for i, l in enumerate(lines) if l.strip().startswith("echo '"))
        request = lines[i].strip()[len("echo '"):lines[i].strip().index("' |")]
        self.assertEqual(json.loads(test_cli.run("import_svg", text=request)[1]), json.loads(lines[i + 1]))

    def test_errors(self):
        self.bad("import_svg", {"d": "M 10 10 L 20"}, "d[12]", contains="expected a number after 'L'")
        self.bad("import_svg", {"svg": '<svg><path/><path id="p" d="M 10 10 L 20"/></svg>'}, "svg.paths[1](#p).d[12]",
                 contains="expected a number after 'L'")
        self.bad("import_svg", {"svg": "<svg><path d='M 1 1 L 2 2 X'/></svg>"}, "svg.paths[0].d[12]", contains="'X'")
        self.bad("import_svg", {"svg": "<svg><rect width='5em' height='1'/></svg>"}, "svg.paths[0].width", contains="relative")
        self.bad("import_svg", {"svg": "<svg><polyline points='1 2 3'/></svg>"}, "svg.paths[0].points", contains="odd")
        self.bad("import_svg", {"svg": "<svg><g transform='scale()'/></svg>"}, "svg.g[0].transform[6]", contains="scale")
        self.bad("import_svg", {"svg": "<svg><path></svg>"}, "svg[13]", contains="malformed XML")
        self.bad("import_svg", {"svg": "<html/>"}, "svg", contains="root")
        self.bad("import_svg", {}, "svg", contains="missing")
        self.bad("import_svg", {"svg": "<svg/>", "d": "M0 0"}, "d", contains="not both")
        self.bad("import_svg", {"d": 5}, "d", contains="string")
        self.bad("import_svg", {"d": "M 1e400 0"}, "d[2]", contains="out of range")

    @unittest.skipUnless(shutil.which("rsvg-convert"), "rsvg-convert (librsvg2-bin) is not installed")
    def test_pixels_every_element_kind(self):
        self.check_pixels(["drawing"], [DRAWING], 256)

    def test_render_output_read_back(self):
        # render maps the model to the page by x -> q + s (x - c) with the y axis flipped:
        # the cubic comes back as s (x, -y) + offset, s and the offset found from its end
        # points; the inner control points must then agree to the 0.001 px the writer
        # rounds to (two roundings: 2e-3).
        P = [[0, 0], [1, 2], [3, 2], [4, 0]]
        rc, out, err = test_cli.run("render", {"curve": {"type": "bezier", "points": P}, "control_polygon": False})
        self.assertEqual(rc, 0, err)
        r = self.import_svg(svg=out)
        cubics = [s["points"] for p in r["paths"] for c in p["subpaths"] for s in c["segments"] if len(s["points"]) == 4]
        self.assertEqual(len(cubics), 1, r)
        Q = cubics[0]
        scale = (Q[3][0] - Q[0][0]) / (P[3][0] - P[0][0])
        self.assertGreater(scale, 0)
        for p, q in zip(P, Q):
            self.assertAlmostEqual(q[0], Q[0][0] + scale * (p[0] - P[0][0]), delta=2e-3)
            self.assertAlmostEqual(q[1], Q[0][1] - scale * (p[1] - P[0][1]), delta=2e-3)

    @unittest.skipUnless(shutil.which("rsvg-convert"), "rsvg-convert (librsvg2-bin) is not installed")
    def test_pixels_render_output(self):
        # The program's own SVG (render: the gallery's writer) read back: Bézier pieces as
        # L/Q/C, rational ones flattened, control points as circles, the axes as lines.
        cubic = {"type": "bezier", "points": [[0, 0], [1, 2], [3, 2], [4, 0]]}
        h = math.sqrt(0.5)  # a half circle of radius 2 about (1, 1): two exact quarters
        circle = {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 2, 2, 2],
                  "points": [[3, 1], [3, 3], [1, 3], [-1, 3], [-1, 1]], "weights": [1, h, 1, h, 1]}
        path = {"type": "path", "segments": [cubic, {"type": "bezier", "points": [[4, 0], [5, -1], [6, 1]]}]}
        requests = [{"curve": cubic, "axes": True}, {"curve": circle, "width": 300, "height": 300},
                    {"curves": [path, circle], "control_polygon": False}]
        documents = []
        for req in requests:
            rc, out, err = test_cli.run("render", dict(req, background="none"))
            self.assertEqual(rc, 0, err)
            documents.append(out)
        self.check_pixels(["render %d" % k for k in range(len(documents))], documents, 256)

    @unittest.skipUnless(shutil.which("rsvg-convert") and os.path.isdir(ICONS), "no rsvg-convert or no Adwaita icons")
    def test_pixels_adwaita_icons(self):
        files = sorted(glob.glob(os.path.join(ICONS, "*", "*.svg")))
        # Every 32nd icon (about 20: two rsvg-convert runs each) and the ones with
        # transforms, arcs, clips or masks.
        sample = files[::32] + [f for f in files if any(k in read_text(f) for k in ("transform=", " a ", "clip-path", "<mask"))]
        sample = sorted(set(sample))
        self.check_pixels([os.path.basename(f) for f in sample], [read_text(f) for f in sample], 128)


class GalleryReadBackTest(PixelTest):
    """The gallery's page (casteljau-gallery, CASTELJAU_GALLERY: set by ctest
    gallery.import_svg) read back: every figure's inline SVG imported and compared with
    librsvg's rendering of it."""

    @unittest.skipUnless(shutil.which("rsvg-convert") and os.environ.get("CASTELJAU_GALLERY"),
                         "no rsvg-convert, or CASTELJAU_GALLERY is not set (ctest gallery.import_svg sets it)")
    def test_gallery_figures(self):
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([os.environ["CASTELJAU_GALLERY"], tmp], check=True, timeout=300)
            page = read_text(os.path.join(tmp, "index.html"))
        figures, at = [], 0
        while (start := page.find("<svg ", at)) != -1:
            end = page.index("</svg>", start) + len("</svg>")
            figures.append(page[start:end])
            at = end
        self.assertGreaterEqual(len(figures), 10)
        for f in figures:
            ET.fromstring(f)  # each figure is one XML document (no nested svg cut short)
        # Every other figure (about 14: the writer's forms recur from figure to figure),
        # to keep the test near 5 s of CPU.
        self.check_pixels(["figure %d" % k for k in range(0, len(figures), 2)], figures[::2], 256)


if __name__ == "__main__":
    test_cli.BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=1)
