#include "tests/sun_rays.h"

#include <algorithm>
#include <cmath>

namespace grotto::test {

bool SunRays::blocked(const glm::dvec3& p, const glm::dvec3& d) {
    const double vs = world_.voxelSize();
    const double reach = 1e7 * vs;  // the bounds end every ray sooner
    const std::optional<voxel::RayHit> hit = world_.raycast(p, d, reach);
    const glm::dvec3 index = (p - world_.origin()) / vs;
    if (!hit || hit->face != -1 || hit->voxel != glm::ivec3(glm::floor(index))) return hit.has_value();
    ++startsInside;
    if (!table_) table_.emplace(world_);
    double exit = reach / vs;  // where the ray leaves the bounds (it starts inside them)
    for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0)
            exit = std::min(exit, ((d[a] > 0 ? bounds_.max[a] + 1.0 : double(bounds_.min[a])) - index[a]) / d[a]);
    return table_->hitWithin(index, d, exit);
}

}  // namespace grotto::test
