#include "engine/passes/depth_prefilter_pass.h"

#include <algorithm>

namespace grotto {

// depth_prefilter.comp: a group of GROUP x GROUP threads reduces 2 GROUP x 2 GROUP
// MIP-0 texels to exactly one texel of the last MIP.
static_assert(2 * GROTTO_GTAO_GROUP == 1u << (GROTTO_GTAO_DEPTH_MIPS - 1));

// Mirrors gtaoMipRect in shaders/shared/gtao_kernel.h.
DepthMipLayout depthMipLayout(VkExtent2D half) {
    DepthMipLayout l;
    const glm::ivec2 half0(int(half.width), int(half.height));
    for (int k = 0; k < GROTTO_GTAO_DEPTH_MIPS; ++k) {
        const glm::ivec2 size = (half0 + ((1 << k) - 1)) >> k;
        const glm::ivec2 offset = k == 0 ? glm::ivec2(0) : glm::ivec2(half0.x, (k - 1) * ((half0.y + 1) >> 1));
        l.mips[k] = glm::ivec4(offset, size);
    }
    const int slot = (half0.y + 1) >> 1;
    l.atlas = {uint32_t(half0.x + l.mips[1].z), uint32_t(std::max(half0.y, (GROTTO_GTAO_DEPTH_MIPS - 1) * slot))};
    return l;
}

DepthPrefilterPass::DepthPrefilterPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "depth_prefilter.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void DepthPrefilterPass::record(VkCommandBuffer cmd, const vk::Image& depth, const AoTargets& ao,
                                const vk::Buffer& constants) {
    // One thread per MIP-1 texel; each group writes its share of every MIP.
    const glm::ivec4 mip1 = depthMipLayout(ao.half).mips[1];
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(constants.buffer),
                    vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::storageImage(ao.depthAtlas.view)},
                   {uint32_t(mip1.z), uint32_t(mip1.w)}, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
