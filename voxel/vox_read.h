#pragma once
// Reading MagicaVoxel .vox files into plain data: models, palette, materials and
// the scene graph flattened into placed instances. A .vox file comes from
// anywhere, so every size in it is checked against the bytes left before anything
// is read or allocated, and what it may place is bounded (instancing lets a tiny
// file place billions of voxels). Pure C++: no OpenVDB, no Vulkan.
#include <glm/ext/matrix_int3x3.hpp>  // glm::imat3
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace grotto::voxel {

// Larger files are refused before they are read.
constexpr uintmax_t kMaxVoxFileBytes = uintmax_t(512) << 20;
// The most voxels a file may place (summed over its visible instances).
constexpr uint64_t kMaxVoxPlacedVoxels = uint64_t(1) << 24;
// The largest |translation| on any axis, of one node and composed: far inside
// Grotto's index range (2^30) even with a model's 256 voxels added.
constexpr int32_t kMaxVoxTranslation = int32_t(1) << 24;
// A model's size on each axis: 1 to 256, the format's own limit.
constexpr int kMaxVoxModelSize = 256;
// Bounds on what one file may hold; MagicaVoxel's own scenes are far smaller.
constexpr size_t kMaxVoxModels = size_t(1) << 16;
constexpr size_t kMaxVoxNodes = size_t(1) << 20;
constexpr size_t kMaxVoxInstances = size_t(1) << 20;
// Nodes on one path from the root (a MagicaVoxel group nested n deep is 2n + 2).
constexpr int kMaxVoxGraphDepth = 64;

struct VoxColor {
    uint8_t r = 0, g = 0, b = 0, a = 0;
    friend bool operator==(const VoxColor&, const VoxColor&) = default;
};

// From a MATL chunk, per colour index; the defaults are the values MagicaVoxel
// writes for a material nobody edited (_rough 0.1, _spec 0.5, _ior 0.3).
struct VoxMaterial {
    std::string type = "_diffuse";  // _diffuse, _metal, _glass, _emit, _blend, _media ... as written
    float weight = 1.0f;            // _weight
    float rough = 0.1f;             // _rough
    float metal = 0.0f;             // _metal
    float spec = 0.5f;              // _spec
    float ior = 1.3f;               // the refractive index: _ri, else 1 + _ior (MagicaVoxel writes _ior as index - 1)
    float emit = 0.0f;              // _emit
    float flux = 0.0f;              // _flux (power of an emitter)
    float ldr = 0.0f;               // _ldr
    float trans = 0.0f;             // _trans, else _alpha
    bool present = false;           // a MATL chunk named this colour index
};

// One SIZE/XYZI pair: voxels as x, y, z, colour index (1..255), in MagicaVoxel's
// own z-up model space, each inside `size`. Colour index 0 is skipped on reading.
struct VoxModel {
    glm::ivec3 size{0};
    std::vector<std::array<uint8_t, 4>> voxels;
};

// A model placed by the scene graph, at frame 0. The rotation may be a mirror
// (determinant -1): MagicaVoxel's flips are stored that way.
struct VoxInstance {
    uint32_t model = 0;            // index into VoxScene::models
    glm::imat3 rotation{1};        // composed along the node chain (entries -1, 0, 1), as rotation * column vector
    glm::ivec3 translation{0};     // composed, MagicaVoxel units
};

struct VoxScene {
    uint32_t version = 0;                    // 150 or 200
    std::array<VoxColor, 256> palette{};     // palette[c] = colour of colour index c (1..255); index 0 unused
    bool hasPalette = false;                 // the file had an RGBA chunk (else MagicaVoxel's default)
    std::array<VoxMaterial, 256> materials;  // by colour index
    std::vector<VoxModel> models;
    std::vector<VoxInstance> instances;      // visible instances only: hidden layers and nodes skipped
    uint64_t placedVoxels() const;           // sum over instances of their model's voxel count
};

// Throws grotto::Error (input) naming `file` and the chunk ("chunk 'XYZI' at
// byte 60: ...") for anything malformed or past the limits above.
//
// A file without a scene graph places model 0 alone, at the origin: older files
// hold one model, and those with several (a PACK chunk) hold the frames of an
// animation (MagicaVoxel's own samples vox/anim/*.vox), which MagicaVoxel shows
// one at a time, from the first; placing them all would overlap the frames.
VoxScene parseVox(std::span<const uint8_t> bytes, const std::string& file);

// Reads the file (one over kMaxVoxFileBytes is refused before it is read), then parseVox.
VoxScene readVoxFile(const std::filesystem::path& path);

// The rotation a nTRN's `_r` byte stands for: bits 0-1 the column of row 0's
// non-zero entry, bits 2-3 that of row 1 (row 2 takes the one left), bits 4, 5, 6
// the signs of rows 0, 1, 2 (1 = negative). Nothing for a byte outside 0..127 or
// whose two columns are equal or 3.
std::optional<glm::imat3> voxRotation(int byte);

// Where voxel v of an instance lands, as a Grotto voxel index. MagicaVoxel first:
// the model's pivot is the grid point floor(size / 2) (the model centred on its
// node's translation; an odd size leaves the extra voxel on the + side), and the
// voxel's cell, rotated about that point, is translated: cell floor(R (v + 1/2 -
// pivot)) + t. Then the axes: MagicaVoxel is z-up, Grotto y-up, both right-handed,
// Grotto (x, y, z) = MagicaVoxel (x, z, -y), so cell (x, y, z) becomes (x, z, -y - 1).
glm::ivec3 placeVoxel(const VoxScene& scene, const VoxInstance& instance, const std::array<uint8_t, 4>& voxel);

}  // namespace grotto::voxel
