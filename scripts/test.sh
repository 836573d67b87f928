#!/usr/bin/env bash
# Sets up, builds, and runs every test: unit, render (headless on llvmpipe) and command-line
# tests with ctest, then the unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer.
# Each step prints its wall time (docs/performance.md, "Test suite and CI", has the measured ones).
set -euo pipefail
cd "$(dirname "$0")/.."
took() { echo "test: $1 took $((SECONDS - step_start)) s" >&2; step_start=$SECONDS; }
step_start=$SECONDS
# A build directory configured without the render and CLI tests (or build-asan/ without the
# sanitizers) would pass with tests silently missing: refuse it before building.
bash scripts/check_build_dir.sh build full
bash scripts/check_build_dir.sh build-asan sanitizer
bash scripts/setup.sh --test-deps
took "set-up and build"
jobs=$(nproc 2>/dev/null || echo 2)
export RTLAB_LOG=${RTLAB_LOG:-warn}

echo "== unit, render and CLI tests (build/) =="
(cd build && ctest --output-on-failure --no-tests=error -j"$jobs")
took "unit, render and CLI tests"

echo "== unit tests under ASan + UBSan (build-asan/) =="
if [[ ! -f build-asan/CMakeCache.txt ]]; then
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DRTLAB_SANITIZE=ON -DRTLAB_UNIT_ONLY=ON >/dev/null
fi
if ! cmake --build build-asan -j"$jobs" >build-asan/build.log 2>&1; then
  grep -E "error|Error" build-asan/build.log | head -20 >&2 || true
  echo "test: error: the sanitizer build failed; see build-asan/build.log" >&2
  exit 1
fi
took "sanitizer build"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd build-asan && ctest --output-on-failure --no-tests=error -j"$jobs")
took "sanitizer unit tests"
