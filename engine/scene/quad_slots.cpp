#include "engine/scene/quad_slots.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace grotto {

uint32_t slotQuads(uint32_t quads) {
    const uint64_t spare = std::max<uint64_t>(quads / 8, 16);
    return uint32_t((uint64_t(quads) + spare + 15) / 16 * 16);
}

uint64_t bufferQuads(uint64_t slotTotal) { return slotTotal + std::max<uint64_t>(slotTotal / 16, 256); }

uint64_t grownQuads(uint64_t capacity, uint64_t needed) {
    return std::max(capacity + capacity / 2, capacity + needed);
}

QuadSlots::QuadSlots(uint64_t capacity) { grow(capacity); }

std::optional<uint64_t> QuadSlots::allocate(uint32_t count) {
    assert(count > 0);
    for (auto it = ranges_.begin(); it != ranges_.end(); ++it) {
        if (it->second < count) continue;
        const uint64_t first = it->first, left = it->second - count;
        ranges_.erase(it);
        if (left) ranges_.emplace(first + count, left);
        free_ -= count;
        return first;
    }
    return std::nullopt;
}

void QuadSlots::release(uint64_t first, uint64_t count) {
    if (!count) return;
    assert(first + count <= capacity_);
    uint64_t start = first, size = count;
    auto next = ranges_.lower_bound(first);
    assert(next == ranges_.end() || next->first >= first + count);  // not free already
    if (next != ranges_.end() && next->first == first + count) {
        size += next->second;
        next = ranges_.erase(next);
    }
    if (next != ranges_.begin()) {
        auto prev = std::prev(next);
        assert(prev->first + prev->second <= first);
        if (prev->first + prev->second == first) {
            start = prev->first;
            size += prev->second;
            ranges_.erase(prev);
        }
    }
    ranges_.emplace(start, size);
    free_ += count;
}

void QuadSlots::grow(uint64_t newCapacity) {
    if (newCapacity <= capacity_) return;
    const uint64_t old = std::exchange(capacity_, newCapacity);
    release(old, newCapacity - old);  // joins a free tail
}

}  // namespace grotto
