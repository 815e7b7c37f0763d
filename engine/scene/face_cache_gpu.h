#pragma once
// A baked face cache on the GPU: the three arrays of shaders/shared/face_cache.h
// in storage buffers (voxel/face_cache_layout.h lays them out), and what a pass
// that reads it binds after its own inputs (shaders/face_cache.glsl).
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"
#include "voxel/face_cache_layout.h"

#include <vector>

namespace grotto {

// The sun a cache's sun visibility was traced for.
struct FaceCacheSun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};
    float angleDegrees = 0.0f;
};

class GpuFaceCache {
public:
    using Sun = FaceCacheSun;
    GpuFaceCache(vk::Context& ctx, const voxel::FaceCacheArrays& arrays, Sun sun = {});
    ~GpuFaceCache();
    GpuFaceCache(const GpuFaceCache&) = delete;
    GpuFaceCache& operator=(const GpuFaceCache&) = delete;

    uint32_t hashMask() const { return hashMask_; }
    uint32_t texelsPerSide() const { return texelsPerSide_; }
    const Sun& sun() const { return sun_; }
    size_t gpuBytes() const { return size_t(bricks_.size + records_.size + texels_.size); }

    // Appends the three buffers' bindings (bricks, records, texels) to a pass's own.
    static std::vector<VkDescriptorType> withBindings(std::vector<VkDescriptorType> own);
    std::vector<vk::Binding> withBindings(std::vector<vk::Binding> own) const;

private:
    vk::Context& ctx_;
    vk::Buffer bricks_, records_, texels_;
    uint32_t hashMask_, texelsPerSide_;
    Sun sun_;
};

}  // namespace grotto
