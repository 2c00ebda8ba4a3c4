#!/usr/bin/env python3
"""Runs the W1-W9 and W11 benchmarks of bench/ and prints the tables of docs/performance.md
(W10, the server, is bench/w10.py: `make bench-w10`).

Usage: bench/run.py BUILD_DIR [--repetitions N] [--min-time SECONDS] [--filter REGEX]

Runs BUILD_DIR/bench/casteljau_bench_{w1_native,w1_generic,w2,w3,w4,w5,w6,w7,w8} (those that were built:
a missing peer or MPFR drops rows or executables, see bench/CMakeLists.txt) with
Google Benchmark's JSON output (repetitions of different benchmarks interleaved at random,
so that the shared machine's drift hits every row alike), keeps the median repetition
(wall-clock time; the fastest repetition and the CPU time are shown too), and prints:
  * W1 per build: ms per run, ns per point, Mpoints/s, the ratio to memset of the same
    output (time / memset time; below 1 is faster than memset), the speed-up over the
    fastest lib2geom and OCCT variants measured in the same run, and the max abs
    difference from own scalar de Casteljau;
  * W2: max abs error against the 256-bit MPFR reference, per method and degree;
  * W5: ns per point, sorted and random parameters, for us and the peers (OCCT, SISL, GSL);
  * W3 per dataset: us per curve, segments against the near-optimal count, curves over the
    tolerance and the max deviation, time against the uniform method (Wang's bound);
  * W4: build ns per knot, random and sorted evaluation ns per point, us against GSL;
  * W6: us per pair, intersections, pairs missed and extra against the reference, max distance;
  * W7: ns per point, B-spline and NURBS surfaces on a grid and at random (u, v), for us and
    the peers (OCCT, SISL), max abs difference from the long double reference;
  * W8: tessellation of a bicubic, a NURBS torus and sphere per tolerance: ms, triangles,
    max deviation over the tolerance, meshes over it, cracks, against OCCT's mesher;
  * W9 (bench/w9.py, when BUILD_DIR/python holds the Python package): casteljau against
    scipy.interpolate, ms per case, the ratio and the max relative difference;
  * W11 (rows of the W3 program; cu2qu's from bench/w11_cu2qu.py, python3-fonttools):
    quadratic approximation against cu2qu and offsets against lib2geom on W3's datasets,
    segments, curves over the tolerance, max deviation and time against the peer;
  * the goals of the benchmark issue, met or not.
The raw JSON and the tables in Markdown go to BUILD_DIR/bench-results/.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import time

W1_GOAL_VS_MEMSET = 1.15  # batch SoA time / memset time
W1_GOAL_VS_LIB2GEOM = 10.0  # fastest lib2geom time / batch SoA time
W1_GOAL_GENERIC_VS_NATIVE = 1.15  # generic batch SoA time / native batch SoA time
W2_GOAL_ERROR = 2e-15  # fast path max error at every degree
W2_GOAL_VS_LIB2GEOM = 2.0  # lib2geom valueAt time / fast path time, at every degree
W2_DEGREES = (5, 10, 20, 40)
W5_GOAL_VS_FASTEST_PEER = 0.5  # our time / the fastest peer's, sorted and random alike
W5_POINTS = 1e6
W3_GOAL_VS_NEAR_OPTIMAL = 1.05  # segments / near-optimal count, casteljau/optimal
W3_GOAL_VS_UNIFORM = 2.2  # casteljau/optimal time / our uniform method's time (Wang's bound)
W3_TOLERANCE = 0.1
W4_GOAL_VS_GSL = 0.5  # our time / GSL's, for build, eval_random and eval_sorted each
W4_KNOTS = 1e6
W4_QUERIES = 1e6
W7_GOAL_GRID = 0.1  # our time / the fastest peer's on the grid
W7_GOAL_RANDOM = 0.35  # our time / the fastest peer's at random (u, v)
W7_GOAL_DIFF = 1e-13  # max abs difference from the long double reference
W7_POINTS = 1e6
W6_GOAL_VS_LIB2GEOM = 0.5  # our time / the fastest lib2geom method's
W6_PAIRS = 1e4
W9_GOAL_VECTORISED = 0.5  # our time / scipy's: spline_build, spline_eval_random, bspline_eval_random
W9_GOAL_PER_CALL = 1.0  # our time / scipy's: per_call
W9_GOAL_REL_DIFF = 1e-12  # max relative difference from scipy's values
W8_GOAL_TRIANGLES_VS_OCCT = 0.5  # our triangles / OCCT's, where OCCT keeps the tolerance
W8_GOAL_TIME_VS_OCCT = 1.0  # our time / OCCT's


def run(exe, out_json, repetitions, min_time, bench_filter):
    cmd = [exe, "--benchmark_format=json", f"--benchmark_out={out_json}", "--benchmark_out_format=json",
           f"--benchmark_min_time={min_time}"]
    if repetitions > 1:
        cmd += [f"--benchmark_repetitions={repetitions}",
                # repetitions of different benchmarks interleaved in random order, so that the
                # machine's drift hits memset and the libraries alike
                "--benchmark_enable_random_interleaving=true"]
    if bench_filter:
        cmd.append(f"--benchmark_filter={bench_filter}")
    print("$ " + " ".join(cmd), file=sys.stderr, flush=True)
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    print(f"  ({time.time() - t0:.0f} s)", file=sys.stderr, flush=True)
    with open(out_json) as f:
        text = f.read()
    # A filter that matches nothing in this executable leaves the file empty.
    return json.loads(text) if text.strip() else {"benchmarks": [], "context": None}


def medians(doc):
    """name (without /real_time) -> the median repetition's row, with "min_real_time" added,
    in registration order (the runs themselves are interleaved at random)."""
    reps = {}
    for b in doc["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        name = b.get("run_name", b["name"]).removesuffix("/real_time")
        if b.get("error_occurred"):  # a skipped row (SkipWithError): no times to report
            print(f"run.py: {name} skipped: {b.get('error_message', '')}", file=sys.stderr)
            continue
        reps.setdefault(name, []).append(b)
    rows = {}
    for name, runs in sorted(reps.items(), key=lambda kv: kv[1][0].get("family_index", 0)):
        runs = sorted(runs, key=lambda b: b["real_time"])
        row = dict(runs[(len(runs) - 1) // 2])  # the lower median: a measured run, not an average
        row["min_real_time"] = runs[0]["real_time"]
        row["repetitions"] = len(runs)
        rows[name] = row
    return rows


def to_ms(b, key="real_time"):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
    return b[key] * scale


def fmt_ratio(x):
    return f"{x:.2f}x" if x < 10 else f"{x:.0f}x"


def table(headers, rows):
    widths = [max(len(str(r[i])) for r in [headers] + rows) for i in range(len(headers))]
    text = "  ".join(h.ljust(w) for h, w in zip(headers, widths)) + "\n"
    text += "  ".join("-" * w for w in widths) + "\n"
    for r in rows:
        text += "  ".join(str(c).ljust(w) for c, w in zip(r, widths)) + "\n"
    md = "| " + " | ".join(headers) + " |\n|" + "|".join(" --- " for _ in headers) + "|\n"
    for r in rows:
        md += "| " + " | ".join(str(c) for c in r) + " |\n"
    return text, md


def w1_table(rows, label):
    points = 1e7
    memset = rows.get("W1/memset/output")
    peers = {}
    for lib in ("lib2geom", "occt"):
        times = [(to_ms(b), n) for n, b in rows.items() if n.startswith(f"W1/{lib}/")]
        if times:
            peers[lib] = min(times)
    headers = ["benchmark", "ms", "min ms", "cpu ms", "ns/pt", "Mpt/s", "x memset"] + [f"faster than {p} ({n.split('/')[-1]})" for p, (_, n) in peers.items()] + ["max abs diff"]
    out = []
    for name, b in rows.items():
        ms = to_ms(b)
        r = [name, f"{ms:.2f}", f"{to_ms(b, 'min_real_time'):.2f}", f"{to_ms(b, 'cpu_time'):.2f}", f"{ms * 1e6 / points:.2f}", f"{points / (ms * 1e3):.0f}",
             fmt_ratio(ms / to_ms(memset)) if memset else "-"]
        for p, (t, _) in peers.items():
            r.append(fmt_ratio(t / ms))
        diff = b.get("max_abs_diff")
        r.append("-" if diff is None or name.startswith("W1/memset") or "l1_window" in name else f"{diff:.1e}")
        out.append(r)
    text, md = table(headers, out)
    goals = []
    soa = rows.get("W1/casteljau/batch_soa")
    if soa and memset:
        ratio = to_ms(soa) / to_ms(memset)
        goals.append(f"W1 {label}: batch_soa / memset = {ratio:.2f} (goal <= {W1_GOAL_VS_MEMSET}): "
                     + ("MET" if ratio <= W1_GOAL_VS_MEMSET else "NOT MET"))
    # Paired rounds (w1.cpp, paired): the median of per-round ratios, the measure that holds
    # still while the host's bandwidth moves (its own time is two passes: not a result).
    for ref, key in (("the non-temporal ceiling", "W1/paired/batch_soa_over_ceiling_nt"), ("memset", "W1/paired/batch_soa_over_memset")):
        pr = rows.get(key)
        if pr and "ratio" in pr:
            goals.append(f"W1 {label}: paired batch_soa / {ref} = {pr['ratio']:.3f} (rounds' quartiles {pr.get('ratio_q1', 0):.3f}-"
                         f"{pr.get('ratio_q3', 0):.3f}, CPU time {pr.get('ratio_cpu', 0):.3f}; goal <= 1.15): "
                         + ("MET" if pr["ratio"] <= 1.15 else "NOT MET"))
    if soa and "lib2geom" in peers:
        speedup = peers["lib2geom"][0] / to_ms(soa)
        goals.append(f"W1 {label}: fastest lib2geom / batch_soa = {speedup:.1f} (goal > {W1_GOAL_VS_LIB2GEOM:.0f}): "
                     + ("MET" if speedup > W1_GOAL_VS_LIB2GEOM else "NOT MET"))
    return text, md, goals


def w2_table(rows):
    methods = []
    for name in rows:
        method = name.rsplit("/", 1)[0]
        if method not in methods:
            methods.append(method)
    headers = ["method"] + [f"n={n}" for n in W2_DEGREES] + [f"ns/pt n={n}" for n in W2_DEGREES]
    out = []
    for m in methods:
        r = [m]
        for n in W2_DEGREES:
            b = rows.get(f"{m}/{n}")
            r.append(f"{b['max_error']:.1e}" if b else "-")
        for n in W2_DEGREES:
            b = rows.get(f"{m}/{n}")
            r.append(f"{to_ms(b) * 1e6 / 1e4:.1f}" if b else "-")
        out.append(r)
    text, md = table(headers, out)
    goals = []
    for n in W2_DEGREES:
        fast = rows.get(f"W2/casteljau/fast_path/{n}")
        if not fast:
            continue
        e = fast["max_error"]
        goal = f"W2 n={n}: fast path max error {e:.2e} (goal <= {W2_GOAL_ERROR:.0e})"
        ok = e <= W2_GOAL_ERROR
        peer = rows.get(f"W2/lib2geom/valueAt/{n}")
        if peer:
            speedup = to_ms(peer) / to_ms(fast)
            goal += f", {speedup:.1f}x faster than lib2geom valueAt (goal >= {W2_GOAL_VS_LIB2GEOM:.0f}x)"
            ok = ok and speedup >= W2_GOAL_VS_LIB2GEOM
        goals.append(goal + (": MET" if ok else ": NOT MET"))
    return text, md, goals


def w5_table(rows):
    methods = []
    for name in rows:
        method = name.rsplit("/", 1)[0]
        if method not in methods:
            methods.append(method)
    orders = ("sorted", "random")
    headers = ["method"] + [f"ns/pt {o}" for o in orders] + [f"cpu ns/pt {o}" for o in orders] + ["max abs diff"]
    out = []
    for m in methods:
        r = [m]
        for key in ("real_time", "cpu_time"):
            for o in orders:
                b = rows.get(f"{m}/{o}")
                r.append(f"{to_ms(b, key) * 1e6 / W5_POINTS:.1f}" if b else "-")
        b = rows.get(f"{m}/sorted") or rows.get(f"{m}/random")
        r.append(f"{b['max_abs_diff']:.1e}" if b and "max_abs_diff" in b else "-")
        out.append(r)
    text, md = table(headers, out)
    goals = []
    for o in orders:
        ours = rows.get(f"W5/casteljau/span_table/{o}")
        peers = [(to_ms(b), n) for n, b in rows.items()
                 if n.endswith(f"/{o}") and not n.startswith("W5/casteljau/")]
        if ours and peers:
            t, name = min(peers)
            ratio = to_ms(ours) / t
            goals.append(f"W5 {o}: span_table / fastest peer ({name.rsplit('/', 1)[0]}) = {ratio:.2f} "
                         f"(goal <= {W5_GOAL_VS_FASTEST_PEER}): " + ("MET" if ratio <= W5_GOAL_VS_FASTEST_PEER else "NOT MET"))
    return text, md, goals


def w7_table(rows):
    """W7: ns per point per method, kind and query set; the goals against the fastest peer."""
    methods = []
    for name in rows:
        method = name.rsplit("/", 2)[0]
        if method not in methods:
            methods.append(method)
    cases = [(k, q) for k in ("bspline", "nurbs") for q in ("grid", "random")]
    headers = ["method"] + [f"ns/pt {k} {q}" for k, q in cases] + ["max abs diff"]
    out = []
    for m in methods:
        r = [m]
        for k, q in cases:
            b = rows.get(f"{m}/{k}/{q}")
            r.append(f"{to_ms(b) * 1e6 / W7_POINTS:.1f}" if b else "-")
        diffs = [rows[f"{m}/{k}/{q}"]["max_abs_diff"] for k, q in cases if f"{m}/{k}/{q}" in rows]
        r.append(f"{max(diffs):.1e}" if diffs else "-")
        out.append(r)
    text, md = table(headers, out)
    goals = []
    for k, q in cases:
        ours = rows.get(f"W7/casteljau/batch/{k}/{q}")
        peers = [(to_ms(b), n) for n, b in rows.items() if n.endswith(f"/{k}/{q}") and not n.startswith("W7/casteljau/")]
        if ours and peers:
            t, name = min(peers)
            ratio = to_ms(ours) / t
            goal = W7_GOAL_GRID if q == "grid" else W7_GOAL_RANDOM
            ok = ratio <= goal and ours["max_abs_diff"] <= W7_GOAL_DIFF
            goals.append(f"W7 {k} {q}: batch / fastest peer ({name.rsplit('/', 2)[0]}) = {ratio:.3f} (goal <= {goal}), "
                         f"max abs diff {ours['max_abs_diff']:.1e} (goal <= {W7_GOAL_DIFF}): " + ("MET" if ok else "NOT MET"))
    return text, md, goals


def w3_tables(rows):
    """One table per dataset; the goals of issue 8 for casteljau/optimal."""
    rows = {n: b for n, b in rows.items() if n.startswith("W3/")}  # the W11 rows of the same program apart
    out_text, out_md, goals = "", "", []
    sets = []
    for name in rows:
        ds = name.rsplit("/", 1)[1]
        if ds not in sets:
            sets.append(ds)
    for ds in sets:
        sub = {n.rsplit("/", 1)[0]: b for n, b in rows.items() if n.endswith("/" + ds)}
        near = sub.get("W3/near_optimal/greedy")
        uniform_name = "W3/casteljau/uniform" if "W3/casteljau/uniform" in sub else "W3/plain/wang_uniform"
        uniform = sub.get(uniform_name)
        headers = ["method", "ms", "cpu ms", "us/curve", "segments", "x near-opt", "over tol", "max deviation", "time x uniform"]
        out = []
        for m, b in sub.items():
            curves = b.get("curves", 0) or 1
            ms = to_ms(b)
            out.append([m, f"{ms:.1f}", f"{to_ms(b, 'cpu_time'):.1f}", f"{ms * 1e3 / curves:.2f}", f"{b.get('segments', 0):.0f}",
                        f"{b['segments'] / near['segments']:.3f}" if near else "-", f"{b.get('over_tolerance', 0):.0f}",
                        f"{b.get('max_deviation', 0):.4g}", fmt_ratio(ms / to_ms(uniform)) if uniform else "-"])
        text, md = table(headers, out)
        curves = int(next(iter(sub.values())).get("curves", 0))
        title = f"W3, flattening at tolerance {W3_TOLERANCE}, dataset {ds} ({curves} cubics; uniform = {uniform_name.split('/', 1)[1]})"
        out_text += f"\n{title}\n{text}"
        out_md += f"\n### {title}\n\n{md}"
        ours = sub.get("W3/casteljau/optimal")
        if not ours:
            goals.append(f"W3 {ds}: no casteljau/optimal row (the near-optimal method is not in this build): NOT MEASURED")
            continue
        if near and uniform:
            count = ours["segments"] / near["segments"]
            time_ratio = to_ms(ours) / to_ms(uniform)
            over = int(ours.get("over_tolerance", 0))
            ok = count <= W3_GOAL_VS_NEAR_OPTIMAL and time_ratio <= W3_GOAL_VS_UNIFORM and over == 0
            goals.append(f"W3 {ds}: optimal = {count:.3f}x the near-optimal count (goal <= {W3_GOAL_VS_NEAR_OPTIMAL}), "
                         f"{time_ratio:.2f}x the time of {uniform_name.split('/', 1)[1]} (goal <= {W3_GOAL_VS_UNIFORM}), "
                         f"{over} curves over the tolerance (goal 0): " + ("MET" if ok else "NOT MET"))
    return out_text, out_md, goals


def w11_table(rows):
    """W11: casteljau's rows (the W3 program) beside the peer's, per operation, dataset and
    parameter: quadratic approximation against cu2qu (bench/w11_cu2qu.py), offsets against
    lib2geom (the W3 program); goals: 0 over tolerance, fewer segments and less time than
    the peer."""
    headers = ["operation/dataset/parameter", "library", "ms", "us/curve", "segments", "x peer", "over tol", "max deviation",
               "time x peer"]
    out, goals = [], []
    for op, peer_lib in (("quadratic", "cu2qu"), ("offset", "lib2geom")):
        # Quadratic rows by CPU time: cu2qu runs in its own process after the W3 program
        # (bench/w11_cu2qu.py, time.process_time), so wall times would meet different loads.
        key_time = "cpu_time" if op == "quadratic" else "real_time"
        keys = sorted({n.split("/", 3)[3] for n in rows if n.startswith("W11/") and f"/{op}/" in n})
        for key in keys:
            peer = rows.get(f"W11/{peer_lib}/{op}/{key}")
            # cu2qu with its outputs dropped instead of kept: counters of its row (bench/w11_cu2qu.py).
            dropped = None
            if peer and "dropped_cpu_ms" in peer:
                dropped = dict(peer, real_time=peer["dropped_real_ms"], cpu_time=peer["dropped_cpu_ms"], time_unit="ms")
            for lib, b in (("casteljau", rows.get(f"W11/casteljau/{op}/{key}")), (peer_lib, peer), (f"{peer_lib} (outputs dropped)", dropped)):
                if not b:
                    continue
                curves = b.get("curves", 0) or 1
                ms = to_ms(b, key_time)
                out.append([f"{op}/{key}", lib, f"{ms:.1f}", f"{ms * 1e3 / curves:.2f}", f"{b.get('segments', 0):.0f}",
                            f"{b['segments'] / peer['segments']:.3f}" if peer else "-", f"{b.get('over_tolerance', 0):.0f}",
                            f"{b.get('max_deviation', 0):.4g}", fmt_ratio(ms / to_ms(peer, key_time)) if peer else "-"])
            ours = rows.get(f"W11/casteljau/{op}/{key}")
            if ours and peer:
                ok = (ours["segments"] < peer["segments"] and to_ms(ours, key_time) < to_ms(peer, key_time)
                      and int(ours.get("over_tolerance", 0)) == 0)
                goals.append(f"W11 {op} {key}: {ours['segments'] / peer['segments']:.3f}x {peer_lib}'s segments, "
                             f"{to_ms(ours, key_time) / to_ms(peer, key_time):.2f}x its time"
                             f"{' (CPU)' if key_time == 'cpu_time' else ''}, {int(ours.get('over_tolerance', 0))} over the tolerance "
                             "(goal: fewer, faster, 0): " + ("MET" if ok else "NOT MET"))
            if ours and dropped:
                fast = to_ms(ours, key_time) < to_ms(dropped, key_time)
                goals.append(f"W11 {op} {key}: {to_ms(ours, key_time) / to_ms(dropped, key_time):.2f}x the time of cu2qu with its "
                             "outputs dropped (CPU; goal: less): " + ("MET" if fast else "NOT MET"))
    text, md = table(headers, out)
    return text, md, goals


def w4_table(rows):
    libs = []
    for name in rows:
        lib = name.split("/")[1]
        if lib not in libs:
            libs.append(lib)
    headers = ["library", "build ms", "build ns/knot", "eval_random ns/pt", "eval_sorted ns/pt",
               "cpu build / random / sorted (ms)", "max abs diff from GSL (random / sorted)"]
    out = []
    for lib in libs:
        b, r, s = (rows.get(f"W4/{lib}/{v}") for v in ("build", "eval_random", "eval_sorted"))
        diffs = [x.get("max_abs_diff") for x in (r, s) if x]
        out.append([lib, f"{to_ms(b):.1f}" if b else "-", f"{to_ms(b) * 1e6 / W4_KNOTS:.1f}" if b else "-",
                    f"{to_ms(r) * 1e6 / W4_QUERIES:.1f}" if r else "-", f"{to_ms(s) * 1e6 / W4_QUERIES:.1f}" if s else "-",
                    " / ".join(f"{to_ms(x, 'cpu_time'):.1f}" if x else "-" for x in (b, r, s)),
                    " / ".join(f"{d:.1e}" if d is not None and d >= 0 else "-" for d in diffs) or "-"])
    text, md = table(headers, out)
    goals = []
    for v in ("build", "eval_random", "eval_sorted"):
        ours, gsl = rows.get(f"W4/casteljau/{v}"), rows.get(f"W4/gsl/{v}")
        if not gsl:
            continue
        if not ours:
            goals.append(f"W4 {v}: no casteljau row (the cubic spline is not in this build): NOT MEASURED")
            continue
        ratio = to_ms(ours) / to_ms(gsl)
        goals.append(f"W4 {v}: casteljau / GSL = {ratio:.2f} (goal <= {W4_GOAL_VS_GSL}): " + ("MET" if ratio <= W4_GOAL_VS_GSL else "NOT MET"))
    # The extra row: one call per random query (eval_random times the batch call).
    single, gsl = rows.get("W4/casteljau/eval_random_single"), rows.get("W4/gsl/eval_random")
    if single and gsl:
        goals.append(f"W4 eval_random_single (one call per query, not a goal row): {to_ms(single) * 1e6 / W4_QUERIES:.1f} ns/pt, "
                     f"casteljau / GSL = {to_ms(single) / to_ms(gsl):.2f}")
    return text, md, goals


def w6_table(rows):
    ref = rows.get("W6/reference/long_double_subdivision")
    geom = [(to_ms(b), n) for n, b in rows.items() if n.startswith("W6/lib2geom/")]
    fastest_geom = min(geom) if geom else None
    headers = ["method", "ms", "cpu ms", "us/pair", "intersections", "pairs missed", "pairs extra", "max distance"]
    if fastest_geom:
        headers.append(f"time x lib2geom ({fastest_geom[1].split('/')[-1]})")
    out = []
    for n, b in rows.items():
        ms = to_ms(b)
        r = [n, f"{ms:.1f}", f"{to_ms(b, 'cpu_time'):.1f}", f"{ms * 1e3 / W6_PAIRS:.2f}", f"{b.get('intersections', 0):.0f}",
             f"{b.get('pairs_missed', 0):.0f}", f"{b.get('pairs_extra', 0):.0f}", f"{b.get('max_distance', 0):.1e}"]
        if fastest_geom:
            r.append(fmt_ratio(ms / fastest_geom[0]))
        out.append(r)
    text, md = table(headers, out)
    goals = []
    ours = rows.get("W6/casteljau/intersect")
    if not ours:
        goals.append("W6: no casteljau/intersect row (the intersection is not in this build): NOT MEASURED")
    else:
        missed, extra = int(ours.get("pairs_missed", 0)), int(ours.get("pairs_extra", 0))
        found = f"{ours.get('intersections', 0):.0f} of {ref.get('intersections', 0):.0f}" if ref else f"{ours.get('intersections', 0):.0f}"
        goal = f"W6: {found} intersections, {missed} pairs missed, {extra} pairs extra (goal 0 and 0)"
        ok = missed == 0 and extra == 0
        if fastest_geom:
            ratio = to_ms(ours) / fastest_geom[0]
            goal += f", time / lib2geom {fastest_geom[1].split('/')[-1]} = {ratio:.2f} (goal <= {W6_GOAL_VS_LIB2GEOM})"
            ok = ok and ratio <= W6_GOAL_VS_LIB2GEOM
        goals.append(goal + (": MET" if ok else ": NOT MET"))
    return text, md, goals


def w9_table(rows):
    """W9 (bench/w9.py): the Python package against scipy.interpolate, per case; goals: the
    vectorised rows at most W9_GOAL_VECTORISED of scipy's time, per_call at most
    W9_GOAL_PER_CALL, values within W9_GOAL_REL_DIFF of scipy's."""
    cases = []
    for name in rows:
        case = name.split("/", 2)[2]
        if case not in cases:
            cases.append(case)
    headers = ["case", "scipy ms", "casteljau ms", "casteljau / scipy", "cpu ms scipy / casteljau", "cpu ratio",
               "max rel diff"]
    out, goals = [], []
    for case in cases:
        sp, ours = rows.get(f"W9/scipy/{case}"), rows.get(f"W9/casteljau/{case}")
        ratio = to_ms(ours) / to_ms(sp) if sp and ours else None
        out.append([case, f"{to_ms(sp):.2f}" if sp else "-", f"{to_ms(ours):.2f}" if ours else "-",
                    f"{ratio:.2f}x" if ratio is not None else "-",
                    f"{to_ms(sp, 'cpu_time'):.2f} / {to_ms(ours, 'cpu_time'):.2f}" if sp and ours else "-",
                    f"{to_ms(ours, 'cpu_time') / to_ms(sp, 'cpu_time'):.2f}x" if sp and ours else "-",
                    f"{ours.get('max_rel_diff', 0):.1e}" if ours else "-"])
        if ratio is None or case == "spline_eval_sorted":  # the sorted row is an extra, not a goal
            continue
        goal = W9_GOAL_PER_CALL if case == "per_call" else W9_GOAL_VECTORISED
        diff = ours.get("max_rel_diff", 0)
        ok = ratio <= goal and diff < W9_GOAL_REL_DIFF
        goals.append(f"W9 {case}: casteljau / scipy = {ratio:.2f} (goal <= {goal}), max rel diff {diff:.1e} "
                     f"(goal < {W9_GOAL_REL_DIFF:.0e}): " + ("MET" if ok else "NOT MET"))
    text, md = table(headers, out)
