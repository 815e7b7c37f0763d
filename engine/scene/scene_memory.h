#pragma once
// What a .vox world takes in memory once it is rendered, estimated after it is
// meshed and before its scene is uploaded: its grids, its mesh as the live scene
// keeps it (voxel/mesh_footprint.h) and the GPU scene's chunks and clusters
// (sceneHostBytes), and beside them the larger of
// the upload at its peak (the vertices built on the host, their staging copy, the
// buffer itself, then the occupancy the same way) and what stays for the frames:
// the buffers, the staging copy's memory (freed, but not given back: measured on
// lavapipe), culling's list of clusters in view and the draws recorded for them
// (all of them: about 72 bytes a cluster, measured), and the renderer
// (engine/frame/render_memory.h). On a CPU device (lavapipe) the device's buffers
// are host memory too.
#include "voxel/world.h"

#include <algorithm>
#include <cstdint>
#include <span>

namespace grotto {

struct SceneMemory {
    uint64_t worldBytes = 0;   // the grids, the mesh and the scene's chunks as the host keeps them
    uint64_t uploadBytes = 0;  // beside them, the upload's peak
    uint64_t framesBytes = 0;  // beside them, the scene's buffers and the renderer while frames are made
    uint64_t total() const { return worldBytes + std::max(uploadBytes, framesBytes); }
};

// Every level's clusters, as uploadScene makes them (engine/scene/scene.h): while
// frames are made, culling lists those in view, and a CPU device records a draw
// for each.
uint64_t sceneClusters(std::span<const voxel::MeshChunkQuads> chunks);

// `chunks`: the mesh's, lent by it (voxel::LiveMesh::lend), `meshBytes` its
// footprint as the LiveMesh keeps them (voxel::measureMesh); `rendererBytes`: the
// renderer's own host memory (render_memory.h's; on a CPU device its targets too).
SceneMemory estimateSceneMemory(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                                uint64_t rendererBytes, bool cpuDevice);

// The estimate, for a .vox world within its memory budget (zero for other
// worlds, whose budget is checked as they load); else throws grotto::Error
// (input), voxel/work_memory.h's one line, before anything is uploaded.
uint64_t requireSceneFits(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                          uint64_t rendererBytes, bool cpuDevice);

}  // namespace grotto
