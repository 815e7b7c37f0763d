#include "engine/passes/composite_pass.h"

#include "shaders/shared/frame.h"

namespace grotto {

namespace {
// Threads per group side, measured on lavapipe: with AO each thread shades a 2x2
// block, and smaller groups of them run faster.
uint32_t group(bool withAo) { return withAo ? 8u : 16u; }
}  // namespace

CompositePass::CompositePass(vk::Context& ctx, bool withAo, bool withShadow, bool withBentNormals)
    : ctx_(ctx),
      withAo_(withAo),
      pass_(ctx, "composite.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            0, {withAo ? 1u : 0u, group(withAo), group(withAo), withShadow ? 1u : 0u, withBentNormals ? 1u : 0u}) {}

void CompositePass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Image& aoHalf,
                           const vk::Image& color, const vk::Buffer& frame, const vk::Buffer& palette,
                           const vk::Buffer& gtaoConstants, const vk::Buffer& objectUniforms,
                           const vk::Image& shadow, const vk::Image& bentNormals) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(frame.buffer), vk::uniformBuffer(palette.buffer),
                    vk::sampledImage(ctx_.pointSampler, g.surface.view, ro), vk::storageImage(color.view),
                    vk::uniformBuffer(gtaoConstants.buffer), vk::storageImage(aoHalf.view),
                    vk::sampledImage(ctx_.pointSampler, g.depth.view, ro), vk::uniformBuffer(objectUniforms.buffer),
                    vk::storageImage(shadow.view), vk::storageImage(bentNormals.view)},
                   withAo_ ? aoHalf.extent : color.extent,  // with AO, one thread per AO pixel
                   group(withAo_));
}

}  // namespace grotto
