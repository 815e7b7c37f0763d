#!/usr/bin/env bash
# Regenerates docs/tradeoff.md's table and plot: every AO method and preset against
# the ray-traced reference (10000 rays per pixel, so every pixel's standard error is
# at most 0.005, docs/metrics.md; cached) on the standard worlds at 640x360, default
# cameras. CSV in out/tradeoff.csv, plot in docs/images/tradeoff.png; the table is
# spliced into docs/tradeoff.md between its two "tradeoff table" markers.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
mkdir -p out
"$grotto" tradeoff worlds/rooms.json worlds/caves.json worlds/thin.json worlds/city.json \
  --size 640x360 --spp 10000 --frames 24 --warmup 4 --csv out/tradeoff.csv --markdown out/tradeoff-table.md \
  --plot docs/images/tradeoff.png
doc=docs/tradeoff.md
awk -v table=out/tradeoff-table.md '
  /<!-- tradeoff table begin/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /<!-- tradeoff table end/ { skip = 0 }
  !skip' "$doc" > "$doc.tmp"
if ! grep -q "tradeoff table end" "$doc.tmp"; then
  rm -f "$doc.tmp"
  echo "scripts/tradeoff.sh: $doc lacks the tradeoff table markers; the table is in out/tradeoff-table.md" >&2
  exit 1
fi
mv "$doc.tmp" "$doc"
echo "updated $doc"
