#pragma once
// Display pass, for the window and an embedding game only (image files tone-map
// on the CPU). Reads: the composite's scene-linear colour. Writes: RGBA16F
// display-linear colour in [0, 1], through the tone map (shaders/shared/tone_map.h);
// an sRGB target encodes it. No history. A pass of its own: writing the display
// image from the composite's invocations cost 2.5 times as much on lavapipe
// (docs/benchmarks.md).
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/vk/resources.h"

namespace grotto {

class DisplayPass {
public:
    explicit DisplayPass(vk::Context& ctx);
    static bool runs(const FramePlan& plan) { return plan.display; }
    static PassDecl declare() { return {"display", {{TargetId::Color, Access::Read}, {TargetId::Display, Access::Write}}}; }
    // `curve`: GROTTO_TONE_MAP_FILMIC or GROTTO_TONE_MAP_CLAMP.
    void record(VkCommandBuffer cmd, const vk::Image& color, const vk::Image& display, uint32_t curve);

private:
    ComputePass pass_;
};

}  // namespace grotto
