#include "engine/passes/object_light_pass.h"

#include "engine/passes/trace_inputs.h"

namespace grotto {

ObjectLightPass::ObjectLightPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "object_light.comp",
            GpuFaceCache::withBindings(withTraceBindings(
                {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                 VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                true)),
            0, {kRays}) {}

PassDecl ObjectLightPass::declare() {
    return {"object light",
            {{TargetId::Depth, Access::Sampled},
             {TargetId::Surface, Access::Sampled},
             {TargetId::ObjectLight, Access::Write},
             {{TargetId::ObjectLightHistory, Copy::Previous}, Access::Read},
             {TargetId::ObjectLightHistory, Access::Write}}};
}

void ObjectLightPass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Buffer& objectUniforms,
                             const vk::Image& light, const vk::Image& history, const vk::Image& nextHistory,
                             const vk::Buffer& traceConstants, const GpuOccupancy& occupancy,
                             const vk::Buffer& objectGrids, const vk::Buffer& palette, const GpuFaceCache& faceCache) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pass_.dispatch(cmd,
                   faceCache.withBindings(withTraceBindings(
                       {vk::sampledImage(ctx_.pointSampler, g.depth.view, ro),
                        vk::sampledImage(ctx_.pointSampler, g.surface.view, ro), vk::uniformBuffer(objectUniforms.buffer),
                        vk::storageImage(light.view), vk::storageImage(history.view), vk::storageImage(nextHistory.view),
                        vk::uniformBuffer(palette.buffer)},
                       traceConstants, occupancy, &objectGrids)),
                   light.extent, GROTTO_TRACE_GROUP);
}

}  // namespace grotto
