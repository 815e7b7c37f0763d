#!/usr/bin/env bash
# Regenerates the shipped grids in worlds/ with `grotto mkworld`, and the demo's
# MagicaVoxel model with scripts/make-demo-vox.py (both deterministic).
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
"$grotto" mkworld rooms  -o worlds/rooms.vdb  --seed 1
"$grotto" mkworld caves  -o worlds/caves.vdb  --seed 1
"$grotto" mkworld thin   -o worlds/thin.vdb   --seed 1
"$grotto" mkworld city   -o worlds/city.vdb   --seed 1
"$grotto" mkworld sphere -o worlds/sphere.vdb --seed 1
"$grotto" mkworld houses -o worlds/houses.vdb --seed 1
"$grotto" mkworld houses --lamps -o worlds/houses-night.vdb --seed 1
"$grotto" mkworld mine   -o worlds/mine.vdb   --seed 1
python3 scripts/make-demo-vox.py worlds/demo.vox