def w8_table(rows):
    cases = {}
    for n, b in rows.items():
        _, lib, _, surface, tol = n.split("/")
        cases.setdefault((surface, tol), {})[lib] = (n, b)
    headers = ["surface/tolerance", "library", "ms", "triangles", "max deviation / tol", "over", "cracks", "triangles x occt", "time x occt"]
    out, goals = [], []
    over = cracks = 0
    tri_ok = time_ok = True
    for (surface, tol), libs in cases.items():
        occt = libs.get("occt")
        for lib, (n, b) in sorted(libs.items()):
            r = [f"{surface}/{tol}", lib, f"{to_ms(b):.2f}", f"{b.get('triangles', 0):.0f}",
                 f"{b.get('max_deviation', 0) / float(tol):.3f}", f"{b.get('over_tolerance', 0):.0f}", f"{b.get('cracks', 0):.0f}"]
            if occt and lib != "occt":
                r += [fmt_ratio(b.get("triangles", 0) / max(occt[1].get("triangles", 1), 1)), fmt_ratio(to_ms(b) / to_ms(occt[1]))]
            else:
                r += ["", ""]
            out.append(r)
            if lib == "casteljau":
                over += int(b.get("over_tolerance", 0))
                cracks += int(b.get("cracks", 0))
                if occt:
                    time_ok = time_ok and to_ms(b) <= W8_GOAL_TIME_VS_OCCT * to_ms(occt[1])
                    if not occt[1].get("over_tolerance", 0):
                        tri_ok = tri_ok and b.get("triangles", 0) <= W8_GOAL_TRIANGLES_VS_OCCT * occt[1].get("triangles", 0)
    text, md = table(headers, out)
    goals.append(f"W8: {over} meshes over tolerance, {cracks} cracks (goal 0 and 0): " + ("MET" if over == 0 and cracks == 0 else "NOT MET"))
    goals.append(f"W8: triangles <= {W8_GOAL_TRIANGLES_VS_OCCT} x OCCT's where OCCT keeps the tolerance: " + ("MET" if tri_ok else "NOT MET"))
    goals.append(f"W8: time <= OCCT's: " + ("MET" if time_ok else "NOT MET"))
    return text, md, goals


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build_dir")
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--min-time", type=float, default=0.5, help="seconds per repetition of a W1 benchmark")
    ap.add_argument("--filter", default="", help="benchmark regex (default: all)")
    args = ap.parse_args()

    bench_dir = os.path.join(args.build_dir, "bench")
    res_dir = os.path.join(args.build_dir, "bench-results")
    os.makedirs(res_dir, exist_ok=True)
    text_all, md_all, goals = "", "", []

    context = None
    soa_ms = {}
    w11_rows = {}
    os.environ["CASTELJAU_W11_DUMP"] = res_dir  # the W3 program writes W11's datasets there
    for label, exe_name in (("-O3 -march=native", "casteljau_bench_w1_native"), ("-O2 generic x86-64", "casteljau_bench_w1_generic")):
        exe = os.path.join(bench_dir, exe_name)
        if not os.path.exists(exe):
            print(f"run.py: {exe} not built, skipping", file=sys.stderr)
            continue
        doc = run(exe, os.path.join(res_dir, exe_name + ".json"), args.repetitions, args.min_time, args.filter)
        context = context or doc["context"]
        rows = medians(doc)
        if not rows:
            continue
        if "W1/casteljau/batch_soa" in rows:
            soa_ms[exe_name] = to_ms(rows["W1/casteljau/batch_soa"])
        text, md, g = w1_table(rows, label)
        title = f"W1, 1000 cubics x 10^4 parameters, {label} (median of {args.repetitions})"
        text_all += f"\n{title}\n{text}"
        md_all += f"\n### {title}\n\n{md}"
        goals += g

    if len(soa_ms) == 2:
        ratio = soa_ms["casteljau_bench_w1_generic"] / soa_ms["casteljau_bench_w1_native"]
        goals.append(f"W1: generic batch_soa / native batch_soa = {ratio:.2f} (separate runs; goal <= {W1_GOAL_GENERIC_VS_NATIVE}): "
                     + ("MET" if ratio <= W1_GOAL_GENERIC_VS_NATIVE else "NOT MET"))

    # The other workloads: one executable each, one table (or a set of tables with their own
    # titles when the title is None). W2 runs the same repetitions with shorter minimum
    # times: the error does not change between runs, and each row takes 10-4000 us.
    workloads = (
        ("casteljau_bench_w2", 0.1, w2_table,
         "W2, max abs error vs 256-bit MPFR de Casteljau (10 curves x 1000 parameters x 2 coordinates)"),
        ("casteljau_bench_w5", 0.2, w5_table, "W5, cubic B-spline in 3-D, 1000 control points, 10^6 parameters"),
        ("casteljau_bench_w3", 0.2, w3_tables, None),
        ("casteljau_bench_w4", 0.2, w4_table, "W4, natural cubic spline through 10^6 points, 10^6 queries"),
        ("casteljau_bench_w6", 0.2, w6_table, "W6, 10,000 random cubic pairs"),
        ("casteljau_bench_w7", 0.2, w7_table, "W7, bicubic surface of 50 x 50 control points, 10^6 points (1000 x 1000 grid, random)"),
        ("casteljau_bench_w8", 0.2, w8_table, "W8, tessellation: W7's bicubic (heights x 0.1), a NURBS torus and sphere"),
    )
    for exe_name, min_time, table, title in workloads:
        exe = os.path.join(bench_dir, exe_name)
        if not os.path.exists(exe):
            if exe_name == "casteljau_bench_w2":
                print(f"run.py: {exe} not built (MPFR missing?), skipping W2", file=sys.stderr)
            continue
        doc = run(exe, os.path.join(res_dir, exe_name + ".json"), args.repetitions, min_time, args.filter)
        context = context or doc["context"]
        rows = medians(doc)
        if not rows:
            continue
        text, md, g = table(rows)
        if title is None:
            text_all += text
            md_all += md
        else:
            text_all += f"\n{title}\n{text}"
            md_all += f"\n### {title}\n\n{md}"
        goals += g
        if exe_name == "casteljau_bench_w3":
            w11_rows = {n: b for n, b in rows.items() if n.startswith("W11/")}

    # W11: fonttools' cu2qu on the datasets the W3 program wrote (CASTELJAU_W11_DUMP, set by
    # main() before running it), beside the W3 program's W11 rows (casteljau's, and
    # lib2geom's offsets).
    if w11_rows:
        w11_json = os.path.join(res_dir, "W11.json")
        if os.path.exists(w11_json):
            os.remove(w11_json)
    if any("/quadratic/" in n for n in w11_rows):  # cu2qu only beside casteljau's quadratic rows
        subprocess.run(["/usr/bin/python3", os.path.join(os.path.dirname(os.path.abspath(__file__)), "w11_cu2qu.py"), res_dir, w11_json,
                        "--repetitions", str(args.repetitions)], check=False)
        if os.path.exists(w11_json):
            with open(w11_json) as f:
                for b in json.load(f)["benchmarks"]:
                    w11_rows[b["name"]] = b
    if w11_rows:
        text, md, g = w11_table(w11_rows)
        title = ("W11, W3's datasets: quadratic approximation at 1e-3 and 1e-1 of the unit (box 100, em 2048), "
                 "offsets by 1e-2 and 1e-1 of it at 1e-3")
        text_all += f"\n{title}\n{text}"
        md_all += f"\n### {title}\n\n{md}"
        goals += g

    # W9: the Python package (built into BUILD_DIR/python) against scipy, by bench/w9.py.
    if glob.glob(os.path.join(args.build_dir, "python", "casteljau", "_casteljau*.so")) and not args.filter:
        w9_json = os.path.join(res_dir, "W9.json")
        if os.path.exists(w9_json):
            os.remove(w9_json)
        print("$ bench/w9.py", file=sys.stderr, flush=True)
        t0 = time.time()
        subprocess.run(["/usr/bin/python3", os.path.join(os.path.dirname(os.path.abspath(__file__)), "w9.py"), args.build_dir,
                        w9_json, "--repetitions", str(max(args.repetitions, 5))], check=False)
        print(f"  ({time.time() - t0:.0f} s)", file=sys.stderr, flush=True)
        if os.path.exists(w9_json):
            with open(w9_json) as f:
                w9_rows = {b["name"]: b for b in json.load(f)["benchmarks"]}
            text, md, g = w9_table(w9_rows)
            title = "W9, the Python package against scipy.interpolate (W4's spline, W5's B-spline, per call), medians of 5"
            text_all += f"\n{title}\n{text}"
            md_all += f"\n### {title}\n\n{md}"
            goals += g
    else:
        print("run.py: the Python package is not built (or --filter given): skipping W9", file=sys.stderr)

    if context:
        head = (f"{context.get('host_name', '?')}: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
                f"load average {' '.join(f'{x:.2f}' for x in context.get('load_avg', []))}, {context.get('date', '')}")
        text_all = head + "\n" + text_all
        md_all = head + "\n" + md_all
    text_all += "\nGoals\n" + "\n".join("  " + g for g in goals) + "\n"
    md_all += "\n### Goals\n\n" + "\n".join("- " + g for g in goals) + "\n"
    print(text_all)
    with open(os.path.join(res_dir, "summary.md"), "w") as f:
        f.write(md_all)
    print(f"Markdown tables and raw JSON: {res_dir}/", file=sys.stderr)


if __name__ == "__main__":
    main()
