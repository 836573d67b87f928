#!/usr/bin/env bash
# Coverage-guided fuzzing of rtlab's parsers with libFuzzer (docs/testing.md "Fuzzing").
set -euo pipefail
cd "$(dirname "$0")/.."

ALL_TARGETS=(gltf glb preset script bookmarks cli pfm exr png)
usage() {
  cat <<USAGE
Usage: scripts/fuzz.sh [--merge] [SECONDS] [TARGET...]

Configures build-fuzz/ (clang-14, -DRTLAB_FUZZ=ON: libFuzzer + ASan + UBSan), builds the fuzz
targets and runs each for SECONDS (default 60) from its seed corpus (tests/fuzz/corpus/TARGET and
tests/fuzz/regressions/TARGET) with its dictionary (tests/fuzz/dict). New corpus entries and
crash inputs go to a scratch folder, never into the repository: \$FUZZ_OUT, default
build-fuzz/fuzz-out/TARGET/{corpus,artifacts,log.txt}. Prints per target the executions, the
new corpus entries, the coverage (edges) before and after, and the crashes; exits 1 if any target
crashed, hung (over 10 s on one input), leaked or ran out of memory (2 GiB).

Targets: ${ALL_TARGETS[*]} (default: all).
Options:
  --merge    afterwards, merge each target's new entries that add coverage into
             tests/fuzz/corpus/TARGET (libFuzzer -merge=1; commit them if they are small)
  -h, --help this help

Needs clang-14 and libclang-rt-14-dev (Debian). Replaying the corpora without fuzzing is a ctest
test of every normal build: ctest -L fuzz.
USAGE
}

seconds=60 merge=0 targets=()
for arg in "$@"; do
  case "$arg" in
    -h|--help) usage; exit 0 ;;
    --merge) merge=1 ;;
    -*) echo "fuzz: error: unknown option '$arg' (see 'scripts/fuzz.sh --help')" >&2; exit 2 ;;
    *)
      if [[ "$arg" =~ ^[0-9]+$ ]]; then
        if (( arg < 1 )); then echo "fuzz: error: SECONDS must be at least 1, got '$arg'" >&2; exit 2; fi
        seconds=$arg
      elif [[ " ${ALL_TARGETS[*]} " == *" $arg "* ]]; then
        targets+=("$arg")
      else
        echo "fuzz: error: '$arg' is neither a number of seconds nor a target (targets: ${ALL_TARGETS[*]})" >&2
        exit 2
      fi ;;
  esac
done
(( ${#targets[@]} )) || targets=("${ALL_TARGETS[@]}")

for tool in clang-14 clang++-14; do
  command -v "$tool" >/dev/null || { echo "fuzz: error: $tool not found (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 1; }
done
if [[ ! -f build-fuzz/CMakeCache.txt ]]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DRTLAB_FUZZ=ON \
    -DRTLAB_UNIT_ONLY=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" >/dev/null
elif ! grep -q '^RTLAB_FUZZ:BOOL=ON' build-fuzz/CMakeCache.txt; then
  echo "fuzz: error: build-fuzz/ is configured without -DRTLAB_FUZZ=ON; remove it and rerun" >&2
  exit 1
fi
echo "fuzz: building ${targets[*]/#/fuzz_} in build-fuzz/ (log: build-fuzz/build.log)" >&2
if ! cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)" --target "${targets[@]/#/fuzz_}" >build-fuzz/build.log 2>&1; then
  grep -E "error" build-fuzz/build.log | head -20 >&2 || true
  echo "fuzz: error: the fuzz build failed; see build-fuzz/build.log" >&2
  exit 1
fi

out=${FUZZ_OUT:-build-fuzz/fuzz-out}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# JSON-based targets fuzz with the JSON syntax dictionary plus their own; glb adds glTF's keys.
dict_parts() {
  case "$1" in
    gltf) echo json gltf ;;
    glb) echo json gltf glb ;;
    preset|script|bookmarks) echo json "$1" ;;
    *) echo "$1" ;;
  esac
}
stat_of() { sed -n "s/^stat::$2: *//p" "$1" | tail -1; }
# The coverage (edges) on libFuzzer's first status line of kind $2 (INITED) or its last (DONE, ...).
cov_first() { grep -E "^#[0-9]+[[:space:]]+$2 " "$1" | head -1 | sed -n 's/.* cov: \([0-9]*\).*/\1/p'; }
cov_last() { grep -E "^#[0-9]+[[:space:]]+[A-Z]+ +cov: " "$1" | tail -1 | sed -n 's/.* cov: \([0-9]*\).*/\1/p'; }

failed=0
printf '%-10s %8s %12s %8s %10s %10s  %s\n' target seconds execs new_units cov_start cov_end findings
for t in "${targets[@]}"; do
  dir="$out/$t"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  dict="$dir/fuzz.dict"
  : >"$dict"
  for part in $(dict_parts "$t"); do cat "tests/fuzz/dict/$part.dict" >>"$dict"; done
  status=0
  "build-fuzz/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -dict="$dict" -artifact_prefix="$dir/artifacts/" -print_final_stats=1 \
    "$dir/corpus" "tests/fuzz/corpus/$t" "tests/fuzz/regressions/$t" >"$dir/log.txt" 2>&1 || status=$?
  findings=$(find "$dir/artifacts" -type f -newer "$dict" -printf '%f ' 2>/dev/null)
  if (( status != 0 )) || [[ -n "$findings" ]]; then
    failed=1
    [[ -n "$findings" ]] || findings="exit $status, see $dir/log.txt"
  fi
  printf '%-10s %8s %12s %8s %10s %10s  %s\n' "$t" "$seconds" "$(stat_of "$dir/log.txt" number_of_executed_units)" \
    "$(stat_of "$dir/log.txt" new_units_added)" "$(cov_first "$dir/log.txt" INITED)" "$(cov_last "$dir/log.txt")" \
    "${findings:-none}"
  if (( merge )) && (( status == 0 )); then
    "build-fuzz/tests/fuzz/fuzz_$t" -merge=1 "tests/fuzz/corpus/$t" "$dir/corpus" >>"$dir/log.txt" 2>&1
  fi
done
if (( failed )); then
  echo "fuzz: error: a target crashed, hung or leaked: the inputs are in $out/TARGET/artifacts, the reports in $out/TARGET/log.txt" >&2
  exit 1
fi
