#pragma once
// A minimal MagicaVoxel .vox writer for tests and fuzz seeds: models (SIZE/XYZI),
// an RGBA palette, the scene graph (nTRN/nGRP/nSHP), layers (LAYR), materials
// (MATL) and any chunk built by hand, written into bytes in the order given.
// It writes what it is told, malformed included, so tests can build hostile files.
#include "voxel/vox_read.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grotto::voxel::test {

using VoxDict = std::vector<std::pair<std::string, std::string>>;

// Little-endian pieces of chunk content, for chunks built by hand.
void appendU32(std::vector<uint8_t>& out, uint32_t v);
void appendString(std::vector<uint8_t>& out, std::string_view s);  // STRING: length, bytes
void appendDict(std::vector<uint8_t>& out, const VoxDict& dict);   // DICT: count, key-value STRINGs

// The `_r` byte of a signed permutation matrix (glm's m[column][row]); the
// inverse of voxRotation.
uint8_t voxRotationByte(const glm::imat3& m);

class VoxWriter {
public:
    static constexpr uint8_t kIdentity = 4;  // `_r` of the identity: row 0 column 0, row 1 column 1

    explicit VoxWriter(uint32_t version = 200) : version_(version) {}

    VoxWriter& pack(uint32_t models);
    VoxWriter& model(glm::ivec3 size, const std::vector<std::array<uint8_t, 4>>& voxels);  // SIZE + XYZI
    // RGBA as stored: entries[i] is colour index i + 1; entries[255] has no index.
    VoxWriter& palette(const std::array<VoxColor, 256>& entries);

    // nTRN with one frame of `_t` and `_r` (both left out when identity).
    VoxWriter& transform(int32_t id, int32_t child, glm::ivec3 t = glm::ivec3(0), uint8_t r = kIdentity,
                         int32_t layer = 0, bool hidden = false);
    // nTRN as given: node attributes (`_name`, `_hidden`) and frame dicts (`_r`, `_t`, `_f`).
    VoxWriter& transformFrames(int32_t id, int32_t child, const VoxDict& attributes, int32_t layer,
                               const std::vector<VoxDict>& frames);
    VoxWriter& group(int32_t id, const std::vector<int32_t>& children);
    VoxWriter& shape(int32_t id, int32_t model);
    VoxWriter& shapeFrames(int32_t id, const std::vector<std::pair<int32_t, VoxDict>>& models);  // model id, `_f`
    VoxWriter& layer(int32_t id, bool hidden);
    VoxWriter& material(int32_t id, const VoxDict& properties);
    VoxWriter& chunk(std::string_view id, const std::vector<uint8_t>& content,
                     const std::vector<uint8_t>& children = {});

    // 'VOX ', the version, and MAIN holding the chunks.
    std::vector<uint8_t> bytes() const;

private:
    uint32_t version_;
    std::vector<uint8_t> chunks_;
};

}  // namespace grotto::voxel::test
