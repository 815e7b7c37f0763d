#!/bin/bash
# docs/guide.md cannot rot: run every ```sh block in it, in order, as one script,
# in an empty directory that sees the repository's worlds/ and examples/ and the
# build as build/ (HOME there too, for the install prefix). The only changes are
# the ones the guide's last section lists: --size 160x90, --fps 2, and an
# interactive `grotto view` under xvfb-run for 10 frames at 160x90. A
# ```sh blender block runs only where blender is on the PATH. Then each step's
# output must exist.
#   test_guide.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
unset GROTTO_SHADER_DIR

blender=no
command -v blender >/dev/null && blender=yes
awk -v blender="$blender" '
    /^```sh$/ { run = 1; next }
    /^```sh blender$/ { run = (blender == "yes"); next }
    /^```/ { run = 0; next }
    run { print }
' "$source/docs/guide.md" |
sed -E -e 's/--size [0-9]+x[0-9]+/--size 160x90/g' -e 's/--fps [0-9]+/--fps 2/g' \
       -e "/^grotto view /{/--frames/!s/^(grotto view .*)\$/xvfb-run -a -s '-screen 0 320x180x24' \\1 --size 160x90 --frames 10/}" \
    > "$scratch/guide.sh"
grep -q '^grotto ' "$scratch/guide.sh" || { echo "docs/guide.md: no sh block runs grotto" >&2; exit 1; }

run="$scratch/run"
mkdir "$run"
ln -s "$source/worlds" "$run/worlds"
ln -s "$source/examples" "$run/examples"
ln -s "$build" "$run/build"
if ! (cd "$run" && HOME="$run" bash -euxo pipefail "$scratch/guide.sh") > "$scratch/log" 2>&1; then
    tail -40 "$scratch/log" >&2
    echo "docs/guide.md: the last command above failed" >&2
    exit 1
fi
outputs="first.png island.gfc island.png island.mp4 island.glb view.png game.png"
[ "$blender" = no ] || outputs+=" island.blend"
for f in $outputs; do
    test -s "$run/$f" || { echo "docs/guide.md: its commands wrote no $f" >&2; exit 1; }
done
