#pragma once
// The final spatial blur and temporal accumulation at AO resolution, in one pass.
// Reads: the final blur's input (AoTargets::denoised(passes - 1)), the raw AO (the
// clamp's range), the previous frame's output (history), GTAO and temporal
// constants. Writes: the next history, which the composite reads. History: the
// output image itself, kept by the renderer for the next frame.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class TemporalPass {
public:
    // `denoisePasses`: the spatial denoise's pass count; this pass runs the last.
    TemporalPass(vk::Context& ctx, uint32_t denoisePasses);
    void record(VkCommandBuffer cmd, const AoTargets& ao, const vk::Image& history, const vk::Image& target,
                const vk::Buffer& gtaoConstants, const vk::Buffer& temporalConstants);

private:
    uint32_t denoisePasses_;
    ComputePass pass_;
};

}  // namespace grotto
