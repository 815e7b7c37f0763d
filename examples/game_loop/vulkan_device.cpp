#include "vulkan_device.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace {

void check(VkResult r, const char* call) {
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(call) + " failed: " + std::to_string(r));
}

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    ++*static_cast<std::atomic<int>*>(user);
    return VK_FALSE;
}

bool hasExtension(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> all(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, all.data());
    for (const auto& e : all)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

}  // namespace

GameDevice::GameDevice() {
    const char* v = std::getenv("GROTTO_VALIDATION");
    const bool validate = v && std::string(v) == "1";
    VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO, .pApplicationName = "game_loop",
                          .apiVersion = VK_API_VERSION_1_3};
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* debugUtils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
        .pfnUserCallback = &onMessage,
        .pUserData = &messages_};
    // Synchronisation validation too: it checks the hand-over between the game's
    // work and Grotto's frames in flight (GROTTO_SYNC_VALIDATION=0: without it).
    const char* syncOff = std::getenv("GROTTO_SYNC_VALIDATION");
    const VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, .pNext = &messenger,
                                     .enabledValidationFeatureCount = syncOff && std::string(syncOff) == "0" ? 0u : 1u,
                                     .pEnabledValidationFeatures = &sync};
    VkInstanceCreateInfo ici{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                             .pNext = validate ? &features : nullptr,
                             .pApplicationInfo = &app,
                             .enabledLayerCount = validate ? 1u : 0u,
                             .ppEnabledLayerNames = &layer,
                             .enabledExtensionCount = validate ? 1u : 0u,
                             .ppEnabledExtensionNames = &debugUtils};
    check(vkCreateInstance(&ici, nullptr, &instance_), "vkCreateInstance");
    if (validate) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }

    // Lavapipe unless GROTTO_DEVICE names another; a Vulkan 1.3 device with push descriptors.
    const char* wanted = std::getenv("GROTTO_DEVICE");
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(instance_, &n, nullptr);
    std::vector<VkPhysicalDevice> all(n);
    vkEnumeratePhysicalDevices(instance_, &n, all.data());
    for (VkPhysicalDevice pd : all) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        const bool named = std::strstr(p.deviceName, wanted && *wanted ? wanted : "llvmpipe") != nullptr;
        if (p.apiVersion >= VK_API_VERSION_1_3 && hasExtension(pd, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME) &&
            (named || !physical))
            physical = pd;
        if (named && physical == pd) break;
    }
    if (!physical) throw std::runtime_error("no Vulkan 1.3 device with VK_KHR_push_descriptor");

    uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> families(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, families.data());
    queueFamily = UINT32_MAX;
    for (uint32_t i = 0; i < nq && queueFamily == UINT32_MAX; ++i)
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
            families[i].timestampValidBits > 0)
            queueFamily = i;
    if (queueFamily == UINT32_MAX) throw std::runtime_error("no graphics + compute queue with timestamps");

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, .queueFamilyIndex = queueFamily,
                                .queueCount = 1, .pQueuePriorities = &priority};
    // Grotto's frames in flight signal a timeline semaphore (Vulkan 1.2).
    VkPhysicalDeviceVulkan12Features features12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                                .timelineSemaphore = VK_TRUE};
    VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                                .pNext = &features12, .dynamicRendering = VK_TRUE};
    const char* extension = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
    VkDeviceCreateInfo dci{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, .pNext = &features13,
                           .queueCreateInfoCount = 1, .pQueueCreateInfos = &qci,
                           .enabledExtensionCount = 1, .ppEnabledExtensionNames = &extension};
    check(vkCreateDevice(physical, &dci, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
}

GameDevice::~GameDevice() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

grotto::VulkanDevice GameDevice::handles() const {
    return {.instance = instance_, .physical = physical, .device = device, .queue = queue, .queueFamily = queueFamily};
}

std::string GameDevice::name() const {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(physical, &p);
    return p.deviceName;
}
