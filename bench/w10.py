#!/usr/bin/env python3
"""W10, serving requests (docs/performance.md): `casteljau serve` on the loopback address
under a bounded load, against the same requests through the command line's `--jsonl` in
one process.

Usage: bench/w10.py CASTELJAU OUT_DIR [--connections 8] [--jobs N]

  (a) eval: 20,000 requests, each a random cubic (splitmix64, seed 10: per request the
      four points' x, y in [0, 1), in that order) at the 100 parameters j / 99;
  (b) mixed: 2,000 requests, in turn `intersect` of two random cubics, `flatten` of one at
      tolerance 1e-3, `project` of a random point (drawn after the cubic) onto one.
Each set goes over CONNECTIONS concurrent keep-alive connections (bench/w10_client.cpp,
compiled here into OUT_DIR), after 200 warm-up requests that are not counted. The
reference: the set through `casteljau COMMAND --jsonl` (throughput: all lines at once, one
process per command; latency: one line at a time through a pipe, the response read
before the next line is written).

Writes OUT_DIR/W10.json in Google Benchmark's JSON shape (names W10/casteljau/<serve|jsonl>/
<eval|mixed>, counters rps, p50_us, p99_us, errors) and prints the table and the goals:
p99 under 5 ms for eval at 8 connections, 0 errors, serve at least 0.5x jsonl's rps.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

MASK = (1 << 64) - 1


class SplitMix64:
    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def uniform(self):
        return (self.next() >> 11) * 2.0 ** -53


def cubic(rng):
    return {"type": "bezier", "points": [[rng.uniform(), rng.uniform()] for _ in range(4)]}


def dump(request):
    return json.dumps(request, separators=(",", ":"))


def workloads():
    rng = SplitMix64(10)
    ts = [j / 99 for j in range(100)]
    evals = [("eval", dump({"curve": cubic(rng), "t": ts})) for _ in range(20000)]
    mixed = []
    for i in range(2000):
        if i % 3 == 0:
            mixed.append(("intersect", dump({"curves": [cubic(rng), cubic(rng)]})))
        elif i % 3 == 1:
            mixed.append(("flatten", dump({"curve": cubic(rng), "tolerance": 1e-3})))
        else:
            c = cubic(rng)
            mixed.append(("project", dump({"curve": c, "point": [rng.uniform(), rng.uniform()]})))
    return {"eval": evals, "mixed": mixed}


def percentile(sorted_values, q):
    return sorted_values[min(len(sorted_values) - 1, int(q * len(sorted_values)))]


def build_client(out_dir):
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "w10_client.cpp")
    exe = os.path.join(out_dir, "w10_client")
    if not os.path.exists(exe) or os.path.getmtime(exe) < os.path.getmtime(source):
        subprocess.run(["c++", "-std=c++17", "-O2", "-pthread", source, "-o", exe], check=True)
    return exe


def serve_run(client, host, port, connections, requests, out_dir, name):
    path = os.path.join(out_dir, f"w10-{name}.requests")
    with open(path, "w") as f:
        for command, body in requests:
            f.write(command + "\t" + body + "\n")
    out = subprocess.run([client, host, str(port), str(connections), path], stdout=subprocess.PIPE, check=True,
                         timeout=600).stdout.decode().splitlines()
    wall = float(out[0].split()[1])
    lat, errors = [], 0
    for line in out[1:]:
        us, status = line.split()
        lat.append(float(us))
        errors += status != "200"
    lat.sort()
    return {"seconds": wall, "rps": len(requests) / wall, "p50_us": percentile(lat, 0.5), "p99_us": percentile(lat, 0.99),
            "errors": errors}


def jsonl_run(binary, requests):
    by_command = {}
    for command, body in requests:
        by_command.setdefault(command, []).append(body)
    # Throughput: each command's lines at once, one process each.
    wall, errors = 0.0, 0
    for command, bodies in by_command.items():
        start = time.perf_counter()
        out = subprocess.run([binary, command, "--jsonl"], input=("\n".join(bodies) + "\n").encode(), stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, timeout=600).stdout.decode().splitlines()
        wall += time.perf_counter() - start
        errors += sum(1 for line in out if line.startswith('{"error"')) + (len(bodies) - len(out))
    # Latency: one line at a time, in the input order, one process per command.
    procs = {c: subprocess.Popen([binary, c, "--jsonl"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
             for c in by_command}
    lat = []
    for command, body in requests:
        p = procs[command]
        start = time.perf_counter()
        p.stdin.write(body.encode() + b"\n")
        p.stdin.flush()
        p.stdout.readline()
        lat.append((time.perf_counter() - start) * 1e6)
    for p in procs.values():
        p.stdin.close()
        p.wait(timeout=60)
    lat.sort()
    return {"seconds": wall, "rps": len(requests) / wall, "p50_us": percentile(lat, 0.5), "p99_us": percentile(lat, 0.99),
            "errors": errors}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("casteljau")
    ap.add_argument("out_dir")
    ap.add_argument("--connections", type=int, default=8)
    ap.add_argument("--jobs", type=int, default=0, help="the server's --jobs (default: its own, the number of cores)")
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    client = build_client(args.out_dir)
    sets = workloads()

    cmd = [args.casteljau, "serve", "--port", "0"] + (["--jobs", str(args.jobs)] if args.jobs else [])
    server = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    line = server.stdout.readline().decode()
    m = re.search(r"http://(.+):(\d+)/", line)
    if not m:
        server.kill()
        sys.exit("w10: the server did not start: " + line)
    host, port = m.group(1), int(m.group(2))
    rows = {}
    try:
        for name, requests in sets.items():
            serve_run(client, host, port, args.connections, requests[:200], args.out_dir, name + "-warmup")
            rows[f"W10/casteljau/serve/{name}"] = serve_run(client, host, port, args.connections, requests, args.out_dir, name)
    finally:
        server.terminate()
        server.wait(timeout=10)
    for name, requests in sets.items():
        rows[f"W10/casteljau/jsonl/{name}"] = jsonl_run(args.casteljau, requests)

    benchmarks = [{"name": n, "run_name": n, "run_type": "iteration", "iterations": 1, "real_time": r["seconds"] * 1e3,
                   "cpu_time": r["seconds"] * 1e3, "time_unit": "ms", "rps": r["rps"], "p50_us": r["p50_us"],
                   "p99_us": r["p99_us"], "errors": r["errors"]} for n, r in rows.items()]
    with open(os.path.join(args.out_dir, "W10.json"), "w") as f:
        json.dump({"context": {"connections": args.connections, "server": line.strip(), "load_average": os.getloadavg()},
                   "benchmarks": benchmarks}, f, indent=1)
    print(f"W10 ({line.strip()}; {args.connections} connections; load average {os.getloadavg()[0]:.1f})")
    print("| benchmark | requests/s | p50 us | p99 us | errors |")
    print("| --- | --- | --- | --- | --- |")
    for n, r in rows.items():
        print(f"| {n} | {r['rps']:.0f} | {r['p50_us']:.0f} | {r['p99_us']:.0f} | {r['errors']} |")
    for name in sets:
        s, j = rows[f"W10/casteljau/serve/{name}"], rows[f"W10/casteljau/jsonl/{name}"]
        print(f"{name}: serve / jsonl throughput {s['rps'] / j['rps']:.2f}x (goal >= 0.5), errors {s['errors']} (goal 0)"
              + (f", p99 {s['p99_us'] / 1e3:.2f} ms (goal < 5 ms)" if name == "eval" else ""))


if __name__ == "__main__":
    main()
