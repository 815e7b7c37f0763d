#include "engine/vk/context.h"

#include "engine/vk/cpu_device_heap.h"
#include "engine/vk/pin_libraries.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace grotto::vk {
namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

bool envOff(const char* name) {
    const char* v = std::getenv(name);
    return v && std::strcmp(v, "0") == 0;
}

bool hasLayer(const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    for (auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> ext(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, ext.data());
    for (auto& e : ext)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

// A frame in flight signals a timeline semaphore (Vulkan 1.2's feature).
void requireTimelineSemaphores(VkPhysicalDevice pd, const char* where, const char* hint) {
    VkPhysicalDeviceVulkan12Features f12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 f{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f12};
    vkGetPhysicalDeviceFeatures2(pd, &f);
    if (!f12.timelineSemaphore) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        throw Error(where, std::string(p.deviceName) + " lacks Vulkan 1.2's timelineSemaphore feature", hint);
    }
}

const char* kNoDevice = "install the Debian package mesa-vulkan-drivers for lavapipe (CPU Vulkan)";

VkPhysicalDevice pickDevice(VkInstance instance, const std::string& wanted) {
    uint32_t n = 0;
    VkResult r = vkEnumeratePhysicalDevices(instance, &n, nullptr);
    if (r != VK_SUCCESS || n == 0) throw Error("vulkan", "no Vulkan device found", kNoDevice);
    std::vector<VkPhysicalDevice> devices(n);
    vkEnumeratePhysicalDevices(instance, &n, devices.data());
    std::string names;
    VkPhysicalDevice lavapipe = VK_NULL_HANDLE;
    for (VkPhysicalDevice pd : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        names += (names.empty() ? "" : ", ") + std::string(p.deviceName);
        if (!wanted.empty() && std::strstr(p.deviceName, wanted.c_str())) return pd;
        if (std::strstr(p.deviceName, "llvmpipe")) lavapipe = pd;
    }
    if (!wanted.empty())
        throw Error("GROTTO_DEVICE", "no Vulkan device matches '" + wanted + "'", "devices: " + names);
    return lavapipe ? lavapipe : devices[0];
}

}  // namespace

