#include "engine/vk/memory.h"

#include "engine/vk/check.h"

#include <algorithm>
#include <optional>

namespace grotto::vk {
namespace {
constexpr VkDeviceSize kBlockSize = VkDeviceSize(64) << 20;
VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) { return (v + a - 1) / a * a; }
}  // namespace

Allocator::Allocator(VkPhysicalDevice physical, VkDevice device) : device_(device) {
    vkGetPhysicalDeviceMemoryProperties(physical, &props_);
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(physical, &p);
    // Buffers and optimal images may share a block only bufferImageGranularity apart.
    granularity_ = std::max<VkDeviceSize>(1, p.limits.bufferImageGranularity);
}

Allocator::~Allocator() {
    for (Block& b : blocks_)
        if (b.memory) vkFreeMemory(device_, b.memory, nullptr);
}

uint32_t Allocator::findType(uint32_t bits, bool hostVisible) const {
    const VkMemoryPropertyFlags need = hostVisible
        ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
    const VkMemoryPropertyFlags prefer = hostVisible ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                                                     : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    uint32_t fallback = UINT32_MAX;
    for (uint32_t i = 0; i < props_.memoryTypeCount; ++i) {
        const VkMemoryPropertyFlags f = props_.memoryTypes[i].propertyFlags;
        if (!(bits & (1u << i)) || (f & need) != need) continue;
        if ((f & prefer) == prefer) return i;
        if (fallback == UINT32_MAX) fallback = i;
    }
    if (fallback == UINT32_MAX) throw Error::internal("vulkan", "no suitable memory type");
    return fallback;
}

VkDeviceMemory Allocator::allocateMemory(uint32_t type, VkDeviceSize size, void** mapped) {
    VkMemoryAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                            .allocationSize = size,
                            .memoryTypeIndex = type};
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(device_, &ai, nullptr, &memory));
    *mapped = nullptr;
    if (props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VK_CHECK(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, mapped));
    return memory;
}

VkDeviceSize Allocator::sizeOf(const VkMemoryRequirements& req) const { return alignUp(req.size, granularity_); }

Allocation Allocator::allocate(const VkMemoryRequirements& req, bool hostVisible) {
    const uint32_t type = findType(req.memoryTypeBits, hostVisible);
    const VkDeviceSize align = std::max(req.alignment, granularity_);
    const VkDeviceSize size = sizeOf(req);
    if (size > kBlockSize / 2) {
        Allocation a{.size = size, .type = type};
        a.memory = allocateMemory(type, size, &a.mapped);
        return a;
    }
    auto take = [&](int bi) -> std::optional<Allocation> {
        Block& b = blocks_[bi];
        for (size_t i = 0; i < b.freeRanges.size(); ++i) {
            Range& r = b.freeRanges[i];
            const VkDeviceSize start = alignUp(r.offset, align);
            if (start + size > r.offset + r.size) continue;
            const Range before{r.offset, start - r.offset};
            const Range after{start + size, r.offset + r.size - (start + size)};
            b.freeRanges.erase(b.freeRanges.begin() + i);
            if (after.size) b.freeRanges.insert(b.freeRanges.begin() + i, after);
            if (before.size) b.freeRanges.insert(b.freeRanges.begin() + i, before);
            return Allocation{b.memory, start, size, b.mapped ? static_cast<char*>(b.mapped) + start : nullptr,
                              bi, type};
        }
        return std::nullopt;
    };
    for (int i = 0; i < int(blocks_.size()); ++i)
        if (blocks_[i].memory && blocks_[i].type == type)
            if (auto a = take(i)) return *a;
    Block b{.type = type, .size = kBlockSize};
    b.memory = allocateMemory(type, kBlockSize, &b.mapped);
    b.freeRanges.push_back({0, kBlockSize});
    blocks_.push_back(std::move(b));
    return *take(int(blocks_.size()) - 1);
}

void Allocator::free(const Allocation& a) {
    if (!a.memory) return;
    if (a.block < 0) {
        vkFreeMemory(device_, a.memory, nullptr);
        return;
    }
    auto& ranges = blocks_[a.block].freeRanges;
    auto it = std::lower_bound(ranges.begin(), ranges.end(), a.offset,
                               [](const Range& r, VkDeviceSize o) { return r.offset < o; });
    it = ranges.insert(it, Range{a.offset, a.size});
    // Merge with the neighbours so free space does not fragment.
    if (it + 1 != ranges.end() && it->offset + it->size == (it + 1)->offset) {
        it->size += (it + 1)->size;
        ranges.erase(it + 1);
    }
    if (it != ranges.begin() && (it - 1)->offset + (it - 1)->size == it->offset) {
        (it - 1)->size += it->size;
        ranges.erase(it);
    }
}

}  // namespace grotto::vk
