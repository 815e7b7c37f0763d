#include "engine/passes/shadow_pass.h"

#include "engine/passes/trace_inputs.h"

namespace grotto {

ShadowPass::ShadowPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "shadow.comp",
            withTraceBindings({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                               VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE})) {}

void ShadowPass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Buffer& objectUniforms,
                        const vk::Image& shadow, const vk::Buffer& traceConstants, const GpuOccupancy& occupancy) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pass_.dispatch(cmd,
                   withTraceBindings({vk::sampledImage(ctx_.pointSampler, g.depth.view, ro),
                                      vk::sampledImage(ctx_.pointSampler, g.surface.view, ro),
                                      vk::uniformBuffer(objectUniforms.buffer), vk::storageImage(shadow.view)},
                                     traceConstants, occupancy),
                   shadow.extent, GROTTO_TRACE_GROUP);
}

}  // namespace grotto
