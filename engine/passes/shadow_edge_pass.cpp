#include "engine/passes/shadow_edge_pass.h"

#include "engine/passes/trace_inputs.h"
#include "shaders/shared/face_trace.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace grotto {

ShadowEdgePass::ShadowEdgePass(vk::Context& ctx, uint32_t width, uint32_t height, bool daySun)
    : ctx_(ctx), args_(ctx, "shadow_edge_args.comp", {kBuffer}),
      trace_(ctx, "shadow_edge.comp",
             withTraceBindings({kSampled, kSampled, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kBuffer})) {
    const uint32_t capacity = std::max(1024u, uint32_t(uint64_t(width) * height / (daySun ? 1 : 8)));
    std::vector<uint32_t> words(GROTTO_EDGE_HEADER_WORDS + 8 * size_t(capacity), 0u);
    words[GROTTO_EDGE_CAPACITY] = capacity;
    edges_ = vk::uploadBuffer(ctx, words.data(), words.size() * sizeof(uint32_t),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
}

ShadowEdgePass::~ShadowEdgePass() { vk::destroy(ctx_, edges_); }

void ShadowEdgePass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Image& color,
                            const vk::Buffer& traceConstants, const GpuOccupancy& occupancy) {
    args_.dispatch(cmd, {vk::storageBuffer(edges_.buffer)}, {1, 1}, 1);
    VkMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                      .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                      .dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    trace_.dispatchIndirect(cmd,
                            withTraceBindings({vk::sampledImage(ctx_.pointSampler, g.depth.view, ro),
                                               vk::sampledImage(ctx_.pointSampler, g.surface.view, ro),
                                               vk::storageImage(color.view), vk::storageBuffer(edges_.buffer)},
                                              traceConstants, occupancy),
                            edges_.buffer, GROTTO_EDGE_DISPATCH * sizeof(uint32_t));
    // The next frame's composite lists afresh.
    b = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
         .srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
         .dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
    vkCmdFillBuffer(cmd, edges_.buffer, GROTTO_EDGE_COUNT * sizeof(uint32_t), sizeof(uint32_t), 0);
    b = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
         .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
         .dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
}

}  // namespace grotto
