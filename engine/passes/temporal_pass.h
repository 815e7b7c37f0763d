#pragma once
// Temporal accumulation at AO resolution. Reads: the raw and the spatially
// denoised AO (with depth and face), the previous frame's output (history), GTAO and temporal
// constants. Writes: the next history, which the upsample reads. History: the
// output image itself, kept by the renderer for the next frame.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class TemporalPass {
public:
    explicit TemporalPass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const vk::Image& raw, const vk::Image& current, const vk::Image& history,
                const vk::Image& target, const vk::Buffer& gtaoConstants, const vk::Buffer& temporalConstants);

private:
    ComputePass pass_;
};

}  // namespace grotto
