#pragma once
// Greedy rectangles cut into quads that meet corner to corner. Where a corner of
// one rectangle lies inside the edge of another (a T-junction), rasterising the two
// leaves single-pixel cracks along the edge: the shared point, rounded to the
// rasteriser's grid, no longer lies on the longer edge. Each rectangle becomes a
// convex polygon with those points among its corners, cut into convex quads and
// triangles, so every edge a quad has is an edge of the quad beside it too.
//
// Within a chunk the points come from the same level's rectangles. On the chunk's
// boundary they come from every level of the chunk and of its neighbours, so two
// chunks meet corner to corner whatever levels they are drawn at.
#include "voxel/mesh.h"

#include <span>
#include <vector>

namespace grotto::voxel {

// The corners of a chunk's rectangles, every level's, that lie on its closed
// cube's boundary, chunk-relative. Only these can meet another chunk's quads.
std::vector<glm::ivec3> boundaryCorners(const MeshChunkQuads& chunk);

// A chunk's boundaryCorners, with its origin.
struct ChunkBoundary {
    glm::ivec3 origin{0};
    const std::vector<glm::ivec3>* corners = nullptr;
};

// Fills chunk.quads (and each coarser level's) from its rectangles, given the
// boundary corners of the chunk itself and of those around it (any of the 26;
// chunks that are not there have none).
void weld(MeshChunkQuads& chunk, std::span<const ChunkBoundary> around);

// The corners of a rectangle, chunk-relative, counter-clockwise about its normal.
std::array<glm::ivec3, 4> rectCorners(const gpu::PackedQuad& rect);

}  // namespace grotto::voxel
