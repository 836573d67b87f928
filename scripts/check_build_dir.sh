#!/usr/bin/env bash
# Refuses a build directory whose configuration would silently drop tests (scripts/test.sh runs it
# before building): DIR's CMakeCache.txt, if there is one, must be the KIND the test script expects.
#   full            build/, every test: RTLAB_UNIT_ONLY off (the render and CLI tests are built),
#                   BUILD_TESTING on
#   sanitizer       build-asan/, the unit tests and the fuzz replays under ASan + UBSan:
#                   RTLAB_SANITIZE on, BUILD_TESTING on
#   sanitizer-full  build-asan-all/ (scripts/test.sh --sanitize-all), the whole suite under ASan +
#                   UBSan: RTLAB_SANITIZE on, RTLAB_UNIT_ONLY off, BUILD_TESTING on
#   tsan            build-tsan/, the reference's thread tests under TSan: RTLAB_TSAN on, BUILD_TESTING on
# No CMakeCache.txt: nothing to check (the test script configures DIR itself). Exit 0 when DIR
# fits, 1 with one line on stderr when it does not, 2 on a usage error.
#   bash scripts/check_build_dir.sh DIR full|sanitizer|sanitizer-full|tsan
set -euo pipefail
case ${2:-} in full | sanitizer | sanitizer-full | tsan) ;; *) false ;; esac && [[ $# -eq 2 ]] || {
  echo "check_build_dir: error: usage: check_build_dir.sh DIR full|sanitizer|sanitizer-full|tsan" >&2
  exit 2
}
dir=$1 kind=$2
cache=$dir/CMakeCache.txt
[[ -f $cache ]] || exit 0

# The value of cache entry $1 as on/off (CMake's true constants; absent: $2).
flag() {
  local value
  value=$(sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1)
  [[ -z $value ]] && { echo "$2"; return; }
  case ${value^^} in
    ON | TRUE | YES | Y | 1) echo on ;;
    *) echo off ;;
  esac
}

refuse() {
  echo "test: error: $dir/ was configured with $1: $2; remove $dir/ (or reconfigure it with $3) and run again" >&2
  exit 1
}

[[ $(flag BUILD_TESTING on) == on ]] || refuse "BUILD_TESTING=OFF" "it builds no tests" "-DBUILD_TESTING=ON"
if [[ $kind == sanitizer || $kind == sanitizer-full ]]; then
  [[ $(flag RTLAB_SANITIZE off) == on ]] ||
    refuse "RTLAB_SANITIZE=OFF" "its tests would run without the sanitizers" "-DRTLAB_SANITIZE=ON"
fi
if [[ $kind == full || $kind == sanitizer-full ]]; then
  [[ $(flag RTLAB_UNIT_ONLY off) == off ]] ||
    refuse "RTLAB_UNIT_ONLY=ON" "it has no render or CLI tests" "-DRTLAB_UNIT_ONLY=OFF"
fi
if [[ $kind == tsan ]]; then
  [[ $(flag RTLAB_TSAN off) == on ]] ||
    refuse "RTLAB_TSAN=OFF" "its tests would run without ThreadSanitizer" "-DRTLAB_TSAN=ON"
fi
