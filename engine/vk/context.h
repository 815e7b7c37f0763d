#pragma once
// The Vulkan instance, one device and its queue: headless, lavapipe by default.
// GROTTO_DEVICE=<substring> picks another device by name; GROTTO_VALIDATION=1
// (always set by the tests) turns the Khronos validation layer on, with its
// synchronisation validation, and every message it reports is printed and counted.
// The device has Vulkan 1.2's timeline semaphores (a frame in flight signals one).
#include "engine/vk/check.h"
#include "engine/vk/external_device.h"
#include "engine/vk/memory.h"

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grotto::vk {

struct ContextOptions {
    bool validation = false;   // also on when GROTTO_VALIDATION=1
    // With validation: the layer's synchronisation validation too (hazards between
    // commands, submissions and the host). GROTTO_SYNC_VALIDATION=0 turns it off.
    bool syncValidation = true;
    std::string deviceName;    // substring; empty = GROTTO_DEVICE, else lavapipe, else the first
    // Presenting to a window (the viewer): the instance extensions its window system
    // needs, and a function that makes the window's surface once the instance
    // exists. The queue is then one that can also present to that surface, and the
    // device has VK_KHR_swapchain.
    std::vector<const char*> instanceExtensions;
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

class Context {
public:
    explicit Context(ContextOptions options = {});
    // Throws grotto::Error (input) naming what the device lacks.
    explicit Context(const ExternalDevice& external);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkSampler pointSampler = VK_NULL_HANDLE;  // nearest, clamp to edge: for texelFetch reads
    VkSurfaceKHR surface = VK_NULL_HANDLE;    // with ContextOptions::createSurface; destroyed with the context
    VkPhysicalDeviceProperties properties{};
    std::unique_ptr<Allocator> allocator;

    PFN_vkCmdBeginRendering cmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering cmdEndRendering = nullptr;
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;
    // An image's memory requirements without making it: Vulkan 1.3 devices only (else null).
    PFN_vkGetDeviceImageMemoryRequirements getDeviceImageMemoryRequirements = nullptr;

    std::string deviceName() const { return properties.deviceName; }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    // Validation messages (warnings and errors) reported since creation.
    int validationMessages() const { return validationMessages_.load(); }

    // Records with record(cmd), submits and waits.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

private:
    void create(const ContextOptions& options);
    void adopt(const ExternalDevice& external);
    void finishSetup();  // after device and queue exist: entry points, command pool, sampler, allocator
    void release();
    bool ownsDevice_ = true;
    static VkBool32 VKAPI_PTR onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                        VkDebugUtilsMessageTypeFlagsEXT,
                                        const VkDebugUtilsMessengerCallbackDataEXT*, void*);
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<int> validationMessages_{0};
};

}  // namespace grotto::vk
