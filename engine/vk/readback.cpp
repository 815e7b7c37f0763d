#include "engine/vk/readback.h"

#include <cstring>

namespace grotto::vk {

VkDeviceSize recordImageCopy(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, uint32_t bytesPerPixel,
                             const Buffer& buffer, VkDeviceSize offset) {
    const VkPipelineStageFlags all = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    transition(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, all, VK_ACCESS_MEMORY_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{.bufferOffset = offset,
                             .imageSubresource = {image.aspect, 0, 0, 1},
                             .imageExtent = {image.extent.width, image.extent.height, 1}};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
    transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, all, VK_ACCESS_MEMORY_READ_BIT);
    return VkDeviceSize(image.extent.width) * image.extent.height * bytesPerPixel;
}

void recordHostRead(VkCommandBuffer cmd, VkPipelineStageFlags stage, VkAccessFlags access) {
    VkMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                           .srcAccessMask = access,
                           .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
    vkCmdPipelineBarrier(cmd, stage, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
}

std::vector<uint8_t> readImage(Context& ctx, const Image& image, VkImageLayout layout, uint32_t bytesPerPixel) {
    const VkDeviceSize size = VkDeviceSize(image.extent.width) * image.extent.height * bytesPerPixel;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        recordImageCopy(cmd, image, layout, bytesPerPixel, staging, 0);
        recordHostRead(cmd);
    });
    std::vector<uint8_t> out(size);
    std::memcpy(out.data(), staging.mapped(), size);
    destroy(ctx, staging);
    return out;
}

std::vector<uint8_t> readBuffer(Context& ctx, const Buffer& buffer) {
    Buffer staging = createBuffer(ctx, buffer.size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        const VkMemoryBarrier before{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                     .srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT,
                                     .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0,
                             nullptr, 0, nullptr);
        const VkBufferCopy region{.size = buffer.size};
        vkCmdCopyBuffer(cmd, buffer.buffer, staging.buffer, 1, &region);
        recordHostRead(cmd);
    });
    std::vector<uint8_t> out(buffer.size);
    std::memcpy(out.data(), staging.mapped(), buffer.size);
    destroy(ctx, staging);
    return out;
}

}  // namespace grotto::vk
