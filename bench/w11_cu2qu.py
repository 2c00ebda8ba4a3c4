#!/usr/bin/python3
"""W11 (quadratic half) for fonttools' cu2qu (curve_to_quadratic, python3-fonttools): W3's
datasets, read from the raw float64 files the W3 program writes with CASTELJAU_W11_DUMP=DIR
(x0 y0 ... x3 y3 per cubic), at tolerance 1e-3 and 1e-1 of the unit (random: the box, 100;
glyphs: the em, 2048). Writes Google Benchmark's JSON shape (`benchmarks`: [{name,
real_time, time_unit, counters...}]) with names W11/cu2qu/quadratic/<dataset>/<1e-3|1e-1>
(real_time: wall, cpu_time: time.process_time, medians of the repetitions; the cubics passed
as lists of (x, y) tuples, cu2qu's own interface) and counters segments, over_tolerance
(curves whose deviation exceeds 1.0001 x tol),
max_deviation: the same two-sided measure as bench/w3.cpp's quad_deviation (the cubic at
S = 64 + 16 k parameters to the chain, each quadratic at 65 parameters to the cubic, each
distance from every local minimum of the sampled distances refined by Newton's method).

Also counters dropped_real_ms and dropped_cpu_ms on the same rows (medians of the
repetitions): the same calls with each output dropped at once (`for c in curves:
curve_to_quadratic(c, tol)`) instead of kept in a list, timed in the same repetitions just
before the kept loop. Dropping times cu2qu 1.5-2x faster. (Counters, not rows of their own:
the names keep `<library>` a library's name.)

Usage: w11_cu2qu.py DUMP_DIR OUT_JSON [--repetitions N]
"""
import argparse
import json
import os
import sys
import time

import numpy as np

try:
    from fontTools.cu2qu import curve_to_quadratic
    from fontTools.cu2qu.cu2qu import COMPILED  # True where the Cython module is in use (Debian's build ships it)
except ImportError:
    curve_to_quadratic, COMPILED = None, None

UNIT = {"random": 100.0, "glyphs": 2048.0}


def chain(spline):
    """cu2qu's spline [p0, q1, ..., qn, p3] (on-curve points implied between consecutive
    off-curve ones) as explicit quadratics, an (n, 3, 2) array."""
    s = np.asarray(spline, float)
    off = s[1:-1]
    n = len(off)
    ons = [s[0]] + [(off[i] + off[i + 1]) / 2 for i in range(n - 1)] + [s[-1]]
    return np.array([[ons[i], off[i], ons[i + 1]] for i in range(n)])


def newton(f, p, s, lo, hi, iters=8):
    """Newton on (x(s) - p) . x'(s) = 0 from s (arrays), kept in [lo, hi]; distances: the
    smaller of the start's and the end's (both points of the curve, so never below the
    true distance: an iteration that strays cannot inflate it). f(s) gives the point and
    the first two derivatives, row by row."""
    d0 = np.linalg.norm(f(s)[0] - p, axis=-1)
    for _ in range(iters):
        x, d1, d2 = f(s)
        r = x - p
        g = np.sum(r * d1, axis=-1)
        gp = np.sum(d1 * d1, axis=-1) + np.sum(r * d2, axis=-1)
        gp = np.where(gp > 0, gp, np.sum(d1 * d1, axis=-1))
        step = np.where(gp > 0, g / np.where(gp > 0, gp, 1), 0)
        s = np.clip(s - step, lo, hi)
    x = f(s)[0]
    return np.minimum(d0, np.linalg.norm(x - p, axis=-1))


def bezier_f(ctrl):
    """Point, first and second derivative of the Bézier curves ctrl (array (m, n + 1, 2),
    n = 2 or 3), curve i at s[i], for arrays s of m parameters."""
    n = ctrl.shape[1] - 1
    d1c = n * (ctrl[:, 1:] - ctrl[:, :-1])
    d2c = (n - 1) * (d1c[:, 1:] - d1c[:, :-1])

    def ev(c, s):
        s = s[:, None]
        pts = [c[:, i] for i in range(c.shape[1])]
        while len(pts) > 1:
            pts = [(1 - s) * pts[i] + s * pts[i + 1] for i in range(len(pts) - 1)]
        return pts[0]

    return lambda s: (ev(ctrl, s), ev(d1c, s), ev(d2c, s))


def distances(points, ctrl, ts):
    """The distance from each of `points` (P, 2) to the nearest of the curves ctrl (k, n + 1, 2),
    each sampled at the parameters ts (M): every local minimum of the sampled distance along
    each curve (the ends included) refined by Newton within its neighbouring samples, the
    smallest kept. Not only the nearest sample: where a curve passes close to itself, or
    moves fast, the nearest sample can lie on another branch than the nearest point."""
    k, M = len(ctrl), len(ts)
    samples = bezier_f(np.repeat(ctrl, M, axis=0))(np.tile(ts, k))[0].reshape(k, M, 2)
    D = np.linalg.norm(points[:, None, None, :] - samples[None, :, :, :], axis=3)  # (P, k, M)
    pad = np.pad(D, ((0, 0), (0, 0), (1, 1)), constant_values=np.inf)
    rows, curve, cols = np.nonzero((D <= pad[:, :, :-2]) & (D <= pad[:, :, 2:]))
    d = newton(bezier_f(ctrl[curve]), points[rows], ts[cols], ts[np.maximum(cols - 1, 0)], ts[np.minimum(cols + 1, M - 1)])
    out = np.full(len(points), np.inf)
    np.minimum.at(out, rows, d)
    return out


