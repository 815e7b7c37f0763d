#include "engine/passes/temporal_pass.h"

#include <algorithm>

namespace grotto {

namespace {

std::vector<VkDescriptorType> temporalBindings(bool objects) {
    std::vector<VkDescriptorType> b = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                       VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,  VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                       VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,  VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    if (objects) b.insert(b.end(), {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    return b;
}

}  // namespace

TemporalPass::TemporalPass(vk::Context& ctx, uint32_t denoisePasses, bool objects, bool motion)
    : ctx_(ctx),
      denoisePasses_(denoisePasses),
      objects_(objects),
      pass_(ctx, objects ? "temporal_objects.comp" : "temporal.comp", temporalBindings(objects), 0,
            objects ? std::vector<uint32_t>{denoisePasses >= 1 ? 1u : 0u, denoisePasses <= 1 ? 1u : 0u, motion ? 1u : 0u}
                    : std::vector<uint32_t>{denoisePasses >= 1 ? 1u : 0u, denoisePasses <= 1 ? 1u : 0u}) {}  // blur, sourceIsRaw[, motion]

PassDecl TemporalPass::declare(bool motion) const {
    PassDecl d{"temporal", {{denoisedTarget(std::max(denoisePasses_, 1u) - 1), Access::Read},
                            {{TargetId::AoHistory, Copy::Previous}, Access::Read},
                            {TargetId::AoHistory, Access::Write},
                            {TargetId::AoRaw, Access::Read}}};
    if (objects_) d.uses.push_back({motion ? TargetId::Motion : TargetId::Depth, Access::Sampled});
    return d;
}

void TemporalPass::record(VkCommandBuffer cmd, const AoTargets& ao, const vk::Image& history,
                          const vk::Image& target, const vk::Buffer& gtaoConstants,
                          const vk::Buffer& temporalConstants, const vk::Buffer* objectUniforms, const vk::Image* motion) {
    const vk::Image& source = ao.denoised(std::max(denoisePasses_, 1u) - 1);
    std::vector<vk::Binding> b = {vk::uniformBuffer(gtaoConstants.buffer), vk::uniformBuffer(temporalConstants.buffer),
                                  vk::storageImage(source.view), vk::storageImage(history.view),
                                  vk::storageImage(target.view), vk::storageImage(ao.raw.view)};
    if (objects_)
        b.insert(b.end(), {vk::uniformBuffer(objectUniforms->buffer),
                           vk::sampledImage(ctx_.pointSampler, motion->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)});
    pass_.dispatch(cmd, b, target.extent, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
