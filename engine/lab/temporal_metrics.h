#pragma once
// The temporal metrics (docs/metrics.md) at AO resolution. An AO pixel (x, y) stands for
// full-res pixel (2x, 2y) exactly (1:1 with --ao-full-res), so its world position,
// and the reference there, are that pixel's.
//   flicker: mean |V_t(p) - V_t-1(q)| over pixels p whose reprojection q shows the
//            same surface (world positions within half a voxel); V_t-1(q) is
//            interpolated bilinearly from the taps on p's plane, so a steady image
//            under a moving camera reads (nearly) no flicker;
//   age:     frames since a pixel was last disoccluded (no such q), for ghosting.
// The display colour's flicker is the same figure on the colour a PNG of the
// frame shows (tone-mapped, sRGB-encoded, in [0, 1]) at the same pixels.
// A point on an object is carried along with it: q must show the same point of the
// same object at the object's previous pose.
#include "engine/camera.h"
#include "engine/frame/frame_images.h"
#include "voxel/object_pose.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace grotto {

struct AoFrame {
    uint32_t width = 0, height = 0;     // AO resolution
    uint32_t scale = 2;                 // full-res pixels per AO pixel
    std::vector<glm::dvec3> world;      // surface position per AO pixel
    std::vector<glm::dvec3> normal;     // its face normal (world; axis-aligned on the world)
    std::vector<uint8_t> surface;       // 0 for sky
    std::vector<uint8_t> object;        // the object it shows (1, 2, ...), 0 for the world
    std::vector<float> raw, spatial, temporal;
    // The display colour there: the 8-bit sRGB of a PNG of the frame (srgb8Pixels),
    // in [0, 1], one vector per channel; empty for a frame read back without colour.
    std::array<std::vector<float>, 3> display;
};

// Needs a readback with AOVs.
AoFrame aoFrame(const FrameImages& frame, const Camera& camera, uint32_t scale);

// Where each pixel of `now` was in `before`: the nearest pixel showing the same
// surface point (within `tolerance` world units; -1: off-screen or disoccluded),
// and the bilinear taps around the exact position that lie on the same plane.
struct Reprojection {
    std::vector<int32_t> nearest;
    std::vector<std::array<int32_t, 4>> taps;  // -1 = unused
    std::vector<std::array<float, 4>> weights; // normalised over the used taps
};
// `poses`, `beforePoses`: the objects' poses in the two frames (none: no objects).
Reprojection reproject(const AoFrame& now, const AoFrame& before, const Camera& beforeCamera, double tolerance,
                       std::span<const voxel::ObjectPose> poses = {},
                       std::span<const voxel::ObjectPose> beforePoses = {});

// Mean |now(p) - before(q)| over reprojected pixels; 0 when there are none.
double flicker(const std::vector<float>& now, const std::vector<float>& before, const Reprojection& r);

// flicker() of the display colour, averaged over its three channels: the mean
// absolute change of a channel over the reprojected pixels; 0 without colour.
double colorFlicker(const AoFrame& now, const AoFrame& before, const Reprojection& r);

// Frames since each pixel was disoccluded: 0 where unmatched, else the matched
// pixel's age + 1 (capped). `previous`: the last frame's ages.
std::vector<uint16_t> disocclusionAge(const Reprojection& r, const std::vector<uint16_t>& previous, size_t pixels);

}  // namespace grotto
