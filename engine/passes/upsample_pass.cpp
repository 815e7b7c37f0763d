#include "engine/passes/upsample_pass.h"

namespace grotto {

UpsamplePass::UpsamplePass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "upsample.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void UpsamplePass::record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& surface,
                          const vk::Image& aoHalf, const vk::Image& full, const vk::Buffer& constants) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(constants.buffer),
                    vk::storageImage(aoHalf.view),
                    vk::sampledImage(ctx_.pointSampler, depth.view, ro),
                    vk::sampledImage(ctx_.pointSampler, surface.view, ro), vk::storageImage(full.view)},
                   aoHalf.extent, GROTTO_GTAO_GROUP);  // one thread per AO pixel
}

}  // namespace grotto
