#pragma once
// Small worlds built in memory for the renderer tests.
#include "voxel/object_pose.h"
#include "voxel/world.h"

#include <glm/gtc/quaternion.hpp>

#include <functional>

namespace grotto::test {

// A world of unit voxels (times voxelSize) where solid(x, y, z) is true, over the
// inclusive index box [lo, hi]; material 1 everywhere, from `materials`.
voxel::World makeVoxelWorld(glm::ivec3 lo, glm::ivec3 hi, const std::function<bool(int, int, int)>& solid,
                            double voxelSize = 1.0, glm::dvec3 offset = glm::dvec3(0.0),
                            std::vector<voxel::Material> materials = voxel::defaultMaterials());

// A world of exactly the voxels `solid` (unit voxels, material 1): for voxels
// scattered far apart, where a box's every cell would be asked.
voxel::World makeVoxelWorld(const std::vector<glm::ivec3>& solid);

// A 49 x 49 floor one voxel thick whose top is the plane y = -0.5, plus `extra`
// voxels (index y from -1 to 8): the ground the object tests stand things on.
voxel::World floorWorld(const std::function<bool(int, int, int)>& extra = {});
// A solid box of voxels [0, size) as an object's grid (local units = voxels).
voxel::World boxWorld(glm::ivec3 size);

// An object's pose on no axis: moved, turned 35 degrees about a tilted axis, about a
// pivot inside its box.
inline const voxel::ObjectPose kTurned{glm::dvec3(2.0, 3.5, 1.0),
                                       glm::angleAxis(glm::radians(35.0), glm::normalize(glm::dvec3(0.3, 1.0, 0.2))),
                                       glm::dvec3(1.5, 2.5, 2.0)};

// A camera at `position` looking at `target` with a vertical field of view in degrees.
voxel::CameraDesc lookAt(glm::dvec3 position, glm::dvec3 target, double fov = 60.0);

}  // namespace grotto::test
