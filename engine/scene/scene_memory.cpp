#include "engine/scene/scene_memory.h"

#include "engine/scene/scene.h"
#include "voxel/work_memory.h"

namespace grotto {

SceneMemory estimateSceneMemory(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                                uint64_t rendererBytes, bool cpuDevice) {
    const voxel::WorldStats s = world.stats();
    // Buffers are made in host memory (the vertices built, or a staging copy), and
    // on a CPU device the buffer itself is host memory too.
    const uint64_t copies = cpuDevice ? 3 : 2, kept = cpuDevice ? 1 : 0;
    const uint64_t scene = sceneBufferBytes(chunks), sceneHost = sceneHostBytes(chunks);
    // The occupancy: a 16-word mask a brick, with a quarter more room (engine/scene/occupancy.cpp).
    const uint64_t occupancy = s.bricks * 64 * 5 / 4;
    SceneMemory m;
    m.worldBytes = s.hostBytes + meshBytes + sceneHost;  // the scene's chunks and clusters are kept from the upload on
    // The scene's vertices, then its occupancy, made beside the chunks moved out of the mesh.
    m.uploadBytes = chunks.size() * sizeof(voxel::MeshChunkQuads) + std::max(copies * scene, kept * scene + copies * occupancy);
    m.framesBytes = kept * (scene + occupancy) + rendererBytes;
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
