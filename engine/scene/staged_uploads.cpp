#include "engine/scene/staged_uploads.h"

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
    for (vk::Buffer& b : retired_) vk::destroy(ctx_, b);
    for (std::vector<vk::Buffer>& buffers : finishing_)
        for (vk::Buffer& b : buffers) vk::destroy(ctx_, b);
}

void StagedUploads::write(const vk::Buffer& dst, VkDeviceSize offset, const void* data, VkDeviceSize bytes) {
    if (!bytes) return;
    const VkDeviceSize at = bytes_.size();
    const auto* from = static_cast<const std::byte*>(data);
    bytes_.insert(bytes_.end(), from, from + bytes);
    writes_.insert_or_assign({dst.buffer, offset}, Write{at, bytes});
}

void StagedUploads::discard(const vk::Buffer& dst, VkDeviceSize offset, VkDeviceSize bytes) {
    auto first = writes_.lower_bound({dst.buffer, offset});
    // Only the write just before may start earlier and reach into the range.
    if (first != writes_.begin()) {
        const auto before = std::prev(first);
        if (before->first.dst == dst.buffer && before->first.offset + before->second.size > offset) first = before;
    }
    auto last = first;
    while (last != writes_.end() && last->first.dst == dst.buffer && last->first.offset < offset + bytes) ++last;
    writes_.erase(first, last);
}

std::pair<StagedUploads::Writes::iterator, StagedUploads::Writes::iterator> StagedUploads::writesInto(VkBuffer dst) {
    const auto first = writes_.lower_bound({dst, 0});
    auto last = first;
    while (last != writes_.end() && last->first.dst == dst) ++last;
    return {first, last};
}

void StagedUploads::reallocate(vk::Buffer& buffer, VkDeviceSize size, VkBufferUsageFlags usage, bool keepContents) {
    vk::Buffer fresh = vk::createBuffer(
        ctx_, size, usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    const VkBuffer old = buffer.buffer;
    // A buffer made since the last record() has never reached the GPU: it goes at
    // once, and the copy into it comes from its own source instead.
    const auto into = std::find_if(moves_.begin(), moves_.end(), [&](const Move& m) { return m.to == old; });
    const bool unused = into != moves_.end();
    const auto [first, last] = writesInto(old);
    if (keepContents) {
        Writes moved;
        for (auto it = first; it != last; ++it) moved.emplace_hint(moved.end(), Target{fresh.buffer, it->first.offset}, it->second);
        writes_.erase(first, last);
        writes_.merge(moved);
        if (unused)
            *into = {into->from, fresh.buffer, std::min(into->size, size), size};
        else if (old)
            moves_.push_back({old, fresh.buffer, std::min(buffer.size, size), size});
    } else {
        writes_.erase(first, last);
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

void StagedUploads::record(VkCommandBuffer cmd, vk::Buffer& staging, VkPipelineStageFlags dstStage,
                           VkAccessFlags dstAccess) {
    // The frame two records back has finished (the renderer waited for it).
    for (vk::Buffer& b : finishing_[0]) vk::destroy(ctx_, b);
    finishing_[0] = std::move(finishing_[1]);
    finishing_[1] = std::move(retired_);
    retired_.clear();
    if (!pending()) return;
    if (staging.size < bytes_.size()) {  // no frame in flight uses it
        vk::destroy(ctx_, staging);
        const VkDeviceSize size = std::max(VkDeviceSize(bytes_.size()), VkDeviceSize(64) << 10);
        staging = vk::createBuffer(ctx_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    }
    if (!bytes_.empty()) std::memcpy(staging.mapped(), bytes_.data(), bytes_.size());
    for (const Move& m : moves_) {
        const VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = m.size};
        vkCmdCopyBuffer(cmd, m.from, m.to, 1, &region);
        // The new room: fresh memory holds whatever it held before, and a user may
        // rely on unwritten room reading zero (the occupancy's absent bricks do).
        if (m.toSize > m.size) vkCmdFillBuffer(cmd, m.to, m.size, VK_WHOLE_SIZE, 0u);
    }
    if (!moves_.empty() && !writes_.empty())  // the writes land on top of the moved contents
        transferBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    std::vector<VkBufferCopy> regions;  // one copy command per destination, its writes in offset order
    for (auto it = writes_.begin(); it != writes_.end(); ++it) {
        regions.push_back({.srcOffset = it->second.src, .dstOffset = it->first.offset, .size = it->second.size});
        const auto next = std::next(it);
        if (next != writes_.end() && next->first.dst == it->first.dst) continue;
        vkCmdCopyBuffer(cmd, staging.buffer, it->first.dst, uint32_t(regions.size()), regions.data());
        regions.clear();
    }
    transferBarrier(cmd, dstStage, dstAccess);
    writes_.clear();
    moves_.clear();
    bytes_.clear();
}

}  // namespace grotto
