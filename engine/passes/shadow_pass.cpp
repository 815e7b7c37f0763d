#include "engine/passes/shadow_pass.h"

#include "engine/passes/trace_inputs.h"

namespace grotto {

namespace {

std::vector<VkDescriptorType> shadowBindings(bool soft) {
    std::vector<VkDescriptorType> b = {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                       VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    if (soft) b.insert(b.end(), 2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    return withTraceBindings(std::move(b), true);
}

}  // namespace

ShadowPass::ShadowPass(vk::Context& ctx, bool soft, bool objectsOnlyOnWorld)
    : ctx_(ctx), soft_(soft),
      pass_(ctx, soft ? "soft_shadow.comp" : "shadow.comp", shadowBindings(soft), 0, {objectsOnlyOnWorld ? 1u : 0u}) {}

PassDecl ShadowPass::declare() const {
    PassDecl d{"shadow", {{TargetId::Depth, Access::Sampled}, {TargetId::Surface, Access::Sampled},
                          {TargetId::Shadow, Access::Write}}};
    if (soft_)
        d.uses.insert(d.uses.end(), {{{TargetId::ShadowHistory, Copy::Previous}, Access::Read},
                                     {TargetId::ShadowHistory, Access::Write}});
    return d;
}

void ShadowPass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Buffer& objectUniforms,
                        const vk::Image& shadow, const vk::Buffer& traceConstants, const GpuOccupancy& occupancy,
                        const vk::Buffer& objectGrids, const vk::Image* history, const vk::Image* nextHistory) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    std::vector<vk::Binding> b = {vk::sampledImage(ctx_.pointSampler, g.depth.view, ro),
                                  vk::sampledImage(ctx_.pointSampler, g.surface.view, ro),
                                  vk::uniformBuffer(objectUniforms.buffer), vk::storageImage(shadow.view)};
    if (soft_) b.insert(b.end(), {vk::storageImage(history->view), vk::storageImage(nextHistory->view)});
    pass_.dispatch(cmd, withTraceBindings(std::move(b), traceConstants, occupancy, &objectGrids), shadow.extent, GROTTO_TRACE_GROUP);
}

}  // namespace grotto
