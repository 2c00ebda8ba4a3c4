"""Label placement in the gallery's figures: no text box overlaps another text box or a
drawn curve. Used by check_gallery.py on every figure of the generated page.

A text's box is estimated from its font size and its characters (advance widths of a
Helvetica-like sans in em, a little generous, so that the check errs towards finding a
collision), its anchor (start, middle, end) and its baseline: from 0.75 em above the
baseline to 0.22 em below. A drawn curve is a stroked <path> or <polyline> at least 1 px
wide, dashed or not, and the outline of a stroked <polygon> or <rect> (curves, graphs, control polygons, construction lines, boxes; axes, ticks,
grid lines, arrows and legend swatches are <line> elements, and hairlines below 1 px are
faint guides a label may cross), flattened into short segments. Boxes are shrunk by a small margin before the tests (text edges touching a
curve's antialiased edge are not collisions a reader sees)."""
import math
import re

SVG = "{http://www.w3.org/2000/svg}"

# Advance widths in em (apps/gallery/draw.hpp's text_width_px places labels with the same
# estimate, about DejaVu Sans's, the widest fallback font). Characters not listed take 0.72
# (capitals), 0.62 (other ASCII) or 0.6 (symbols, Greek, arrows);
# sub- and superscripts (U+2070..U+209F, ¹ ² ³, ᵢ, ⱼ) 0.36.
_WIDTHS = {}
for chars, w in (("ijl.,:;'|!", 0.28), ("frtI()[]-/ ", 0.36), ("mwMW", 0.9), ("\u00b9\u00b2\u00b3\u1d62\u2c7c", 0.36)):
    for ch in chars:
        _WIDTHS[ch] = w


def _char_width(ch):
    if ch in _WIDTHS:
        return _WIDTHS[ch]
    if 0x2070 <= ord(ch) <= 0x209F:
        return 0.36
    if ch.isascii():
        return 0.72 if ch.isupper() else 0.62
    return 0.6


ASCENT, DESCENT = 0.75, 0.22
# Margins in px: a box is shrunk by this much on each side before a test.
LABEL_MARGIN = 0.5
CURVE_MARGIN = 1.0


def text_width(s, size):
    return size * sum(_char_width(ch) for ch in s)


def text_box(el, offset=(0.0, 0.0)):
    """(x0, y0, x1, y1) of a <text> element in the SVG's coordinates (moved by offset), or
    None for an empty text."""
    s = "".join(el.itertext())
    if not s.strip():
        return None
    size = float(el.get("font-size", "16"))
    x, y = float(el.get("x", "0")) + offset[0], float(el.get("y", "0")) + offset[1]
    w = text_width(s, size)
    anchor = el.get("text-anchor", "start")
    x0 = x - w / 2 if anchor == "middle" else (x - w if anchor == "end" else x)
    return (x0, y - ASCENT * size, x0 + w, y + DESCENT * size)


def walk(el, offset=(0.0, 0.0)):
    """Every element under el with the offset of its coordinates: the sum of the
    translate() transforms of the groups around it (the only transform the gallery's
    figures use; another kind is an error)."""
    t = el.get("transform")
    if t:
        m = re.fullmatch(r"\s*translate\(\s*([-+.\deE]+)(?:[\s,]+([-+.\deE]+))?\s*\)\s*", t)
        if not m:
            raise ValueError(f"label_boxes: unsupported transform {t!r}")
        offset = (offset[0] + float(m.group(1)), offset[1] + float(m.group(2) or 0))
    yield el, offset
    for child in el:
        yield from walk(child, offset)


def _numbers(s):
    return [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", s)]


def path_polylines(d, steps=12):
    """The subpaths of SVG path data as polylines (curves sampled at `steps` points; the
    commands SvgDocument writes, M L H V Q C Z, and arcs A as their chords)."""
    out, cur, start = [], None, (0.0, 0.0)
    x = y = 0.0
    for cmd, args in re.findall(r"([MmLlHhVvCcQqAaZz])([^MmLlHhVvCcQqAaZz]*)", d):
        v = _numbers(args)
        rel = cmd.islower()
        c = cmd.upper()
        if c == "Z":
            if cur:
                cur.append(start)
            x, y = start
            cur = None
            continue
        arity = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "Q": 4, "A": 7}[c]
        for k in range(0, len(v) - arity + 1, arity):
            a = v[k:k + arity]
            if c in "ML":
                p = (x + a[0], y + a[1]) if rel else (a[0], a[1])
                if c == "M" and k == 0:
                    cur = [p]
                    out.append(cur)
                    start = p
                else:
                    if cur is None:
                        cur = [(x, y)]
                        out.append(cur)
                    cur.append(p)
                x, y = p
                continue
            if cur is None:
                cur = [(x, y)]
                out.append(cur)
            if c == "H":
                x = x + a[0] if rel else a[0]
                cur.append((x, y))
            elif c == "V":
                y = y + a[0] if rel else a[0]
                cur.append((x, y))
            elif c == "A":
                x, y = (x + a[5], y + a[6]) if rel else (a[5], a[6])
                cur.append((x, y))
            else:
                pts = [(x, y)] + [((x + a[i], y + a[i + 1]) if rel else (a[i], a[i + 1])) for i in range(0, len(a), 2)]
                for j in range(1, steps + 1):
                    t = j / steps
                    q = pts
                    while len(q) > 1:  # de Casteljau on the page points
                        q = [((1 - t) * q[i][0] + t * q[i + 1][0], (1 - t) * q[i][1] + t * q[i + 1][1]) for i in range(len(q) - 1)]
                    cur.append(q[0])
                x, y = pts[-1]
    return [p for p in out if len(p) > 1]


