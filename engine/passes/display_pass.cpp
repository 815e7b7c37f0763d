#include "engine/passes/display_pass.h"

namespace grotto {

DisplayPass::DisplayPass(vk::Context& ctx)
    : pass_(ctx, "display.comp", {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(uint32_t)) {}

void DisplayPass::record(VkCommandBuffer cmd, const vk::Image& color, const vk::Image& display, uint32_t curve) {
    pass_.dispatch(cmd, {vk::storageImage(color.view), vk::storageImage(display.view)}, display.extent, 16, &curve);
}

}  // namespace grotto
