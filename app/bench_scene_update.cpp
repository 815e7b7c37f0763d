#include "app/bench_scene_update.h"

#include "app/options.h"
#include "common/elapsed.h"

#include <chrono>
#include <cstdio>

namespace grotto::app {

std::optional<voxel::MeshChunkQuads> busiestChunk(const voxel::Mesh& mesh) {
    const voxel::MeshChunk* best = nullptr;
    for (const voxel::MeshChunk& c : mesh.chunks)
        if (!best || c.quadCount() > best->quadCount()) best = &c;
    if (!best) return std::nullopt;
    voxel::MeshChunkQuads q{best->origin, best->faceCount, {}};
    q.quads.assign(mesh.quads.begin() + best->firstQuad, mesh.quads.begin() + best->firstQuad + best->quadCount());
    return q;
}

SceneUpdateCost measureSceneUpdate(GpuScene& scene, const voxel::MeshChunkQuads& chunk, int updates) {
    SceneUpdateCost cost;
    cost.chunkQuads = uint32_t(chunk.quads.size());
    cost.updates = updates;
    std::vector<double> ms;
    vk::Buffer staging;
    for (int i = 0; i < updates; ++i) {
        const auto start = std::chrono::steady_clock::now();
        scene.updateChunks({&chunk, 1}, {});
        ms.push_back(msSince(start));
        cost.stagedBytes = scene.stagedBytesLast;
        scene.ctx.submitAndWait([&](VkCommandBuffer cmd) { scene.recordUploads(cmd, staging); });
    }
    vk::destroy(scene.ctx, staging);
    cost.medianMs = median(ms);
    return cost;
}

void reportSceneUpdate(const SceneUpdateCost& cost, nlohmann::json& j) {
    j["scene_update"] = {{"chunk_quads", cost.chunkQuads}, {"median_ms", cost.medianMs},
                         {"staged_bytes", cost.stagedBytes}, {"updates", cost.updates}};
    std::printf("  scene update %.3f ms CPU for one chunk of %u quads (median of %d), %llu bytes staged\n",
                cost.medianMs, cost.chunkQuads, cost.updates, (unsigned long long)cost.stagedBytes);
}

}  // namespace grotto::app
