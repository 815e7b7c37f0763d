#!/usr/bin/env bash
# Benchmarks in one run (compare ratios within a run; absolute times drift on
# shared machines). Figures go to out/bench/*.json and the terminal.
#  - foundation: caves at 1280x720 without AO (G-buffer + composite), both cameras;
#    memory against OpenVDB's memUsage; load + mesh of a ~10M-voxel world
#  - GTAO: the AO chain per preset on caves at 1280x720, half and full resolution
#  - live worlds: the CPU cost of edits on caves and of staging a chunk's quads
#  - moving objects: the yard world's frame at 1280x720
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
mkdir -p out/bench
for camera in walk overview; do
  "$grotto" bench worlds/caves.json --camera "$camera" --size 1280x720 --frames 40 --warmup 5 --ao off \
    --json "out/bench/caves-$camera-noao.json"
done
# Levels of detail and occlusion culling: the caves walk with AO high, both off
# (every quad in view, as before they existed) and at the world's defaults.
"$grotto" bench worlds/caves.json --camera walk --size 1280x720 --frames 20 --warmup 3 --quality high \
  --lod-bias 0 --occlusion-culling false --json out/bench/caves-walk-high-exact.json
"$grotto" bench worlds/caves.json --camera walk --size 1280x720 --frames 20 --warmup 3 --quality high \
  --json out/bench/caves-walk-high.json
for world in rooms thin city; do
  "$grotto" bench "worlds/$world.json" --size 1280x720 --frames 20 --warmup 3 --ao off --json "out/bench/$world-noao.json"
done
[ -f out/bench/caves10m.vdb ] || "$grotto" mkworld caves --size 680 -o out/bench/caves10m.vdb
"$grotto" bench out/bench/caves10m.vdb --size 640x360 --frames 3 --warmup 1 --ao off --json out/bench/caves10m.json
for quality in low medium high ultra; do
  "$grotto" bench worlds/caves.json --size 1280x720 --frames 20 --warmup 3 --quality "$quality" \
    --json "out/bench/caves-gtao-$quality.json"
  "$grotto" bench worlds/caves.json --size 1280x720 --frames 10 --warmup 2 --quality "$quality" --ao-full-res \
    --json "out/bench/caves-gtao-$quality-fullres.json"
done
"$grotto" bench worlds/caves.json --edits --size 320x180 --frames 10 --warmup 2 --json out/bench/caves-edits.json
"$grotto" bench worlds/yard.json --size 1280x720 --frames 20 --warmup 3 --json out/bench/yard.json
