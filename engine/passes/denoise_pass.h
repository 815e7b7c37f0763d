#pragma once
// Spatial denoise: N edge-aware blur passes at half resolution. Reads:
// AoTargets::raw, GTAO constants. Writes: AoTargets::spatial (ping-pong). No history.
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class DenoisePass {
public:
    explicit DenoisePass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
