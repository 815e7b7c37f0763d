#pragma once
// G-buffer pass. Reads: the scene's quads and palette, frame uniforms.
// Writes: depth (D32, reverse-Z), normal, albedo. Keeps no history.
// Chunks outside the frustum are skipped; inside one, faces turned away from the
// camera are skipped as whole per-face ranges; chunks are drawn front to back.
#include "engine/camera.h"
#include "engine/scene.h"

namespace grotto {

struct GBufferTargets {
    vk::Image depth, normal, albedo;
};

class GBufferPass {
public:
    GBufferPass(vk::Context& ctx, VkFormat normalFormat, VkFormat albedoFormat);
    ~GBufferPass();

    // Returns the number of quads drawn.
    uint64_t record(VkCommandBuffer cmd, const GBufferTargets& targets, const GpuScene& scene,
                    const vk::Buffer& frame, const Camera& camera);

private:
    vk::Context& ctx_;
    VkDescriptorSetLayout setLayout_;
    VkPipelineLayout layout_;
    VkPipeline pipeline_;
};

}  // namespace grotto
