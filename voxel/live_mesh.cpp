// LiveMesh: World::mesh() split by chunk, re-meshed chunk by chunk after edits.
#include "voxel/live_mesh.h"

#include "voxel/watertight.h"

#include <tbb/parallel_for.h>

#include <set>

namespace grotto::voxel {
namespace {


bool sameQuads(const MeshChunkQuads& a, const MeshChunkQuads& b) {
    if (a.quads != b.quads || a.coarser.size() != b.coarser.size()) return false;
    for (size_t i = 0; i < a.coarser.size(); ++i)
        if (a.coarser[i].quads != b.coarser[i].quads) return false;
    return true;
}

}  // namespace

LiveMesh::LiveMesh(const World& world, const MeshOptions& options)
    : options_(options), voxelSize_(world.voxelSize()), origin_(world.origin()) {
    const std::vector<glm::ivec3> origins = world.chunkOrigins();
    std::vector<MeshChunkQuads> meshed(origins.size());
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) { meshed[i] = world.meshChunk(origins[i], options_); });
    for (MeshChunkQuads& q : meshed)
        if (!q.rects.empty()) chunks_[q.origin] = std::move(q);
    std::vector<glm::ivec3> all;
    for (const auto& [origin, q] : chunks_) all.push_back(origin);
    weld(all);
}

std::vector<glm::ivec3> LiveMesh::update(const World& world, const IndexBox& changed) {
    std::vector<glm::ivec3> origins = world.chunksTouching(changed);
    std::vector<MeshChunkQuads> meshed(origins.size());
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) { meshed[i] = world.meshChunk(origins[i], options_); });
    for (MeshChunkQuads& q : meshed) {
        if (q.rects.empty()) chunks_.erase(q.origin);
        else chunks_[q.origin] = std::move(q);
    }
    // Their neighbours' quads meet theirs: welded again, and listed where they changed.
    std::set<glm::ivec3, Less> around;
    for (const glm::ivec3& o : origins)
        for (int i = 0; i < 27; ++i) {
            const glm::ivec3 n = o + kChunkEdge * glm::ivec3(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1);
            if (chunks_.count(n)) around.insert(n);
        }
    std::set<glm::ivec3, Less> changedSet(origins.begin(), origins.end());
    std::vector<glm::ivec3> toWeld(around.begin(), around.end());
    std::vector<MeshChunkQuads> before;
    for (const glm::ivec3& n : toWeld)
        if (!changedSet.count(n)) before.push_back(chunks_.at(n));
    weld(toWeld);
    for (const MeshChunkQuads& b : before)
        if (!sameQuads(b, chunks_.at(b.origin))) origins.push_back(b.origin);
    return origins;
}

void LiveMesh::weld(const std::vector<glm::ivec3>& origins) {
    // Each chunk's boundary corners once: a chunk meets up to 26 others.
    auto neighbour = [](glm::ivec3 origin, int k) { return origin + kChunkEdge * glm::ivec3(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1); };
    std::map<glm::ivec3, size_t, Less> index;
    std::vector<glm::ivec3> listed;
    for (const glm::ivec3& o : origins)
        for (int k = 0; k < 27; ++k)
            if (const glm::ivec3 n = neighbour(o, k); chunks_.count(n) && index.emplace(n, listed.size()).second)
                listed.push_back(n);
    std::vector<std::vector<glm::ivec3>> corners(listed.size());
    tbb::parallel_for(size_t(0), listed.size(), [&](size_t i) { corners[i] = boundaryCorners(chunks_.at(listed[i])); });
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) {
        MeshChunkQuads& chunk = chunks_.at(origins[i]);
        std::vector<ChunkBoundary> around;
        for (int k = 0; k < 27; ++k)
            if (const auto it = index.find(neighbour(chunk.origin, k)); it != index.end())
                around.push_back({it->first, &corners[it->second]});
        voxel::weld(chunk, around);
    });
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

std::vector<MeshChunkQuads> LiveMesh::take() && {
    std::vector<MeshChunkQuads> out;
    out.reserve(chunks_.size());
    for (auto& [origin, q] : chunks_) out.push_back(std::move(q));
    return out;
}

void LiveMesh::giveBack(std::vector<MeshChunkQuads>&& chunks) {
    auto it = chunks_.begin();
    for (MeshChunkQuads& q : chunks) (it++)->second = std::move(q);
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
