#pragma once
// What the first frame from a camera draws, counted from a mesh's chunks before
// they are uploaded: each chunk in the frustum at the level ChunkCulling picks for
// it (engine/frame/chunk_culling.h), and of its faces those seen from the camera's
// side. The first frame has no depth to hide anything behind, so every cluster in
// view is drawn. Faces are judged at the chunk's bounds where culling judges each
// cluster's: a chunk the camera's plane crosses counts a few quads more.
#include "engine/camera.h"
#include "voxel/mesh.h"

#include <cstdint>
#include <span>

namespace grotto {

struct ViewDraw {
    uint64_t quads = 0;     // drawn
    uint64_t clusters = 0;  // in view: culling lists each, then draws its quads
};

ViewDraw countViewDraw(std::span<const voxel::MeshChunkQuads> chunks, double voxelSize, glm::dvec3 worldOrigin,
                       const Camera& camera, double lodBias);

}  // namespace grotto
