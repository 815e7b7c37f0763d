// Exact voxel traversal on the CPU: the GPU's own code (shaders/shared/voxel_ray.h)
// over the OpenVDB tree, so World::raycast and the GPU's sun shadows agree ray for
// ray. The walk starts where the ray enters the solid bounds, so a camera far from
// the world costs nothing extra.
#include "grotto/error.h"
#include "voxel/solid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace grotto::voxel {
namespace {
using namespace glm;

// The kernel's functions become members; the grid answers its questions. The
// accessor lives for one ray on a world nothing edits meanwhile, so it need not
// register with the tree (a registered one costs a locked hash-map insert and
// erase per ray: a fifth of an exact soft-shadow reference's time).
struct VdbRays {
    openvdb::MaskGrid::ConstUnsafeAccessor acc;

    // -1 for a solid voxel, else the size (log2) of the empty node or tile holding it.
    int voxelRayBlock(ivec3 v) {
        const openvdb::Coord c(v.x, v.y, v.z);
        if (acc.isValueOn(c)) return -1;
        switch (acc.getValueDepth(c)) {
            case 3: return 0;   // within a leaf
            case 2: return 3;   // a tile of a leaf's size
            case 1: return 7;   // a tile of the lower internal node's size
            default: return 12;  // absent below the root: the upper internal node's size
        }
    }

#include "shaders/shared/voxel_ray.h"
};

// Long enough for any ray across the largest world; the GPU stops sooner (trace.glsl).
constexpr int kCpuMaxSteps = 1 << 30;

VdbRays::VoxelRayStart kernelStart(const RayStart& s) {
    VdbRays::VoxelRayStart k;
    k.voxel = s.voxel;
    k.fraction = glm::clamp(s.fraction, 0.0f, 1.0f);
    return k;
}

}  // namespace

std::optional<RayHit> World::raycast(const RayStart& start, glm::vec3 direction, double maxDistance) const {
    const Impl& w = *impl_;
    if (!(std::abs(glm::length(direction) - 1.0f) < 1e-3f))
        throw Error::internal("raycast", "ray direction must be a unit vector");
    if (w.bounds.empty()) return std::nullopt;
    VdbRays rays{w.solid->getConstUnsafeAccessor()};
    const float maxT = float(std::min(maxDistance / w.voxelSize, 1e15));
    const VdbRays::VoxelRayHit hit =
        rays.voxelRay(kernelStart(start), direction, maxT, w.bounds.min, w.bounds.max, false, kCpuMaxSteps);
    if (hit.t < 0.0f) return std::nullopt;
    return RayHit{double(hit.t) * w.voxelSize, hit.voxel, hit.face};
}

double World::solidRun(const RayStart& start, glm::vec3 direction, double maxDistance) const {
    const Impl& w = *impl_;
    if (!(std::abs(glm::length(direction) - 1.0f) < 1e-3f))
        throw Error::internal("solidRun", "ray direction must be a unit vector");
    VdbRays rays{w.solid->getConstUnsafeAccessor()};
    const float maxT = float(std::min(maxDistance / w.voxelSize, 1e15));
    return double(rays.voxelRayExit(kernelStart(start), direction, maxT)) * w.voxelSize;
}

RayStart World::faceRayStart(const RayStart& start, int normalAxis) const {
    if (normalAxis < 0 || normalAxis > 2) throw Error::internal("faceRayStart", "the face's axis must be 0, 1 or 2");
    VdbRays rays{impl_->solid->getConstUnsafeAccessor()};
    const VdbRays::VoxelRayStart s = rays.voxelRayOpenStart(kernelStart(start), normalAxis);
    return {s.voxel, s.fraction};
}

std::optional<RayHit> World::raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const {
    const Impl& w = *impl_;
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(origin.x + origin.y + origin.z))
        throw Error::internal("raycast", "ray origin and direction must be finite and non-zero");
    if (w.bounds.empty()) return std::nullopt;
    const glm::dvec3 dir = direction / length;
    const glm::dvec3 p = (origin - w.origin) / w.voxelSize;  // voxel-corner index units
    const double tMax = std::min(maxDistance / w.voxelSize, 1e15);

    // Slab test against the bounds: where the walk starts.
    const glm::dvec3 lo(w.bounds.min), hi(w.bounds.max + 1);
    double tEnter = 0.0, tExit = tMax;
    int enterAxis = -1;
    for (int i = 0; i < 3; ++i) {
        if (dir[i] == 0.0) {
            if (p[i] < lo[i] || p[i] >= hi[i]) return std::nullopt;
            continue;
        }
        double t0 = (lo[i] - p[i]) / dir[i], t1 = (hi[i] - p[i]) / dir[i];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tEnter) tEnter = t0, enterAxis = i;
        tExit = std::min(tExit, t1);
    }
    if (tEnter > tExit) return std::nullopt;

    // From outside the bounds the walk starts on them, in the voxel just outside, so
    // its first crossing names the face it enters through.
    const glm::dvec3 at = p + dir * tEnter;
    RayStart start;
    start.voxel = glm::ivec3(glm::floor(at));
    if (enterAxis >= 0) {
        for (int i = 0; i < 3; ++i) start.voxel[i] = std::clamp(start.voxel[i], w.bounds.min[i], w.bounds.max[i]);
        start.voxel[enterAxis] = dir[enterAxis] > 0 ? w.bounds.min[enterAxis] - 1 : w.bounds.max[enterAxis] + 1;
    }
    start.fraction = glm::vec3(at - glm::dvec3(start.voxel));
    std::optional<RayHit> hit = raycast(start, glm::vec3(dir), (tMax - tEnter) * w.voxelSize);
    if (hit) hit->distance += tEnter * w.voxelSize;
    return hit;
}

}  // namespace grotto::voxel
