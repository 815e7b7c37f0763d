#pragma once
// Exact CPU rays toward the sun, as the shadow pass casts them on the GPU: is a
// direction blocked from a point on a face, up to where the ray leaves the world's
// solid bounds? For the shadow tests (test_trace.cpp, test_soft_sun.cpp).
#include "voxel/world.h"

#include <glm/vec3.hpp>

namespace grotto::test {

class SunRays {
public:
    explicit SunRays(const voxel::World& world) : world_(world) {}

    // Is the unit direction `d` blocked from the point `p` (world units) on a face of
    // axis-aligned unit normal `n`? As on the GPU (shaders/trace.glsl): the ray starts
    // kNormalOffset voxel in front of the face's plane, in the open voxel there
    // (World::faceRayStart), and runs World::raycast's traversal, the GPU's own code.
    bool blocked(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& d) const;

    static constexpr float kNormalOffset = 1e-4f;  // voxels, as the shadow pass offsets its rays

private:
    const voxel::World& world_;
};

}  // namespace grotto::test
