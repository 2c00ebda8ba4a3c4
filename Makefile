# The quick start: `make demo` (main job: the gallery) and `make test` (every test).
# Both install missing Debian packages first (scripts/install-deps.sh, idempotent).
JOBS ?= $(shell nproc)
BUILD ?= build
ASAN_BUILD ?= build-asan
BENCH_BUILD ?= build-bench
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 120
# Ninja for new build trees: it compiles a target's sources while the libraries they link
# are still being built (the Makefile generator waits for whole targets), which keeps both
# cores busy. A tree configured earlier keeps its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

.PHONY: deps configure build demo explorer test test-release test-headers test-asan test-asan-smoke bench bench-w10 fuzz package clean

deps:
	@scripts/install-deps.sh build

configure: deps
	cmake -S . -B $(BUILD) $(call generator,$(BUILD)) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The gallery alone: the library's io layer and the figures, no test executables.
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target casteljau-gallery
	$(BUILD)/apps/gallery/casteljau-gallery $(BUILD)/gallery
	@echo "gallery: $(abspath $(BUILD)/gallery/index.html)"

# The explorer: builds the program and serves the page (prints its address; Ctrl-C stops it).
# PORT=0 takes any free port. FONT_DIR: the fonts the explorer's text outlines may use
# (the `glyph` command; DejaVu's by default, when installed).
PORT ?= 8080
FONT_DIR ?= /usr/share/fonts/truetype/dejavu
explorer: configure
	cmake --build $(BUILD) -j $(JOBS) --target casteljau_cli
	$(BUILD)/apps/cli/casteljau serve --port $(PORT) $(if $(wildcard $(FONT_DIR)),--font-dir $(FONT_DIR))

# The header check (ctest label `headers`, tests/headers): every header alone with g++ and
# with clang, and every header with a user's file at -O0 and -O2 with g++ and clang, two
# compilations at a time; 518 s of CPU in session 17 (1035 s of wall at a load of 5-16;
# 280 s of CPU before each header alone was compiled by both compilers):
# left out of make test until it is cheaper; `make test-headers` runs it. make test runs
# its cheap version (label `headers-quick`: every header together, syntax only, per
# compiler). ctest's -L and -LE take regular expressions: anchored, so that `headers`
# does not also select `headers-quick`.
test-release: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE '^headers$$'

test-headers: build
	cd $(BUILD) && ctest --output-on-failure -L '^headers$$'

# The sanitizer build: clang at -O0 with line tables only. With ASan, -O1 triples the
# compile time for no gain in what the tests detect here, and clang with line tables
# compiles in half of g++ -g's CPU time (35 s against 68 s for src/io/any_curve.cpp);
# stack traces keep file and line.
ASAN_CMAKE = cmake -S . -B $(ASAN_BUILD) $(call generator,$(ASAN_BUILD)) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -gline-tables-only" -DCASTELJAU_SANITIZE=ON
test-asan: deps
	$(ASAN_CMAKE)
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -LE no-sanitizer

# The command line under the sanitizers (not part of `make test` since session 8: the
# sanitizer build compiles the io layer a second time, about 110 s of the 7-minute budget
# on 2 cores): the whole library behind it, on the fuzz corpus (every command, in one
# process), the hostile inputs and every command on every curve type (cli_registry).
# test_cli.py's contract checks run on the Release program only: under the sanitizers each
# of its ~300 processes starts in about 0.13 s (43 s in all). Run this (about 2 minutes)
# or `make test-asan` (every test under them, about 10 minutes) before merging a change
# to the library; `make fuzz` runs libFuzzer with the same sanitizers. The suites of the
# newer commands (offset, surfaces, the queries' extensions) run too: the fuzz corpus has
# one seed per command, they reach their geometry.
ASAN_SMOKE_TESTS = ^(fuzz_corpus_replay|cli\.hostile|cli_registry|cli_offset|cli_surfaces|cli_surface_mesh|cli_queries_ext)$$
test-asan-smoke: deps
	$(ASAN_CMAKE)
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target casteljau_cli casteljau_fuzz_replay
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -R '$(ASAN_SMOKE_TESTS)'

