#include "engine/frame/render_memory.h"

#include "common/error.h"
#include "engine/passes/ao_targets.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace grotto {

RenderMemory estimateRenderMemory(uint32_t width, uint32_t height, const AoOptions& ao) {
    // Bytes per pixel of each target, as Renderer::createTargets and readback make them.
    const uint64_t n = uint64_t(width) * height;
    const VkExtent2D half = ao.chain.fullResolution ? VkExtent2D{width, height} : VkExtent2D{(width + 1) / 2, (height + 1) / 2};
    const uint64_t m = uint64_t(half.width) * half.height;
    RenderMemory r;
    const uint64_t colour = 16 * n;                    // RGBA32F
    r.targetBytes = 4 * n + 2 * n + colour;            // depth D32, surface ids R16, colour
    uint64_t chainImages = 0;                          // RGBA32F at AO resolution: raw, denoise, history
    if (ao.enabled) {
        const VkExtent2D atlas = depthMipLayout(half).atlas;
        chainImages = 1 + std::min(ao.chain.denoisePasses, 2u) + (ao.chain.temporalHistory > 0 ? 2 : 0);
        r.targetBytes += 4 * uint64_t(atlas.width) * atlas.height + 16 * m * chainImages + 4 * n;  // + the AO AOV
    }
    r.stagingBytes = colour;
    r.largestBytes = std::max(colour, 16 * m);
    // FrameImages with AOVs: colour 16, depth, raw depth and ids 10, normal and
    // albedo 24, six AO AOVs 24 bytes a pixel, the packed half-res AO 8 per AO pixel.
    r.hostBytes = 74 * n + 8 * m;
    return r;
}

namespace {

std::string gib(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    return text;
}

struct DeviceMemory {
    uint64_t largestAllocation = 0, deviceHeap = 0, physical = 0;
    bool cpu = false;  // targets in host memory (lavapipe)
};

DeviceMemory deviceMemory(const vk::Context& ctx) {
    DeviceMemory d;
    VkPhysicalDeviceMaintenance3Properties m3{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 p{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &m3};
    vkGetPhysicalDeviceProperties2(ctx.physical, &p);
    d.largestAllocation = m3.maxMemoryAllocationSize;
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(ctx.physical, &mp);
    for (uint32_t i = 0; i < mp.memoryHeapCount; ++i)
        if (mp.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            d.deviceHeap = std::max<uint64_t>(d.deviceHeap, mp.memoryHeaps[i].size);
    d.physical = uint64_t(sysconf(_SC_PHYS_PAGES)) * uint64_t(sysconf(_SC_PAGESIZE));
    d.cpu = p.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    return d;
}

// Empty when it fits, else why not.
std::string whyNot(const DeviceMemory& d, const RenderMemory& r) {
    const uint64_t device = r.targetBytes + r.stagingBytes;
    if (r.largestBytes > d.largestAllocation)
        return "its colour target alone needs " + gib(r.largestBytes) + ", over the device's largest allocation (" +
               gib(d.largestAllocation) + ")";
    if (d.cpu && device + r.hostBytes > d.physical)
        return "it needs about " + gib(device + r.hostBytes) + " (targets " + gib(device) + ", read-back " +
               gib(r.hostBytes) + "), over this machine's " + gib(d.physical) + " of memory";
    if (!d.cpu && device > d.deviceHeap)
        return "its targets need about " + gib(device) + ", over the device's " + gib(d.deviceHeap) + " of memory";
    if (!d.cpu && r.hostBytes > d.physical)
        return "its read-back needs about " + gib(r.hostBytes) + ", over this machine's " + gib(d.physical) + " of memory";
    return {};
}

}  // namespace

void requireRenderFits(const vk::Context& ctx, uint32_t width, uint32_t height, const AoOptions& ao,
                       const std::string& where) {
    const DeviceMemory d = deviceMemory(ctx);
    const std::string why = whyNot(d, estimateRenderMemory(width, height, ao));
    if (why.empty()) return;
    // The largest size of the same shape that fits, for the hint.
    uint32_t lo = 1, hi = width;
    while (lo < hi) {
        const uint32_t w = (lo + hi + 1) / 2, h = std::max<uint32_t>(1, uint32_t(uint64_t(height) * w / width));
        if (whyNot(d, estimateRenderMemory(w, h, ao)).empty()) lo = w;
        else hi = w - 1;
    }
    const uint32_t fitHeight = std::max<uint32_t>(1, uint32_t(uint64_t(height) * lo / width));
    throw Error(where, std::to_string(width) + "x" + std::to_string(height) + " is too large for " + ctx.deviceName() +
                           ": " + why,
                "accepted here: up to about " + std::to_string(lo) + "x" + std::to_string(fitHeight) + " at this shape");
}

}  // namespace grotto
