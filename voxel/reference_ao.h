#pragma once
// The ray-traced reference AO (docs/metrics.md): from each surface
// point p with normal n, N cosine-weighted rays leave p + epsilon * n and a ray is
// occluded when it enters a solid voxel within the radius R. V = unoccluded / N.
// OpenVDB-free interface, so the engine and every command can use it.
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace grotto::voxel {

class BrickTable;

struct ReferenceAoSettings {
    double radius = 4.0;      // R, world units (> 0)
    uint32_t spp = 256;       // rays per point (> 0)
    double epsilon = 1e-4;    // offset along the normal, in voxels
    uint64_t seed = 0;        // scrambles the per-point rotations; same seed, same bits
};

struct ReferenceAo {
    std::vector<float> visibility;  // V per point, in [0, 1]
    std::vector<float> stderror;    // binomial standard error sqrt(V (1 - V) / N)
    uint64_t rays = 0;              // rays cast in all
};

// Bumped whenever the estimator or its directions change, so caches go stale.
inline constexpr int kReferenceAoVersion = 1;

// Points and normals in world units (normals need not be unit length but must be
// non-zero). Multithreaded; the result does not depend on the thread count.
// Throws grotto::Error (input) for a radius <= 0, spp 0 or mismatched spans.
ReferenceAo referenceAo(const World& world, std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& settings);
// The same with the world's bricks already in a table (voxel/brick_table.h), so a
// caller that keeps one up to date across edits (BrickTable::update) does not
// rebuild it per call. `table` must match `world`.
ReferenceAo referenceAo(const BrickTable& table, const World& world, std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& settings);

}  // namespace grotto::voxel
