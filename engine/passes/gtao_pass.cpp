#include "engine/passes/gtao_pass.h"

#include <bit>

namespace grotto {
namespace {

std::vector<uint32_t> specialization(const AoOptions& ao) {
    const gpu::GtaoSettings& s = ao.gtao;
    switch (ao.method) {
    case AoMethod::Ssao: return {ao.ssaoSamples};
    case AoMethod::Hbao: return {2 * s.sliceCount, s.stepsPerSlice};
    default: return {s.sliceCount, s.stepsPerSlice, std::bit_cast<uint32_t>(s.sampleDistributionPower)};
    }
}

}  // namespace

GtaoPass::GtaoPass(vk::Context& ctx, const AoOptions& ao)
    : ctx_(ctx),
      pass_(ctx, std::string(aoMethodName(ao.method)) + ".comp",
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            0, specialization(ao)) {}

void GtaoPass::record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants) {
    pass_.dispatch(cmd,
                   {vk::uniformBuffer(constants.buffer),
                    vk::storageImage(ao.depthAtlas.view),
                    vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::storageImage(ao.raw.view)},
                   ao.half, GROTTO_GTAO_GROUP);
}

}  // namespace grotto
