#pragma once
// Depth prefilter. Reads: full-res depth (D32), GTAO constants.
// Writes: the half-res view-depth MIP chain (AoTargets::depthMips). No history.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class DepthPrefilterPass {
public:
    explicit DepthPrefilterPass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const vk::Image& depth, const AoTargets& ao, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
