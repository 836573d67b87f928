#!/usr/bin/env bash
# The main job: set up, then render every built-in scene and every technique headless into out/,
# with out/index.html showing the images, their stats and parameters.
#   bash scripts/showcase.sh [rtlab showcase options, e.g. --out DIR --size 640x360 --frames 5]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec build/rtlab showcase "$@"
