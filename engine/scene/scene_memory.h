#pragma once
// What a .vox world takes in memory once it is rendered, estimated after it is
// meshed and before its scene is uploaded: its grids, its mesh as the live scene
// keeps it (voxel/mesh_footprint.h) and the GPU scene's chunks and clusters
// (sceneHostBytes), and beside them the larger of
// the upload at its peak (the vertices built on the host, their staging copy, the
// buffer itself, then the occupancy the same way) and what stays for the frames:
// the buffers, the staging copy's memory (freed, but not given back: measured on
// lavapipe), the renderer (engine/frame/render_memory.h) and the first frame's
// draw (view_draw.h): culling lists the clusters in view, and a CPU device bins
// the triangles of every quad drawn before it rasterises them (about 370 bytes a
// quad on lavapipe, measured: many times the clusters' share where a cluster holds
// many small quads, as in a speckled model). On a CPU device (lavapipe) the
// device's buffers are host memory too.
#include "engine/camera.h"
#include "engine/scene/scene.h"
#include "voxel/world.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace grotto {

struct SceneMemory {
    uint64_t worldBytes = 0;   // the grids, the mesh and the scene's chunks as the host keeps them
    uint64_t uploadBytes = 0;  // beside them, the upload's peak
    uint64_t framesBytes = 0;  // beside them, the scene's buffers and the renderer while frames are made
    uint64_t total() const { return worldBytes + std::max(uploadBytes, framesBytes); }
};

// The frames a session will make of the scene, as far as the estimate needs them.
struct SceneFrames {
    uint64_t rendererBytes = 0;        // the renderer's own host memory (render_memory.h's; on a CPU device its targets too)
    std::optional<Camera> firstView;   // the first frame's camera, at the frame's size; none: no frame counted
    double lodBias = 0.0;              // culling's (CullingOptions::lodBias)
};

// `chunks`: the mesh's, lent by it (voxel::LiveMesh::lend), `meshBytes` its
// footprint as the LiveMesh keeps them (voxel::measureMesh).
SceneMemory estimateSceneMemory(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                                const SceneFrames& frames, bool cpuDevice);

// The estimate, for a .vox world within its memory budget (zero for other
// worlds, whose budget is checked as they load); else throws grotto::Error
// (input), voxel/work_memory.h's one line, before anything is uploaded.
uint64_t requireSceneFits(const voxel::World& world, uint64_t meshBytes, std::span<const voxel::MeshChunkQuads> chunks,
                          const SceneFrames& frames, bool cpuDevice);

// uploadScene(ctx, world.mesh(), desc) (the exact voxels, no levels of detail:
// the reference's view, the scenes of objects) after requireSceneFits, with no
// frame counted: a .vox world over its budget is refused before the upload.
std::unique_ptr<GpuScene> uploadMeshWithinBudget(vk::Context& ctx, const voxel::World& world, const voxel::WorldDesc& desc);

}  // namespace grotto
