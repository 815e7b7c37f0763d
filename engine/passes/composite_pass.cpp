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
    return b;
}
}  // namespace

CompositeShape CompositePass::shapeFor(const FramePlan& plan, bool askFaces) {
    return {.withAo = plan.chain, .withShadow = plan.tracedShadows, .withBentNormals = plan.bentNormals,
            .faceCache = plan.faceCache, .cachedSun = plan.cachedSun, .objectLight = plan.objectLight,
            .shadowEdges = plan.shadowEdges, .askFaces = askFaces, .fullLight = plan.cacheFullLight,
            .dayLight = plan.cacheDayLight, .daySun = plan.daySun, .atlas = plan.faceAtlas && !askFaces};
}

CompositePass::CompositePass(vk::Context& ctx, const CompositeShape& shape)
    : ctx_(ctx),
      shape_(shape),
      pass_(ctx, shape.faceCache ? "composite_cache.comp" : "composite.comp", bindings(shape), 0,
            {shape.withAo ? 1u : 0u, group(shape), group(shape), shape.withShadow ? 1u : 0u,
             shape.withBentNormals ? 1u : 0u, shape.cachedSun ? 1u : 0u, shape.objectLight ? 1u : 0u,
             shape.shadowEdges ? 1u : 0u, shape.askFaces ? 1u : 0u, shape.fullLight ? 1u : 0u,
             shape.dayLight ? 1u : 0u, shape.daySun ? 1u : 0u, shape.atlas ? 1u : 0u}) {}

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
    }
    pass_.dispatch(cmd, b, shape_.withAo ? in.aoHalf.extent : color.extent, group(shape_));  // with AO, per AO pixel
}

}  // namespace grotto
