#!/usr/bin/env bash
# Temporal-stability figures for the shipped paths (docs/temporal.md): high with
# the temporal pass against ultra without it, at 320x180 over 64 frames, the
# reference (256 spp) on a pair of frames every 4. Writes out/stability/*.json.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
mkdir -p out/stability
for run in rooms:orbit caves:walk thin:fence; do
  world=${run%%:*} path=${run##*:}
  common=(--path "$path" --size 320x180 --frames 64 --spp 256 --reference-every 4)
  "$grotto" stability "worlds/$world.json" "${common[@]}" --quality high --json "out/stability/$world-$path-high.json"
  "$grotto" stability "worlds/$world.json" "${common[@]}" --quality ultra --temporal 0 \
    --json "out/stability/$world-$path-ultra-spatial.json"
done
