#include "engine/passes/gtao_pass.h"

#include <bit>

namespace grotto {

GtaoPass::GtaoPass(vk::Context& ctx, const gpu::GtaoSettings& settings)
    : ctx_(ctx),
      pass_(ctx, "gtao.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            0, {settings.sliceCount, settings.stepsPerSlice, std::bit_cast<uint32_t>(settings.sampleDistributionPower)}) {}

void GtaoPass::record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants) {
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(constants.buffer),
                    vk::storageImage(ao.depthAtlas.view),
                    vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::storageImage(ao.raw.view)},
                   ao.half, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
