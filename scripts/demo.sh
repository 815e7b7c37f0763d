#!/usr/bin/env bash
# Sets up, builds, and renders the demo island's flythrough into out/demo/: a
# MagicaVoxel model lit by its face cache (AO, sky light and a soft sun, baked
# once by `grotto bake`, read by every frame with --bake). docs/guide.md goes on
# from here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
rm -rf out/demo  # a fresh sequence each time (flythrough refuses to mix settings)
mkdir -p out
build/grotto bake worlds/demo.json --texels 2 --rays 32 --sun-rays 8 -o out/demo.gfc
build/grotto flythrough worlds/demo.json --path orbit --bake out/demo.gfc --fps 1 --frames 1-8 --size 640x360 -o out/demo  # the orbit, 45 degrees a frame
