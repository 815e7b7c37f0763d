#include "engine/scene/scene_memory.h"

#include "engine/scene/scene.h"
#include "voxel/work_memory.h"

namespace grotto {

SceneMemory estimateSceneMemory(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                                uint64_t rendererBytes, bool cpuDevice) {
    const voxel::WorldStats s = world.stats();
    // Buffers are made in host memory (a staging copy, which stays resident once
    // freed: measured on lavapipe), and on a CPU device the buffer itself is host memory too.
    const uint64_t copies = cpuDevice ? 2 : 1, kept = copies;
    const uint64_t scene = sceneBufferBytes(chunks);
    // The occupancy: a 16-word mask a brick, with a quarter more room (engine/scene/occupancy.cpp).
    const uint64_t occupancy = s.bricks * 64 * 5 / 4;
    constexpr uint64_t kClusterDrawBytes = 72;
    SceneMemory m;
    m.worldBytes = s.hostBytes + meshBytes + sceneHostBytes(chunks);
    // The scene's vertices, then its occupancy (built on the host too), beside the chunks lent by the mesh.
    m.uploadBytes = chunks.size() * sizeof(voxel::MeshChunkQuads) + std::max(copies * scene, kept * scene + (copies + 1) * occupancy);
    m.framesBytes = kept * scene + (cpuDevice ? occupancy : 0) + kClusterDrawBytes * sceneClusters(chunks) + rendererBytes;
    return m;
}

uint64_t requireSceneFits(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                          uint64_t rendererBytes, bool cpuDevice) {
    if (!world.stats().workBytesEstimate) return 0;
    const SceneMemory m = estimateSceneMemory(world, meshBytes, chunks, rendererBytes, cpuDevice);
    if (m.total() <= voxel::budgetRoom(world)) return m.total();
    uint64_t quads = 0;
    for (const voxel::MeshChunkQuads& c : chunks) {
        quads += c.quads.size();
        for (const voxel::MeshLevel& l : c.coarser) quads += l.quads.size();
    }
    voxel::refuseOverBudget(world, "loading, meshing and rendering it needs an estimated " + voxel::mibText(m.total()) +
                                       " (grids and a mesh of " + std::to_string(quads) + " quads " +
                                       voxel::mibText(m.worldBytes) + ", its upload " + voxel::mibText(m.uploadBytes) +
                                       ", its GPU scene and the renderer " + voxel::mibText(m.framesBytes) + ")");
}

}  // namespace grotto
