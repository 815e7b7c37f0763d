// Exact voxel traversal (Amanatides & Woo) through the solid grid, in double precision.
#include "voxel/solid.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace grotto::voxel {

std::optional<RayHit> World::raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const {
    const Impl& w = *impl_;
    const glm::dvec3 dir = glm::normalize(direction);
    const glm::dvec3 p = (origin - w.origin) / w.voxelSize;  // voxel-corner index units
    const double tMax = maxDistance / w.voxelSize;
    openvdb::MaskGrid::ConstAccessor acc = w.solid->getConstAccessor();

    glm::ivec3 cell(std::floor(p.x), std::floor(p.y), std::floor(p.z));
    glm::ivec3 step;
    glm::dvec3 tNext, tDelta;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (dir[i] > 0) {
            step[i] = 1;
            tDelta[i] = 1.0 / dir[i];
            tNext[i] = (cell[i] + 1 - p[i]) / dir[i];
        } else if (dir[i] < 0) {
            step[i] = -1;
            tDelta[i] = -1.0 / dir[i];
            tNext[i] = (cell[i] - p[i]) / dir[i];
        } else {
            step[i] = 0;
            tDelta[i] = inf;
            tNext[i] = inf;
        }
    }
    if (acc.isValueOn(openvdb::Coord(cell.x, cell.y, cell.z)))
        return RayHit{0.0, cell, -1};  // starts inside solid
    // Bound the walk to the world's solid bounds so an escaping ray stops early.
    const IndexBox box = bounds();
    if (box.empty()) return std::nullopt;
    double tLimit = tMax;
    for (int i = 0; i < 3; ++i) {
        if (dir[i] == 0) {
            if (p[i] < box.min[i] || p[i] > box.max[i] + 1) return std::nullopt;
            continue;
        }
        const double exit = ((dir[i] > 0 ? box.max[i] + 1 : box.min[i]) - p[i]) / dir[i];
        tLimit = std::min(tLimit, exit);
    }
    double t = 0;
    while (true) {
        int axis = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        t = tNext[axis];
        if (t > tLimit) return std::nullopt;
        cell[axis] += step[axis];
        tNext[axis] += tDelta[axis];
        if (acc.isValueOn(openvdb::Coord(cell.x, cell.y, cell.z))) {
            // Entered through the face pointing back along the step.
            const int face = axis * 2 + (step[axis] > 0 ? 1 : 0);
            return RayHit{t * w.voxelSize, cell, face};
        }
    }
}

}  // namespace grotto::voxel
