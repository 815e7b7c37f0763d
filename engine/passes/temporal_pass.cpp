#include "engine/passes/temporal_pass.h"

namespace grotto {

TemporalPass::TemporalPass(vk::Context& ctx)
    : pass_(ctx, "temporal.comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void TemporalPass::record(VkCommandBuffer cmd, const vk::Image& raw, const vk::Image& current,
                          const vk::Image& history, const vk::Image& target, const vk::Buffer& gtaoConstants,
                          const vk::Buffer& temporalConstants) {
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(gtaoConstants.buffer), vk::uniformBuffer(temporalConstants.buffer),
                    vk::storageImage(current.view), vk::storageImage(history.view), vk::storageImage(target.view),
                    vk::storageImage(raw.view)},
                   target.extent, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
