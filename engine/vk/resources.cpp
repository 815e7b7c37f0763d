#include "engine/vk/resources.h"

#include "grotto/error.h"

#include <cstring>
#include <string>

namespace grotto::vk {

Buffer createBuffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo ci{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                          .size = std::max<VkDeviceSize>(size, 16),
                          .usage = usage,
                          .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VK_CHECK(vkCreateBuffer(ctx.device, &ci, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
    b.memory = ctx.allocator->allocate(req, hostVisible);
    VK_CHECK(vkBindBufferMemory(ctx.device, b.buffer, b.memory.memory, b.memory.offset));
    return b;
}

void destroy(Context& ctx, Buffer& b) {
    if (b.buffer) vkDestroyBuffer(ctx.device, b.buffer, nullptr);
    ctx.allocator->free(b.memory);
    b = {};
}

namespace {

VkImageCreateInfo imageInfo(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage) {
    return {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
            .imageType = VK_IMAGE_TYPE_2D,
            .format = format,
            .extent = {extent.width, extent.height, 1},
            .mipLevels = 1,
            .arrayLayers = 1,
            .samples = VK_SAMPLE_COUNT_1_BIT,
            .tiling = VK_IMAGE_TILING_OPTIMAL,
            .usage = usage,
            .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
            .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
}

}  // namespace

VkDeviceSize texelBytes(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R16_UINT: return 2;
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_UINT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT: return 16;
    default: throw Error::internal("vk::texelBytes", "no texel size for format " + std::to_string(int(format)));
    }
}

Image createImage(Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage) {
    Image img;
    img.format = format;
    img.extent = extent;
    const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM;
    img.aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    const VkImageCreateInfo ci = imageInfo(extent, format, usage);
    VK_CHECK(vkCreateImage(ctx.device, &ci, nullptr, &img.image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device, img.image, &req);
    img.memory = ctx.allocator->allocate(req, false);
    VK_CHECK(vkBindImageMemory(ctx.device, img.image, img.memory.memory, img.memory.offset));
    VkImageViewCreateInfo vi{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                             .image = img.image,
                             .viewType = VK_IMAGE_VIEW_TYPE_2D,
                             .format = format,
                             .subresourceRange = {img.aspect, 0, 1, 0, 1}};
    VK_CHECK(vkCreateImageView(ctx.device, &vi, nullptr, &img.view));
    return img;
}

VkDeviceSize imageBytes(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage) {
    const uint32_t limit = ctx.properties.limits.maxImageDimension2D;
    if (ctx.getDeviceImageMemoryRequirements && extent.width <= limit && extent.height <= limit) {
        const VkImageCreateInfo ci = imageInfo(extent, format, usage);
        const VkDeviceImageMemoryRequirements query{.sType = VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS,
                                                    .pCreateInfo = &ci};
        VkMemoryRequirements2 req{.sType = VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
        ctx.getDeviceImageMemoryRequirements(ctx.device, &query, &req);
        return ctx.allocator->sizeOf(req.memoryRequirements);
    }
    return VkDeviceSize(extent.width) * extent.height * texelBytes(format);
}

void destroy(Context& ctx, Image& i) {
    if (i.view) vkDestroyImageView(ctx.device, i.view, nullptr);
    if (i.image) vkDestroyImage(ctx.device, i.image, nullptr);
    ctx.allocator->free(i.memory);
    i = {};
}

Buffer uploadBuffer(Context& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage) {
    return uploadBuffer(ctx, size, usage, [&](void* staging) { std::memcpy(staging, data, size); });
}

Buffer uploadBuffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, const std::function<void(void*)>& fill) {
    Buffer dst = createBuffer(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    if (size == 0) return dst;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    try {
        fill(staging.mapped());
    } catch (...) {
        destroy(ctx, staging);
        destroy(ctx, dst);
        throw;
    }
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{.size = size};
        vkCmdCopyBuffer(cmd, staging.buffer, dst.buffer, 1, &region);
        // Later submissions read the buffer; make the copy visible to them.
        VkMemoryBarrier visible{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_MEMORY_READ_BIT};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1,
                             &visible, 0, nullptr, 0, nullptr);
    });
    destroy(ctx, staging);
    return dst;
}

void transition(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                VkAccessFlags dstAccess) {
    transition(cmd, image.image, image.aspect, from, to, srcStage, srcAccess, dstStage, dstAccess);
}

void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                           .srcAccessMask = srcAccess,
                           .dstAccessMask = dstAccess,
                           .oldLayout = from,
                           .newLayout = to,
                           .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                           .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                           .image = image,
                           .subresourceRange = {aspect, 0, 1, 0, 1}};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

VkCommandBuffer allocateCommandBuffer(Context& ctx) {
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                   .commandPool = ctx.commandPool,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                   .commandBufferCount = 1};
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &ai, &cmd));
    return cmd;
}

VkFence createFence(Context& ctx) {
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK_CHECK(vkCreateFence(ctx.device, &fci, nullptr, &fence));
    return fence;
}

}  // namespace grotto::vk
