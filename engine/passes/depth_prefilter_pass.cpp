#include "engine/passes/depth_prefilter_pass.h"

namespace grotto {

DepthPrefilterPass::DepthPrefilterPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "depth_prefilter.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            sizeof(int32_t)) {}

void DepthPrefilterPass::record(VkCommandBuffer cmd, const vk::Image& depth, const AoTargets& ao,
                                const vk::Buffer& constants) {
    for (int32_t level = 0; level < GROTTO_GTAO_DEPTH_MIPS; ++level) {
        // Level 0 reads the depth buffer; the source binding then only needs to be valid.
        const vk::Image& source = ao.depthMips[level == 0 ? 0 : level - 1];
        pass_.dispatch(cmd,
                       {vk::uniformBuffer(constants.buffer),
                        vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                        vk::sampledImage(ctx_.pointSampler, source.view, VK_IMAGE_LAYOUT_GENERAL),
                        vk::storageImage(ao.depthMips[level].view)},
                       ao.depthMips[level].extent, GROTTO_GTAO_GROUP, &level);
        computeToCompute(cmd);
    }
}

}  // namespace grotto