VkBool32 Context::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                            VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                            void* self) {
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        static_cast<Context*>(self)->validationMessages_++;
        std::fprintf(stderr, "grotto: vulkan validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

Context::Context(ContextOptions options) {
    try {
        create(options);
    } catch (...) {
        release();  // a half-made context (no device found, say) must not leak
        throw;
    }
}

Context::Context(const ExternalDevice& external) {
    try {
        adopt(external);
    } catch (...) {
        release();
        throw;
    }
}

void Context::create(const ContextOptions& options) {
    const bool validate = options.validation || envFlag("GROTTO_VALIDATION");
    std::string wanted = options.deviceName;
    if (wanted.empty())
        if (const char* env = std::getenv("GROTTO_DEVICE")) wanted = env;

    VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                          .pApplicationName = "grotto",
                          .applicationVersion = VK_MAKE_VERSION(0, 1, 0),
                          .pEngineName = "grotto",
                          .apiVersion = VK_API_VERSION_1_3};
    std::vector<const char*> layers, extensions = options.instanceExtensions;
    if (validate) {
        if (!hasLayer(kValidationLayer))
            throw Error("vulkan", "validation requested but VK_LAYER_KHRONOS_validation is missing",
                        "install the Debian package vulkan-validationlayers");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = &Context::onMessage,
        .pUserData = this};
    // Synchronisation validation checks the hazards between frames in flight, the
    // host and the game's own work.
    const VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    const bool syncValidation = options.syncValidation && !envOff("GROTTO_SYNC_VALIDATION");
    VkValidationFeaturesEXT validationFeatures{.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
                                               .pNext = &messengerInfo,
                                               .enabledValidationFeatureCount = 1,
                                               .pEnabledValidationFeatures = &syncFeature};
    VkInstanceCreateInfo ici{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                             .pNext = !validate         ? nullptr
                                      : syncValidation ? static_cast<const void*>(&validationFeatures)
                                                       : static_cast<const void*>(&messengerInfo),
                             .pApplicationInfo = &app,
                             .enabledLayerCount = uint32_t(layers.size()),
                             .ppEnabledLayerNames = layers.data(),
                             .enabledExtensionCount = uint32_t(extensions.size()),
                             .ppEnabledExtensionNames = extensions.data()};
    VkResult r = vkCreateInstance(&ici, nullptr, &instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED)
        throw Error("vulkan", std::string("no Vulkan driver could be loaded (") + resultName(r) + ")", kNoDevice);
    VK_CHECK(r);
    pinLoadedLibraries();  // sanitizer builds: the driver and layers stay loaded for the leak check
    if (validate) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(instance, &messengerInfo, nullptr, &messenger_));
    }

    if (options.createSurface) surface = options.createSurface(instance);
    physical = pickDevice(instance, wanted);
    vkGetPhysicalDeviceProperties(physical, &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) keepHeapForCpuDevice();

    uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> families(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, families.data());
    queueFamily = UINT32_MAX;
    auto presents = [&](uint32_t family) {
        VkBool32 supported = VK_FALSE;
        return !surface || (vkGetPhysicalDeviceSurfaceSupportKHR(physical, family, surface, &supported) == VK_SUCCESS &&
                            supported);
    };
    for (uint32_t i = 0; i < nq; ++i)
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
            families[i].timestampValidBits > 0 && presents(i)) {
            queueFamily = i;
            break;
        }
    if (queueFamily == UINT32_MAX)
        throw Error("vulkan", std::string(properties.deviceName) + " has no graphics+compute queue with timestamps" +
                                  (surface ? " that presents to the window" : ""));

    // The instance asks for 1.3; a 1.2 device gets dynamic rendering as an extension.
    const bool core13 = properties.apiVersion >= VK_API_VERSION_1_3;
    if (properties.apiVersion < VK_API_VERSION_1_2)
        throw Error("vulkan", std::string(properties.deviceName) + " supports only Vulkan " +
                    std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                    std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)),
                    "Grotto needs Vulkan 1.2; set GROTTO_DEVICE to another device");
    std::vector<const char*> deviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (surface) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    if (!core13) deviceExtensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
    for (const char* e : deviceExtensions)
        if (!hasDeviceExtension(physical, e))
            throw Error("vulkan", std::string(properties.deviceName) + " lacks " + e,
                        "Grotto needs Vulkan 1.2 with push descriptors and dynamic rendering");

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                .queueFamilyIndex = queueFamily,
                                .queueCount = 1,
                                .pQueuePriorities = &priority};
    VkPhysicalDeviceDynamicRenderingFeatures dynamicRendering{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES, .dynamicRendering = VK_TRUE};
    requireTimelineSemaphores(physical, "vulkan", "set GROTTO_DEVICE to another device");
    VkPhysicalDeviceVulkan12Features features12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                                .pNext = &dynamicRendering,
                                                .timelineSemaphore = VK_TRUE};
    VkDeviceCreateInfo dci{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                           .pNext = &features12,
                           .queueCreateInfoCount = 1,
                           .pQueueCreateInfos = &qci,
                           .enabledExtensionCount = uint32_t(deviceExtensions.size()),
                           .ppEnabledExtensionNames = deviceExtensions.data()};
    VK_CHECK(vkCreateDevice(physical, &dci, nullptr, &device));
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
    finishSetup();
}

