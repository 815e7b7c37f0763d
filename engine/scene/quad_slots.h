#pragma once
// Ranges of quads inside one vertex buffer: a first-fit free list, so each chunk
// of a live scene owns a slot it can be rewritten into, with room to grow.
// Counts and offsets are in quads (4 vertices each). Pure CPU, no Vulkan.
#include <cstdint>
#include <map>
#include <optional>

namespace grotto {

// The slot a chunk of `quads` quads gets: an eighth more, rounded up to a
// multiple of 16 and at least 16 spare, so small edits rewrite it in place.
uint32_t slotQuads(uint32_t quads);
// A vertex buffer's capacity for slots totalling `slotTotal` quads: a sixteenth
// more (at least 256 quads), so new chunks and chunks that outgrow their slot
// fit without growing the buffer.
uint64_t bufferQuads(uint64_t slotTotal);
// The capacity a full buffer grows to when `needed` more quads must fit: half
// again as much, or enough for the request.
uint64_t grownQuads(uint64_t capacity, uint64_t needed);

class QuadSlots {
public:
    explicit QuadSlots(uint64_t capacity = 0);

    // The first free range of `count` quads (first fit), or none when no free
    // range is that long. count > 0.
    std::optional<uint64_t> allocate(uint32_t count);
    // Returns a range from allocate(); neighbours merge.
    void release(uint64_t first, uint64_t count);
    // Adds [capacity, newCapacity) as free space.
    void grow(uint64_t newCapacity);

    uint64_t capacity() const { return capacity_; }
    uint64_t freeQuads() const { return free_; }
    size_t freeRanges() const { return ranges_.size(); }

private:
    std::map<uint64_t, uint64_t> ranges_;  // first -> count, never adjacent nor overlapping
    uint64_t capacity_ = 0, free_ = 0;
};

}  // namespace grotto
