#!/usr/bin/env python3
"""The public headers compile on their own and together, warning-free, in a user's build.

Each header of include/casteljau alone (-fsyntax-only, with every compiler given), and one translation unit with
every header followed by a user's file (tests/headers/user.cpp, which instantiates the
header algorithms) compiled to an object at -O0 and -O2, with every compiler given,
under -std=c++20 -Wall -Wextra -Wpedantic -Werror. Catches a header that misses an
include, names defined twice (two headers that do not compile together), and warnings
a user's flags bring out of header code (GCC's -Wpsabi at -O0, for one).

--quick (the `make test` version, ctest label `headers-quick`): only the translation unit
of every header together (casteljau.hpp first, no user file), -fsyntax-only at -O0, with
each compiler given: names defined twice, a header that does not parse after the others,
warnings from non-template header code. No object code (so no -Wpsabi) and no header alone.

usage: check_headers.py INCLUDE_DIR USER_FILE --isystem DIR ... --compiler CXX ... [--jobs N] [--quick]
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys
import tempfile
import time

FLAGS = ["-std=c++20", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("include")
    ap.add_argument("user")
    ap.add_argument("--isystem", action="append", default=[])
    ap.add_argument("--compiler", action="append", default=[])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    compilers = [c for c in a.compiler if c]
    if not compilers:
        print("no compiler given")
        return 1
    headers = sorted(
        os.path.relpath(os.path.join(d, f), a.include)
        for d, _, files in os.walk(os.path.join(a.include, "casteljau"))
        for f in files
        if f.endswith(".hpp"))
    base = [f"-I{a.include}"] + [x for d in a.isystem for x in ("-isystem", d)]
    with tempfile.TemporaryDirectory(prefix="casteljau_headers_") as tmp:
        return check(a, compilers, headers, base, tmp)


def check(a, compilers, headers, base, tmp):
    if a.quick:
        return run_jobs(a, compilers, headers, quick_jobs(compilers, headers, base, tmp))
    jobs = []  # (name, command, stdin text)
    # Each header alone, with every compiler: a header that misses an include, or that
    # leans on one compiler's leniency (two-phase lookup, an extension) fails here. A header
    # alone instantiates nothing, so syntax only sees all its code at any -O level.
    for cxx in compilers:
        for h in headers:
            jobs.append((f"{h} alone ({cxx})", [cxx, *FLAGS, *base, "-fsyntax-only", "-x", "c++", "-"], f'#include "{h}"\n'))
    together = os.path.join(tmp, "together.cpp")
    with open(together, "w") as f:
        for h in headers:
            f.write(f'#include "{h}"\n')
        f.write(f'#include "{os.path.abspath(a.user)}"\n')
    for cxx in compilers:
        for level in ("-O0", "-O2"):
            obj = os.path.join(tmp, f"together_{os.path.basename(cxx)}{level}.o")
            jobs.append((f"every header and user.cpp ({cxx} {level})", [cxx, *FLAGS, *base, level, "-c", together, "-o", obj], None))
    return run_jobs(a, compilers, headers, jobs)


def quick_jobs(compilers, headers, base, tmp):
    """Every header in one translation unit, the umbrella first, syntax only, per compiler."""
    together = os.path.join(tmp, "together_quick.cpp")
    umbrella = "casteljau/casteljau.hpp"
    with open(together, "w") as f:
        for h in sorted(headers, key=lambda h: h != umbrella):
            f.write(f'#include "{h}"\n')
    return [(f"every header together, syntax only ({cxx} -O0)", [cxx, *FLAGS, *base, "-O0", "-fsyntax-only", together], None)
            for cxx in compilers]


def run_jobs(a, compilers, headers, jobs):
    def run(job):
        name, cmd, text = job
        t0 = time.monotonic()
        r = subprocess.run(cmd, input=text, capture_output=True, text=True)
        return name, r.returncode, r.stderr, time.monotonic() - t0

    failed = 0
    t0 = time.monotonic()
    # the long compilations first, so that the short ones fill in around them
    jobs.sort(key=lambda j: j[2] is not None)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        for name, rc, err, secs in ex.map(run, jobs):
            if rc != 0 or err.strip():
                failed += 1
                print(f"FAIL {name} ({secs:.1f} s):\n{err}")
            elif secs > 5:
                print(f"ok   {name} ({secs:.1f} s)")
    print(f"{len(jobs) - failed} of {len(jobs)} compilations clean ({len(headers)} headers, compilers {' '.join(compilers)}) "
          f"in {time.monotonic() - t0:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
