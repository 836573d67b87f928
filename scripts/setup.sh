#!/usr/bin/env bash
# Installs rtlab's Debian 12 packages when any is missing (as root, non-interactive, one
# 'apt-get update'), then configures and builds into build/ (Release). Idempotent: with every
# package present and the build up to date it only runs the (no-op) incremental build.
#   bash scripts/setup.sh [--test-deps] [--no-build]
#     --test-deps  also installs what the tests need
#     --no-build   installs only (scripts/test.sh builds its own sanitized directories)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ make pkg-config git ca-certificates
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libtinygltf-dev
  libosmesa6-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri
  python3-glad nlohmann-json3-dev libtinyexr-dev libembree-dev libtbb-dev
)
# googletest is needed to configure the test targets, which are part of every build.
packages+=(googletest libgtest-dev)
# The viewer's lecture mode draws its text with a TrueType font at the scaled size (docs/viewer.md).
packages+=(fonts-dejavu-core)
# What only the tests use: Xvfb runs the window path under a virtual display; Chromium opens
# the HTML reports headless.
test_packages=(xvfb xauth chromium)
build=1
for arg in "$@"; do
  case $arg in
    --test-deps) packages+=("${test_packages[@]}") ;;
    --no-build) build=0 ;;
    *) echo "setup: error: unknown option '$arg' (usage: setup.sh [--test-deps] [--no-build])" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then missing+=("$p"); fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  if [[ $(id -u) -ne 0 ]]; then
    echo "setup: error: packages are missing and this is not root; run as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

((build)) || exit 0
jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
echo "setup: building (log in build/build.log)" >&2
if ! cmake --build build -j"$jobs" >build/build.log 2>&1; then
  grep -E "error|Error" build/build.log | head -20 >&2 || true
  echo "setup: error: the build failed; see build/build.log" >&2
  exit 1
fi
echo "setup: build/rtlab is ready" >&2