def curve_polylines(root):
    """The drawn curves of an SVG element tree: [(description, polyline)]."""
    out = []
    for el, (ox, oy) in walk(root):
        tag = el.tag.replace(SVG, "")
        if tag not in ("path", "polyline", "polygon", "rect"):
            continue
        stroke = el.get("stroke", "none")
        if stroke == "none" or float(el.get("stroke-width", "1")) < 1:
            continue
        if tag == "path":
            lines = path_polylines(el.get("d", ""))
        elif tag == "rect":  # its outline (a filled box's edge is drawn as a curve is)
            x, y = float(el.get("x", "0")), float(el.get("y", "0"))
            w, h = float(el.get("width", "0")), float(el.get("height", "0"))
            lines = [[(x, y), (x + w, y), (x + w, y + h), (x, y + h), (x, y)]]
        else:
            v = _numbers(el.get("points", ""))
            lines = [list(zip(v[0::2], v[1::2]))]
            if tag == "polygon" and lines[0]:
                lines[0].append(lines[0][0])  # closed
        for line in lines:
            out.append((f"<{tag} stroke={stroke}>", [(x + ox, y + oy) for x, y in line]))
    return out


def _shrunk(b, m):
    return (b[0] + m, b[1] + m, b[2] - m, b[3] - m)


def boxes_overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def segment_hits_box(p, q, b):
    """Whether the segment pq meets the box b (Liang-Barsky clipping)."""
    t0, t1 = 0.0, 1.0
    dx, dy = q[0] - p[0], q[1] - p[1]
    for den, num in ((-dx, p[0] - b[0]), (dx, b[2] - p[0]), (-dy, p[1] - b[1]), (dy, b[3] - p[1])):
        if den == 0:
            if num < 0:
                return False
            continue
        r = num / den
        if den < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return False
    return True


def label_collisions(root):
    """Descriptions of every label overlapping another label or crossing a drawn curve."""
    labels = []
    for el, offset in walk(root):
        if el.tag != SVG + "text":
            continue
        box = text_box(el, offset)
        if box is not None:
            labels.append(("".join(el.itertext()), box))
    found = []
    for i, (s, a) in enumerate(labels):
        for t, b in labels[i + 1:]:
            if boxes_overlap(_shrunk(a, LABEL_MARGIN), _shrunk(b, LABEL_MARGIN)):
                found.append(f"label {s!r} overlaps label {t!r}")
    curves = curve_polylines(root)
    for s, a in labels:
        box = _shrunk(a, CURVE_MARGIN)
        if box[0] >= box[2] or box[1] >= box[3]:
            continue
        for what, line in curves:
            xs = [p[0] for p in line]
            ys = [p[1] for p in line]
            if max(xs) < box[0] or min(xs) > box[2] or max(ys) < box[1] or min(ys) > box[3]:
                continue
            if any(segment_hits_box(line[k], line[k + 1], box) for k in range(len(line) - 1)):
                found.append(f"label {s!r} crosses a curve {what}")
                break
    return found


def _self_test():
    """The geometry on hand-made cases (run by check_gallery.py before the page)."""
    assert segment_hits_box((0, 0), (10, 10), (4, 4, 6, 6))
    assert not segment_hits_box((0, 10), (3, 0), (4, 4, 6, 6))
    assert segment_hits_box((5, 0), (5, 10), (4, 4, 6, 6))
    assert boxes_overlap((0, 0, 2, 2), (1, 1, 3, 3)) and not boxes_overlap((0, 0, 1, 1), (2, 0, 3, 1))
    line = path_polylines("M0 0C0 10 10 10 10 0")[0]
    # The cubic's midpoint is (5, 7.5).
    assert any(math.dist(p, (5, 7.5)) < 1e-9 for p in line)
    assert path_polylines("M0 0L1 0 1 1Z")[0] == [(0, 0), (1, 0), (1, 1), (0, 0)]
    # A filled box's outline and a polygon's closing edge count as drawn lines; the box's
    # inside does not (a label may sit on a shaded area).
    import xml.etree.ElementTree as ET
    svg = ('<svg xmlns="http://www.w3.org/2000/svg">'
           '<rect x="10" y="10" width="100" height="50" fill="#eee" stroke="#000" stroke-width="1.4"/>'
           '<polygon points="200,0 300,0 300,100" fill="none" stroke="#000" stroke-width="1.5"/>'
           '<text x="60" y="14" font-size="11">u=1</text>'
           '<text x="60" y="40" font-size="11">u=2</text>'
           '<text x="245" y="52" font-size="11">P</text></svg>')
    found = label_collisions(ET.fromstring(svg))
    assert found == ["label 'u=1' crosses a curve <rect stroke=#000>", "label 'P' crosses a curve <polygon stroke=#000>"], found
