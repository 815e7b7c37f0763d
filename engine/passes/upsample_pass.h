#pragma once
// Depth-aware upsample to full resolution, for the AO AOV only: a frame's
// composite upsamples for itself with the same code (upsample.glsl). Reads: the
// half-res AO (with its depth and face), full-res depth and surface ids, GTAO
// constants. Writes: AoTargets::full. No history.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class UpsamplePass {
public:
    explicit UpsamplePass(vk::Context& ctx);
    // `aoHalf`: the chain's last half-res output (spatial or temporal).
    void record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& surface, const vk::Image& aoHalf,
                const vk::Image& full, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
