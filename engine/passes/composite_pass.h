#pragma once
// Composite pass. Reads: the surface id, the palette, full-res AO, frame uniforms.
// Writes: linear RGBA32F colour: sun Lambert + ambient x AO (multi-bounce from
// albedo; the sun is not occluded), and the sky. No history.
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"

namespace grotto {

class CompositePass {
public:
    explicit CompositePass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Image& ao, const vk::Image& color,
                const vk::Buffer& frame, const vk::Buffer& palette);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