void Context::adopt(const ExternalDevice& external) {
    ownsDevice_ = false;
    pinLoadedLibraries();  // sanitizer builds: the caller's driver and layers stay loaded for the leak check
    if (!external.instance || !external.physical || !external.device || !external.queue)
        throw Error("external Vulkan device", "a handle is null", "give the instance, physical device, device and queue");
    instance = external.instance;
    physical = external.physical;
    device = external.device;
    queue = external.queue;
    queueFamily = external.queueFamily;
    vkGetPhysicalDeviceProperties(physical, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_2)
        throw Error("external Vulkan device", std::string(properties.deviceName) + " is below Vulkan 1.2",
                    "Grotto needs Vulkan 1.2 with push descriptors, dynamic rendering and timeline semaphores");
    // Enabled features cannot be queried from a VkDevice: the device must support it,
    // and ExternalDevice asks the caller to enable it.
    requireTimelineSemaphores(physical, "external Vulkan device",
                              "Grotto needs Vulkan 1.2's timelineSemaphore feature, enabled when creating the device");
    uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> families(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, families.data());
    if (queueFamily >= nq || !(families[queueFamily].queueFlags & VK_QUEUE_GRAPHICS_BIT) ||
        !(families[queueFamily].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[queueFamily].timestampValidBits == 0)
        throw Error("external Vulkan device", "queue family " + std::to_string(queueFamily) +
                                                   " lacks graphics, compute or timestamps",
                    "hand Grotto a queue of a family with all three");
    finishSetup();
    // Enabled extensions cannot be queried from a VkDevice: the entry points tell.
    if (!cmdPushDescriptorSet || !cmdBeginRendering || !cmdEndRendering)
        throw Error("external Vulkan device", std::string("was not created with ") +
                                                  (!cmdPushDescriptorSet ? "VK_KHR_push_descriptor" : "dynamic rendering"),
                    "enable VK_KHR_push_descriptor and dynamic rendering when creating the device");
}

void Context::finishSetup() {
    const bool core13 = properties.apiVersion >= VK_API_VERSION_1_3;
    auto proc = [&](const char* core, const char* khr) {
        PFN_vkVoidFunction f = core13 ? vkGetDeviceProcAddr(device, core) : nullptr;
        return f ? f : vkGetDeviceProcAddr(device, khr);
    };
    cmdBeginRendering = reinterpret_cast<PFN_vkCmdBeginRendering>(proc("vkCmdBeginRendering", "vkCmdBeginRenderingKHR"));
    cmdEndRendering = reinterpret_cast<PFN_vkCmdEndRendering>(proc("vkCmdEndRendering", "vkCmdEndRenderingKHR"));
    cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device, "vkCmdPushDescriptorSetKHR"));
    if (core13)
        getDeviceImageMemoryRequirements = reinterpret_cast<PFN_vkGetDeviceImageMemoryRequirements>(
            vkGetDeviceProcAddr(device, "vkGetDeviceImageMemoryRequirements"));

    VkCommandPoolCreateInfo pci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                .queueFamilyIndex = queueFamily};
    VK_CHECK(vkCreateCommandPool(device, &pci, nullptr, &commandPool));
    VkSamplerCreateInfo si{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                           .magFilter = VK_FILTER_NEAREST,
                           .minFilter = VK_FILTER_NEAREST,
                           .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                           .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                           .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                           .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE};
    VK_CHECK(vkCreateSampler(device, &si, nullptr, &pointSampler));
    allocator = std::make_unique<Allocator>(physical, device);
}

Context::~Context() { release(); }

void Context::release() {
    // A borrowed device keeps running the caller's work: wait for Grotto's queue only.
    if (device && ownsDevice_) vkDeviceWaitIdle(device);
    else if (device && queue) vkQueueWaitIdle(queue);
    allocator.reset();
    if (pointSampler) vkDestroySampler(device, pointSampler, nullptr);
    pointSampler = VK_NULL_HANDLE;
    if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
    if (!ownsDevice_) {  // the caller's: theirs to destroy
        device = VK_NULL_HANDLE;
        instance = VK_NULL_HANDLE;
        commandPool = VK_NULL_HANDLE;
        return;
    }
    if (device) vkDestroyDevice(device, nullptr);
    if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
    surface = VK_NULL_HANDLE;
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
    commandPool = VK_NULL_HANDLE;
    device = VK_NULL_HANDLE;
    messenger_ = VK_NULL_HANDLE;
    instance = VK_NULL_HANDLE;
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                   .commandPool = commandPool,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                   .commandBufferCount = 1};
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(device, &ai, &cmd));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK_CHECK(vkCreateFence(device, &fci, nullptr, &fence));
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    VK_CHECK(vkQueueSubmit(queue, 1, &si, fence));
    VK_CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
    vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, commandPool, 1, &cmd);
}

}  // namespace grotto::vk
