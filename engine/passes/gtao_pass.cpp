#include "engine/passes/gtao_pass.h"

namespace grotto {

GtaoPass::GtaoPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "gtao.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void GtaoPass::record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants) {
    std::vector<vk::Binding> bindings = {vk::uniformBuffer(constants.buffer)};
    for (const vk::Image& mip : ao.depthMips)
        bindings.push_back(vk::sampledImage(ctx_.pointSampler, mip.view, VK_IMAGE_LAYOUT_GENERAL));
    bindings.push_back(vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    bindings.push_back(vk::storageImage(ao.raw.view));
    pass_.dispatch(cmd, bindings, ao.half, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
