#pragma once
// Reading glTF 2.0 files (.gltf with its buffers, or .glb) with tinygltf, as
// files from anywhere: their size is bounded before they are read, images are
// never decoded (nothing here needs them), and every accessor is checked against
// its buffer before a byte of it is read. OpenVDB- and Vulkan-free.
#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace grotto::voxel {

// Larger files are refused before they are read.
constexpr uintmax_t kMaxGltfFileBytes = uintmax_t(256) << 20;

// Throws grotto::Error (input) naming the file for a missing, oversized or malformed file.
tinygltf::Model readGltf(const std::filesystem::path& path);

// Accessor `index` as `components` floats per element (FLOAT components only),
// checked against its buffer view and buffer: errors name `file` and `field`.
std::vector<float> gltfFloats(const tinygltf::Model& model, int index, int components, const std::string& file,
                              const std::string& field);

}  // namespace grotto::voxel
