#!/usr/bin/env bash
# Sets up, builds, and renders the default world's flythrough into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
rm -rf out/rooms  # a fresh sequence each time (flythrough refuses to mix settings)
build/grotto flythrough worlds/rooms.json --path orbit --fps 2 --size 640x360 -o out/rooms  # 25 frames
