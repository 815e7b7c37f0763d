#pragma once
// A live world and its GPU copy kept in step: an edit changes the world's grid,
// re-meshes only the chunks it touched and stages only their quads, which the
// renderer copies into the existing buffers at the start of its next frame. The
// brick table the reference traces is updated the same way, once it exists.
#include "engine/scene/scene.h"
#include "voxel/brick_table.h"
#include "voxel/live_mesh.h"
#include "voxel/world.h"

#include <memory>
#include <optional>

namespace grotto {

class LiveScene {
public:
    LiveScene(vk::Context& ctx, voxel::World world);

    // Throws grotto::Error (input) for an edit the world refuses; nothing changes then.
    voxel::EditResult apply(const voxel::Edit& edit);
    voxel::EditResult undo();

    const voxel::World& world() const { return world_; }
    const voxel::LiveMesh& mesh() const { return mesh_; }
    GpuScene& gpu() { return *gpu_; }
    // Built on first use (the reference needs it; rendering does not), then kept up to date.
    const voxel::BrickTable& bricks();

private:
    void changed(const voxel::EditResult& result);

    voxel::World world_;
    voxel::LiveMesh mesh_;
    std::unique_ptr<GpuScene> gpu_;
    std::optional<voxel::BrickTable> bricks_;
};

}  // namespace grotto
