// A game loop embedding Grotto on the game's own Vulkan device: build a world in
// memory, then for 120 frames dig a tunnel into a hill while a crate slides and
// turns in front of it and the camera follows the digging, render, and at the end copy Grotto's colour image with the game's
// own commands (as a game compositing it would) and write the last frame.
//   game_loop OUT.png
#include "vulkan_device.h"

#include <grotto/grotto.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <vector>

namespace {

constexpr int kFrames = 120;
constexpr glm::ivec3 kSize{96, 40, 96};

// Grass ground with a rock hill on it, as a game's generator would make it.
grotto::VoxelGrid buildWorld() {
    grotto::VoxelGrid grid{.size = kSize, .materials = std::vector<uint8_t>(size_t(kSize.x) * kSize.y * kSize.z, 0)};
    for (int z = 0; z < kSize.z; ++z)
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                const bool ground = y < 6, hill = x >= 28 && x < 72 && z >= 24 && z < 64 && y < 30 - std::abs(x - 50) / 3;
                // The default palette: 1 stone, 2 grass.
                grid.materials[(size_t(z) * kSize.y + y) * kSize.x + x] = ground ? 2 : hill ? 1 : 0;
            }
    return grid;
}

// A crate: an object the game adds and moves itself, turning about its base's centre.
grotto::Object crate() {
    return {.name = "crate", .voxels = {.size = {4, 4, 4}, .materials = std::vector<uint8_t>(64, 4)},  // 4: brick
            .pivot = {2.0, 0.0, 2.0}};
}

// Copies Grotto's colour image into a host buffer with the game's own command
// buffer, observing the synchronisation grotto.h states.
std::vector<float> copyColor(const GameDevice& game, const grotto::RenderedImage& color) {
    VkDevice d = game.device;
    const VkDeviceSize bytes = VkDeviceSize(color.extent.width) * color.extent.height * 16;
    VkBufferCreateInfo bci{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = bytes,
                           .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT};
    VkBuffer buffer;
    if (vkCreateBuffer(d, &bci, nullptr, &buffer) != VK_SUCCESS) throw std::runtime_error("vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(d, buffer, &req);
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(game.physical, &mp);
    uint32_t type = UINT32_MAX;
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (uint32_t i = 0; i < mp.memoryTypeCount && type == UINT32_MAX; ++i)
        if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) type = i;
    VkMemoryAllocateInfo mai{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size, .memoryTypeIndex = type};
    VkDeviceMemory memory;
    if (type == UINT32_MAX || vkAllocateMemory(d, &mai, nullptr, &memory) != VK_SUCCESS) throw std::runtime_error("vkAllocateMemory");
    vkBindBufferMemory(d, buffer, memory, 0);

    VkCommandPoolCreateInfo pci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, .queueFamilyIndex = game.queueFamily};
    VkCommandPool pool;
    vkCreateCommandPool(d, &pci, nullptr, &pool);
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = pool,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    VkCommandBuffer cmd;
    vkAllocateCommandBuffers(d, &ai, &cmd);
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(cmd, &bi);
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    // Grotto's compute writes before our transfer read; GENERAL -> TRANSFER_SRC and back again after.
    VkImageMemoryBarrier toCopy{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT, .oldLayout = color.layout,
                                .newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .image = color.image, .subresourceRange = all};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &toCopy);
    VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .imageExtent = {color.extent.width, color.extent.height, 1}};
    vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    VkImageMemoryBarrier back = toCopy;
    back.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    back.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    back.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    back.newLayout = color.layout;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &back);
    VkBufferMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                 .dstAccessMask = VK_ACCESS_HOST_READ_BIT, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                 .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .buffer = buffer, .size = VK_WHOLE_SIZE};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0, nullptr);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    vkQueueSubmit(game.queue, 1, &si, VK_NULL_HANDLE);
    vkQueueWaitIdle(game.queue);

    std::vector<float> pixels(bytes / 4);
    void* mapped;
    vkMapMemory(d, memory, 0, bytes, 0, &mapped);
    std::memcpy(pixels.data(), mapped, bytes);
    vkUnmapMemory(d, memory);
    vkDestroyCommandPool(d, pool, nullptr);
    vkDestroyBuffer(d, buffer, nullptr);
    vkFreeMemory(d, memory, nullptr);
    return pixels;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    try {
        GameDevice game;
        uint64_t carved = 0;
        {
            grotto::Engine engine(game.handles(), {.width = 320, .height = 180});
            engine.setWorld(buildWorld());
            engine.addObject(crate());
            grotto::RenderedFrame frame;
            for (int i = 0; i < kFrames; ++i) {
                // The digging head moves into the hill's side at z = 63, one sphere a frame.
                const double t = double(i) / (kFrames - 1);
                const glm::dvec3 head(50.0, 11.0, 66.0 - 24.0 * t);
                carved += engine.edit(grotto::Edit::carveSphere(head, 3.0)).changed;
                // The crate slides across the tunnel's mouth on the grass, turning as it goes.
                engine.setObjectPose(0, glm::dvec3(40.0 + 20.0 * t, 6.0, 70.0),
                                     glm::angleAxis(3.0 * t, glm::dvec3(0.0, 1.0, 0.0)));
                // The camera stands back outside the hill, looking into the tunnel.
                engine.setCamera({.position = glm::dvec3(58.0, 16.0, 92.0), .target = head, .fovDegrees = 50.0});
                frame = engine.render();
            }
            // The game composites Grotto's image itself: its copy must be the frame Grotto reads back.
            const std::vector<float> ours = copyColor(game, frame.color);
            const grotto::Pixels pixels = engine.readPixels();
            if (ours != pixels.rgba) throw std::runtime_error("the colour image copied by the game differs from Grotto's readback");
            engine.saveFrame(argv[1]);
            std::printf("wrote %s: frame %d on %s, %llu voxels dug, %llu quads drawn\n", argv[1], kFrames,
                        game.name().c_str(), (unsigned long long)carved, (unsigned long long)frame.quadsDrawn);
        }
        if (game.validationMessages() > 0) {
            std::fprintf(stderr, "game_loop: %d validation messages\n", game.validationMessages());
            return 1;
        }
        return carved > 0 ? 0 : 1;
    } catch (const grotto::Error& e) {
        std::fprintf(stderr, "game_loop: error: %s\n", e.what());
        return e.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "game_loop: %s\n", e.what());
        return 1;
    }
}
