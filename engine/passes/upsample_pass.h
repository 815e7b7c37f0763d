#pragma once
// Depth-aware upsample to full resolution, for the AO AOV only: a frame's
// composite upsamples for itself with the same code (upsample.glsl). Reads: the
// AO chain's output (with its depth and face), full-res depth and surface ids, the
// AO constants. Writes: AoTargets::full. No history. Not timed: read-backs only.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class UpsamplePass {
public:
    explicit UpsamplePass(vk::Context& ctx);
    // For read-backs with AOVs: frames do not store the full-resolution AO.
    static bool runs(const FramePlan& plan) { return plan.chain; }
    static PassDecl declare(TargetRef ao) {
        return {nullptr, {{ao, Access::Read}, {TargetId::Depth, Access::Sampled}, {TargetId::Surface, Access::Sampled},
                          {TargetId::AoFull, Access::Write}}};
    }
    // `aoHalf`: the chain's last output (spatial or temporal).
    void record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& surface, const vk::Image& aoHalf,
                const vk::Image& full, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