def deviation(c, qs):
    """The two-sided distance between the cubic c and its chain qs: the cubic at
    S = 64 + 16 k parameters (k segments) to the chain, each quadratic at 65 parameters to
    the cubic; each distance as in distances() (the quadratics sampled at 33 parameters,
    the cubic at its S)."""
    k = len(qs)
    S = 64 + 16 * k
    ts = np.linspace(0, 1, S)
    cp = bezier_f(np.repeat(c[None], S, axis=0))(ts)[0]
    to_chain = distances(cp, qs, np.linspace(0, 1, 33)).max()
    qt = np.linspace(0, 1, 65)
    qp = bezier_f(np.repeat(qs, 65, axis=0))(np.tile(qt, k))[0]
    to_cubic = distances(qp, c[None], ts).max()
    return max(to_chain, to_cubic)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dump_dir")
    ap.add_argument("out_json")
    ap.add_argument("--repetitions", type=int, default=3)
    args = ap.parse_args()
    doc = {"context": {"library": "fonttools cu2qu", "compiled": COMPILED}, "benchmarks": []}
    print(f"W11: cu2qu {'compiled (Cython)' if COMPILED else 'pure Python'}", file=sys.stderr)
    if curve_to_quadratic is None:
        print("W11: fontTools not importable (python3-fonttools): no cu2qu rows", file=sys.stderr)
    else:
        for dataset in ("random", "glyphs"):
            path = os.path.join(args.dump_dir, f"w11_{dataset}.f64")
            if not os.path.exists(path):
                print(f"W11: {path} missing: no cu2qu rows for {dataset}", file=sys.stderr)
                continue
            cubics = np.fromfile(path, dtype="<f8").reshape(-1, 4, 2)
            curves = [[tuple(p) for p in c] for c in cubics.tolist()]
            for rel, label in ((1e-3, "1e-3"), (1e-1, "1e-1")):
                tol = rel * UNIT[dataset]
                times, cpu = [], []
                times_dropped, cpu_dropped = [], []
                for _ in range(args.repetitions):
                    t0, c0 = time.perf_counter(), time.process_time()
                    for c in curves:
                        curve_to_quadratic(c, tol)
                    times_dropped.append(time.perf_counter() - t0)
                    cpu_dropped.append(time.process_time() - c0)
                    t0, c0 = time.perf_counter(), time.process_time()
                    out = [curve_to_quadratic(c, tol) for c in curves]
                    times.append(time.perf_counter() - t0)
                    cpu.append(time.process_time() - c0)
                segments, over, worst = 0, 0, 0.0
                for c, spl in zip(cubics, out):
                    qs = chain(spl)
                    segments += len(qs)
                    d = deviation(c, qs)
                    worst = max(worst, d)
                    over += not (d <= 1.0001 * tol)
                doc["benchmarks"].append({
                    "name": f"W11/cu2qu/quadratic/{dataset}/{label}", "run_name": f"W11/cu2qu/quadratic/{dataset}/{label}",
                    "run_type": "iteration", "iterations": 1, "real_time": sorted(times)[len(times) // 2] * 1e3,
                    "cpu_time": sorted(cpu)[len(cpu) // 2] * 1e3, "time_unit": "ms", "curves": len(curves),
                    "segments": segments, "over_tolerance": over, "max_deviation": worst,
                    "dropped_real_ms": sorted(times_dropped)[len(times_dropped) // 2] * 1e3,
                    "dropped_cpu_ms": sorted(cpu_dropped)[len(cpu_dropped) // 2] * 1e3})
                print(f"W11/cu2qu/quadratic/{dataset}/{label}: {segments} segments, {over} over, "
                      f"max deviation {worst:.6g}, {sorted(times)[len(times) // 2] * 1e3:.1f} ms wall, "
                      f"{sorted(cpu)[len(cpu) // 2] * 1e3:.1f} ms CPU", file=sys.stderr)
                print(f"W11/cu2qu/quadratic/{dataset}/{label}, outputs dropped: "
                      f"{sorted(times_dropped)[len(times_dropped) // 2] * 1e3:.1f} ms wall, "
                      f"{sorted(cpu_dropped)[len(cpu_dropped) // 2] * 1e3:.1f} ms CPU", file=sys.stderr)
    with open(args.out_json, "w") as f:
        json.dump(doc, f, indent=1)


if __name__ == "__main__":
    main()
