#include "engine/passes/hiz_pass.h"
#include <glm/vec2.hpp>

namespace grotto {
namespace {

struct HizPush {
    glm::uvec2 size, tiles;
    uint32_t tileSize;
};

uint32_t tilesOf(uint32_t pixels) { return (pixels + kHizTile - 1) / kHizTile; }

}  // namespace

HizPass::HizPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "hiz.comp", {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            sizeof(HizPush)) {}

void HizPass::record(VkCommandBuffer cmd, const vk::Image& depth, HizReadback& into) {
    const uint32_t w = depth.extent.width, h = depth.extent.height;
    if (w != into.width || h != into.height || !into.buffer.buffer) {
        vk::destroy(ctx_, into.buffer);
        into.buffer = vk::createBuffer(ctx_, VkDeviceSize(tilesOf(w)) * tilesOf(h) * sizeof(float),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        into.width = w, into.height = h;
    }
    const HizPush push{{w, h}, {tilesOf(w), tilesOf(h)}, kHizTile};
    pass_.dispatch(cmd,
                   {vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::storageBuffer(into.buffer.buffer)},
                   {push.tiles.x, push.tiles.y}, 8, &push);
    computeToHost(cmd);
}

DepthTiles HizReadback::tiles() const {
    if (!buffer.buffer) return {};
    const uint32_t tx = tilesOf(width), ty = tilesOf(height);
    return {width, height, tx, ty, {static_cast<const float*>(buffer.mapped()), size_t(tx) * ty}};
}

}  // namespace grotto
