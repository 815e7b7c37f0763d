#!/usr/bin/env bash
# Regenerates docs/tradeoff.md's table and plot: every AO method and preset against
# the ray-traced reference (1024 rays per pixel, cached) on the standard worlds at
# 640x360, default cameras. CSV in out/tradeoff.csv, plot in docs/images/tradeoff.png.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
mkdir -p out
"$grotto" tradeoff worlds/rooms.json worlds/caves.json worlds/thin.json worlds/city.json \
  --size 640x360 --spp 1024 --frames 24 --warmup 4 --csv out/tradeoff.csv --plot docs/images/tradeoff.png
