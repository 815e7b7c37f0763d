#pragma once
// Full light over the day (voxel/light_bake.h): each face's day words, the light
// bounced to it from a white zenith sky, a white horizon sky and a white sun at
// each of the day's bounce positions (voxel/face_cache.h), solved face by face.
// A frame reads them per face, so the bake keeps them per face too: what a face
// sends is its albedo times its texels' mean light, and what its rays bring back
// is merged by the face they hit. The passes then cost a few hundred terms a
// face rather than every ray of its texels, for 18 words at once.
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <utility>
#include <span>
#include <vector>

namespace grotto::voxel {

// Which faces a relit face's rays reach, and each one's share of the face's
// bounced light (the mean over its texels of their rays' shares), merged by face:
// a row a relit face.
using FaceRow = std::vector<std::pair<uint32_t, float>>;
// Sorts a row by face and adds up each face's shares.
void mergeByFace(FaceRow& row);

// Every face's sources, each white: its texels' mean direct light of the zenith
// and the horizon sky (irradiance over pi per unit radiance, 2 a face) and of
// the sun at each bounce position (cos x visibility, kDayBouncePositions a face),
// and its albedo.
struct DaySources {
    std::vector<glm::vec3> albedo;
    std::vector<float> direct;  // kDayLightWords a face
};
// Of `faces` (k x k `texels` each, their sky weights and day's sun bits traced)
// on the day `path`, with `albedo` of each.
DaySources daySources(std::span<const ExposedFace> faces, uint32_t k, std::span<const FaceTexel> texels,
                      const SunPath& path, const std::function<glm::vec3(size_t face)>& albedo);

// The day words of the faces `relit` (ascending, `rows` in their order) by
// feedback passes: each word of a relit face is what its rows' faces send back,
// their albedo times their own word and source, from the pass before; the other
// faces send what `dayLight` holds. Passes repeat until no relit face's word
// changes by more than `tolerance` of itself (floored at 1e-4 of the word's mean
// source), at most `maxPasses`. Writes the relit faces' words into `dayLight`
// (kDayLightWords a face); returns the passes run.
uint32_t solveDayLight(std::span<const uint32_t> relit, std::span<const FaceRow> rows, const DaySources& sources,
                       double tolerance, uint32_t maxPasses, std::span<glm::vec3> dayLight);

// What face f sends back in word w: its albedo times its word and its source.
inline glm::vec3 daySent(const DaySources& s, std::span<const glm::vec3> dayLight, size_t f, uint32_t w) {
    return s.albedo[f] * (dayLight[f * kDayLightWords + w] + s.direct[f * kDayLightWords + w]);
}

}  // namespace grotto::voxel
