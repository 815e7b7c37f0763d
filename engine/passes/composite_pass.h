#pragma once
// Composite pass. Reads: the surface id, the palette, frame uniforms.
// Writes: linear RGBA32F colour (sun Lambert + ambient x AO, sky). No history.
#include "engine/passes/gbuffer_pass.h"

namespace grotto {

class CompositePass {
public:
    explicit CompositePass(vk::Context& ctx);
    ~CompositePass();

    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Image& color,
                const vk::Buffer& frame, const vk::Buffer& palette);

private:
    vk::Context& ctx_;
    VkSampler sampler_;
    VkDescriptorSetLayout setLayout_;
    VkPipelineLayout layout_;
    VkPipeline pipeline_;
};

}  // namespace grotto
