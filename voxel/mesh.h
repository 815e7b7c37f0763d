#pragma once
// Face-culled, greedy-merged quads grouped in 32^3 chunks, each chunk's quads
// sorted by face so a renderer can skip faces turned away from the camera. The
// greedy rectangles are split where a corner of another one lies on their edge
// (voxel/watertight.h), so the quads meet corner to corner and rasterise without
// pinholes.
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
inline constexpr int kChunkEdge = int(GROTTO_CHUNK_SIZE);  // voxels along a mesh chunk's edge

// A quad as drawn: a convex quadrilateral within one voxel face's plane, or a
// triangle (its last corner repeats the third), as four gpu::packVertex corners
// (chunk-relative, counter-clockwise about the face's normal).
struct MeshQuad {
    std::array<uint32_t, 4> corners{};
    uint32_t face() const { return gpu::vertexFace(corners[0]); }
    uint32_t material() const { return gpu::vertexMaterial(corners[0]); }
    glm::ivec3 corner(int i) const {
        return {int(gpu::vertexCoord(corners[size_t(i)], 0)), int(gpu::vertexCoord(corners[size_t(i)], 1)),
                int(gpu::vertexCoord(corners[size_t(i)], 2))};
    }
    bool operator==(const MeshQuad&) const = default;
};

// One level's quads (positions in voxels), and the greedy rectangles they were
// cut from (gpu::PackedQuad), which the neighbouring chunks' quads meet.
struct MeshLevel {
    std::array<uint32_t, 6> faceCount{};
    std::vector<MeshQuad> quads;         // in face order
    std::vector<gpu::PackedQuad> rects;  // in face order
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
    std::vector<MeshQuad> quads;         // in face order
    std::vector<gpu::PackedQuad> rects;  // the greedy rectangles, in face order
    std::vector<MeshLevel> coarser;      // levels 1, 2, ... when MeshOptions::coarseLevels asked for them
};

struct Mesh {
    std::vector<MeshQuad> quads;
    std::vector<MeshChunk> chunks;
    glm::dvec3 origin{0.0};  // world position of voxel corner (0, 0, 0)
    double voxelSize = 1.0;

    // The 4 corners of quad q of chunk c, in voxel-corner index units (CCW about the
    // normal; a triangle's last two are the same).
    std::array<glm::ivec3, 4> corners(const MeshChunk& c, const MeshQuad& q) const;
};

// Appends one chunk's quads to a mesh as its next chunk (nothing for a chunk
// without quads): how World::mesh() lays chunks out, in the order given.
void appendChunk(Mesh& mesh, const MeshChunkQuads& chunk);

}  // namespace grotto::voxel
