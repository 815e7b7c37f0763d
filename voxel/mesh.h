#pragma once
// Face-culled, greedy-merged quads grouped in 32^3 chunks, each chunk's quads
// sorted by face so a renderer can skip faces turned away from the camera.
#include "shaders/shared/quad.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace grotto::voxel {

struct MeshOptions {
    bool greedy = true;  // false: one quad per exposed face
    // Coarser meshes of each chunk for level of detail (0 to kMaxCoarseLevels):
    // level L treats cells of 2^L voxels as one, solid where any voxel is, so a
    // coarse surface never lies inside the exact one and never opens a hole.
    int coarseLevels = 0;
};

inline constexpr int kMaxCoarseLevels = 3;  // cells of 2, 4 and 8 voxels

// One level's quads, in the chunk's quad format (positions and sizes in voxels).
struct MeshLevel {
    std::array<uint32_t, 6> faceCount{};
    std::vector<gpu::PackedQuad> quads;  // in face order
};

struct MeshChunk {
    glm::ivec3 origin;                  // voxel index of the chunk's minimum corner
    uint32_t firstQuad = 0;
    std::array<uint32_t, 6> faceCount{};  // quads per face, stored in face order
    uint32_t quadCount() const {
        uint32_t n = 0;
        for (uint32_t c : faceCount) n += c;
        return n;
    }
};

// One chunk's quads on their own, for meshes updated chunk by chunk.
struct MeshChunkQuads {
    glm::ivec3 origin{0};
    std::array<uint32_t, 6> faceCount{};
    std::vector<gpu::PackedQuad> quads;  // in face order
    std::vector<MeshLevel> coarser;      // levels 1, 2, ... when MeshOptions::coarseLevels asked for them
};

struct Mesh {
    std::vector<gpu::PackedQuad> quads;
    std::vector<MeshChunk> chunks;
    glm::dvec3 origin{0.0};  // world position of voxel corner (0, 0, 0)
    double voxelSize = 1.0;

    // The 4 corners of quad q of chunk c, in voxel-corner index units (CCW about the normal).
    std::array<glm::ivec3, 4> corners(const MeshChunk& c, const gpu::PackedQuad& q) const;
};

// Appends one chunk's quads to a mesh as its next chunk (nothing for a chunk
// without quads): how World::mesh() lays chunks out, in the order given.
void appendChunk(Mesh& mesh, const MeshChunkQuads& chunk);

}  // namespace grotto::voxel
