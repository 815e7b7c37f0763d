#pragma once
// Orders the passes of a frame and places every barrier between them.
#include "engine/camera.h"
#include "engine/passes/composite_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene.h"
#include "engine/vk/timestamps.h"
#include "voxel/world_desc.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace grotto {

struct FrameStats {
    std::vector<std::pair<std::string, double>> passMs;  // GPU time per pass
    double wallMs = 0.0;                                 // record + submit + wait
    uint64_t quadsDrawn = 0;
};

// A frame read back to host memory; pixel (x, y) at index y * width + x, row 0 on top.
struct FrameImages {
    uint32_t width = 0, height = 0;
    std::vector<float> color;   // linear RGBA
    std::vector<float> depth;   // view-axis distance in world units; +inf for sky
    std::vector<float> normal;  // world-space xyz; 0 for sky
    std::vector<float> albedo;  // linear rgb; 0 for sky
};

class Renderer {
public:
    Renderer(vk::Context& ctx, const GpuScene& scene, const voxel::Lighting& lighting, uint32_t width,
             uint32_t height);
    ~Renderer();

    FrameStats render(const Camera& camera);
    // Reads back the last frame; the G-buffer AOVs only when asked for.
    FrameImages readback(const Camera& camera, bool aovs);

    size_t targetBytes() const;

private:
    vk::Context& ctx_;
    const GpuScene& scene_;
    voxel::Lighting lighting_;
    GBufferTargets gbuffer_;
    vk::Image color_;
    vk::Buffer frame_;
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<CompositePass> compositePass_;
    vk::Timestamps timestamps_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace grotto
