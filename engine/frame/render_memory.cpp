#include "engine/frame/render_memory.h"

#include "grotto/error.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace grotto {

RenderMemory estimateRenderMemory(const vk::Context& ctx, const FramePlan& plan) {
    RenderMemory r;
    for (const TargetRow& row : targetRows()) {
        const VkExtent2D extent = targetExtent(row, plan);
        if (extent.width == 0) continue;
        const uint64_t bytes = vk::imageBytes(ctx, extent, row.format, row.usage);
        r.targetBytes += row.copies * bytes;
        r.largestBytes = std::max(r.largestBytes, bytes);
    }
    r.stagingBytes = 16 * uint64_t(plan.width) * plan.height;  // the colour, RGBA32F
    r.largestBytes = std::max(r.largestBytes, r.stagingBytes);
    r.hostBytes = readbackHostBytes(plan);
    return r;
}

bool cpuDevice(const vk::Context& ctx) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(ctx.physical, &p);
    return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

uint64_t rendererHostBytes(const vk::Context& ctx, const FramePlan& plan) {
    const RenderMemory r = estimateRenderMemory(ctx, plan);
    return r.hostBytes + r.stagingBytes + (cpuDevice(ctx) ? r.targetBytes : 0);
}

uint64_t readbackHostBytes(const FramePlan& plan) {
    // FrameImages with AOVs: colour 16, depth, raw depth and ids 10, normal and
    // albedo 24, six AO AOVs 24, the shadow 4 bytes a pixel (and the motion 16 where
    // objects move), the packed half-res AO 8 per AO pixel.
    const uint64_t n = uint64_t(plan.width) * plan.height;
    const VkExtent2D ao = plan.aoExtent();
    return (78 + (plan.motion ? 16 : 0)) * n + 8 * uint64_t(ao.width) * ao.height;
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
    d.cpu = cpuDevice(ctx);
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

void requireRenderFits(const vk::Context& ctx, const FramePlan& plan, const std::string& where) {
    const DeviceMemory d = deviceMemory(ctx);
    FramePlan at = plan;
    at.aoAov = true;
    const std::string why = whyNot(d, estimateRenderMemory(ctx, at));
    if (why.empty()) return;
    // The largest size of the same plan that fits, for the hint.
    const uint32_t width = plan.width, height = plan.height;
    uint32_t lo = 1, hi = width;
    while (lo < hi) {
        at.width = (lo + hi + 1) / 2;
        at.height = std::max<uint32_t>(1, uint32_t(uint64_t(height) * at.width / width));
        if (whyNot(d, estimateRenderMemory(ctx, at)).empty()) lo = at.width;
        else hi = at.width - 1;
    }
    const uint32_t fitHeight = std::max<uint32_t>(1, uint32_t(uint64_t(height) * lo / width));
    throw Error(where, std::to_string(width) + "x" + std::to_string(height) + " is too large for " + ctx.deviceName() +
                           ": " + why,
                "accepted here: up to about " + std::to_string(lo) + "x" + std::to_string(fitHeight) + " at this shape");
}

}  // namespace grotto
