#!/usr/bin/env bash
# Sets up, builds and runs every test (validation layer on for all GPU tests),
# twice: a release build, then the same suite under AddressSanitizer and
# UndefinedBehaviorSanitizer with leak checking (the `sanitize` preset, build-sanitize/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
for preset in release sanitize; do
    echo "== $preset"
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset"
    ctest --preset "$preset"
done
