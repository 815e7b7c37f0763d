#include "engine/passes/composite_pass.h"

#include "shaders/shared/frame.h"

namespace grotto {

CompositePass::CompositePass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "composite.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void CompositePass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Image& ao, const vk::Image& color,
                           const vk::Buffer& frame, const vk::Buffer& palette) {
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(frame.buffer), vk::uniformBuffer(palette.buffer),
                    vk::sampledImage(ctx_.pointSampler, g.surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::sampledImage(ctx_.pointSampler, ao.view, VK_IMAGE_LAYOUT_GENERAL),
                    vk::storageImage(color.view)},
                   color.extent, GROTTO_COMPOSITE_GROUP);
}

}  // namespace grotto
