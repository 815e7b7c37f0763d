#pragma once
// DESIGN.md's temporal metrics at AO resolution. An AO pixel (x, y) stands for
// full-res pixel (2x, 2y) exactly (1:1 with --ao-full-res), so its world position,
// and the reference there, are that pixel's.
//   flicker: mean |V_t(p) - V_t-1(q)| over pixels p whose reprojection q shows the
//            same surface (world positions within half a voxel);
//   age:     frames since a pixel was last disoccluded (no such q), for ghosting.
#include "engine/camera.h"
#include "engine/renderer.h"

#include <cstdint>
#include <vector>

namespace grotto {

struct AoFrame {
    uint32_t width = 0, height = 0;     // AO resolution
    uint32_t scale = 2;                 // full-res pixels per AO pixel
    std::vector<glm::dvec3> world;      // surface position per AO pixel
    std::vector<uint8_t> surface;       // 0 for sky
    std::vector<float> raw, spatial, temporal;
};

// Needs a readback with AOVs.
AoFrame aoFrame(const FrameImages& frame, const Camera& camera, uint32_t scale);

// For each pixel of `now`, the index of the pixel of `before` that shows the same
// surface point (within `tolerance` world units), or -1: off-screen or disoccluded.
std::vector<int32_t> reproject(const AoFrame& now, const AoFrame& before, const Camera& beforeCamera,
                               double tolerance);

// Mean |now(p) - before(match(p))| over matched pixels; 0 when none matched.
double flicker(const std::vector<float>& now, const std::vector<float>& before, const std::vector<int32_t>& match);

// Frames since each pixel was disoccluded: 0 where unmatched, else the matched
// pixel's age + 1 (capped). `previous`: the last frame's ages.
std::vector<uint16_t> disocclusionAge(const std::vector<int32_t>& match, const std::vector<uint16_t>& previous,
                                      size_t pixels);

}  // namespace grotto
