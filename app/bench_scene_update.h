#pragma once
// grotto bench's figure for live worlds: the CPU cost of GpuScene::updateChunks
// for one chunk (its vertices packed and staged), and the bytes it stages. Each
// update is followed by a submission that records its copies, as a frame would,
// outside the timing.
#include "engine/scene/scene.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace grotto::app {

struct SceneUpdateCost {
    uint32_t chunkQuads = 0;   // quads of the chunk rewritten
    double medianMs = 0.0;     // updateChunks, CPU
    uint64_t stagedBytes = 0;  // staged by one update
    int updates = 0;
};

// The mesh's chunk with the most quads (GROTTO_CHUNK_SIZE^3 voxels, the default
// chunk), as an update carries it; none when the mesh is empty.
std::optional<voxel::MeshChunkQuads> busiestChunk(const voxel::Mesh& mesh);

// Rewrites `chunk` into `scene` `updates` times.
SceneUpdateCost measureSceneUpdate(GpuScene& scene, const voxel::MeshChunkQuads& chunk, int updates);

// Prints the figures and adds them to `j` as "scene_update".
void reportSceneUpdate(const SceneUpdateCost& cost, nlohmann::json& j);

}  // namespace grotto::app
