#include "engine/passes/face_cache_aov_pass.h"

namespace grotto {

FaceCacheAovPass::FaceCacheAovPass(vk::Context& ctx, bool cachedSun, bool tracedShadows, bool objectLight)
    : ctx_(ctx),
      pass_(ctx, "face_cache_aov.comp",
            GpuFaceCache::withLevelsBinding(GpuFaceCache::withBindings(
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                 VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE})),
            0, {cachedSun ? 1u : 0u, tracedShadows ? 1u : 0u, objectLight ? 1u : 0u}) {}

void FaceCacheAovPass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Buffer& frame,
                              const GpuFaceCache& cache, const vk::Image& ao, const vk::Image& sun,
                              const vk::Image& objectLight, const vk::Image& light) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pass_.dispatch(cmd,
                   cache.withLevelsBinding(cache.withBindings(
                       {vk::uniformBuffer(frame.buffer), vk::sampledImage(ctx_.pointSampler, g.surface.view, ro),
                        vk::sampledImage(ctx_.pointSampler, g.depth.view, ro), vk::storageImage(ao.view),
                        vk::storageImage(sun.view), vk::storageImage(objectLight.view), vk::storageImage(light.view)})),
                   ao.extent, 16);
}

}  // namespace grotto
