#pragma once
// Depth prefilter. Reads: full-res depth (D32), the AO constants.
// Writes: the AO-resolution view-depth MIP chain (AoTargets::depthAtlas). No history.
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class DepthPrefilterPass {
public:
    explicit DepthPrefilterPass(vk::Context& ctx);
    static PassDecl declare() {
        return {"prefilter", {{TargetId::Depth, Access::Sampled}, {TargetId::AoDepthAtlas, Access::Write}}};
    }
    void record(VkCommandBuffer cmd, const vk::Image& depth, const AoTargets& ao, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
