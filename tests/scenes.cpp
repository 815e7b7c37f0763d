#include "tests/scenes.h"

#include "voxel/solid.h"

namespace grotto::test {

voxel::World makeVoxelWorld(glm::ivec3 lo, glm::ivec3 hi, const std::function<bool(int, int, int)>& solid,
                            double voxelSize, glm::dvec3 offset, std::vector<voxel::Material> materials) {
    openvdb::initialize();
    auto grid = openvdb::MaskGrid::create();
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->transform().postTranslate(openvdb::Vec3d(offset.x, offset.y, offset.z));
    auto acc = grid->getAccessor();
    for (int x = lo.x; x <= hi.x; ++x)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int z = lo.z; z <= hi.z; ++z)
                if (solid(x, y, z)) acc.setValueOn(openvdb::Coord(x, y, z));
    voxel::WorldDesc d;
    d.materials = std::move(materials);
    return voxel::makeWorld(grid, d);
}

voxel::World makeVoxelWorld(const std::vector<glm::ivec3>& solid) {
    openvdb::initialize();
    auto grid = openvdb::MaskGrid::create();
    auto acc = grid->getAccessor();
    for (const glm::ivec3& v : solid) acc.setValueOn(openvdb::Coord(v.x, v.y, v.z));
    voxel::WorldDesc d;
    d.materials = voxel::defaultMaterials();
    return voxel::makeWorld(grid, d);
}

voxel::CameraDesc lookAt(glm::dvec3 position, glm::dvec3 target, double fov) {
    voxel::CameraDesc c;
    c.position = position;
    c.target = target;
    c.fovDegrees = fov;
    return c;
}

voxel::World floorWorld(const std::function<bool(int, int, int)>& extra) {
    return makeVoxelWorld({-24, -1, -24}, {24, 8, 24},
                          [&](int x, int y, int z) { return y == -1 || (extra && extra(x, y, z)); });
}

voxel::World boxWorld(glm::ivec3 size) {
    return makeVoxelWorld({0, 0, 0}, size - 1, [](int, int, int) { return true; });
}

}  // namespace grotto::test
