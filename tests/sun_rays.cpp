#include "tests/sun_rays.h"

#include <cmath>

namespace grotto::test {

bool SunRays::blocked(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& d) const {
    const glm::dvec3 index = (p - world_.origin()) / world_.voxelSize();
    const int a = n.x != 0.0 ? 0 : n.y != 0.0 ? 1 : 2;
    const bool positive = n[a] > 0.0;
    voxel::RayStart start;
    start.voxel = glm::ivec3(glm::floor(index));
    start.fraction = glm::vec3(index - glm::floor(index));
    const int plane = int(std::lround(index[a]));
    start.voxel[a] = positive ? plane : plane - 1;
    start.fraction[a] = positive ? kNormalOffset : 1.0f - kNormalOffset;
    const double reach = 1e7 * world_.voxelSize();  // the bounds end every ray sooner
    return world_.raycast(world_.faceRayStart(start, a), glm::vec3(d), reach).has_value();
}

}  // namespace grotto::test
