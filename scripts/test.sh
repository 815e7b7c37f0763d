#!/usr/bin/env bash
# Sets up, builds and runs every test (validation layer on for all GPU tests).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
