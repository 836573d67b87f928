#!/usr/bin/env bash
# The main job: set up, then the measured atlas and every built-in scene and technique, headless,
# into out/ (docs/cli.md "rtlab showcase"): per stage (shadow, ao) each technique beside the
# reference with its RMSE, FLIP and heat map and the stage's error-against-time chart from a small
# sweep (out/sweeps/<stage>/), then every render with its stats; open out/index.html.
#   bash scripts/showcase.sh [rtlab showcase options, e.g. --out DIR --size 320x180 --frames 3 --spp 16]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec build/rtlab showcase "$@"
