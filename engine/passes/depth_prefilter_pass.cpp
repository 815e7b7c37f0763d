#include "engine/passes/depth_prefilter_pass.h"

#include "engine/passes/trace_inputs.h"

#include <algorithm>

namespace grotto {

// depth_prefilter.comp: a group of GROUP x GROUP threads reduces 2 GROUP x 2 GROUP
// MIP-0 texels to exactly one texel of the last MIP.
static_assert(2 * GROTTO_GTAO_GROUP == 1u << (GROTTO_GTAO_DEPTH_MIPS - 1));

// Mirrors gtaoMipRect in shaders/shared/gtao_kernel.h.
DepthMipLayout depthMipLayout(VkExtent2D half) {
    DepthMipLayout l;
    const glm::ivec2 half0(int(half.width), int(half.height));
    for (int k = 0; k < GROTTO_GTAO_DEPTH_MIPS; ++k) {
        const glm::ivec2 size = (half0 + ((1 << k) - 1)) >> k;
        const glm::ivec2 offset = k == 0 ? glm::ivec2(0) : glm::ivec2(half0.x, (k - 1) * ((half0.y + 1) >> 1));
        l.mips[k] = glm::ivec4(offset, size);
    }
    const int slot = (half0.y + 1) >> 1;
    l.atlas = {uint32_t(half0.x + l.mips[1].z), uint32_t(std::max(half0.y, (GROTTO_GTAO_DEPTH_MIPS - 1) * slot))};
    return l;
}

namespace {

std::vector<VkDescriptorType> bindingTypes(bool thickness) {
    std::vector<VkDescriptorType> own = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    if (!thickness) return own;
    own.insert(own.end(), {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    return withTraceBindings(own);
}

}  // namespace

DepthPrefilterPass::DepthPrefilterPass(vk::Context& ctx, bool thickness)
    : ctx_(ctx),
      thickness_(thickness),
      pass_(ctx, thickness ? "depth_prefilter_thickness.comp" : "depth_prefilter.comp", bindingTypes(thickness)) {}

PassDecl DepthPrefilterPass::declare() const {
    PassDecl d{"prefilter", {{TargetId::Depth, Access::Sampled}, {TargetId::AoDepthAtlas, Access::Write}}};
    if (thickness_) {
        d.uses.push_back({TargetId::Surface, Access::Sampled});
        d.uses.push_back({TargetId::AoThickness, Access::Write});
    }
    return d;
}

void DepthPrefilterPass::record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& surface,
                                const AoTargets& ao, const vk::Buffer& constants, const vk::Buffer& traceConstants,
                                const GpuOccupancy* occupancy) {
    // One thread per MIP-1 texel; each group writes its share of every MIP.
    const glm::ivec4 mip1 = depthMipLayout(ao.half).mips[1];
    std::vector<vk::Binding> own = {
        vk::uniformBuffer(constants.buffer),
        vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
        vk::storageImage(ao.depthAtlas.view)};
    if (thickness_) {
        own.push_back(vk::storageImage(ao.thickness.view));
        own.push_back(vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
        own = withTraceBindings(std::move(own), traceConstants, *occupancy);
    }
    pass_.dispatch(cmd, own, {uint32_t(mip1.z), uint32_t(mip1.w)}, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
