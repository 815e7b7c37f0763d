#pragma once
// The ray-traced reference AO (docs/metrics.md): from each surface
// point p with normal n, N cosine-weighted rays leave p + epsilon * n and a ray is
// occluded when it enters a solid voxel within the radius R. V = unoccluded / N.
// OpenVDB-free interface, so the engine and every command can use it.
#include "voxel/object_pose.h"
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

// A world placed at a pose (an object of the scene at one time): the reference
// traces rays against the world and every such object.
struct PosedWorld {
    const World* world = nullptr;
    ObjectPose pose;
};

// The objects `worlds` at `poses` (same order and count).
inline std::vector<PosedWorld> posedWorlds(std::span<const World> worlds, std::span<const ObjectPose> poses) {
    std::vector<PosedWorld> out;
    for (size_t k = 0; k < worlds.size() && k < poses.size(); ++k) out.push_back({&worlds[k], poses[k]});
    return out;
}

// As above, occluded when a ray enters a solid voxel of the world or of any object
// (at its pose) within R: each ray is carried into the object's voxel index space.
ReferenceAo referenceAo(const World& world, std::span<const PosedWorld> objects, std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& settings);
// Both: a kept brick table for the world, and objects at their poses.
ReferenceAo referenceAo(const BrickTable& table, const World& world, std::span<const PosedWorld> objects,
                        std::span<const glm::dvec3> points, std::span<const glm::dvec3> normals,
                        const ReferenceAoSettings& settings);

}  // namespace grotto::voxel
