// LiveMesh: World::mesh() split by chunk, re-meshed chunk by chunk after edits.
#include "voxel/live_mesh.h"

#include <tbb/parallel_for.h>

namespace grotto::voxel {

LiveMesh::LiveMesh(const World& world, const MeshOptions& options)
    : options_(options), voxelSize_(world.voxelSize()), origin_(world.origin()) {
    const std::vector<glm::ivec3> origins = world.chunkOrigins();
    std::vector<MeshChunkQuads> meshed(origins.size());
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) { meshed[i] = world.meshChunk(origins[i], options_); });
    for (MeshChunkQuads& q : meshed)
        if (!q.quads.empty()) chunks_[q.origin] = std::move(q);
}

std::vector<glm::ivec3> LiveMesh::update(const World& world, const IndexBox& changed) {
    std::vector<glm::ivec3> origins = world.chunksTouching(changed);
    std::vector<MeshChunkQuads> meshed(origins.size());
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) { meshed[i] = world.meshChunk(origins[i], options_); });
    for (MeshChunkQuads& q : meshed) {
        if (q.quads.empty()) chunks_.erase(q.origin);
        else chunks_[q.origin] = std::move(q);
    }
    return origins;
}

const MeshChunkQuads* LiveMesh::find(glm::ivec3 origin) const {
    const auto it = chunks_.find(origin);
    return it == chunks_.end() ? nullptr : &it->second;
}

uint64_t LiveMesh::quadCount() const {
    uint64_t n = 0;
    for (const auto& [origin, q] : chunks_) n += q.quads.size();
    return n;
}

std::vector<MeshChunkQuads> LiveMesh::list() const {
    std::vector<MeshChunkQuads> out;
    out.reserve(chunks_.size());
    for (const auto& [origin, q] : chunks_) out.push_back(q);
    return out;
}

Mesh LiveMesh::flatten() const {
    Mesh mesh;
    mesh.origin = origin_;
    mesh.voxelSize = voxelSize_;
    mesh.quads.reserve(quadCount());
    for (const auto& [origin, q] : chunks_) appendChunk(mesh, q);
    return mesh;
}

}  // namespace grotto::voxel
