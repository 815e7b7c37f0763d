#pragma once
// Which faces an edit of a world with full light (voxel/light_bake.h) must light
// again, beyond those its rays reach (voxel/face_cache_edit.h): the faces a
// glowing face that came, went or changed colour could light, and those a
// glowing face could light through the edited box, that now blocks or opens.
//
// A glowing face of radiance L lights a point at distance d with at most
// L / (pi d^2) of irradiance over pi (a unit square seen face on). A face is lit
// again when that bound passes kRelightShare of its own light, or of the world's
// mean light where its own is less. Then the light bounced off the faces lit
// again: a face whose rays (kProbeRays from its centre) find it changed by more
// than that share is lit again too, and so on, a few rounds. The light left
// standing elsewhere is off by about that share at most.
#include "voxel/face_cache.h"
#include "voxel/face_cache_edit.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace grotto::voxel {

inline constexpr double kRelightShare = 1.0 / 64.0;
inline constexpr uint32_t kProbeRays = 16;
inline constexpr uint32_t kRelightRounds = 4;  // of bounced change, at most

struct GlowingFace {
    ExposedFace face;
    glm::dvec3 radiance{0.0};
    bool operator==(const GlowingFace&) const = default;
};

// The faces of `faces` whose voxel's material glows in `world`, in their order.
std::vector<GlowingFace> glowingFaces(const World& world, std::span<const ExposedFace> faces);

struct RelightStats {
    uint64_t faces = 0;   // lit again, in all
    uint32_t rounds = 0;  // of bounced change that found more
};

// What each texel of `faces` (k x k each) sends back but for its glow: albedo x
// (its light and its sun), by `world`'s materials. Kept before an edit (12 bytes
// a texel) for relightAfterEdit.
// Over the day, with `dayLight` (kDayLightWords a face): the texels' light with
// their faces' words, the sun spread over its positions.
std::vector<glm::vec3> sentLight(const World& world, std::span<const ExposedFace> faces,
                                 std::span<const FaceTexel> texels, uint32_t k, std::span<const glm::vec3> dayLight = {});

// Each face's day words (kDayLightWords a face) carried from the faces `before`
// an edit to those `after` it; 0 for a face the edit made.
std::vector<glm::vec3> carriedDayLight(std::span<const ExposedFace> before, std::span<const ExposedFace> after,
                                       std::span<const glm::vec3> dayLight);

// The full light of a world after an edit of `changed`, updateAfterEdit already
// run with its rays traced at once: `faces` and `texels` as it left them,
// `before` the faces then, `sentBefore` their sentLight then and `glowingBefore`
// the glowing faces then. With the day's sun, `dayLight` (kDayLightWords a face
// of `faces`, carried over) is lit again with them.
RelightStats relightAfterEdit(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                              uint32_t k, std::span<FaceTexel> texels, std::span<const FaceReach> reach,
                              const IndexBox& changed, std::span<const ExposedFace> before,
                              std::span<const glm::vec3> sentBefore, std::span<const GlowingFace> glowingBefore,
                              std::span<glm::vec3> dayLight = {});

}  // namespace grotto::voxel
