#include "frame_reader.h"

#include <cstring>
#include <string>
#include <stdexcept>

namespace {

void check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed");
}

}  // namespace

FrameReader::FrameReader(const GameDevice& game, VkExtent2D extent) : game_(game), extent_(extent) {
    VkCommandPoolCreateInfo pci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                .queueFamilyIndex = game.queueFamily};
    check(vkCreateCommandPool(game.device, &pci, nullptr, &pool_), "vkCreateCommandPool");
    for (Slot& s : slots_) {
        makeBuffer(VkDeviceSize(extent.width) * extent.height * 8, s.buffer, s.memory);
        VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = pool_,
                                       .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
        check(vkAllocateCommandBuffers(game.device, &ai, &s.cmd), "vkAllocateCommandBuffers");
        VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(vkCreateFence(game.device, &fci, nullptr, &s.fence), "vkCreateFence");
    }
}

FrameReader::~FrameReader() {
    vkDeviceWaitIdle(game_.device);
    for (Slot& s : slots_) {
        vkDestroyFence(game_.device, s.fence, nullptr);
        vkDestroyBuffer(game_.device, s.buffer, nullptr);
        vkFreeMemory(game_.device, s.memory, nullptr);
    }
    vkDestroyCommandPool(game_.device, pool_, nullptr);
}

void FrameReader::makeBuffer(VkDeviceSize bytes, VkBuffer& buffer, VkDeviceMemory& memory) const {
    VkBufferCreateInfo bci{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = bytes,
                           .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT};
    check(vkCreateBuffer(game_.device, &bci, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(game_.device, buffer, &req);
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(game_.physical, &mp);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = UINT32_MAX;
    for (uint32_t i = 0; i < mp.memoryTypeCount && type == UINT32_MAX; ++i)
        if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) type = i;
    if (type == UINT32_MAX) throw std::runtime_error("no host-visible memory");
    VkMemoryAllocateInfo mai{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size,
                             .memoryTypeIndex = type};
    check(vkAllocateMemory(game_.device, &mai, nullptr, &memory), "vkAllocateMemory");
    vkBindBufferMemory(game_.device, buffer, memory, 0);
}

void FrameReader::recordCopy(VkCommandBuffer cmd, const grotto::RenderedImage& image, VkBuffer buffer) const {
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    // Grotto's compute writes before our transfer read; GENERAL -> TRANSFER_SRC and back again after.
    VkImageMemoryBarrier toCopy{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT, .oldLayout = image.layout,
                                .newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .image = image.image, .subresourceRange = all};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toCopy);
    VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .imageExtent = {image.extent.width, image.extent.height, 1}};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    VkImageMemoryBarrier back = toCopy;
    back.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    back.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    back.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    back.newLayout = image.layout;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &back);
    VkBufferMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                 .dstAccessMask = VK_ACCESS_HOST_READ_BIT, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                 .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .buffer = buffer, .size = VK_WHOLE_SIZE};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0,
                         nullptr);
}

void FrameReader::read(const grotto::RenderedFrame& frame, int slot) {
    Slot& s = slots_[slot];
    if (s.pending) pixels(slot);  // the slot's last copy has landed: its buffer and command buffer are free
    vkResetCommandBuffer(s.cmd, 0);
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(s.cmd, &bi);
    recordCopy(s.cmd, frame.display, s.buffer);
    vkEndCommandBuffer(s.cmd);
    // On the GPU, after Grotto's frame: its timeline value.
    VkTimelineSemaphoreSubmitInfo values{.sType = VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO,
                                         .waitSemaphoreValueCount = 1, .pWaitSemaphoreValues = &frame.timelineValue};
    const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .pNext = &values, .waitSemaphoreCount = 1,
                    .pWaitSemaphores = &frame.timeline, .pWaitDstStageMask = &stage, .commandBufferCount = 1,
                    .pCommandBuffers = &s.cmd};
    check(vkQueueSubmit(game_.queue, 1, &si, s.fence), "vkQueueSubmit");
    s.pending = true;
}

std::vector<uint16_t> FrameReader::pixels(int slot) {
    Slot& s = slots_[slot];
    if (!s.pending) return {};
    check(vkWaitForFences(game_.device, 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vkResetFences(game_.device, 1, &s.fence);
    s.pending = false;
    std::vector<uint16_t> out(size_t(extent_.width) * extent_.height * 4);
    void* mapped;
    check(vkMapMemory(game_.device, s.memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    std::memcpy(out.data(), mapped, out.size() * 2);
    vkUnmapMemory(game_.device, s.memory);
    return out;
}

std::vector<float> FrameReader::copyNow(const grotto::RenderedImage& color) {
    VkBuffer buffer;
    VkDeviceMemory memory;
    const VkDeviceSize bytes = VkDeviceSize(color.extent.width) * color.extent.height * 16;
    makeBuffer(bytes, buffer, memory);
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = pool_,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(game_.device, &ai, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(cmd, &bi);
    recordCopy(cmd, color, buffer);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    check(vkQueueSubmit(game_.queue, 1, &si, VK_NULL_HANDLE), "vkQueueSubmit");
    vkQueueWaitIdle(game_.queue);
    std::vector<float> out(bytes / 4);
    void* mapped;
    check(vkMapMemory(game_.device, memory, 0, bytes, 0, &mapped), "vkMapMemory");
    std::memcpy(out.data(), mapped, bytes);
    vkUnmapMemory(game_.device, memory);
    vkFreeCommandBuffers(game_.device, pool_, 1, &cmd);
    vkDestroyBuffer(game_.device, buffer, nullptr);
    vkFreeMemory(game_.device, memory, nullptr);
    return out;
}
