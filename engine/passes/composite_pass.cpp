#include "engine/passes/composite_pass.h"

#include "engine/vk/pipeline.h"
#include "shaders/shared/frame.h"

namespace grotto {

CompositePass::CompositePass(vk::Context& ctx) : ctx_(ctx) {
    VkSamplerCreateInfo si{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                           .magFilter = VK_FILTER_NEAREST,
                           .minFilter = VK_FILTER_NEAREST,
                           .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                           .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                           .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                           .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE};
    VK_CHECK(vkCreateSampler(ctx.device, &si, nullptr, &sampler_));
    setLayout_ = vk::pushDescriptorLayout(ctx,
                                          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                          VK_SHADER_STAGE_COMPUTE_BIT);
    layout_ = vk::pipelineLayout(ctx, setLayout_, 0, 0);
    pipeline_ = vk::computePipeline(ctx, layout_, "composite.comp");
}

CompositePass::~CompositePass() {
    vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, setLayout_, nullptr);
    vkDestroySampler(ctx_.device, sampler_, nullptr);
}

void CompositePass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Image& color,
                           const vk::Buffer& frame, const vk::Buffer& palette) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vk::pushBindings(ctx_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_,
                     {vk::uniformBuffer(frame.buffer), vk::uniformBuffer(palette.buffer),
                      vk::sampledImage(sampler_, g.surface.view, ro), vk::storageImage(color.view)});
    const uint32_t group = GROTTO_COMPOSITE_GROUP;
    vkCmdDispatch(cmd, (color.extent.width + group - 1) / group, (color.extent.height + group - 1) / group, 1);
}

}  // namespace grotto
