#!/usr/bin/env bash
# The foundation's benchmark targets in one run: caves at 1280x720 (both cameras),
# memory against OpenVDB's memUsage, and load + mesh of a ~10M-voxel world.
# Figures go to out/bench/*.json; compare ratios from one run, not absolute times.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
mkdir -p out/bench
for camera in walk overview; do
  "$grotto" bench worlds/caves.json --camera "$camera" --size 1280x720 --frames 60 --warmup 10 \
    --json "out/bench/caves-$camera.json"
done
for world in rooms thin city; do
  "$grotto" bench "worlds/$world.json" --size 1280x720 --frames 30 --warmup 5 --json "out/bench/$world.json"
done
[ -f out/bench/caves10m.vdb ] || "$grotto" mkworld caves --size 680 -o out/bench/caves10m.vdb
"$grotto" bench out/bench/caves10m.vdb --size 640x360 --frames 5 --warmup 1 --json out/bench/caves10m.json
