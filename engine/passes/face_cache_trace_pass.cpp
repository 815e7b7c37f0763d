#include "engine/passes/face_cache_trace_pass.h"

#include "engine/passes/trace_inputs.h"

#include <cmath>

namespace grotto {

namespace {
void barrier(VkCommandBuffer cmd, VkPipelineStageFlags from, VkAccessFlags written, VkPipelineStageFlags to,
             VkAccessFlags read) {
    const VkMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER, .srcAccessMask = written, .dstAccessMask = read};
    vkCmdPipelineBarrier(cmd, from, to, 0, 1, &b, 0, nullptr, 0, nullptr);
}
}  // namespace

uint32_t defaultCacheRays(const vk::Context& ctx) {
    return ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 2'000'000u : 64'000'000u;
}

FaceCacheTracePass::FaceCacheTracePass(vk::Context& ctx)
    : ctx_(ctx),
      gate_(ctx, "face_cache_gate.comp", {kBuffer}, sizeof(gpu::FaceTraceConstants)),
      request_(ctx, "face_cache_request.comp",
               GpuFaceCache::withRequestBindings(
                   GpuFaceCache::withBindings({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kSampled, kSampled}))),
      backlog_(ctx, "face_cache_backlog.comp", GpuFaceCache::withRequestBindings(std::vector<VkDescriptorType>{kBuffer})),
      plan_(ctx, "face_cache_plan.comp", {kBuffer}, sizeof(gpu::FaceTraceConstants)),
      trace_(ctx, "face_cache_trace.comp", withTraceBindings({kBuffer, kBuffer, kBuffer, kBuffer, kBuffer}),
             sizeof(gpu::FaceTraceConstants)) {}

void FaceCacheTracePass::record(VkCommandBuffer cmd, const GBufferTargets& g, VkExtent2D size, const vk::Buffer& frame,
                                const vk::Buffer& traceConstants, const GpuOccupancy& occupancy,
                                const GpuFaceCache& cache, uint32_t budget) {
    if (cache.afterEdit() && cache.id() != traced_) budget = 0;
    traced_ = cache.id();
    const FaceCacheRays& s = cache.rays();
    const GpuFaceCache::Sun& sun = cache.sun();
    const bool pointSun = !(sun.angleDegrees > 0.0f);
    const gpu::FaceTraceConstants c{
        .sun = glm::vec4(glm::normalize(sun.direction),
                         pointSun ? 1.0f : float(std::cos(0.5 * double(sun.angleDegrees) * M_PI / 180.0))),
        .rays = s.rays,
        .sunRays = s.sunRays,
        .coarseRays = std::min<uint32_t>(GROTTO_FACE_COARSE_RAYS, s.rays),
        .coarseSunRays = std::min<uint32_t>(GROTTO_FACE_COARSE_SUN_RAYS, s.sunRays),
        .radiusVoxels = s.radiusVoxels,
        .epsilon = 1e-4f,
        .texelsPerSide = cache.texelsPerSide(),
        .budget = budget,
        .width = size.width,
        .height = size.height,
        .dayPositions = sun.day ? voxel::kDaySunPositions : 0u,
        .daySunFirst = cache.daySunFirst(),
        .skyZenith = glm::vec4(cache.sky().zenith, cache.sky().fullLight ? 1.0f : 0.0f),
        .skyHorizon = glm::vec4(cache.sky().horizon, 0.0f)};
    if (cache.faceCount() == 0) return;
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    gate_.dispatch(cmd, {vk::storageBuffer(cache.header().buffer)}, {1, 1}, 1, &c);
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    request_.dispatchIndirect(cmd,
                              cache.withRequestBindings(cache.withBindings(
                                  {vk::uniformBuffer(frame.buffer), vk::sampledImage(ctx_.pointSampler, g.depth.view, ro),
                                   vk::sampledImage(ctx_.pointSampler, g.surface.view, ro)})),
                              cache.header().buffer, GROTTO_FACE_REQUEST_DISPATCH * sizeof(uint32_t));
    computeToCompute(cmd);
    backlog_.dispatchIndirect(cmd, cache.withRequestBindings(std::vector<vk::Binding>{vk::storageBuffer(cache.backlog().buffer)}),
                              cache.header().buffer, GROTTO_FACE_BACKLOG_DISPATCH * sizeof(uint32_t));
    computeToCompute(cmd);
    plan_.dispatch(cmd, {vk::storageBuffer(cache.header().buffer)}, {1, 1}, 1, &c);
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
    trace_.dispatchIndirect(cmd,
                            withTraceBindings({vk::storageBuffer(cache.queue().buffer),
                                               vk::storageBuffer(cache.header().buffer),
                                               vk::storageBuffer(cache.levels().buffer),
                                               vk::storageBuffer(cache.texels().buffer),
                                               vk::storageBuffer(cache.dayPositions().buffer)},
                                              traceConstants, occupancy),
                            cache.header().buffer, GROTTO_FACE_DISPATCH * sizeof(uint32_t), &c);
    // The requests start afresh for the composite, which asks for the next frame:
    // the counts and the request bits (the rest of the header is the plan's).
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, cache.requested().buffer, 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, cache.header().buffer, 0, 2 * sizeof(uint32_t), 0);
    // The composite and the AOVs read the texels next and ask anew; the host reads the header.
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT);
}

}  // namespace grotto
