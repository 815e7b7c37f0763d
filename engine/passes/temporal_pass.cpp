#include "engine/passes/temporal_pass.h"

#include <algorithm>

namespace grotto {

TemporalPass::TemporalPass(vk::Context& ctx, uint32_t denoisePasses)
    : denoisePasses_(denoisePasses),
      pass_(ctx, "temporal.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            0, {denoisePasses >= 1 ? 1u : 0u, denoisePasses <= 1 ? 1u : 0u}) {}  // blur, sourceIsRaw

void TemporalPass::record(VkCommandBuffer cmd, const AoTargets& ao, const vk::Image& history,
                          const vk::Image& target, const vk::Buffer& gtaoConstants,
                          const vk::Buffer& temporalConstants) {
    const vk::Image& source = ao.denoised(std::max(denoisePasses_, 1u) - 1);
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(gtaoConstants.buffer), vk::uniformBuffer(temporalConstants.buffer),
                    vk::storageImage(source.view), vk::storageImage(history.view), vk::storageImage(target.view),
                    vk::storageImage(ao.raw.view)},
                   target.extent, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
