#!/usr/bin/env bash
# Temporal-stability figures for the shipped paths (docs/temporal.md): high with
# the temporal pass against ultra without it, at 320x180 over 64 frames, the
# reference (256 spp) on a pair of frames every 4. Writes out/stability/*.json.
# SIZE=640x360 (or 1280x720, ~10 min) scripts/stability.sh runs the same at another size.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
size=${SIZE:-320x180}
out=out/stability/$size
mkdir -p "$out"
for run in rooms:orbit caves:walk thin:fence; do
  world=${run%%:*} path=${run##*:}
  common=(--path "$path" --size "$size" --frames 64 --spp 256 --reference-every 4)
  "$grotto" stability "worlds/$world.json" "${common[@]}" --quality high --json "$out/$world-$path-high.json"
  "$grotto" stability "worlds/$world.json" "${common[@]}" --quality ultra --temporal 0 \
    --json "$out/$world-$path-ultra-spatial.json"
done
