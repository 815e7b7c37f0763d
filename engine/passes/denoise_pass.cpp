#include "engine/passes/denoise_pass.h"

namespace grotto {

DenoisePass::DenoisePass(vk::Context& ctx)
    : pass_(ctx, "denoise.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            sizeof(uint32_t)) {}

void DenoisePass::record(VkCommandBuffer cmd, const AoTargets& ao, uint32_t passes, uint32_t index,
                         const vk::Buffer& constants) {
    const uint32_t finalPass = index + 1 == passes ? 1u : 0u;
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(constants.buffer), vk::storageImage(ao.denoised(index).view),
                    vk::storageImage(ao.denoised(index + 1).view)},
                   ao.half, GROTTO_GTAO_GROUP, &finalPass);
}

}  // namespace grotto
