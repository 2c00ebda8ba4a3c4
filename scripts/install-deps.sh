#!/usr/bin/env bash
# Installs the Debian packages casteljau needs; idempotent, runs `apt-get update` only
# when something is missing. Usage: scripts/install-deps.sh [build|bench|fuzz]...
#   build (default): compilers (g++; clang for the sanitizer build), CMake, libraries, test tools (enough for `make demo` and `make test`)
#   bench: also the peer libraries benchmarked in bench/ (lib2geom, OpenCASCADE, GSL, SISL, cairo) and the W3 font
#   fuzz: nothing more (clang and its libFuzzer runtime are in build; kept for `make fuzz`)
set -euo pipefail

build_pkgs=(
  g++ clang libclang-rt-dev lld make cmake ninja-build pkg-config python3 dpkg-dev  # lld: the linker of every target (CMakeLists.txt)
  libeigen3-dev nlohmann-json3-dev libcli11-dev libpugixml-dev librsvg2-bin
  libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
  libmpfr-dev libgmp-dev
  python3-scipy python3-mpmath python3-fonttools
  libocct-modeling-data-dev libocct-foundation-dev
  libfreetype-dev fonts-dejavu-core fonts-urw-base35
  python3-dev python3-pybind11 pybind11-dev python3-numpy python3-pytest python3-dask python3-distributed  # the Python package (python/, docs/python.md)
  libcpp-httplib-dev chromium chromium-driver python3-selenium  # casteljau serve (cpp-httplib) and its browser test (headless chromium)
  # HarfBuzz: the glyph command's GPOS pair kerning (issue 17)
  libharfbuzz-dev
  adwaita-icon-theme  # real SVG drawings for import_svg's pixel comparison with librsvg (tests/cli/test_import_svg.py)
)
fuzz_pkgs=()
bench_pkgs=(lib2geom-dev libocct-modeling-data-dev libocct-foundation-dev libocct-modeling-algorithms-dev libboost-dev libdouble-conversion-dev libgsl-dev libsisl-dev
            libcairo2-dev libfreetype-dev fonts-dejavu-core)

want=("${build_pkgs[@]}")
for arg in "$@"; do
  case "$arg" in
    build) ;;
    bench) want+=("${bench_pkgs[@]}") ;;
    fuzz) want+=("${fuzz_pkgs[@]}") ;;
    *) echo "install-deps.sh: unknown package set '$arg' (expected build, bench or fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps.sh: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
