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
    // The same, moved out of a mesh no longer needed: no second copy of it at the peak.
    std::vector<MeshChunkQuads> take() &&;
    // The chunks in order, moved out for `use` (a span of them) and moved back
    // after: a scene uploaded from a mesh that is kept, without a copy of it.
    template <class Use>
    auto lend(Use&& use) {
        std::vector<MeshChunkQuads> chunks = std::move(*this).take();
        struct Back {
            LiveMesh& mesh;
            std::vector<MeshChunkQuads>& chunks;
            ~Back() { mesh.giveBack(std::move(chunks)); }
        } back{*this, chunks};
        return use(std::span<const MeshChunkQuads>(chunks));
    }
    // The same quads as one Mesh, as World::mesh() lays it out (exact voxels only).
    Mesh flatten() const;

private:
    void giveBack(std::vector<MeshChunkQuads>&& chunks);  // what take() moved out, in its order
    void weld(const std::vector<glm::ivec3>& origins);  // their quads, from every chunk's rectangles

    MeshOptions options_;
    double voxelSize_ = 1.0;
    glm::dvec3 origin_{0.0};
    std::map<glm::ivec3, MeshChunkQuads, Less> chunks_;
};

}  // namespace grotto::voxel
