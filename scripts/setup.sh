#!/usr/bin/env bash
# Installs exactly the Debian 12 packages Grotto builds, runs and tests with.
# Idempotent: prints nothing and touches nothing when all are present.
# Arguments name extra packages for optional tools (scripts/fuzz.sh passes its own).
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  clang libclang-rt-14-dev                                        # the sanitize preset (docs/hardening.md)
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglm-dev
  libopenvdb-dev libboost-dev libboost-iostreams-dev libtbb-dev   # for OpenVDB headers and its CMake module
  libopenimageio-dev libpng-dev                                   # images; 8-bit PNGs written by libpng itself
  libgtest-dev libcli11-dev nlohmann-json3-dev
  gnuplot-nox                                                     # grotto tradeoff --plot
  ffmpeg                                                          # grotto flythrough --video
  libglfw3-dev libimgui-dev                                       # grotto view
  libtinygltf-dev                                                 # glTF in (cameras) and out (meshes)
  xvfb xauth                                                      # the viewer's tests, headless
  slurm-wlm munge                                                 # docs/farm.md's Slurm recipes, on a one-node cluster
  python3-yaml nodejs                                             # examples/farm/'s job templates and job types, checked
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing packages: ${missing[*]}; run this script as root (or install them with apt-get)" >&2
  exit 2
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
