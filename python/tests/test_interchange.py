"""The interchange commands through the Python package: import_svg, to_svg_path, glyph
(generated from the command registry). Expected values are closed forms and the font's
own metrics; the commands' full checks are the command-line tests."""

import os

import numpy as np
import pytest

import casteljau

DEJAVU = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def test_import_svg_arc_is_exact_and_the_subpath_closes():
    # A line, then a half circle of radius 5 about (15, 0) from (10, 0) to (20, 0), closed.
    r = casteljau.import_svg(d="M0 0 L10 0 A5 5 0 0 1 20 0 Z")
    assert len(r.paths) == 1
    p = r.paths[0]
    assert p.id is None
    assert list(p.closed) == [True]
    (path,) = p.subpaths
    lo, hi = path.domain
    ts = np.linspace(lo, hi, 401)
    pts = path(ts)
    np.testing.assert_allclose(pts[0], [0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(pts[-1], pts[0], atol=1e-12)
    # Points of the arc piece lie on the circle (rational quadratics: exact up to rounding).
    on_arc = np.abs(np.hypot(pts[:, 0] - 15.0, pts[:, 1])) - 5.0
    arc = (pts[:, 0] > 10.0 + 1e-9) & (pts[:, 0] < 20.0 - 1e-9) & (np.abs(pts[:, 1]) > 1e-9)
    assert arc.sum() > 10
    # Rounding of the rational evaluation on coordinates of size 20: a few ulp of 20.
    assert np.max(np.abs(on_arc[arc])) < 1e-13


def test_import_svg_error_names_the_offset():
    with pytest.raises(casteljau.Error, match=r"d\[5\]: expected a number after 'L'"):
        casteljau.import_svg(d="M0 0L")


def test_to_svg_path_of_a_cubic_is_exact():
    c = casteljau.Bezier([[0, 0], [1, 2], [3, 2], [4, 0]])
    r = c.to_svg_path()
    assert r.exact
    assert r.d == "M 0 0 C 1 2 3 2 4 0"


@pytest.mark.skipif(not os.path.exists(DEJAVU), reason="fonts-dejavu-core not installed")
def test_glyph_advance_and_closed_contours():
    # DejaVu Sans: unitsPerEm 2048, the advance width of 'A' 1401 units (its hmtx entry).
    size = 1000.0
    g = casteljau.glyph(font=DEJAVU, text="A", size=size)
    (a,) = g.glyphs
    assert a.char == "A"
    np.testing.assert_allclose(a.origin, [0.0, 0.0])
    assert a.advance == pytest.approx(1401 * size / 2048, rel=1e-15)
    # The outline: the contours' segments in one path (the library's Path holds segments, so
    # the contract's path of closed paths arrives flattened). Split it where a segment does
    # not start at the previous end: two contours (the outer shape and the counter), each
    # ending where it starts.
    segments = [s["points"] for s in a.curve.to_json()["segments"]]
    contours = [[segments[0]]]
    for seg in segments[1:]:
        if np.allclose(seg[0], contours[-1][-1][-1], atol=1e-9):
            contours[-1].append(seg)
        else:
            contours.append([seg])
    assert len(contours) == 2
    for contour in contours:
        np.testing.assert_allclose(contour[-1][-1], contour[0][0], atol=1e-9)
