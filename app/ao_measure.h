#pragma once
// One AO setting measured against the reference: wall-time cost of the AO chain
// (the frame minus the same frame without AO) and of the whole frame, medians
// after warm-up, and the error of the final AO. Shared by `grotto tradeoff`,
// `grotto compare` and `grotto tune`.
#include "app/cost_difference.h"
#include "engine/lab/ao_metrics.h"
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/frame/chunk_culling.h"
#include "engine/lab/reference_view.h"
#include "engine/session.h"

namespace grotto::app {

struct AoMeasurement {
    AoError error;        // of the last frame's full-res AO against the reference
    CostDifference ao;    // all AO costs: prefilter, estimator, denoise, temporal, the composite's upsample;
                          // the face cache's: its AO and sun, against a frame without either
    double msFrame = 0.0; // the whole frame
    // How much the AO shows in the image: the mean absolute change of the displayed
    // colour (tone-mapped, sRGB-encoded as a PNG holds it, in [0, 1]), over the RGB
    // channels of the surface pixels, between the last frame and the same frame
    // with AO off.
    double imageChange = 0.0;
    double msGbuffer = 0.0;   // the "gbuffer" pass's GPU time, median (both culling phases)
    uint64_t quadsDrawn = 0;  // by the last frame's G-buffer
    CullingStats culling;     // of the last frame: chunks drawn at each level of detail
    std::vector<float> linearColor;  // the last frame's scene-linear RGBA (radiance x exposure)
};

// Throws grotto::Error (input) naming the world and camera when the view shows no
// surface (sky only, an empty world): every error would be a perfect score over no pixels.
void requireSurface(const ReferenceView& reference, const voxel::World& world, const std::string& camera);

// Mean |sRGB(a) - sRGB(b)| over the RGB of display-linear RGBA pixels (displayColor)
// where `surface` is set (0 for none).
double imageChange(const std::vector<float>& withAo, const std::vector<float>& withoutAo,
                   const std::vector<uint8_t>& surface);

// Renders frames 0 .. frames-1 of a static camera (consecutive indices, so the
// temporal pass accumulates) of the session's world and objects (at its poses),
// the G-buffer drawn as `culling` says; times are
// medians over the frames after `warmup`, the AO chain's and the frame's left at 0
// when `timed` is false (no frames without AO are rendered then). `color`, when
// given, receives the last frame's displayed RGBA (tone-mapped, before sRGB
// encoding: displayColor).
AoMeasurement measureAo(vk::Context& ctx, RenderSession& session, const Camera& camera,
                        const AoOptions& ao, const CullingOptions& culling, const ReferenceView& reference,
                        int frames, int warmup, bool timed = true, std::vector<float>* color = nullptr);

}  // namespace grotto::app
