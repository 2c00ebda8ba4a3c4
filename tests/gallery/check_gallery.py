"""Runs casteljau-gallery into a temporary directory and checks the page it writes:
index.html exists, holds the required figure captions, every inline <svg> parses as XML
and has no NaN or infinite number, no label box overlaps another label or a drawn curve
(label_boxes.py), the links to the explorer name views it has, and the page is
self-contained (no scripts, no external resources). Usage: check_gallery.py
PATH/TO/casteljau-gallery"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import label_boxes  # noqa: E402

# The checklist of docs/gallery.md: one caption title per required figure.
REQUIRED_CAPTIONS = [
    "Bernstein basis polynomials",
    "de Casteljau construction",
    "Subdivision",
    "Degree elevation",
    "Convex hull property",
    "Affine invariance",
    "Continuity of a composite curve",
    "Rational quarter circle",
    "Cubic spline end conditions",
    "Monotone interpolation against spline overshoot",
]

# A NaN or infinity as C++ streams or to_chars would write it, as a whole word.
BAD_NUMBER = re.compile(r"(?<![A-Za-z])[-+]?(nan|inf|infinity)(?![A-Za-z])", re.IGNORECASE)


def main() -> int:
    gallery = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "nested" / "out"  # the program creates missing directories
        run = subprocess.run([gallery, str(out)], capture_output=True, text=True, timeout=120)
        if run.returncode != 0:
            print(f"casteljau-gallery exited with {run.returncode}: {run.stderr}")
            return 1
        if run.stdout or run.stderr:
            failures.append(f"the program should print nothing, printed {run.stdout!r} {run.stderr!r}")
        page_path = out / "index.html"
        if not page_path.is_file():
            print(f"{page_path} was not written")
            return 1
        page = page_path.read_text(encoding="utf-8")

    captions = re.findall(r"<figcaption>(.*?)</figcaption>", page, re.DOTALL)
    for title in REQUIRED_CAPTIONS:
        if not any(title in c for c in captions):
            failures.append(f"no figure caption contains {title!r}")
    for c in captions:
        # The page writes each title once ("Figure N. title"); a caption repeating it reads twice.
        title = re.match(r'<span class="title">Figure \d+\. (.*?)</span>(.*)', c, re.DOTALL)
        if not title or 'class="title"' in title.group(2) or title.group(2).lstrip().startswith(title.group(1)):
            failures.append(f"caption {c[:60]!r}: the title once, then text that does not repeat it")
    figures = re.findall(r"<figure\b.*?</figure>", page, re.DOTALL)
    if len(figures) < len(REQUIRED_CAPTIONS):
        failures.append(f"only {len(figures)} figures")

    label_boxes._self_test()
    svgs = re.findall(r"<svg\b.*?</svg>", page, re.DOTALL)
    if len(svgs) != len(figures):
        failures.append(f"{len(svgs)} <svg> elements for {len(figures)} figures")
    for i, svg in enumerate(svgs):
        try:
            root = ET.fromstring(svg)
        except ET.ParseError as e:
            failures.append(f"svg {i + 1} is not well-formed XML: {e}")
            continue
        if root.tag != "{http://www.w3.org/2000/svg}svg":
            failures.append(f"svg {i + 1}: root element is {root.tag}")
        if len(list(root.iter())) < 10:
            failures.append(f"svg {i + 1} draws almost nothing")
        for el in root.iter():
            for name, value in el.attrib.items():
                if BAD_NUMBER.search(value):
                    failures.append(f"svg {i + 1}: <{el.tag}> {name}={value[:80]!r} holds NaN or inf")
        # Every label clear of the other labels and of the drawn curves (label_boxes.py).
        for problem in label_boxes.label_collisions(root):
            failures.append(f"figure {i + 1}: {problem}")

    if re.search(r"<script\b", page, re.IGNORECASE):
        failures.append("the page has a script")
    # Links out go only to the explorer's views (make explorer: 127.0.0.1:8080/#VIEW), each
    # a view the explorer page has (apps/explorer/index.html, data-view).
    explorer = re.findall(r"""<a class="live" href="http://127\.0\.0\.1:8080/#([a-z]+)">""", page)
    index_html = Path(__file__).resolve().parents[2] / "apps" / "explorer" / "index.html"
    views = set(re.findall(r'data-view="([a-z]+)"', index_html.read_text(encoding="utf-8")))
    for view in explorer:
        if view not in views:
            failures.append(f"a figure links to the explorer view {view!r}, which the explorer does not have")
    if len(explorer) < len(figures):
        failures.append(f"only {len(explorer)} of {len(figures)} figures link to the explorer")
    external = re.findall(r"""(?:src|href)\s*=\s*["'](?!#|http://127\.0\.0\.1:8080/#)[^"']*""", page)
    if external or "@import" in page or "url(" in page:
        failures.append(f"the page loads external resources: {external[:3]}")

    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"ok: {len(figures)} figures, {len(svgs)} inline SVGs, all required captions, labels clear, "
              f"{len(explorer)} links to the explorer")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
