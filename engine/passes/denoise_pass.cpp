#include "engine/passes/denoise_pass.h"

namespace grotto {

DenoisePass::DenoisePass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "denoise.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            sizeof(uint32_t)) {}

void DenoisePass::record(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, const vk::Buffer& constants) {
    for (uint32_t i = 0; i < passes; ++i) {
        const vk::Image& source = i == 0 ? ao.raw : ao.spatial[(i - 1) % 2];
        const uint32_t finalPass = i + 1 == passes ? 1u : 0u;
        pass_.dispatch(cmd,
                       {vk::uniformBuffer(constants.buffer),
                        vk::storageImage(source.view),
                        vk::storageImage(ao.spatial[i % 2].view)},
                       ao.half, GROTTO_GTAO_GROUP, &finalPass);
        computeToCompute(cmd);
    }
}

}  // namespace grotto
