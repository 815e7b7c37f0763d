#include "engine/passes/composite_pass.h"

#include "grotto/error.h"
#include "shaders/shared/frame.h"

namespace grotto {

namespace {
// Threads per group side, measured on lavapipe: with AO each thread shades a 2x2
// block, and smaller groups of them run faster.
uint32_t group(const CompositeShape& s) { return s.withAo ? 8u : 16u; }

std::vector<VkDescriptorType> bindings(const CompositeShape& s) {
    std::vector<VkDescriptorType> b = {
        VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
        VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,         VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,          VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    if (!s.faceCache) return b;
    b.push_back(VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);  // the object light
    b = GpuFaceCache::withBindings(std::move(b));
    b.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);  // the shadow edges' list
    b = GpuFaceCache::withRequestBindings(std::move(b));
    b.push_back(VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);  // the atlas: each pixel's quad record
    b.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);          // and its cells
    b.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);          // the pixels left to the chain's read
    return b;
}
}  // namespace

CompositeShape CompositePass::shapeFor(const FramePlan& plan, bool askFaces) {
    return {.withAo = plan.chain, .withShadow = plan.tracedShadows, .withBentNormals = plan.bentNormals,
            .faceCache = plan.faceCache, .cachedSun = plan.cachedSun, .objectLight = plan.objectLight,
            .shadowEdges = plan.shadowEdges, .askFaces = askFaces, .fullLight = plan.cacheFullLight,
            .dayLight = plan.cacheDayLight, .daySun = plan.daySun, .atlas = plan.faceAtlas && !askFaces,
            .listPixels = plan.faceAtlas && !askFaces ? plan.width * plan.height : 0};
}

namespace {
// The shader's specialization constants; `withoutRegion`: the chain's pass after the atlas's.
std::vector<uint32_t> constants(const CompositeShape& s, bool withoutRegion) {
    return {s.withAo ? 1u : 0u,        withoutRegion ? 64u : group(s),
            withoutRegion ? 1u : group(s), s.withShadow ? 1u : 0u,
            s.withBentNormals ? 1u : 0u, s.cachedSun ? 1u : 0u,
            s.objectLight ? 1u : 0u,   s.shadowEdges ? 1u : 0u,
            s.askFaces ? 1u : 0u,      s.fullLight ? 1u : 0u,
            s.dayLight ? 1u : 0u,      s.daySun ? 1u : 0u,
            s.atlas && !withoutRegion ? 1u : 0u, withoutRegion ? 1u : 0u};
}
}  // namespace

CompositePass::CompositePass(vk::Context& ctx, const CompositeShape& shape)
    : ctx_(ctx),
      shape_(shape),
      pass_(ctx, shape.faceCache ? "composite_cache.comp" : "composite.comp", bindings(shape), 0, constants(shape, false)) {
    if (!shape.atlas) return;
    withoutRegion_.emplace(ctx, "composite_cache.comp", bindings(shape), 0, constants(shape, true));
    chainList_ = vk::createBuffer(ctx, (4 + uint64_t(shape.listPixels)) * sizeof(uint32_t),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  false);
}

CompositePass::~CompositePass() { vk::destroy(ctx_, chainList_); }

void CompositePass::record(VkCommandBuffer cmd, const GBufferTargets& g, const vk::Image& color, const Inputs& in) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    std::vector<vk::Binding> b = {
        vk::uniformBuffer(in.frame.buffer),          vk::uniformBuffer(in.palette.buffer),
        vk::sampledImage(ctx_.pointSampler, g.surface.view, ro), vk::storageImage(color.view),
        vk::uniformBuffer(in.gtaoConstants.buffer),  vk::storageImage(in.aoHalf.view),
        vk::sampledImage(ctx_.pointSampler, g.depth.view, ro), vk::uniformBuffer(in.objectUniforms.buffer),
        vk::storageImage(in.shadow.view),            vk::storageImage(in.bentNormals.view)};
    if (shape_.faceCache) {
        if (!in.faceCache || !in.objectLight)
            throw Error::internal("CompositePass", "the face cache's composite without the cache or the object light");
        b.push_back(vk::storageImage(in.objectLight->view));
        if (shape_.shadowEdges && !in.shadowEdges)
            throw Error::internal("CompositePass", "shadow edges without their list");
        b = in.faceCache->withBindings(std::move(b));
        // Without edges the binding is never read: any buffer holds its place.
        b.push_back(vk::storageBuffer(in.shadowEdges ? in.shadowEdges->buffer : in.faceCache->header().buffer));
        b = in.faceCache->withRequestBindings(std::move(b));
        if (shape_.atlas && (!in.atlasRecord || !in.atlasCells))
            throw Error::internal("CompositePass", "the atlas's read without its records or cells");
        // Without the atlas neither is read: the G-buffer's surface and the cache's header hold their places.
        b.push_back(vk::sampledImage(ctx_.pointSampler, shape_.atlas ? in.atlasRecord->view : g.surface.view, ro));
        b.push_back(vk::storageBuffer(shape_.atlas ? in.atlasCells->buffer : in.faceCache->header().buffer));
        b.push_back(vk::storageBuffer(shape_.atlas ? chainList_.buffer : in.faceCache->header().buffer));
    }
    if (!withoutRegion_) {
        pass_.dispatch(cmd, b, shape_.withAo ? in.aoHalf.extent : color.extent, group(shape_));  // with AO, per AO pixel
        return;
    }
    // The list starts empty, its dispatch at no groups (y and z 1); the atlas's pass
    // lists the pixels it leaves, and the chain's pass shades them.
    const uint32_t empty[4] = {0u, 0u, 1u, 1u};
    vkCmdUpdateBuffer(cmd, chainList_.buffer, 0, sizeof empty, empty);
    VkMemoryBarrier filled{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                           .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                           .dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &filled, 0,
                         nullptr, 0, nullptr);
    pass_.dispatch(cmd, b, color.extent, group(shape_));
    VkMemoryBarrier listed{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                           .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                           .dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT |
                                            VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &listed, 0,
                         nullptr, 0, nullptr);
    withoutRegion_->dispatchIndirect(cmd, b, chainList_.buffer, sizeof(uint32_t));
    // The next frame's first pass writes the list again.
    VkMemoryBarrier read{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                         .srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT,
                         .dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &read, 0, nullptr, 0, nullptr);
}

}  // namespace grotto
