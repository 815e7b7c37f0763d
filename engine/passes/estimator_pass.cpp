#include "engine/passes/estimator_pass.h"

#include "engine/passes/trace_inputs.h"
#include <bit>

namespace grotto {

std::vector<uint32_t> EstimatorPass::constants(const AoOptions& ao, bool bentNormals) {
    const voxel::EstimatorSettings& s = ao.estimator;
    switch (ao.method) {
    case AoMethod::Ssao: return {s.ssaoSamples};
    case AoMethod::Hbao: return {2 * s.slices, s.steps};
    case AoMethod::Voxel:
    case AoMethod::Hybrid:
        return {s.slices, s.steps, std::bit_cast<uint32_t>(s.sampleDistributionPower), s.rays};
    case AoMethod::Vbao:
        return {s.slices, s.steps, std::bit_cast<uint32_t>(s.sampleDistributionPower), bentNormals ? 1u : 0u};
    default: return {s.slices, s.steps, std::bit_cast<uint32_t>(s.sampleDistributionPower)};
    }
}

namespace {

std::vector<VkDescriptorType> bindingTypes(AoMethod method) {
    std::vector<VkDescriptorType> own = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    if (method == AoMethod::Vbao) {
        own.push_back(VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);  // the thickness atlas
        own.push_back(VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);  // the bent normals
    }
    return tracesVoxels(method) ? withTraceBindings(own, true) : own;  // the rays see objects
}

}  // namespace

EstimatorPass::EstimatorPass(vk::Context& ctx, AoMethod method, const std::vector<uint32_t>& constants)
    : ctx_(ctx),
      method_(method),
      traces_(tracesVoxels(method)),
      pass_(ctx, std::string(aoMethodName(method)) + ".comp", bindingTypes(method), 0, constants) {}

PassDecl EstimatorPass::declare() const {
    PassDecl d{aoMethodName(method_), {{TargetId::AoDepthAtlas, Access::Read}, {TargetId::Surface, Access::Sampled},
                                       {TargetId::AoRaw, Access::Write}}};
    if (method_ == AoMethod::Vbao) {
        d.uses.push_back({TargetId::AoThickness, Access::Read});
        d.uses.push_back({TargetId::AoBentNormal, Access::Write});
    }
    return d;
}

void EstimatorPass::record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants,
                      const vk::Buffer& traceConstants, const GpuOccupancy* occupancy, const vk::Buffer* objectGrids) {
    std::vector<vk::Binding> own = {
        vk::uniformBuffer(constants.buffer), vk::storageImage(ao.depthAtlas.view),
        vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
        vk::storageImage(ao.raw.view)};
    if (method_ == AoMethod::Vbao) {
        own.push_back(vk::storageImage(ao.thickness.view));
        own.push_back(vk::storageImage(ao.bentNormal.view));
    }
    pass_.dispatch(cmd, traces_ ? withTraceBindings(std::move(own), traceConstants, *occupancy, objectGrids) : own, ao.half,
                   GROTTO_GTAO_GROUP);
}

}  // namespace grotto
