#pragma once
// Grotto on a game's own Vulkan device: the device handed over, and the images a
// frame hands back (grotto/grotto.h says when they are valid and how to read them).
#include <vulkan/vulkan.h>

#include <cstdint>

namespace grotto {

// A device the game made and keeps, which Grotto renders with and never destroys.
// It must be Vulkan 1.2 or later, created with VK_KHR_push_descriptor, dynamic
// rendering (core in 1.3, else VK_KHR_dynamic_rendering, with the feature enabled)
// and Vulkan 1.2's timelineSemaphore feature enabled (frames in flight signal a
// timeline semaphore; a device that does not support it is refused), and `queue`
// must be of a family with graphics, compute and timestamps. Grotto
// submits to `queue` from the thread that calls Engine::render: the game must not
// submit to it from another thread at the same time (Vulkan's external
// synchronisation of queues).
struct VulkanDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
};

// An image Grotto rendered and owns, valid until the next render(), resize(),
// setAo(), setLighting() or the engine's end. `layout` is the layout it is in
// when render() returns.
struct RenderedImage {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
};

// A semaphore of the game's that a frame in flight (Engine::submit) waits for
// before its first command: binary (value ignored) or timeline (until it reaches
// `value`), at `stages` of the frame's commands.
struct FrameWait {
    VkSemaphore semaphore = VK_NULL_HANDLE;
    uint64_t value = 0;
    VkPipelineStageFlags stages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
};

}  // namespace grotto
