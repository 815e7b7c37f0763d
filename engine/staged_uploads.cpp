#include "engine/staged_uploads.h"

#include <algorithm>
#include <cstring>
#include <functional>

namespace grotto {
namespace {

void transferBarrier(VkCommandBuffer cmd, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                      .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                      .dstAccessMask = dstAccess};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, dstStage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace

StagedUploads::~StagedUploads() {
    vk::destroy(ctx_, staging_);
    for (vk::Buffer& b : retired_) vk::destroy(ctx_, b);
    for (vk::Buffer& b : finishing_) vk::destroy(ctx_, b);
}

void StagedUploads::write(const vk::Buffer& dst, VkDeviceSize offset, const void* data, VkDeviceSize bytes) {
    if (!bytes) return;
    if (used_ + bytes > staging_.size) {
        // No frame is in flight between frames, so the old staging buffer can go at once.
        const VkDeviceSize size = std::max({2 * staging_.size, used_ + bytes, VkDeviceSize(64) << 10});
        vk::Buffer bigger = vk::createBuffer(ctx_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        if (used_) std::memcpy(bigger.mapped(), staging_.mapped(), used_);
        vk::destroy(ctx_, staging_);
        staging_ = bigger;
    }
    std::memcpy(static_cast<char*>(staging_.mapped()) + used_, data, bytes);
    writes_.push_back({dst.buffer, used_, offset, bytes});
    used_ += bytes;
}

void StagedUploads::discard(const vk::Buffer& dst, VkDeviceSize offset, VkDeviceSize bytes) {
    std::erase_if(writes_, [&](const Write& w) {
        return w.dst == dst.buffer && w.offset < offset + bytes && offset < w.offset + w.size;
    });
}

void StagedUploads::reallocate(vk::Buffer& buffer, VkDeviceSize size, VkBufferUsageFlags usage, bool keepContents) {
    vk::Buffer fresh = vk::createBuffer(
        ctx_, size, usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    const VkBuffer old = buffer.buffer;
    // A buffer made since the last record() has never reached the GPU: it goes at
    // once, and the copy into it comes from its own source instead.
    const auto into = std::find_if(moves_.begin(), moves_.end(), [&](const Move& m) { return m.to == old; });
    const bool unused = into != moves_.end();
    if (keepContents) {
        for (Write& w : writes_)
            if (w.dst == old) w.dst = fresh.buffer;
        if (unused)
            *into = {into->from, fresh.buffer, std::min(into->size, size), size};
        else if (old)
            moves_.push_back({old, fresh.buffer, std::min(buffer.size, size), size});
    } else {
        std::erase_if(writes_, [&](const Write& w) { return w.dst == old; });
        if (unused) moves_.erase(into);
    }
    if (unused)
        vk::destroy(ctx_, buffer);
    else
        retire(buffer);
    buffer = fresh;
}

void StagedUploads::retire(vk::Buffer& buffer) {
    if (buffer.buffer) retired_.push_back(buffer);
    buffer = {};
}

void StagedUploads::record(VkCommandBuffer cmd, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    // The frame that recorded the last copies has finished (its fence was waited on).
    for (vk::Buffer& b : finishing_) vk::destroy(ctx_, b);
    finishing_ = std::move(retired_);
    retired_.clear();
    if (!pending()) return;
    for (const Move& m : moves_) {
        const VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = m.size};
        vkCmdCopyBuffer(cmd, m.from, m.to, 1, &region);
        // The new room: fresh memory holds whatever it held before, and a user may
        // rely on unwritten room reading zero (the occupancy's absent bricks do).
        if (m.toSize > m.size) vkCmdFillBuffer(cmd, m.to, m.size, VK_WHOLE_SIZE, 0u);
    }
    if (!moves_.empty() && !writes_.empty())  // the writes land on top of the moved contents
        transferBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    std::sort(writes_.begin(), writes_.end(), [](const Write& a, const Write& b) {
        return a.dst != b.dst ? std::less<VkBuffer>()(a.dst, b.dst) : a.offset < b.offset;
    });
    std::vector<VkBufferCopy> regions;
    for (size_t i = 0; i < writes_.size(); ++i) {
        const Write& w = writes_[i];
        regions.push_back({.srcOffset = w.src, .dstOffset = w.offset, .size = w.size});
        if (i + 1 < writes_.size() && writes_[i + 1].dst == w.dst) continue;
        vkCmdCopyBuffer(cmd, staging_.buffer, w.dst, uint32_t(regions.size()), regions.data());
        regions.clear();
    }
    transferBarrier(cmd, dstStage, dstAccess);
    writes_.clear();
    moves_.clear();
    used_ = 0;
}

}  // namespace grotto
