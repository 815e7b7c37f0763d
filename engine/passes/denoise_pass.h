#pragma once
// Spatial denoise: N edge-aware blur passes at AO resolution. Reads:
// AoTargets::raw, the AO constants. Writes: AoTargets::spatial (ping-pong). No history.
// With the temporal pass on, that pass runs the final blur itself (temporal.comp),
// so the frame records only the passes before it; the final pass alone
// reproduces its output on demand (the AO_spatial AOV).
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class DenoisePass {
public:
    explicit DenoisePass(vk::Context& ctx);
    static bool runs(const FramePlan& plan) { return plan.chain; }
    // Every pass of a frame is timed together under this name.
    static constexpr const char* kTimestamp = "denoise";
    // Pass `index` reads denoised(index) and writes denoised(index + 1).
    static PassDecl declare(uint32_t index) {
        return {nullptr, {{denoisedTarget(index), Access::Read}, {denoisedTarget(index + 1), Access::Write}}};
    }
    // Pass `index` of `passes` (the last one blurs with the final weights).
    void record(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, uint32_t index, const vk::Buffer& constants);

private:
    ComputePass pass_;
};

}  // namespace grotto
