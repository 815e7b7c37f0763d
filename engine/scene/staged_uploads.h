#pragma once
// Writes into device-local buffers through a host-visible staging buffer, recorded
// into the next frame's command buffer: no submission and no wait of their own.
// The writes wait in host memory until record(), which copies them into the
// staging buffer it is given: the frame's own (engine/frame/frame_slot.h), which
// no frame in flight reads, so a game may edit while two frames are in flight.
// A buffer retired before one record() is freed at the second record() after it:
// by then the frame that recorded it has finished (the renderer waits for the
// frame two before each frame it records).
#include "engine/vk/resources.h"

#include <functional>
#include <map>
#include <vector>

namespace grotto {

class StagedUploads {
public:
    explicit StagedUploads(vk::Context& ctx) : ctx_(ctx) {}
    ~StagedUploads();  // frees the retired buffers (no frame may be in flight)
    StagedUploads(const StagedUploads&) = delete;
    StagedUploads& operator=(const StagedUploads&) = delete;

    // Keeps a copy of `bytes` of `data`; record() copies them into `dst`
    // at `offset`. Writes pending together must not overlap (see discard).
    void write(const vk::Buffer& dst, VkDeviceSize offset, const void* data, VkDeviceSize bytes);
    // Drops the pending writes into [offset, offset + bytes) of `dst`: a range given
    // up before its data landed, which a later write may reuse.
    void discard(const vk::Buffer& dst, VkDeviceSize offset, VkDeviceSize bytes);
    // Replaces `buffer` by a new one of `size` bytes and `usage` (plus transfer
    // source and destination). With `keepContents` the old contents are copied
    // into it on the GPU at record(), before the pending writes, which move to the
    // new buffer, and the room past them reads zero; without, pending writes into
    // the old one are dropped. The old buffer is freed once the frame that records
    // the copy has finished.
    void reallocate(vk::Buffer& buffer, VkDeviceSize size, VkBufferUsageFlags usage, bool keepContents);

    bool pending() const { return !writes_.empty() || !moves_.empty(); }
    // Records the copies through `staging` (made or grown to hold them; the GPU
    // must use it no more) and one barrier from them to (dstStage, dstAccess).
    void record(VkCommandBuffer cmd, vk::Buffer& staging, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

    size_t pendingBytes() const { return bytes_.capacity(); }  // host memory holding the writes

private:
    // Pending writes by destination and offset. They never overlap, so those a
    // range meets are found in order rather than by a scan: an edit across a
    // large region queues millions.
    struct Target {
        VkBuffer dst;
        VkDeviceSize offset;
    };
    struct TargetOrder {
        bool operator()(const Target& a, const Target& b) const {
            return a.dst != b.dst ? std::less<VkBuffer>()(a.dst, b.dst) : a.offset < b.offset;
        }
    };
    struct Write { VkDeviceSize src, size; };  // bytes_ [src, src + size), staging's at record()
    using Writes = std::map<Target, Write, TargetOrder>;
    struct Move { VkBuffer from, to; VkDeviceSize size, toSize; };  // copy `size` bytes, zero the rest

    // The pending writes into `dst`, in offset order.
    std::pair<Writes::iterator, Writes::iterator> writesInto(VkBuffer dst);

    void retire(vk::Buffer& buffer);

    vk::Context& ctx_;
    std::vector<std::byte> bytes_;       // the pending writes' data
    Writes writes_;
    std::vector<Move> moves_;            // whole-buffer copies into reallocated buffers
    std::vector<vk::Buffer> retired_;    // replaced since the last record(): the next frame may read them
    // Replaced before the last two records: freed once those frames are done ([0]: the older).
    std::vector<vk::Buffer> finishing_[2];
};

}  // namespace grotto
