#include "voxel/face_brick_table.h"

#define GROTTO_FACE_CACHE_LAYOUT_ONLY
#include "shaders/shared/face_cache.h"

#include "grotto/error.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace grotto::voxel {

namespace {

// About four bricks a bucket, a power of two.
uint32_t bucketBits(size_t bricks) { return uint32_t(std::bit_width(std::bit_ceil(std::max<size_t>((bricks + 3) / 4, 1)) - 1)); }

// At most 8/9 full: the last buckets, placed when most slots are taken, find a
// seed within about nine tries.
size_t slotCount(size_t bricks) { return bricks + bricks / 8 + 1; }

}  // namespace

size_t faceBrickTableBytes(size_t bricks) { return 16 * slotCount(bricks) + 4 * (size_t(1) << bucketBits(bricks)); }

FaceBrickTable layFaceBrickTable(std::span<const glm::ivec3> bricks) {
    const uint32_t bits = bucketBits(bricks.size());
    const uint32_t buckets = 1u << bits;
    const size_t slots = slotCount(bricks.size());
    if (slots >= (size_t(1) << 27))
        throw Error("face cache", std::to_string(bricks.size()) + " bricks with exposed faces, more than its table holds",
                    "split the world, or render it with another --ao");
    std::vector<std::vector<uint32_t>> members(buckets);
    for (uint32_t i = 0; i < bricks.size(); ++i) {
        const glm::ivec3 b = bricks[i];
        members[gpu::faceCacheBucket(b.x, b.y, b.z, buckets - 1)].push_back(i);
    }
    std::vector<uint32_t> order(buckets);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return members[a].size() > members[b].size(); });

    FaceBrickTable t;
    t.shape = uint32_t(slots << 5) | bits;
    t.slots.assign(slots, glm::uvec4(0));
    t.seeds.assign(buckets, 0u);
    std::vector<bool> taken(slots, false);
    std::vector<uint32_t> placed;
    for (uint32_t bucket : order) {
        const std::vector<uint32_t>& m = members[bucket];
        if (m.empty()) break;
        for (uint32_t seed = 0;; ++seed) {
            if (seed == (1u << 24))
                throw Error::internal("face cache", "no seed places bucket " + std::to_string(bucket) + "'s bricks");
            placed.clear();
            for (uint32_t i : m) {
                const glm::ivec3 b = bricks[i];
                const uint32_t s = gpu::faceCacheSlot(b.x, b.y, b.z, seed, uint32_t(slots));
                if (taken[s] || std::find(placed.begin(), placed.end(), s) != placed.end()) break;
                placed.push_back(s);
            }
            if (placed.size() < m.size()) continue;
            for (size_t j = 0; j < m.size(); ++j) {
                const glm::ivec3 b = bricks[m[j]];
                taken[placed[j]] = true;
                t.slots[placed[j]] = glm::uvec4(uint32_t(b.x), uint32_t(b.y), uint32_t(b.z), m[j] + 1);
            }
            t.seeds[bucket] = seed;
            break;
        }
    }
    return t;
}

}  // namespace grotto::voxel
