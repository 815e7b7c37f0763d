#pragma once
// The face cache's full light: on top of a bake's AO, sky and sun texels, the
// light each texel receives from everything but the sun's direct beam (which the
// frame draws per pixel, shadow edges exact): the sky through the world, the
// glowing faces, and every bounce of all of it off the world's faces.
//  - Sky: the texel's cosine-weighted rays that leave the world take the sky's
//    radiance in their direction.
//  - Glowing faces: sampled, not waited for. Each region of 8^3 voxels lists the
//    glowing faces that can reach it; a texel takes each one's light in closed
//    form (Lambert's polygon formula) and draws its shadow rays among them by
//    that light, so an unoccluded lamp is exact and only what blocks it is noisy.
//  - Bounces by feedback: the same cosine rays remember the texel they hit, and
//    each pass gives every texel what its hits send back (their albedo times their
//    light and their sun), so pass n holds n bounces. Passes repeat until no
//    texel's light changes by more than a tolerance of itself. The faces that
//    pass a region the most light are drawn toward rather than waited for
//    (voxel/bounce_guide.h): a room lit by a sunlit patch on its floor.
// A texel's `light` is irradiance over pi: radiance leaving = albedo x (light +
// the sun's direct light) + emission. OpenVDB-free interface.
#include "voxel/face_bake.h"
#include "voxel/path_trace.h"

#include <cstdint>
#include <span>

namespace grotto::voxel {

struct LightBakeSettings {
    uint32_t rays = 96;  // cosine rays per texel: the sky, and the hits bounces feed back through
    uint32_t emitterRays = 16;         // shadow rays per texel toward the glowing faces
    // Rays per texel drawn toward the faces that pass its region the most light
    // (voxel/bounce_guide.h): up to guidedFaces of them, found by guideProbeRays
    // rays from each face of the region, none nearer than guidedNearest voxels.
    // 0: bounces from the cosine rays alone.
    uint32_t guidedRays = 16;
    uint32_t guidedFaces = 16;
    uint32_t guideProbeRays = 32;
    double guidedNearest = 2.0;
    double tolerance = 1e-3;           // stop when a pass changes no texel's light by this share of it
    uint32_t maxPasses = 500;          // and in any case after this many bounces
    double epsilon = 1e-4;             // rays leave this far (voxels) in front of the face
    // Texels whose light is still noisy after the passes get rays more, enough to
    // bring its standard error under this share of it (of a hundredth of the
    // world's mean, where dimmer), up to maxExtraRays each, in all no more than
    // extraShare of the rays above; then the passes run on. 0: none. Near a lone
    // lamp the worst texel reads 1.4%, against 3.1% with 128 rays everywhere (the
    // same rays a texel on average).
    double relativeError = 0.005;
    uint32_t maxExtraRays = 1024;
    double extraShare = 1.0 / 3.0;
};

struct LightBakeStats {
    uint32_t passes = 0;      // bounce passes run
    double change = 0.0;      // the last pass's largest change of a texel, as a share of its light
    uint64_t rays = 0;        // rays traced
    uint64_t extraRays = 0;   // of those, cosine rays more where the light was noisy
};

// The bytes the bounce passes keep for `texels` texels, with the day's words
// (`dayLight`: a bake of the day's sun, voxel/face_cache.h) or without: what a
// bake checks against its memory budget before it starts.
uint64_t lightBakeBytes(uint64_t texels, const LightBakeSettings& settings, bool dayLight = false);

// The remembered hits grow with the faces: throws grotto::Error (input) naming the
// world's file when a bake of `faces` faces at k texels a side would not fit its
// memory budget. For callers to ask before any of the bake's work.
void requireLightBakeFits(const World& world, uint64_t faces, uint32_t k, const LightBakeSettings& settings,
                          bool dayLight = false);

// Sets each texel's `light`, and its sky weights from these rays (bakeFaces with
// fullLight leaves them to this). `faces`: every exposed face of the world
// (exposedFaces; bounces need them all), `texels` k x k per face holding their
// sun visibility already (bakeFaces). Multithreaded; the result does not depend
// on the thread count. `progress` is told each pass (done = passes, total = the
// most). Throws grotto::Error (input) when lightBakeBytes is over the world's
// memory budget, before anything is allocated, and (internal) for mismatched spans.
// With the day's sun (lights.day) the light is kept by source, so that any hour
// sums it without tracing: each texel's `light` holds the glowing faces' light
// alone, its sky weights the sky's direct light, and `dayLight` (kDayLightWords
// a face) each face's bounced light of the sky's two colours and of the sun at
// each bounce position.
LightBakeStats bakeLight(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                         const LightSources& lights, const LightBakeSettings& settings, std::span<FaceTexel> texels,
                         const BakeProgress& progress = {}, std::span<glm::vec3> dayLight = {});

// bakeLight for the faces `relit` alone (indices into `faces`, ascending), the
// others' light standing as their texels (and dayLight) hold it: what their hits send back
// through every pass. After an edit, the faces whose light it moved.
LightBakeStats relightFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                            const LightSources& lights, const LightBakeSettings& settings, std::span<FaceTexel> texels,
                            std::span<const uint32_t> relit, const BakeProgress& progress = {},
                            std::span<glm::vec3> dayLight = {});

// The faces, of those `skip` does not mark, that see a change of light: `change`
// holds the change of the radiance each texel sends (0 where none), and a face
// is listed when `probeRays` cosine rays from its centre find the light it
// receives (its luminance) changed by more than its `threshold`. After an edit,
// the faces lit again pass their change on this way.
std::vector<uint32_t> facesSeeingChange(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                                        uint32_t k, std::span<const FaceTexel> texels, std::span<const glm::vec3> change,
                                        std::span<const double> threshold, std::span<const uint8_t> skip,
                                        uint32_t probeRays);

}  // namespace grotto::voxel
