#pragma once
// The final spatial blur and temporal accumulation at AO resolution, in one pass.
// Reads: the final blur's input (AoTargets::denoised(passes - 1)), the raw AO (the
// clamp's range), the previous frame's output (history), GTAO and temporal
// constants. Writes: the next history, which the composite reads. History: the
// output image itself, kept by the renderer for the next frame. In worlds with
// objects it runs temporal_objects.comp, which also reads the objects' normal
// tables and, where objects move, the G-buffer's motion target.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

#include <tuple>

namespace grotto {

class TemporalPass {
public:
    // `denoisePasses`: the spatial denoise's pass count; this pass runs the last.
    // `objects`: the world has objects; `motion`: some of them move.
    TemporalPass(vk::Context& ctx, uint32_t denoisePasses, bool objects = false, bool motion = false);
    static bool runs(const FramePlan& plan) { return plan.temporal; }
    static auto key(const FramePlan& plan) { return std::tuple(plan.ao.chain.denoisePasses, plan.objects, plan.motion); }
    // Reads history image `previous`, writes the other; with objects, samples the
    // motion target where objects move (else the depth, which it ignores).
    PassDecl declare(bool motion) const;
    // With objects, `objectUniforms` and `motion` (the motion target, or any
    // sampled float image when nothing moves; SHADER_READ_ONLY_OPTIMAL) are read too.
    void record(VkCommandBuffer cmd, const AoTargets& ao, const vk::Image& history, const vk::Image& target,
                const vk::Buffer& gtaoConstants, const vk::Buffer& temporalConstants,
                const vk::Buffer* objectUniforms = nullptr, const vk::Image* motion = nullptr);

private:
    vk::Context& ctx_;
    uint32_t denoisePasses_;
    bool objects_;
    ComputePass pass_;
};

}  // namespace grotto
