#!/bin/bash
# find_package(Grotto) from an installed tree: install this build into a scratch
# prefix, build examples/embed and examples/game_loop against that prefix alone,
# and run them with the validation layer on and no shader directory, so the
# built-in shaders are used.
# The example is built by the build's compiler with its flags (a sanitizer build's).
#   test_package.sh BUILD_DIR SOURCE_DIR [CXX_COMPILER [CXX_FLAGS [EXE_LINKER_FLAGS]]]
set -euo pipefail
build=$1 source=$2 cxx=${3:-c++} cxxflags=${4:-} ldflags=${5:-}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
unset GROTTO_SHADER_DIR
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$source/examples/embed" -B "$scratch/build" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$scratch/build" >/dev/null
GROTTO_VALIDATION=1 "$scratch/build/walk_path" "$source/worlds/rooms.json" orbit 3 "$scratch/out.png"
test -s "$scratch/out.png" || { echo "walk_path wrote no image" >&2; exit 1; }
# The game loop: its own Vulkan device handed to Grotto, a world built in memory and dug into.
cmake -S "$source/examples/game_loop" -B "$scratch/game" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$scratch/game" >/dev/null
GROTTO_VALIDATION=1 "$scratch/game/game_loop" "$scratch/game.png"
test -s "$scratch/game.png" || { echo "game_loop wrote no image" >&2; exit 1; }
