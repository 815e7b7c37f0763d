#!/usr/bin/env bash
# The independent check of `grotto reference --light full` against Blender's Cycles
# (docs/reference.md, "Checked against Cycles"): for each case, exports the world's
# mesh, path-traces the view with Grotto and renders it with Cycles
# (scripts/cycles_check.py), and prints how far apart the two are.
#
# Run by hand, never by CI: it needs Debian's blender and python3-numpy
# (apt-get install blender python3-numpy) and takes about 30 minutes on 2 busy cores.
#
#   scripts/cycles_check.sh [OUT_DIR]        (default cycles-check; GROTTO=path/to/grotto)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
grotto=${GROTTO:-$root/build/grotto}
out=${1:-cycles-check}
command -v blender >/dev/null || { echo "cycles_check.sh: blender not found (apt-get install blender python3-numpy)" >&2; exit 2; }
[ -x "$grotto" ] || { echo "cycles_check.sh: $grotto not found (build it, or set GROTTO)" >&2; exit 2; }
mkdir -p "$out"
rm -f "$out"/*.gltf  # exported afresh, once a world
python3 "$root/scripts/cycles_worlds.py" "$out"

# check NAME WORLD CAMERA SIZE SPP BOUNCES [SAMPLES]: Grotto at SPP paths a pixel and
# Cycles at SAMPLES (default SPP), BOUNCES at most (all: every bounce; Cycles then
# stops at 128, beyond any light here).
check() {
    local name=$1 world=$2 camera=$3 size=$4 spp=$5 bounces=$6 samples=${7:-$5}
    local mesh="$out/$(basename "$world" .json).gltf" grotto_bounces=() cycles_bounces=128
    if [ "$bounces" != all ]; then grotto_bounces=(--bounces "$bounces"); cycles_bounces=$bounces; fi
    local log="$out/$name.log"
    : >"$log"
    run() { "$@" >>"$log" 2>&1 || { echo "cycles_check.sh: $1 failed on $name, see $log" >&2; exit 1; }; }
    # The AO baked into the mesh plays no part: one ray is enough.
    [ -e "$mesh" ] || run "$grotto" export-mesh "$world" --origin world --rays 1 --texels 1 -o "$mesh"
    run "$grotto" reference "$world" --camera "$camera" --size "$size" --spp "$spp" --light full \
        "${grotto_bounces[@]}" -o "$out/$name.grotto.exr"
    run blender -b --factory-startup -P "$root/scripts/cycles_check.py" -- --world "$world" --camera "$camera" \
        --mesh "$mesh" --grotto "$out/$name.grotto.exr" --size "$size" --samples "$samples" \
        --bounces "$cycles_bounces" --out "$out/$name.cycles"
    python3 - "$name" "$out/$name.cycles.json" "$spp" <<'EOF'
import json, sys
f = json.load(open(sys.argv[2]))
print(f"{sys.argv[1]:<16} {f['size']:>7} Grotto {sys.argv[3]:>5}, Cycles {f['samples']:>5} a pixel  mean ratio {f['mean_ratio']:.5f} +- {f['mean_ratio_stderr']:.5f}"
      f"  (R G B {' '.join(f'{r:.4f}' for r in f['channel_mean_ratios'])})  median ratio {f['median_ratio']:.4f}"
      f"  relative RMSE {f['relative_rmse']:.4f} (noise {f['relative_rmse_of_noise']:.4f})")
EOF
}

check slab "$out/slab.json" top 160x90 64 all
check sunlit-slab "$out/sunlit.json" top 160x90 256 all
check lamp-box "$out/lamp.json" corner 160x90 2048 all
# Direct light alone: Cycles samples the lamp, Grotto only meets it, so Grotto needs more paths.
check lamp-direct "$out/lamp.json" corner 160x90 8192 0 1024
# ... and both against the closed form of that direct light.
blender -b --factory-startup -P "$root/scripts/cycles_lamp_closed_form.py" -- "$out/lamp.json" \
    "$out/lamp-direct.grotto.exr" "$out/lamp-direct.cycles" >"$out/lamp-closed-form.log" 2>&1 &&
    grep '^CLOSED_FORM' "$out/lamp-closed-form.log" | sed 's/^CLOSED_FORM/lamp-direct     /' ||
    { echo "cycles_check.sh: the closed form failed, see $out/lamp-closed-form.log" >&2; exit 1; }
check rooms "$root/worlds/rooms.json" table 160x90 1024 all
check rooms-direct "$root/worlds/rooms.json" table 160x90 1024 0
check rooms-1-bounce "$root/worlds/rooms.json" table 160x90 1024 1
