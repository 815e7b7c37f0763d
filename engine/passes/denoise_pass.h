#pragma once
// Spatial denoise: N edge-aware blur passes at half resolution. Reads:
// AoTargets::raw, GTAO constants. Writes: AoTargets::spatial (ping-pong). No history.
// With the temporal pass on, that pass runs the final blur itself (temporal.comp),
// so the frame records only the passes before it; recordFinal reproduces the
// final pass's output on demand (the AO_spatial AOV).
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class DenoisePass {
public:
    explicit DenoisePass(vk::Context& ctx);
    // Passes 0 .. count - 1 of `passes` (all, or all but the last when the temporal
    // pass runs that), each followed by a barrier.
    void record(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, uint32_t count, const vk::Buffer& constants);
    // The last of `passes` alone, into ao.denoised(passes) (needs passes > 0).
    void recordFinal(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, const vk::Buffer& constants);

private:
    void dispatch(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, uint32_t index,
                  const vk::Buffer& constants);

    ComputePass pass_;
};

}  // namespace grotto
