#include "engine/scene/scene_memory.h"

#include "engine/frame/render_memory.h"
#include "engine/scene/scene.h"
#include "engine/scene/view_draw.h"
#include "voxel/mesh_footprint.h"
#include "voxel/work_memory.h"

namespace grotto {

SceneMemory estimateSceneMemory(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                                const SceneFrames& frames, bool cpuDevice) {
    const voxel::WorldStats s = world.stats();
    // Buffers are made in host memory (a staging copy, which stays resident once
    // freed: measured on lavapipe), and on a CPU device the buffer itself is host memory too.
    const uint64_t copies = cpuDevice ? 2 : 1, kept = copies;
    const uint64_t scene = sceneBufferBytes(chunks);
    // The occupancy: a 16-word mask a brick, with a quarter more room (engine/scene/occupancy.cpp).
    const uint64_t occupancy = s.bricks * 64 * 5 / 4;
    // Culling's candidate and the draw recorded for a cluster in view; a CPU
    // device's binned triangles for a quad drawn, which level off where llvmpipe
    // rasterises a full scene (36 MiB) before binning more: at 70 to 104 MiB
    // measured, counted as at most three scenes (all measured on lavapipe).
    constexpr uint64_t kClusterBytes = 140, kBinnedQuadBytes = 370, kMostBinnedBytes = 3 * (36ull << 20);
    const ViewDraw draw = frames.firstView ? countViewDraw(chunks, world.voxelSize(), world.origin(), *frames.firstView, frames.lodBias)
                                           : ViewDraw{};
    const uint64_t binned = cpuDevice ? std::min(kBinnedQuadBytes * draw.quads, kMostBinnedBytes) : 0;
    SceneMemory m;
    m.worldBytes = s.hostBytes + meshBytes + sceneHostBytes(chunks);
    // The scene's vertices, then its occupancy (built on the host too), beside the chunks lent by the mesh.
    m.uploadBytes = chunks.size() * sizeof(voxel::MeshChunkQuads) + std::max(copies * scene, kept * scene + (copies + 1) * occupancy);
    m.framesBytes = kept * scene + (cpuDevice ? occupancy : 0) + kClusterBytes * draw.clusters + binned + frames.rendererBytes;
    return m;
}

uint64_t requireSceneFits(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                          const SceneFrames& frames, bool cpuDevice) {
    if (!world.stats().workBytesEstimate) return 0;
    const SceneMemory m = estimateSceneMemory(world, meshBytes, chunks, frames, cpuDevice);
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

std::unique_ptr<GpuScene> uploadMeshWithinBudget(vk::Context& ctx, const voxel::World& world, const voxel::WorldDesc& desc) {
    const voxel::Mesh mesh = world.mesh();
    const std::vector<voxel::MeshChunkQuads> chunks = meshChunks(mesh);
    // The mesh and its chunks' copy of it, both held while they are uploaded.
    uint64_t meshBytes = voxel::heapBytes(mesh.quads.capacity() * sizeof(voxel::MeshQuad)) +
                         voxel::heapBytes(mesh.chunks.capacity() * sizeof(voxel::MeshChunk));
    for (const voxel::MeshChunkQuads& c : chunks) meshBytes += voxel::heapBytes(c.quads.capacity() * sizeof(voxel::MeshQuad));
    requireSceneFits(world, meshBytes, chunks, {}, cpuDevice(ctx));
    return uploadScene(ctx, chunks, mesh.voxelSize, mesh.origin, desc);
}

}  // namespace grotto
