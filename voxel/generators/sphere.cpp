// sphere: a narrow-band level set resting on the ground, the simplest smooth surface.
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"
#include <openvdb/tools/LevelSetSphere.h>

namespace grotto::voxel {

openvdb::GridBase::Ptr generateSphere(const GeneratorOptions& options) {
    // options.size is the diameter in voxels; the tool works in world units.
    const auto voxel = static_cast<float>(options.voxelSize);
    const float radius = 0.5f * static_cast<float>(options.size) * voxel;
    // Each voxel's distance is computed on its own, so threading cannot change the result.
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        radius, openvdb::Vec3f(0.0f, radius, 0.0f), voxel, 3.0f);
    grid->setName("surface");
    return grid;
}

}  // namespace grotto::voxel
