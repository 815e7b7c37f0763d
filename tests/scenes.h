#pragma once
// Small worlds built in memory for the renderer tests.
#include "voxel/world.h"

#include <functional>

namespace grotto::test {

// A world of unit voxels (times voxelSize) where solid(x, y, z) is true, over the
// inclusive index box [lo, hi]; material 1 everywhere, from `materials`.
voxel::World makeVoxelWorld(glm::ivec3 lo, glm::ivec3 hi, const std::function<bool(int, int, int)>& solid,
                            double voxelSize = 1.0, glm::dvec3 offset = glm::dvec3(0.0),
                            std::vector<voxel::Material> materials = voxel::defaultMaterials());

// A 49 x 49 floor one voxel thick whose top is the plane y = -0.5, plus `extra`
// voxels (index y from -1 to 8): the ground the object tests stand things on.
voxel::World floorWorld(const std::function<bool(int, int, int)>& extra = {});
// A solid box of voxels [0, size) as an object's grid (local units = voxels).
voxel::World boxWorld(glm::ivec3 size);

// A camera at `position` looking at `target` with a vertical field of view in degrees.
voxel::CameraDesc lookAt(glm::dvec3 position, glm::dvec3 target, double fov = 60.0);

}  // namespace grotto::test
