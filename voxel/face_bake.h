#pragma once
// Rays for the face cache (voxel/face_cache.h), traced on the CPU: what a bake
// runs on every core, and what tests hold the GPU's texels to. Each texel's rays
// follow one low-discrepancy sequence turned by a hash of the face and texel, so
// a texel gets the same bits whichever faces share its call, in whatever order:
// a bake split into parts and joined equals one bake.
#include "voxel/daylight.h"
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace grotto::voxel {

// `grotto bake`'s defaults: on caves, 3 x 3 texels of 64 rays measured best for
// their cost (docs/face-cache.md).
inline constexpr uint32_t kDefaultBakeTexels = 3, kDefaultBakeRays = 64, kDefaultBakeSunRays = 16;

struct FaceBakeSettings {
    double radius = 4.0;                         // AO's R, world units (> 0)
    uint32_t texelsPerSide = kDefaultBakeTexels; // k: k x k texels per face
    uint32_t rays = kDefaultBakeRays;            // cosine-weighted rays per texel per call (AO and sky)
    uint32_t sunRays = kDefaultBakeSunRays;      // rays per texel per call toward the sun, from all over the texel
    glm::dvec3 sunDirection{0.0, 1.0, 0.0};  // toward the sun, unit length
    double sunAngleDegrees = 0.0;    // the disc's angular diameter; 0: a point
    double epsilon = 1e-4;           // rays leave this far (voxels) in front of the face
    // false: the AO alone, no sky or sun (a mesh export's vertex AO): each ray
    // open within R is not followed out of the world, and no sun ray is traced.
    bool light = true;
    // The world's light is baked too (lighting.ambient.from full; voxel/light_bake.h):
    // the texels' light words hold it, and a texel traced without the bake holds
    // the sky's light alone, from these colours (times the sky's intensity). These
    // rays then leave the sky weights to the light bake's rays.
    bool fullLight = false;
    glm::dvec3 skyZenith{0.0}, skyHorizon{0.0};
    // The day's sun (lighting.sun.from day): one ray a position along its path
    // from each texel's centre (FaceTexel::daySun) instead of sunRays toward one sun.
    std::optional<SunPath> day;
};

// The rays a texel gets toward the sun: sunRays, even for a point sun (they start
// all over the texel's square); none for a bake without light, or for the day's sun.
inline uint32_t sunRaysPerTexel(const FaceBakeSettings& s) { return s.light && !s.day ? s.sunRays : 0; }
// The day's positions a texel traces: kDaySunPositions with the day's sun and light.
inline uint32_t daySunPositions(const FaceBakeSettings& s) { return s.light && s.day ? kDaySunPositions : 0; }

// The hash a texel's rays are turned by: of its face and place alone, so a texel
// traced again after an edit, or in another part of a bake, gets the same rays.
uint64_t texelSeed(const ExposedFace& face, uint32_t i, uint32_t j);

// Adds `rays` and `sunRays` more to each texel of `faces` (texels: faces.size() x
// k x k, face-major, then j, then i), continuing each texel's sequence from the
// samples it holds. Multithreaded. Throws grotto::Error (input) for a radius <= 0,
// k 0 or a texel span of the wrong size.
void bakeFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
               const FaceBakeSettings& settings, std::span<FaceTexel> texels);

// Told the faces baked so far and their total: with 0 before the first run of
// faces, then after each of bakeSteps(total) runs (a long bake's progress).
using BakeProgress = std::function<void(size_t done, size_t total)>;
// A hundred runs, or one a face when there are fewer.
int bakeSteps(size_t faces);
// bakeFaces in bakeSteps(faces.size()) runs of faces, each on every core,
// telling `progress` (when given) of each.
void bakeFacesInSteps(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                      const FaceBakeSettings& settings, std::span<FaceTexel> texels, const BakeProgress& progress);

// The same rays from arbitrary points on face planes (voxel index units) looking
// `dirs`, each turned by a hash of `seed` and its index: a reference for what the
// cache reads between its texels. Throws as bakeFaces.
std::vector<FaceTexel> tracePoints(const BrickTable& table, const World& world, std::span<const glm::dvec3> points,
                                   std::span<const uint8_t> dirs, const FaceBakeSettings& settings, uint64_t seed);

}  // namespace grotto::voxel
