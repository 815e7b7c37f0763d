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
# The public surface stands alone: the prefix's include/ holds grotto/*.h and
# nothing else; they include only each other, Vulkan, GLM and the standard
# library; and <grotto/grotto.h> compiles with no include path but the prefix's
# (Vulkan and GLM come from the system's, as a game has them).
extra=$(cd "$scratch/prefix/include" && find . -type f ! -path './grotto/*.h')
[ -z "$extra" ] || { echo "installed beside the public headers: $extra" >&2; exit 1; }
headers=$(ls "$scratch/prefix/include/grotto" | wc -l)
[ "$headers" -le 6 ] || { echo "$headers public headers: a handful at most" >&2; exit 1; }
if grep -h '^#include' "$scratch/prefix/include/grotto/"*.h | grep -vE '^#include ("grotto/[a-z_]+\.h"|<vulkan/vulkan\.h>|<glm/[a-z0-9_/]+\.hpp>|<[a-z_]+>)$'; then
    echo "a public header includes more than grotto/, Vulkan, GLM and the standard library" >&2; exit 1
fi
printf '#include <grotto/grotto.h>\nint main() { grotto::Engine* e = nullptr; return e == nullptr ? 0 : 1; }\n' > "$scratch/alone.cpp"
"$cxx" -std=c++20 $cxxflags -I"$scratch/prefix/include" -fsyntax-only "$scratch/alone.cpp" ||
    { echo "<grotto/grotto.h> does not compile with only the prefix, Vulkan and GLM" >&2; exit 1; }
# A game's find_package(Grotto) looks for Vulkan and GLM alone: nothing of
# OpenVDB's CMake module (Debian's prints "COMPONENT = openvdb" and a warning
# about Imath) reaches its configure step or the installed package's files.
cmake -S "$source/examples/embed" -B "$scratch/build" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" \
      > "$scratch/configure.log" 2>&1 || { cat "$scratch/configure.log" >&2; exit 1; }
if grep -nE 'COMPONENT|Imath|OpenVDB|openvdb|TBB|Boost' "$scratch/configure.log" >&2; then
    echo "find_package(Grotto) printed the above: the package pulls in the libraries behind the API" >&2; exit 1
fi
# Its CMake files look for no package but Vulkan and GLM, and name no target
# but its own and theirs (the libraries behind the API are named by their files).
package=$(find "$scratch/prefix" -path '*cmake/Grotto/*.cmake')
if grep -hvE '^\s*#' $package | grep -iE 'find_(dependency|package)\(' | grep -viE 'find_(dependency|package)\((Vulkan|glm)\)'; then
    echo "the installed package looks for the above: a game needs Vulkan and GLM alone" >&2; exit 1
fi
if grep -ohE '\b[A-Za-z][A-Za-z0-9_]*::[A-Za-z0-9_]+' $package | sort -u | grep -vE '^(Grotto::[a-z_]+|Vulkan::Vulkan|glm::glm)$'; then
    echo "the installed package names the targets above: none of them is Grotto's, Vulkan's or GLM's" >&2; exit 1
fi
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
    (cd "$run" && GROTTO_VALIDATION=1 LD_DEBUG=libs LD_DEBUG_OUTPUT="$run/loads" bash -c "$line") ||
        { echo "$1: '$line' failed" >&2; exit 1; }
    test -s "$run/out.png" || { echo "$1: '$line' wrote no out.png" >&2; exit 1; }
    # The same run writing an EXR, which the image codec module encodes (an
    # 8-bit PNG is written without it).
    rm -f "$run"/loads.*
    (cd "$run" && GROTTO_VALIDATION=1 LD_DEBUG=libs LD_DEBUG_OUTPUT="$run/loads" bash -c "${line/out.png/out.exr}") ||
        { echo "$1: '${line/out.png/out.exr}' failed" >&2; exit 1; }
    test -s "$run/out.exr" || { echo "$1: '${line/out.png/out.exr}' wrote no out.exr" >&2; exit 1; }
    installed_codec "$run" "$1"
}
# The image codec module that wrote the EXR was the installed one (found through
# the run path Grotto::engine gives a game, or the installed grotto's own), not
# the build tree's. The loader's account: LD_DEBUG=libs, written to DIR/loads.*.
installed_codec() {  # DIR WHAT
    grep -qs "calling init: $scratch/prefix/.*/grotto/libgrotto_image_codec.so" "$1"/loads.* ||
        { echo "$2: the installed image codec module was not loaded" >&2; exit 1; }
}
mkdir "$scratch/installed"
GROTTO_VALIDATION=1 LD_DEBUG=libs LD_DEBUG_OUTPUT="$scratch/installed/loads" \
    "$scratch/prefix/bin/grotto" render "$source/worlds/caves.json" --size 32x18 -o "$scratch/installed/out.exr" >/dev/null
installed_codec "$scratch/installed" "the installed grotto"
documented_run "$source/examples/embed/CMakeLists.txt" "$scratch/build"
# The game loop: its own Vulkan device handed to Grotto, a world built in memory and dug into.
cmake -S "$source/examples/game_loop" -B "$scratch/game" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$scratch/game" >/dev/null
documented_run "$source/examples/game_loop/CMakeLists.txt" "$scratch/game"
