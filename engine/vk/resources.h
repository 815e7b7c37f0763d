#pragma once
// Buffers and images with their memory, plus upload and layout transitions.
#include "engine/vk/context.h"

#include <cstddef>
#include <functional>

namespace grotto::vk {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    Allocation memory;
    VkDeviceSize size = 0;
    void* mapped() const { return memory.mapped; }
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    Allocation memory;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

Buffer createBuffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible);
void destroy(Context& ctx, Buffer& b);

Image createImage(Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage);
// The bytes createImage would allocate for such an image, without making it: the
// device's own requirement where it says so beforehand (Vulkan 1.3) for a size it
// supports, else texels x texel size (short of the driver's padding).
VkDeviceSize imageBytes(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage);
void destroy(Context& ctx, Image& i);
// The bytes of one texel of `format` (the formats the frame's targets use).
VkDeviceSize texelBytes(VkFormat format);

// Device-local buffer filled from host data through a staging buffer.
Buffer uploadBuffer(Context& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage);
// The same, `fill` writing the data straight into the staging buffer (`size`
// bytes): no copy of it built first on the host.
Buffer uploadBuffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, const std::function<void(void*)>& fill);

// One image memory barrier (whole image) between two layouts and stages.
void transition(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);
// The same for an image Grotto did not make (a swapchain's): one mip, one layer.
void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                VkAccessFlags dstAccess);

// A primary command buffer from the context's pool, and an unsignalled fence.
VkCommandBuffer allocateCommandBuffer(Context& ctx);
VkFence createFence(Context& ctx);

}  // namespace grotto::vk
