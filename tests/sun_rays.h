#pragma once
// Exact CPU rays toward the sun, as the shadow pass casts them on the GPU: is a
// direction blocked from a point in front of a face, up to where the ray leaves
// the world's solid bounds? For the shadow tests (test_trace.cpp, test_soft_sun.cpp).
#include "voxel/brick_table.h"
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <optional>

namespace grotto::test {

class SunRays {
public:
    explicit SunRays(const voxel::World& world) : world_(world), bounds_(world.bounds()) {}

    // Is the unit direction `d` blocked from `p` (world units)? As in the reference,
    // the voxel the ray starts in counts as open: it is the empty voxel in front of
    // the face, but at a concave edge the point, placed from float depth, may lie a
    // hair inside the neighbouring solid voxel, where World::raycast stops at once.
    // Such rays (counted in startsInside) go on through the reference's own
    // traversal (BrickTable::hitWithin, which skips the start voxel).
    bool blocked(const glm::dvec3& p, const glm::dvec3& d);

    size_t startsInside = 0;

private:
    const voxel::World& world_;
    voxel::IndexBox bounds_;
    std::optional<voxel::BrickTable> table_;  // built on first need
};

}  // namespace grotto::test
