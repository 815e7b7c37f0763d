#include "voxel/mesh_origin.h"

#include "grotto/error.h"

namespace grotto::voxel {

MeshOrigin meshOrigin(const std::string& name, const std::string& flag) {
    if (name == "base") return MeshOrigin::Base;
    if (name == "centre" || name == "center") return MeshOrigin::Centre;
    if (name == "world") return MeshOrigin::World;
    throw Error(flag, "unknown origin '" + name + "'", "accepted: base, centre, world");
}

const char* meshOriginName(MeshOrigin origin) {
    switch (origin) {
    case MeshOrigin::Base: return "base";
    case MeshOrigin::Centre: return "centre";
    case MeshOrigin::World: break;
    }
    return "world";
}

glm::dvec3 meshShift(const World& world, MeshOrigin origin) {
    const IndexBox b = world.bounds();
    if (origin == MeshOrigin::World || b.empty()) return glm::dvec3(0.0);
    const glm::dvec3 lo = world.origin() + glm::dvec3(b.min) * world.voxelSize();
    const glm::dvec3 hi = world.origin() + glm::dvec3(b.max + 1) * world.voxelSize();
    glm::dvec3 centre = (lo + hi) * 0.5;
    if (origin == MeshOrigin::Base) centre.y = lo.y;
    return -centre;
}

}  // namespace grotto::voxel
