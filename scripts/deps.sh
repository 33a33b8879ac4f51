#!/usr/bin/env bash
# Installs the Debian packages locus needs, if any is missing (idempotent). Sourced by the
# other scripts: `ensure_packages pkg...`.
ensure_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "need root to install: ${missing[*]}" >&2; return 1; }
    sudo="sudo"
  fi
  echo "installing Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
# The toolchain every build needs.
LOCUS_BUILD_PACKAGES=(g++ cmake ninja-build libcli11-dev)
# Test and benchmark dependencies: GoogleTest, GMP rationals (exact oracle), Google Benchmark,
# Eigen (test/benchmark oracle for the numerics).
LOCUS_TEST_PACKAGES=(libgtest-dev libgmp-dev libbenchmark-dev libeigen3-dev)
# Clang with its sanitizer and libFuzzer runtimes: the sanitizer build and the fuzz step of
# scripts/test.
LOCUS_CLANG_PACKAGES=(clang-14 libclang-rt-14-dev)
# The Python step of scripts/test: the pybind11 module and its tests (numpy in and out, scipy
# and shapely as oracles, Dask for the scale-out example), all for Debian's /usr/bin/python3.
LOCUS_PYTHON_PACKAGES=(pybind11-dev python3-dev python3-numpy python3-scipy python3-shapely
                       python3-pytest python3-dask python3-distributed)
# Peer libraries of the benchmarks (scripts/bench, scripts/bench_table), compared in the same run.
LOCUS_BENCH_PEER_PACKAGES=(libcgal-dev libqhull-dev libboost-dev libccd-dev libfcl-dev libassimp-dev)
# The gallery's browser check (gallery/browser_check.sh, a CTest test): headless Chromium.
LOCUS_BROWSER_PACKAGES=(chromium)
