#pragma once
// A scene's objects on the GPU: one GpuScene per object (its own mesh, the
// world's palette), with what the world file says of their keys, so a frame's
// poses can be evaluated at its time, and their solid voxels for rays.
#include "engine/scene/object_grids.h"
#include "engine/scene/scene.h"
#include "voxel/object_pose.h"

#include <memory>
#include <span>
#include <vector>

namespace grotto {
namespace voxel { class World; }

struct SceneObjects {
    std::vector<std::unique_ptr<GpuScene>> scenes;  // in world-file order; object k has index k + 1
    std::vector<voxel::ObjectDesc> descs;
    std::vector<ObjectGrid> grids;                   // for rays (the renderer uploads them)
    uint64_t gridsVersion = 0;                       // counts changes to `grids`
    bool moving = false;                             // some object has more than one pose

    std::vector<const GpuScene*> list() const;
    std::vector<voxel::ObjectPose> poses(double time) const { return voxel::objectPoses(descs, time); }
};

// Uploads each object's mesh. `worlds` are voxel::loadObjectWorlds(desc)'s.
std::unique_ptr<SceneObjects> uploadObjects(vk::Context& ctx, std::span<const voxel::World> worlds,
                                            const voxel::WorldDesc& desc);

}  // namespace grotto
