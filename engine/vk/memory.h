#pragma once
// A small device-memory allocator of our own: 64 MiB blocks per memory type,
// first-fit free lists with alignment, and dedicated allocations for big resources.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace grotto::vk {

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    void* mapped = nullptr;   // host-visible allocations stay mapped
    int block = -1;           // -1 = dedicated
    uint32_t type = 0;
};

class Allocator {
public:
    Allocator(VkPhysicalDevice physical, VkDevice device);
    ~Allocator();

    // Host-visible memory is also host-coherent; device-local is preferred otherwise.
    Allocation allocate(const VkMemoryRequirements& req, bool hostVisible);
    // The bytes allocate(req) takes (its Allocation::size).
    VkDeviceSize sizeOf(const VkMemoryRequirements& req) const;
    void free(const Allocation& a);

private:
    struct Range { VkDeviceSize offset, size; };
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        uint32_t type = 0;
        VkDeviceSize size = 0;
        void* mapped = nullptr;
        std::vector<Range> freeRanges;  // sorted by offset, never adjacent
    };
    uint32_t findType(uint32_t bits, bool hostVisible) const;
    VkDeviceMemory allocateMemory(uint32_t type, VkDeviceSize size, void** mapped);

    VkDevice device_;
    VkPhysicalDeviceMemoryProperties props_{};
    VkDeviceSize granularity_ = 1;
    std::vector<Block> blocks_;
};

}  // namespace grotto::vk
