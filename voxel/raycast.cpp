// Exact voxel traversal (Amanatides & Woo) through the solid grid, in double
// precision. The walk starts where the ray enters the solid bounds, so a camera
// far from the world costs nothing extra.
#include "common/error.h"
#include "voxel/solid.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace grotto::voxel {

std::optional<RayHit> World::raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const {
    const Impl& w = *impl_;
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(origin.x + origin.y + origin.z))
        throw Error::internal("raycast", "ray origin and direction must be finite and non-zero");
    if (w.bounds.empty()) return std::nullopt;
    const glm::dvec3 dir = direction / length;
    const glm::dvec3 p = (origin - w.origin) / w.voxelSize;  // voxel-corner index units
    const double tMax = std::min(maxDistance / w.voxelSize, 1e15);

    // Slab test against the bounds: where the walk starts and must end.
    const glm::dvec3 lo(w.bounds.min), hi(w.bounds.max + 1);
    double tEnter = 0.0, tExit = tMax;
    for (int i = 0; i < 3; ++i) {
        if (dir[i] == 0.0) {
            if (p[i] < lo[i] || p[i] >= hi[i]) return std::nullopt;
            continue;
        }
        double t0 = (lo[i] - p[i]) / dir[i], t1 = (hi[i] - p[i]) / dir[i];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    if (tEnter > tExit) return std::nullopt;

    const glm::dvec3 start = p + dir * tEnter;
    glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor(start)), w.bounds.min, w.bounds.max);
    // The face the walk enters the first cell through, when it starts on the bounds.
    int face = -1;
    if (tEnter > 0.0)
        for (int i = 0; i < 3; ++i)
            if (dir[i] != 0.0 && std::abs(start[i] - (dir[i] > 0 ? lo[i] : hi[i])) < 1e-9)
                face = i * 2 + (dir[i] > 0 ? 1 : 0);
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
    openvdb::MaskGrid::ConstAccessor acc = w.solid->getConstAccessor();
    double t = tEnter;
    while (true) {
        if (acc.isValueOn(openvdb::Coord(cell.x, cell.y, cell.z)))
            return RayHit{t * w.voxelSize, cell, face};  // face -1: the ray starts inside solid
        const int axis = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        t = tNext[axis];
        if (t > tExit) return std::nullopt;
        cell[axis] += step[axis];
        tNext[axis] += tDelta[axis];
        face = axis * 2 + (step[axis] > 0 ? 1 : 0);  // entered through the face facing back
    }
}

}  // namespace grotto::voxel
