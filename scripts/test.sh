#!/usr/bin/env bash
# Sets up, builds and runs every test (docs/testing.md):
#   build/       Release, the whole program; ctest runs every test: unit, render (headless on
#                llvmpipe), command-line and the fuzz-corpus replays; then the suite's GL error total.
#   build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer (Debug) over rtlab_core: the unit
#                tests and the fuzz-corpus replays (the parsers).
#   build-tsan/  ThreadSanitizer over the progressive reference's thread tests (rtlab_tsan_tests).
#   --sanitize-all  also build-asan-all/: the whole program under ASan + UBSan and the whole suite
#                there (the rtlab binary, the render and CLI tests). Far more than the 20 minutes
#                .ci/run may take on the 2-core CI machine, so not part of it (docs/performance.md,
#                "Issue 20: sanitizers and the CI budget").
# Each step prints its wall time (docs/performance.md, "Test suite and CI", has the measured ones).
# Any sanitizer report (in a test, in rtlab run by a CLI test, in a child process) fails the run:
# the reports are written under <dir>/sanitizer-logs/ and printed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
took() { echo "test: $1 took $((SECONDS - step_start)) s" >&2; step_start=$SECONDS; }
step_start=$SECONDS
all=0
case ${1:-} in
  --sanitize-all) all=1 ;;
  "") ;;
  -h | --help) sed -n '2,16p' "$0"; exit 0 ;;
  *) echo "test: error: unknown option '$1' (scripts/test.sh [--sanitize-all])" >&2; exit 2 ;;
esac
# A build directory configured without the tests it is meant to run would pass with tests silently
# missing: refuse it before building.
bash scripts/check_build_dir.sh build full
bash scripts/check_build_dir.sh build-asan sanitizer
bash scripts/check_build_dir.sh build-tsan tsan
if ((all)); then bash scripts/check_build_dir.sh build-asan-all sanitizer-full; fi
jobs=$(nproc 2>/dev/null || echo 2)
export RTLAB_LOG=${RTLAB_LOG:-warn}
bash scripts/setup.sh --test-deps
took "set-up and build"
echo "== unit, render, CLI tests and fuzz replays (build/) =="
(cd build && ctest --output-on-failure --no-tests=error -j"$jobs")
# Every GL error in a test process fails its test; the suite's total (0) is summed from each test
# binary's report (docs/testing.md, "GL errors").
bash scripts/gl_error_total.sh build
took "unit, render and CLI tests"

# build DIR KIND TARGET CMAKE_OPTIONS...: configures DIR once, then builds TARGET into it.
build() {
  local dir=$1 kind=$2 target=$3
  shift 3
  if [[ ! -f $dir/CMakeCache.txt ]]; then
    cmake -S . -B "$dir" "$@" >/dev/null
  fi
  echo "test: building $dir/ (log in $dir/build.log)" >&2
  if ! cmake --build "$dir" -j"$jobs" --target "$target" >"$dir/build.log" 2>&1; then
    grep -E "error|Error" "$dir/build.log" | head -20 >&2 || true
    check_logs "$dir" || true # a report while gtest listed a test executable's tests
    echo "test: error: the $kind build failed; see $dir/build.log" >&2
    exit 1
  fi
}

# Fails the run when DIR/sanitizer-logs/ holds a report (printing them all).
check_logs() {
  local logs=$1/sanitizer-logs
  if compgen -G "$logs/*" >/dev/null; then
    for f in "$logs"/*; do
      echo "== $f" >&2
      cat "$f" >&2
    done
    echo "test: error: sanitizer reports in $logs/ (above)" >&2
    return 1
  fi
}

# halt_on_error/abort_on_error: the first report ends the process; log_path: reports go to files
# (a CLI test reads rtlab's stderr line by line, and a report must fail the run whatever the test
# asserts about exit codes); detect_leaks: LeakSanitizer at every exit. Exported before the builds
# too: gtest_discover_tests runs each test executable at build time. The suppressions, each with
# its reason, are Mesa's and TBB's/Embree's alone (tests/sanitizers/).
supp=$PWD/tests/sanitizers
# sanitize_env DIR: the options below, the reports into DIR/sanitizer-logs/ (emptied first).
sanitize_env() {
  local logs=$PWD/$1/sanitizer-logs
  rm -rf "$logs" && mkdir -p "$logs"
  export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1:log_path=$logs/asan
  export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1:abort_on_error=1:log_path=$logs/ubsan
  export TSAN_OPTIONS=suppressions=$supp/tsan.supp:halt_on_error=1:abort_on_error=1:history_size=7:second_deadlock_stack=1:log_path=$logs/tsan
}

# Debug (-O0, line tables only), asserts on: instrumented, -O1 compiles far slower than -O0
# (exercise_def.cpp: 65.8 s against 28.1 s; docs/performance.md, "Issue 20").
debug_flags=(-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DCMAKE_C_FLAGS_DEBUG=-g1)
sanitize_env build-asan
build build-asan "ASan + UBSan" all "${debug_flags[@]}" -DRTLAB_SANITIZE=ON -DRTLAB_UNIT_ONLY=ON
took "ASan + UBSan build"
echo "== unit tests and fuzz replays under ASan + UBSan (build-asan/) =="
(cd build-asan && ctest --output-on-failure --no-tests=error -j"$jobs") || { check_logs build-asan || true; exit 1; }
check_logs build-asan
took "tests under ASan + UBSan"

# -O1 -g1 without NDEBUG for the one small library: its tests trace rays and wait for the
# progressive reference to converge (27 tests).
flags="-O1 -g1"
sanitize_env build-tsan
build build-tsan "ThreadSanitizer" rtlab_tsan_tests -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$flags" \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$flags" -DRTLAB_TSAN=ON -DRTLAB_UNIT_ONLY=ON
took "ThreadSanitizer build"
echo "== the reference's thread tests under ThreadSanitizer (build-tsan/) =="
(cd build-tsan && ctest --output-on-failure --no-tests=error -j"$jobs") || { check_logs build-tsan || true; exit 1; }
check_logs build-tsan
took "tests under ThreadSanitizer"

if ((all)); then
  sanitize_env build-asan-all
  build build-asan-all "whole-program ASan + UBSan" all "${debug_flags[@]}" -DRTLAB_SANITIZE=ON
  took "whole-program ASan + UBSan build"
  echo "== every test under ASan + UBSan (build-asan-all/) =="
  (cd build-asan-all && ctest --output-on-failure --no-tests=error -j"$jobs") || { check_logs build-asan-all || true; exit 1; }
  check_logs build-asan-all
  bash scripts/gl_error_total.sh build-asan-all
  took "every test under ASan + UBSan"
fi
