#pragma once
// The path-traced reference of the light (docs/reference.md, "Full light"): the
// radiance each surface point sends toward the viewer, through the exact voxels,
// with every diffuse bounce. Lambertian faces of the materials' albedo, the
// materials' emission, the sky's gradient and the sun's disc, in one scale of
// radiance (docs/lighting.md, "Units"). Unbiased: paths end by Russian roulette,
// not at a fixed length. OpenVDB-free interface.
#include "voxel/daylight.h"
#include "voxel/reference_ao.h"
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace grotto::voxel {

// The lights, from a world's lighting block.
struct LightSources {
    glm::dvec3 skyZenith{0.0}, skyHorizon{0.0};  // the gradient (shared/sky.h's skyRadiance)
    double skyIntensity = 0.0;                   // its radiance scale: lighting.ambient.intensity
    glm::dvec3 sunDirection{0.0, 1.0, 0.0};      // toward the sun, unit length
    // The sun's light on a face turned to it, as radiance a white face sends back
    // (irradiance / pi): lighting.sun's colour x intensity. 0: no sun.
    glm::dvec3 sun{0.0};
    double sunAngleDegrees = 0.0;                // the disc's angular diameter; 0: a point
    // The day's sun (lighting.sun.from day): the path the sun above stands on at
    // the hour. A full-light bake then keeps the light of every hour (face_cache.h).
    std::optional<SunPath> day;
};
LightSources lightSources(const Lighting& lighting);

struct PathTraceSettings {
    uint32_t spp = 256;         // paths per point (> 0)
    // Bounces at most after the light reaches the point's own view: 0 the direct
    // light only (sun, sky and emitters the point sees), 1 one bounce, ...;
    // unlimited (the default): every bounce, paths ended by Russian roulette.
    uint32_t maxBounces = UINT32_MAX;
    double epsilon = 1e-4;      // each ray's offset along its face's normal, in voxels
    uint64_t seed = 0;          // same seed, same bits, on any thread count
};

struct PathTraced {
    std::vector<glm::vec3> radiance;  // per point, linear RGB
    std::vector<glm::vec3> stderror;  // per point and channel: the sample standard deviation / sqrt(spp)
    uint64_t rays = 0;                // rays traced in all (bounces and shadow rays)
};

// The radiance leaving each point (world units) along any direction (the faces
// are Lambertian). normals: the faces' unit axis normals. owners: per point, 0
// for the world's voxels or k for objects[k - 1]; empty: every point the world's.
// A point's material is that of the voxel behind its face. Multithreaded; the
// result does not depend on the thread count. Throws grotto::Error (input) for
// spp 0, and (internal) for mismatched spans.
PathTraced pathTrace(const World& world, std::span<const PosedWorld> objects, std::span<const glm::dvec3> points,
                     std::span<const glm::dvec3> normals, std::span<const uint32_t> owners,
                     const LightSources& lights, const PathTraceSettings& settings);

}  // namespace grotto::voxel
