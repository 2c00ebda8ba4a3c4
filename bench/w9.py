#!/usr/bin/python3
"""W9 (docs/performance.md, "Workloads"): the Python package `casteljau` against
scipy.interpolate on the same inputs, in the same process. Rows (Google Benchmark's JSON
shape, `benchmarks`: [{name, real_time, time_unit, counters...}]):

  W9/<scipy|casteljau>/spline_build         W4's natural cubic spline through 10^6 points
  W9/<scipy|casteljau>/spline_eval_random   its 10^6 random queries in one call
  W9/<scipy|casteljau>/spline_eval_sorted   the same queries sorted (an extra row)
  W9/<scipy|casteljau>/bspline_eval_random  W5's cubic B-spline (1000 points in 3-D), 10^6 random u
  W9/<scipy|casteljau>/per_call             a 5-point natural spline built and evaluated at
                                            one point, 10^5 times in a Python loop

real_time: time.perf_counter of one whole run (all points, all 10^5 loops), the median of
the repetitions (5 by default), in ms; cpu_time: time.process_time of that run; counter max_rel_diff on the casteljau rows: max
|ours - scipy| / max |scipy| over the run's values (scipy rows: 0). Inputs from splitmix64
with the workloads' seeds (W4: 4, W5: 5, the per-call data: 9), as bench/common.hpp.

Usage: w9.py BUILD_DIR OUT_JSON [--repetitions N] [--quick]
(BUILD_DIR/python holds the package; --quick: 10^5 points and 10^4 calls, for a smoke run.)
"""
import argparse
import json
import os
import sys
import time

import numpy as np


def splitmix_uniform(seed, count, start=0):
    """uniform() draws start .. start + count - 1 of splitmix64 seeded with seed: the state
    after draw k is seed + (k + 1) * golden (mod 2^64), so the draws vectorise."""
    golden = np.uint64(0x9E3779B97F4A7C15)
    k = np.arange(start + 1, start + count + 1, dtype=np.uint64)
    with np.errstate(over="ignore"):
        z = np.uint64(seed) + k * golden
        z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        z = z ^ (z >> np.uint64(31))
    return (z >> np.uint64(11)).astype(np.float64) * 2.0**-53


def w4_data(n, queries):
    """x_0 = 0, x_i = x_(i-1) + 0.5 + uniform() (in that order of additions, as the C++
    loop), then y, then the queries."""
    u = splitmix_uniform(4, n - 1 + n + queries)
    x = np.empty(n)
    x[0] = 0.0
    acc = 0.0
    steps = u[: n - 1].tolist()
    for i, s in enumerate(steps, 1):
        acc = acc + 0.5 + s
        x[i] = acc
    y = u[n - 1 : 2 * n - 1].copy()
    q = x[0] + (x[-1] - x[0]) * u[2 * n - 1 :]
    return x, y, q


def w5_data(count):
    u = splitmix_uniform(5, 3000 + count)
    P = u[:3000].reshape(1000, 3).copy()
    t = np.r_[[0.0] * 4, np.arange(1, 997) / 997.0, [1.0] * 4]
    return t, P, u[3000:].copy()


def timed(f, repetitions):
    """((median wall seconds, that run's CPU seconds), the last result)."""
    times, out = [], None
    for _ in range(repetitions):
        t0, c0 = time.perf_counter(), time.process_time()
        out = f()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    times.sort()
    return times[(len(times) - 1) // 2], out


def rel_diff(ours, theirs):
    ours, theirs = np.asarray(ours), np.asarray(theirs)
    scale = float(np.max(np.abs(theirs)))
    return float(np.max(np.abs(ours - theirs))) / scale if scale > 0 else float(np.max(np.abs(ours - theirs)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build_dir")
    ap.add_argument("out_json")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    sys.path.insert(0, os.path.join(os.path.abspath(args.build_dir), "python"))
    import scipy.interpolate as si

    import casteljau

    n = 10**5 if args.quick else 10**6
    calls = 10**4 if args.quick else 10**5
    reps = args.repetitions
    rows = []

    def row(lib, case, seconds, diff=None):
        wall, cpu = seconds
        r = {"name": f"W9/{lib}/{case}", "real_time": wall * 1e3, "cpu_time": cpu * 1e3, "time_unit": "ms",
             "repetitions": reps}
        if diff is not None:
            r["max_rel_diff"] = diff
        rows.append(r)
        print(f"  {r['name']}: {wall * 1e3:.2f} ms (cpu {cpu * 1e3:.2f} ms)"
              + (f", max_rel_diff {diff:.1e}" if diff is not None else ""), file=sys.stderr, flush=True)

    # (a) W4's natural spline.
    x, y, q = w4_data(n, n)
    qs = np.sort(q)
    libs = {"scipy": si, "casteljau": casteljau}
    ref = {}
    for lib, mod in libs.items():
        sec, s = timed(lambda: mod.CubicSpline(x, y, bc_type="natural"), reps)
        row(lib, "spline_build", sec, None if lib == "scipy" else 0.0)
        for case, qq in (("spline_eval_random", q), ("spline_eval_sorted", qs)):
            sec, v = timed(lambda: s(qq), reps)
            if lib == "scipy":
                ref[case] = v
            row(lib, case, sec, None if lib == "scipy" else rel_diff(v, ref[case]))
        if lib != "scipy":
            rows[-3]["max_rel_diff"] = max(rows[-2]["max_rel_diff"], rows[-1]["max_rel_diff"])
    del x, y, q, qs

    # (b) W5's B-spline.
    t, P, u = w5_data(n)
    for lib, mod in libs.items():
        b = mod.BSpline(t, P, 3)
        sec, v = timed(lambda: b(u), reps)
        if lib == "scipy":
            ref["bspline"] = v
        row(lib, "bspline_eval_random", sec, None if lib == "scipy" else rel_diff(v, ref["bspline"]))

    # (c) Per call: build a 5-point natural spline and evaluate it at one point.
    d = splitmix_uniform(9, 6)
    xs, ys, x1 = np.arange(5.0), d[:5].copy(), 4 * float(d[5])
    for lib, mod in libs.items():
        cls = mod.CubicSpline

        def loop():
            v = None
            for _ in range(calls):
                v = cls(xs, ys, bc_type="natural")(x1)
            return v

        sec, v = timed(loop, reps)
        if lib == "scipy":
            ref["per_call"] = v
        row(lib, "per_call", sec, None if lib == "scipy" else rel_diff(v, ref["per_call"]))

    for r in rows:
        if r["name"].startswith("W9/scipy/"):
            r["max_rel_diff"] = 0.0
    context = {"date": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "load_avg": list(os.getloadavg()),
               "num_cpus": os.cpu_count(), "points": n, "calls": calls, "scipy": si.__name__}
    with open(args.out_json, "w") as f:
        json.dump({"context": context, "benchmarks": rows}, f, indent=1)


if __name__ == "__main__":
    main()
