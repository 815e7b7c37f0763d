#pragma once
// Copies images to host memory (tightly packed rows), restoring their layouts:
// recorded into a command buffer of the caller's, or at once with readImage.
#include "engine/vk/resources.h"

#include <cstdint>
#include <vector>

namespace grotto::vk {

// Records copying `image` (in `layout`, restored afterwards) into `buffer` at
// `offset`, after every write recorded before it. Returns the bytes copied.
VkDeviceSize recordImageCopy(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, uint32_t bytesPerPixel,
                             const Buffer& buffer, VkDeviceSize offset);
// Records the barrier that makes the copies (or, given their stage and access, other
// writes) before it visible to the host once the command buffer has completed (a
// fence wait alone does not).
void recordHostRead(VkCommandBuffer cmd, VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VkAccessFlags access = VK_ACCESS_TRANSFER_WRITE_BIT);

// A device buffer's bytes, copied out at once (after all work submitted before).
std::vector<uint8_t> readBuffer(Context& ctx, const Buffer& buffer);

std::vector<uint8_t> readImage(Context& ctx, const Image& image, VkImageLayout layout, uint32_t bytesPerPixel);

}  // namespace grotto::vk