test: test-release
	@echo "make test: all tests passed (Release build; sanitizers: make test-asan-smoke, make test-asan)"

# W9's Python package (casteljau_python, for bench/w9.py) is built apart: without pybind11
# the target is missing, the build of it fails harmlessly and run.py skips W9.
bench:
	@scripts/install-deps.sh build bench
	cmake -S . -B $(BENCH_BUILD) -DCMAKE_BUILD_TYPE=Release -DCASTELJAU_BUILD_BENCH=ON -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_APPS=OFF
	cmake --build $(BENCH_BUILD) -j $(JOBS) --target casteljau_bench_w1_native casteljau_bench_w1_generic casteljau_bench_w2 casteljau_bench_w3 casteljau_bench_w4 casteljau_bench_w5 casteljau_bench_w6 casteljau_bench_w7 casteljau_bench_w8
	-cmake --build $(BENCH_BUILD) -j $(JOBS) --target casteljau_python
	/usr/bin/python3 bench/run.py $(BENCH_BUILD)

# W10 (docs/performance.md): `casteljau serve` under a bounded load on the loopback address
# against `--jsonl` in one process; about a minute. Writes $(BENCH_BUILD)/bench-results/W10.json.
bench-w10: configure
	cmake --build $(BUILD) -j $(JOBS) --target casteljau_cli
	/usr/bin/python3 bench/w10.py $(BUILD)/apps/cli/casteljau $(BENCH_BUILD)/bench-results

# libFuzzer (clang) with ASan+UBSan on the fuzz target FUZZ_TARGET (tests/fuzz: `request`,
# the JSON request reader and the command it names; `svg`, SVG documents, path data and
# transform lists; `http`, the server's request path from the bytes of a connection), for FUZZ_SECONDS. The whole project is
# instrumented for coverage (CASTELJAU_FUZZ); -O0 with line tables, as the sanitizer build.
# New inputs go to $(FUZZ_BUILD)/corpus-$(FUZZ_TARGET), crashes to $(FUZZ_BUILD)/crash-*;
# libFuzzer's final statistics (edges: cov, inputs: number_of_executed_units) end the run.
# Copy a crash into tests/fuzz/corpus/$(FUZZ_TARGET)/ once fixed, so every `make test`
# replays it (casteljau_fuzz_replay $(FUZZ_TARGET) FILE replays one input).
FUZZ_TARGET ?= request
# More libFuzzer options, e.g. FUZZ_FLAGS=-timeout=300 on a loaded machine (the timeout is
# wall-clock time).
FUZZ_FLAGS ?=
FUZZ_DICT = $(wildcard tests/fuzz/$(FUZZ_TARGET).dict)
fuzz:
	@scripts/install-deps.sh build fuzz
	cmake -S . -B $(FUZZ_BUILD) $(call generator,$(FUZZ_BUILD)) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
	  "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -gline-tables-only" -DCASTELJAU_SANITIZE=ON -DCASTELJAU_FUZZ=ON
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target casteljau_fuzz_$(FUZZ_TARGET)
	mkdir -p $(FUZZ_BUILD)/corpus-$(FUZZ_TARGET)
	cd $(FUZZ_BUILD) && tests/fuzz/casteljau_fuzz_$(FUZZ_TARGET) -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	  -rss_limit_mb=4096 -print_final_stats=1 $(if $(FUZZ_DICT),-dict=$(abspath $(FUZZ_DICT))) \
	  $(FUZZ_FLAGS) -artifact_prefix=$(abspath $(FUZZ_BUILD))/ corpus-$(FUZZ_TARGET) $(abspath tests/fuzz/corpus/$(FUZZ_TARGET))

# A Debian package of the library, its CMake package and the `casteljau` program (CPack);
# prints the .deb's path. `apt install ./build/casteljau_*.deb` installs it with its
# dependencies (`dpkg -i` alone: then apt-get install -f). The install check (ctest
# install_consumer, in make test) installs it with dpkg into a scratch root.
package: build
	cd $(BUILD) && cpack -G DEB
	@ls $(abspath $(BUILD))/casteljau_*.deb

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(BENCH_BUILD) $(FUZZ_BUILD)
