#!/usr/bin/env bash
# Regenerates the measured tables of the docs; `scripts/tradeoff.sh [methods|lod|all]` (default all).
#  - methods: docs/tradeoff.md's table and plot: every AO method and preset against
#    the ray-traced reference (10000 rays per pixel, so every pixel's standard error
#    is at most 0.005, docs/metrics.md; cached) on the standard worlds at 640x360,
#    default cameras. CSV in out/tradeoff.csv, plot in docs/images/tradeoff.png.
#    The face cache's row reads each world's bake from out/bakes (baked there first
#    when missing: city takes about 7 minutes on 2 cores).
#  - lod: docs/detail.md's tables: the world's AO at each level-of-detail bias
#    against the exact voxels (bias 0), at 640x360 (biases 1, 2, 4, 8) and 320x180
#    (the default bias, 1), on every shipped world's default camera and caves'
#    overview; references of 1024 rays per pixel (cached). CSVs in out/lod-*.csv.
# Each table is spliced into its doc between its two "... table" markers.
set -euo pipefail
cd "$(dirname "$0")/.."
grotto=${GROTTO:-build/grotto}
what=${1:-all}
case "$what" in methods|lod|all) ;; *) echo "usage: scripts/tradeoff.sh [methods|lod|all]" >&2; exit 2 ;; esac
mkdir -p out

# splice DOC NAME TABLE: replaces what lies between DOC's "<!-- NAME begin" and "<!-- NAME end" lines.
splice() {
  local doc=$1 name=$2 table=$3
  awk -v table="$table" -v begin="<!-- $name begin" -v end="<!-- $name end" '
    index($0, begin) == 1 { print; while ((getline line < table) > 0) print line; skip = 1; next }
    index($0, end) == 1 { skip = 0 }
    !skip' "$doc" > "$doc.tmp"
  if ! grep -q "<!-- $name end" "$doc.tmp"; then
    rm -f "$doc.tmp"
    echo "scripts/tradeoff.sh: $doc lacks the $name markers; the table is in $table" >&2
    exit 1
  fi
  mv "$doc.tmp" "$doc"
  echo "updated $doc ($name)"
}

if [ "$what" != lod ]; then
  mkdir -p out/bakes
  for w in rooms caves thin city; do
    [ -f "out/bakes/$w.gfc" ] || "$grotto" bake "worlds/$w.json" -o "out/bakes/$w.gfc"
  done
  "$grotto" tradeoff worlds/rooms.json worlds/caves.json worlds/thin.json worlds/city.json \
    --size 640x360 --spp 10000 --frames 24 --warmup 4 --csv out/tradeoff.csv --markdown out/tradeoff-table.md \
    --plot docs/images/tradeoff.png --bakes out/bakes
  splice docs/tradeoff.md "tradeoff table" out/tradeoff-table.md
fi

# lod SIZE BIASES: every shipped world's default camera, then caves' overview, as one table.
lod() {
  local size=$1 biases=$2 common=(--size "$1" --spp 1024 --frames 24 --warmup 4 --lod-biases "$2")
  "$grotto" tradeoff worlds/rooms.json worlds/caves.json worlds/thin.json worlds/city.json worlds/yard.json \
    "${common[@]}" --csv "out/lod-$size.csv" --markdown "out/lod-$size.md"
  "$grotto" tradeoff worlds/caves.json --camera overview \
    "${common[@]}" --csv "out/lod-$size-overview.csv" --markdown "out/lod-$size-overview.md"
  tail -n +3 "out/lod-$size-overview.md" >> "out/lod-$size.md"
  tail -n +2 "out/lod-$size-overview.csv" >> "out/lod-$size.csv"
  splice docs/detail.md "lod table $size" "out/lod-$size.md"
}
if [ "$what" != methods ]; then
  lod 640x360 1,2,4,8
  lod 320x180 1
fi
