#!/usr/bin/python3
"""W11 (quadratic half) for fonttools' cu2qu (curve_to_quadratic, python3-fonttools): W3's
datasets, read from the raw float64 files the W3 program writes with CASTELJAU_W11_DUMP=DIR
(x0 y0 ... x3 y3 per cubic), at tolerance 1e-3 and 1e-1 of the unit (random: the box, 100;
glyphs: the em, 2048). Writes Google Benchmark's JSON shape (`benchmarks`: [{name,
real_time, time_unit, counters...}]) with names W11/cu2qu/quadratic/<dataset>/<1e-3|1e-1>
and counters segments, over_tolerance (curves whose deviation exceeds 1.0001 x tol),
max_deviation: the same two-sided measure as bench/w3.cpp's quad_deviation (the cubic at
S = 64 + 16 k parameters to the chain, each quadratic at 65 parameters to the cubic, each
distance from every local minimum of the sampled distances refined by Newton's method).

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
except ImportError:
    curve_to_quadratic = None

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
    true distance: an iteration that strays cannot inflate it)."""
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


def distances(points, f, ts, samples):
    """The distance from each of `points` to the curve f sampled at parameters ts (points
    `samples`): every local minimum of the sampled distance (along the samples, the ends
    included) refined by Newton within its neighbouring samples, the smallest kept. Not only
    the nearest sample: where the curve passes close to itself, or moves fast, the nearest
    sample can lie on another branch than the nearest point."""
    D = np.linalg.norm(points[:, None, :] - samples[None, :, :], axis=2)
    pad = np.pad(D, ((0, 0), (1, 1)), constant_values=np.inf)
    rows, cols = np.nonzero((D <= pad[:, :-2]) & (D <= pad[:, 2:]))
    n = len(ts)
    s0 = ts[cols]
    d = newton(f, points[rows], s0, ts[np.maximum(cols - 1, 0)], ts[np.minimum(cols + 1, n - 1)])
    out = np.full(len(points), np.inf)
    np.minimum.at(out, rows, d)
    return out


def cubic_f(c):
    def f(s):
        s = s[..., None]
        u = 1 - s
        x = u ** 3 * c[0] + 3 * u * u * s * c[1] + 3 * u * s * s * c[2] + s ** 3 * c[3]
        d1 = 3 * (u * u * (c[1] - c[0]) + 2 * u * s * (c[2] - c[1]) + s * s * (c[3] - c[2]))
        d2 = 6 * (u * (c[2] - 2 * c[1] + c[0]) + s * (c[3] - 2 * c[2] + c[1]))
        return x, d1, np.broadcast_to(d2, x.shape)
    return f


def quad_f(q):
    def f(s):
        s = s[..., None]
        u = 1 - s
        x = u * u * q[0] + 2 * u * s * q[1] + s * s * q[2]
        d1 = 2 * (u * (q[1] - q[0]) + s * (q[2] - q[1]))
        d2 = 2 * (q[0] - 2 * q[1] + q[2])
        return x, d1, np.broadcast_to(d2, x.shape)
    return f


def deviation(c, qs):
    """The two-sided distance between the cubic c and its chain qs: the cubic at
    S = 64 + 16 k parameters (k segments) to the chain, each quadratic at 65 parameters to
    the cubic; each distance as in distances() (the quadratics sampled at 33 parameters,
    the cubic at its S)."""
    k = len(qs)
    S = 64 + 16 * k
    cf = cubic_f(c)
    ts = np.linspace(0, 1, S)
    cp = cf(ts)[0]
    best = np.full(S, np.inf)
    seeds = np.linspace(0, 1, 33)
    for q in qs:
        best = np.minimum(best, distances(cp, quad_f(q), seeds, quad_f(q)(seeds)[0]))
    worst = best.max()
    qs_t = np.linspace(0, 1, 65)
    for q in qs:
        worst = max(worst, distances(quad_f(q)(qs_t)[0], cf, ts, cp).max())
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dump_dir")
    ap.add_argument("out_json")
    ap.add_argument("--repetitions", type=int, default=3)
    args = ap.parse_args()
    doc = {"context": {"library": "fonttools cu2qu"}, "benchmarks": []}
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
                times = []
                for _ in range(args.repetitions):
                    t0 = time.perf_counter()
                    out = [curve_to_quadratic(c, tol) for c in curves]
                    times.append(time.perf_counter() - t0)
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
                    "cpu_time": sorted(times)[len(times) // 2] * 1e3, "time_unit": "ms", "curves": len(curves),
                    "segments": segments, "over_tolerance": over, "max_deviation": worst})
                print(f"W11/cu2qu/quadratic/{dataset}/{label}: {segments} segments, {over} over, "
                      f"max deviation {worst:.6g}, {sorted(times)[len(times) // 2] * 1e3:.1f} ms", file=sys.stderr)
    with open(args.out_json, "w") as f:
        json.dump(doc, f, indent=1)


if __name__ == "__main__":
    main()
