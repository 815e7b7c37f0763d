#pragma once
// Light cached on the world's exposed voxel faces. A static world's AO, sky light
// and sun visibility belong to its surfaces, not to the view: each exposed face
// (a solid voxel and the direction of its open neighbour) carries k x k texels,
// and each texel accumulates, from the same cosine-weighted rays:
//  - AO: the share of rays that enter no solid voxel within R (the reference's
//    definition, docs/metrics.md, so every AO figure stays comparable);
//  - sky light: the same rays run on through the whole world; an open one adds the
//    sky gradient's radiance in its direction (shaders/shared/sky.h), kept as the
//    weights of its two colours, so a new sky re-weights without tracing;
//  - sun visibility: the share of rays toward the sun's disc that leave the world;
//  - or, for the day's moving sun, whether a ray from the texel's centre toward
//    each of kDaySunPositions positions along the day's path leaves the world.
// Counts stay beside the sums, so more rays can be added later and a texel's
// convergence is known. OpenVDB-free interface.
#include "voxel/daylight.h"
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace grotto::voxel {

class BrickTable;

// The day's sun positions a texel keeps a bit for (voxel/daylight.h's
// sunPositionHour): 32 miss 0.08% of sunlit samples on houses' day
// (docs/face-cache.md, "The day's sun: how many positions").
inline constexpr uint32_t kDaySunPositions = 32;
// Toward the sun at each of them along `path`.
std::vector<glm::dvec3> daySunDirections(const SunPath& path);

// Full light over the day (voxel/light_bake.h) keeps, for each face, the light
// bounced to it split by where it came from, so that a frame at any hour sums it
// with that hour's colours and traces nothing: the light of a zenith-coloured
// and of a horizon-coloured sky (each white, radiance 1) after their first
// bounce, then that of a white sun of irradiance pi at kDayBouncePositions of
// the day's positions (dayBouncePosition), interpolated between them.
inline constexpr uint32_t kDayBouncePositions = 16;
inline constexpr uint32_t kDayLightWords = 2 + kDayBouncePositions;
// The day's sun position (0 to kDaySunPositions - 1) bounce position b stands at:
// spread evenly from sunrise (0) to sunset (the last).
inline constexpr uint32_t dayBouncePosition(uint32_t b) {
    return (b * (kDaySunPositions - 1) + (kDayBouncePositions - 1) / 2) / (kDayBouncePositions - 1);
}
// The two bounce positions either side of the continuous position `at` (0 to
// kDaySunPositions - 1, sunPositionSpan's before + toward) and the weight of the second.
struct DayBounceSpan {
    uint32_t before = 0, after = 0;
    double toward = 0.0;
};
DayBounceSpan dayBounceSpan(double at);

// A solid voxel's face whose neighbour across it is open. `dir` as RayHit::face:
// 0..5 = +X -X +Y -Y +Z -Z (the direction the face looks).
struct ExposedFace {
    glm::ivec3 cell{0};
    uint8_t dir = 0;
    bool operator==(const ExposedFace&) const = default;
};
// The order faces are listed in: by cell (x, then y, then z), then direction.
inline bool operator<(const ExposedFace& a, const ExposedFace& b) {
    if (a.cell.x != b.cell.x) return a.cell.x < b.cell.x;
    if (a.cell.y != b.cell.y) return a.cell.y < b.cell.y;
    if (a.cell.z != b.cell.z) return a.cell.z < b.cell.z;
    return a.dir < b.dir;
}

// Every exposed face of the world, in that order whatever the grid's own.
std::vector<ExposedFace> exposedFaces(const World& world);
std::vector<ExposedFace> exposedFaces(const BrickTable& table, const World& world);
// The same list after an edit of the voxels in `changed`, from `before` (the list
// before it): a face depends only on its cell and the cell it looks into, so
// those of cells more than a voxel outside the box are kept and only the cells
// within one voxel of it are listed again.
std::vector<ExposedFace> exposedFacesAfterEdit(const BrickTable& table, const World& world,
                                               const std::vector<ExposedFace>& before, const IndexBox& changed);

// How many there are, and how many 8^3 bricks hold one, without listing them:
// whole rows of voxels at a time (for `info`).
struct ExposedFaceCount {
    uint64_t faces = 0;
    uint64_t bricks = 0;
};
ExposedFaceCount countExposedFaces(const World& world);

// A texel's sums. Sky light from them: horizon * skyHorizon / samples +
// zenith * skyZenith / samples (irradiance over pi: an open floor under a uniform
// sky of radiance L gets L).
struct FaceTexel {
    uint32_t samples = 0;     // cosine-weighted rays cast
    uint32_t open = 0;        // of those, entering no solid voxel within R
    float skyHorizon = 0.0f;  // sum over rays that leave the world of the horizon colour's weight
    float skyZenith = 0.0f;   // likewise for the zenith colour
    uint32_t sunSamples = 0;  // rays toward the sun's disc cast
    uint32_t sunOpen = 0;     // of those, leaving the world
    // The day's sun (a bake with FaceBakeSettings::day): bit m set where the ray
    // toward position m leaves the world; 0 for a position behind the face.
    uint32_t daySun = 0;
    uint32_t dayPositions = 0;  // positions traced: 0, or kDaySunPositions
    // Full light (voxel/light_bake.h), when baked: the irradiance over pi from
    // the sky, the glowing faces and every bounce, but not the sun's direct beam.
    glm::vec3 light{0.0f};

    double ao() const { return samples ? double(open) / samples : 1.0; }
    double sun() const { return sunSamples ? double(sunOpen) / sunSamples : 1.0; }
    bool operator==(const FaceTexel&) const = default;
};

// How the sky's radiance in a direction of height `up` (its y) splits between the
// horizon and zenith colours: shaders/shared/sky.h's skyRadiance, as two weights.
struct SkyWeights {
    float horizon, zenith;
};
SkyWeights skyWeights(double up);

// Where texel (i, j) of a face with k texels a side lies, in voxel index units
// (relative to voxel corner 0,0,0): on the face's plane, i along the face's U
// axis and j along V (shaders/shared/quad.h).
glm::dvec3 texelPoint(const ExposedFace& face, uint32_t k, uint32_t i, uint32_t j);
// The face's outward unit normal.
glm::dvec3 faceNormal(uint8_t dir);

}  // namespace grotto::voxel
