#pragma once
// GTAO main pass at half resolution. Reads: the depth MIP chain, the full-res
// surface ids (normals), GTAO constants. Writes: AoTargets::raw (visibility and
// packed edges). No history; the noise follows GtaoConstants::frameIndex.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class GtaoPass {
public:
    // The loop shape (slices, steps, distribution power) is compiled in from `settings`.
    GtaoPass(vk::Context& ctx, const gpu::GtaoSettings& settings);
    void record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
