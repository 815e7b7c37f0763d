#pragma once
// A world's mesh kept chunk by chunk, so an edit re-meshes only the chunks it
// touched (World::chunksTouching) and a renderer re-uploads only those.
#include "voxel/world.h"

#include <map>
#include <span>
#include <vector>

namespace grotto::voxel {

class LiveMesh {
public:
    explicit LiveMesh(const World& world, const MeshOptions& options = {});

    // Re-meshes the chunks an edit's changed voxels touch and welds them and their
    // neighbours again (voxel/watertight.h); returns the origins of those whose quads
    // may have changed (a chunk left with no quads is among them, and is dropped).
    std::vector<glm::ivec3> update(const World& world, const IndexBox& changed);

    // Chunks with quads, keyed by origin in the order World::mesh() lists them.
    struct Less {
        bool operator()(const glm::ivec3& a, const glm::ivec3& b) const {
            return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
        }
    };
    const std::map<glm::ivec3, MeshChunkQuads, Less>& chunks() const { return chunks_; }
    const MeshChunkQuads* find(glm::ivec3 origin) const;
    uint64_t quadCount() const;
    double voxelSize() const { return voxelSize_; }
    glm::dvec3 origin() const { return origin_; }

    // The chunks in order, copied: what a GPU scene is uploaded from.
    std::vector<MeshChunkQuads> list() const;
    // The same quads as one Mesh, as World::mesh() lays it out (exact voxels only).
    Mesh flatten() const;

private:
    void weld(const std::vector<glm::ivec3>& origins);  // their quads, from every chunk's rectangles

    MeshOptions options_;
    double voxelSize_ = 1.0;
    glm::dvec3 origin_{0.0};
    std::map<glm::ivec3, MeshChunkQuads, Less> chunks_;
};

}  // namespace grotto::voxel
