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

HizPass::~HizPass() { vk::destroy(ctx_, buffer_); }

void HizPass::record(VkCommandBuffer cmd, const vk::Image& depth) {
    const uint32_t w = depth.extent.width, h = depth.extent.height;
    if (w != width_ || h != height_ || !buffer_.buffer) {
        vk::destroy(ctx_, buffer_);  // no frame in flight uses it: the renderer waits for each
        buffer_ = vk::createBuffer(ctx_, VkDeviceSize(tilesOf(w)) * tilesOf(h) * sizeof(float),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        width_ = w, height_ = h;
    }
    const HizPush push{{w, h}, {tilesOf(w), tilesOf(h)}, kHizTile};
    pass_.dispatch(cmd,
                   {vk::sampledImage(ctx_.pointSampler, depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::storageBuffer(buffer_.buffer)},
                   {push.tiles.x, push.tiles.y}, 8, &push);
    computeToHost(cmd);
}

DepthTiles HizPass::tiles() const {
    const uint32_t tx = tilesOf(width_), ty = tilesOf(height_);
    return {width_, height_, tx, ty, {static_cast<const float*>(buffer_.mapped()), size_t(tx) * ty}};
}

}  // namespace grotto
