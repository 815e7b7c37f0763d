#pragma once
// The game's own Vulkan instance, device and queue, made the way a game would
// (here headless): what it hands to Grotto. With GROTTO_VALIDATION=1 the Khronos
// validation layer is on and every warning or error it reports is counted.
#include <grotto/grotto.h>

#include <atomic>
#include <string>

class GameDevice {
public:
    GameDevice();
    ~GameDevice();
    GameDevice(const GameDevice&) = delete;
    GameDevice& operator=(const GameDevice&) = delete;

    grotto::VulkanDevice handles() const;
    int validationMessages() const { return messages_.load(); }
    std::string name() const;

    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<int> messages_{0};
};
