#include "engine/scene/face_cache_gpu.h"

namespace grotto {

namespace {
constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
}

GpuFaceCache::GpuFaceCache(vk::Context& ctx, const voxel::FaceCacheArrays& a, Sun sun)
    : ctx_(ctx), hashMask_(a.hashMask()), texelsPerSide_(a.texelsPerSide), sun_(sun) {
    // Empty arrays (a world with no faces) still bind: one zero word each.
    const uint32_t zero[4] = {};
    auto upload = [&](const void* data, size_t bytes) {
        return bytes ? vk::uploadBuffer(ctx, data, bytes, kUsage) : vk::uploadBuffer(ctx, zero, sizeof zero, kUsage);
    };
    try {
        bricks_ = upload(a.bricks.data(), a.bricks.size() * sizeof(glm::uvec4));
        records_ = upload(a.records.data(), a.records.size() * sizeof(uint32_t));
        texels_ = upload(a.texels.data(), a.texels.size() * sizeof(uint32_t));
    } catch (...) {
        vk::destroy(ctx_, bricks_), vk::destroy(ctx_, records_), vk::destroy(ctx_, texels_);
        throw;
    }
}

GpuFaceCache::~GpuFaceCache() {
    vk::destroy(ctx_, bricks_);
    vk::destroy(ctx_, records_);
    vk::destroy(ctx_, texels_);
}

std::vector<VkDescriptorType> GpuFaceCache::withBindings(std::vector<VkDescriptorType> own) {
    own.insert(own.end(), 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    return own;
}

std::vector<vk::Binding> GpuFaceCache::withBindings(std::vector<vk::Binding> own) const {
    own.push_back(vk::storageBuffer(bricks_.buffer));
    own.push_back(vk::storageBuffer(records_.buffer));
    own.push_back(vk::storageBuffer(texels_.buffer));
    return own;
}

}  // namespace grotto
