#pragma once
// The handles of a Vulkan device a caller made: plain data, so the game-facing
// header (include/grotto/grotto.h) can name it without the Vulkan layer.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace grotto::vk {

// A device someone else made (a game's own), which Grotto renders with and never
// destroys. It must be Vulkan 1.2 or later, created with VK_KHR_push_descriptor,
// dynamic rendering (core in 1.3, else VK_KHR_dynamic_rendering, with the feature
// enabled) and Vulkan 1.2's timelineSemaphore feature enabled (frames in flight
// signal a timeline semaphore; a device that does not support it is refused), and
// `queue` must be of a family with graphics, compute and timestamps.
// Grotto submits to `queue` from the calling thread: the caller must not submit to
// it from another thread at the same time (Vulkan's external synchronisation).
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
};

}  // namespace grotto::vk
