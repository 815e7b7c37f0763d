#pragma once
// What an edit of the world leaves stale in the face cache (voxel/face_cache.h),
// and the cache brought up to date after one. A texel's rays are a fixed
// sequence of its face and place (voxel/face_bake.h), so re-tracing a texel from
// nothing gives, bit for bit, the parts the edit could not reach: only texels
// with a stale part are traced again, and whole.
#include "voxel/face_bake.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace grotto::voxel {

// The share of a texel's cosine-weighted sky an edit must be able to cover for
// the texel's sky light to be traced again at once; an edit farther away changes
// it by at most this much, and it is refreshed later (LiveFaceCache).
inline constexpr double kSkyStaleShare = 1.0 / 32.0;

struct StaleParts {
    bool ao = false;
    bool sun = false;
    bool skyNear = false;  // the sky light, at once
    bool skyFar = false;   // the sky light, off by at most kSkyStaleShare until refreshed
    bool now() const { return ao || sun || skyNear; }
};

// The rule, for a texel at `point` (voxel index units) on a face looking `dir`
// and an edit of the voxels in `changed` (inclusive), with rays as `settings`
// trace them (radius in world units, hence `voxelSize`):
//  - AO: its rays end R voxels out: stale when the edited box grown by R holds the point;
//  - sun: stale when a ray toward some point of the sun's disc can cross the box:
//    the ray toward the disc's centre passes within the box grown by the disc's
//    spread over the distance; with the day's sun, when the ray from the point
//    toward one of its positions facing the face does: the box swept along the
//    day (`daySun`: daySunDirections of the settings' path, found here when empty);
//  - sky: its rays run on through the world, so any edit in front of the face can
//    reach it: near when the sphere around the box covers more than kSkyStaleShare
//    of its cosine-weighted hemisphere (a sphere of radius r at distance d covers
//    at most (r / d)^2), far otherwise.
StaleParts staleAfterEdit(glm::dvec3 point, uint8_t dir, const IndexBox& changed, const FaceBakeSettings& settings,
                          double voxelSize, std::span<const glm::dvec3> daySun = {});

// The same rule with what depends on the edit alone found once, for the texels
// of every face: the same answers, bit for bit.
class StaleRule {
public:
    StaleRule(const IndexBox& changed, const FaceBakeSettings& settings, double voxelSize,
              std::span<const glm::dvec3> daySun = {});
    StaleParts at(glm::dvec3 point, uint8_t dir) const;
    // Each part stale on any of `face`'s k x k texels (`at` at each texel's point),
    // found from the face's centre alone where that settles it for every texel:
    // the texels lie within a known distance of it, and an edit is far from most
    // faces of a world.
    StaleParts worstOnFace(const ExposedFace& face, uint32_t k) const;

private:
    bool empty_;
    glm::dvec3 lo_, hi_, centre_, sun_;
    double slack_, aoReach_, halfDiagonal_, tanHalfAngle_, texelHalf_;
    bool daySun_;
    std::vector<glm::dvec3> daySunDirections_;
};

// The cache of a world after an edit of `changed`: `faces` and `texels` as they
// were before, replaced by the world's exposed faces now, each texel carried over
// unless the edit reaches it now (staleAfterEdit), new and reached faces traced
// afresh: here at once with `traceNow`, else left for the GPU's tracer (their old
// texels kept as a placeholder, a new face's empty). `reach`, when given: per face
// now, what the edit left (FaceReach).
struct CacheEditStats {
    uint64_t traced = 0;   // faces traced again or anew (or left stale for the GPU)
    uint64_t carried = 0;  // faces carried over untouched
    uint64_t skyFar = 0;   // of those, faces whose sky light the edit may change by at most kSkyStaleShare
    uint64_t relit = 0;    // with full light: faces lit again (voxel/light_edit.h)
};
enum class FaceReach : uint8_t {
    Untouched,  // carried over, still right
    Stale,      // new, or its AO or sun reached: traced again (or to be)
    SkyNear,    // only its sky light reached, by more than kSkyStaleShare: traced again
                // (or kept until it is: its AO and sun still right)
    SkyFar,     // carried over; its sky light off by at most kSkyStaleShare
};
void updateAfterEdit(const BrickTable& table, const World& world, const IndexBox& changed,
                     const FaceBakeSettings& settings, std::vector<ExposedFace>& faces, std::vector<FaceTexel>& texels,
                     CacheEditStats* stats = nullptr, bool traceNow = true, std::vector<FaceReach>* reach = nullptr);

}  // namespace grotto::voxel
