#pragma once
// GTAO main pass at half resolution. Reads: the depth MIP chain, the full-res
// surface ids (normals), GTAO constants. Writes: AoTargets::raw (visibility and
// packed edges). No history; the noise follows GtaoConstants::frameIndex.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class GtaoPass {
public:
    explicit GtaoPass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
