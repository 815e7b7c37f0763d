#!/bin/bash
# find_package(Grotto) from an installed tree: install this build into a scratch
# prefix, build examples/embed and examples/game_loop against that prefix alone,
# and run them as their usage comments say, with the validation layer on and no
# shader directory, so the built-in shaders are used.
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
# Each example runs as the last line of its CMakeLists.txt's usage comment says,
# in a directory where that line's names resolve (the source's worlds/, the
# example's build directory under the name the comment gives it), with the
# validation layer on; it must write the out.png it is given.
documented_run() {  # CMAKELISTS BUILD_DIR
    local line name run
    line=$(grep -E '^#   (GROTTO_VALIDATION=1 )?build-[a-z]+/' "$1" | tail -1 | sed 's/^#   //')
    [ -n "$line" ] || { echo "$1: no usage line that runs the example" >&2; exit 1; }
    name=${line#*build-}
    name=build-${name%%/*}
    run="$scratch/run-$name"
    mkdir "$run"
    ln -s "$source/worlds" "$run/worlds"
    ln -s "$2" "$run/$name"
    (cd "$run" && GROTTO_VALIDATION=1 bash -c "$line") || { echo "$1: '$line' failed" >&2; exit 1; }
    test -s "$run/out.png" || { echo "$1: '$line' wrote no out.png" >&2; exit 1; }
}
documented_run "$source/examples/embed/CMakeLists.txt" "$scratch/build"
# The game loop: its own Vulkan device handed to Grotto, a world built in memory and dug into.
cmake -S "$source/examples/game_loop" -B "$scratch/game" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$scratch/game" >/dev/null
documented_run "$source/examples/game_loop/CMakeLists.txt" "$scratch/game"
