#pragma once
// G-buffer pass. Reads: the scene's vertices, frame uniforms.
// Writes: depth (D32, reverse-Z) and a 16-bit surface id that encodes the normal
// (one of six axes) and the material (albedo from the palette). No history.
// Chunks outside the frustum are skipped; inside one, faces turned away from the
// camera are skipped as whole per-face ranges; chunks are drawn front to back.
#include "engine/camera.h"
#include "engine/scene.h"

namespace grotto {

inline constexpr VkFormat kSurfaceFormat = VK_FORMAT_R16_UINT;

struct GBufferTargets {
    vk::Image depth;
    vk::Image surface;  // R16_UINT, see packSurface in shaders/shared/quad.h
};

class GBufferPass {
public:
    explicit GBufferPass(vk::Context& ctx);
    ~GBufferPass();

    // Returns the number of quads drawn.
    uint64_t record(VkCommandBuffer cmd, const GBufferTargets& targets, const GpuScene& scene,
                    const vk::Buffer& frame, const Camera& camera);

private:
    void release();  // handles not made yet are null, which Vulkan ignores

    vk::Context& ctx_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace grotto
