#include "engine/passes/depth_prefilter_pass.h"

#include <algorithm>

namespace grotto {

DepthMipLayout depthMipLayout(VkExtent2D half) {
    DepthMipLayout l;
    int column = 0, width1 = 0;
    for (int k = 0; k < GROTTO_GTAO_DEPTH_MIPS; ++k) {
        const int round = (1 << k) - 1;
        const glm::ivec2 size((int(half.width) + round) >> k, (int(half.height) + round) >> k);
        if (k == 0) {
            l.mips[0] = glm::ivec4(0, 0, size);
        } else {
            l.mips[k] = glm::ivec4(int(half.width), column, size);
            column += size.y;
            width1 = std::max(width1, size.x);
        }
    }
    l.atlas = {half.width + uint32_t(width1), std::max(half.height, uint32_t(column))};
    return l;
}

DepthPrefilterPass::DepthPrefilterPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "depth_prefilter.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            sizeof(int32_t)) {}

void DepthPrefilterPass::record(VkCommandBuffer cmd, const vk::Image& depth, const AoTargets& ao,
                                const vk::Buffer& constants) {
    const DepthMipLayout layout = depthMipLayout(ao.half);
    for (int32_t level = 0; level < GROTTO_GTAO_DEPTH_MIPS; ++level) {
        // Each level reads the one before from the atlas and writes its own region.
        const glm::ivec4 rect = layout.mips[level];
        pass_.dispatch(cmd,
                       {vk::uniformBuffer(constants.buffer),
                        vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                        vk::sampledImage(ctx_.pointSampler, ao.depthAtlas.view, VK_IMAGE_LAYOUT_GENERAL),
                        vk::storageImage(ao.depthAtlas.view)},
                       {uint32_t(rect.z), uint32_t(rect.w)}, GROTTO_GTAO_GROUP, &level);
        computeToCompute(cmd);
    }
}

}  // namespace grotto
