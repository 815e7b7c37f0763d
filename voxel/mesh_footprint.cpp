// Counting a LiveMesh's memory without keeping it: two passes over the chunks, the
// first meshing them and listing the corners each chunk's neighbours weld to, the
// second welding and measuring each chunk on its own, then dropping it.
#include "voxel/mesh_footprint.h"

#include "voxel/watertight.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <atomic>
#include <bit>
#include <map>
#include <optional>

namespace grotto::voxel {
namespace {

// What a vector of `size` elements in room for `capacity` adds to the resident
// set: small ones their heap chunk; a large one is mapped on its own (glibc,
// from 128 KiB), and only the pages its elements were written to are resident.
template <class T>
uint64_t vectorBytes(uint64_t capacity, uint64_t size) {
    constexpr uint64_t kMapped = 128 << 10, kPage = 4096;
    if (capacity * sizeof(T) < kMapped) return heapBytes(capacity * sizeof(T));
    return (size * sizeof(T) + kPage - 1) / kPage * kPage;
}

// Capacity after push_back one at a time from empty (libstdc++ doubles from 1).
uint64_t grownCapacity(uint64_t size) { return size ? std::bit_ceil(size) : 0; }

// After reserve(reserved) then push_back up to size: doubling from the reserve.
uint64_t grownCapacity(uint64_t reserved, uint64_t size) {
    if (size <= reserved) return reserved;
    uint64_t c = std::max<uint64_t>(reserved, 1);
    while (c < size) c *= 2;
    return c;
}

MeshFootprint measure(const MeshChunkQuads& c) {
    MeshFootprint f;
    // In LiveMesh: a map node; rects as meshCells grew them, quads as weld grew them
    // from a reserve of the rects; the levels pushed back one by one.
    const uint64_t levels = c.coarser.size();
    f.liveBytes = heapBytes(32 + sizeof(std::pair<const glm::ivec3, MeshChunkQuads>)) +
                  vectorBytes<MeshLevel>(grownCapacity(levels), levels);
    // In list(): the chunk, and every vector copied at its size.
    f.listBytes = sizeof(MeshChunkQuads) + vectorBytes<MeshLevel>(levels, levels);
    auto level = [&](const std::vector<MeshQuad>& quads, const std::vector<gpu::PackedQuad>& rects) {
        const uint64_t q = quads.size(), r = rects.size();
        f.quads += q;
        f.liveBytes += vectorBytes<MeshQuad>(grownCapacity(r, q), q) + vectorBytes<gpu::PackedQuad>(grownCapacity(r), r);
        f.listBytes += vectorBytes<MeshQuad>(q, q) + vectorBytes<gpu::PackedQuad>(r, r);
    };
    level(c.quads, c.rects);
    for (const MeshLevel& l : c.coarser) level(l.quads, l.rects);
    return f;
}

MeshFootprint sum(MeshFootprint a, const MeshFootprint& b) {
    a.quads += b.quads;
    a.liveBytes += b.liveBytes;
    a.listBytes += b.listBytes;
    a.cornerBytes += b.cornerBytes;
    return a;
}

}  // namespace

uint64_t heapBytes(uint64_t bytes) { return bytes ? std::max<uint64_t>(32, (bytes + 8 + 15) & ~uint64_t(15)) : 0; }

MeshFootprint measureMesh(const LiveMesh& mesh) {
    MeshFootprint total;
    for (const auto& [origin, c] : mesh.chunks()) total = sum(total, measure(c));
    return total;
}

MeshFootprint countMeshFootprint(const World& world, const MeshOptions& options, uint64_t stopAbove) {
    const std::vector<glm::ivec3> origins = world.chunkOrigins();
    // What the chunks counted so far take at least, in either pass: past stopAbove, the rest is skipped.
    std::atomic<uint64_t> counted{0};
    auto stopped = [&] { return counted.load(std::memory_order_relaxed) > stopAbove; };
    // First pass: every chunk meshed and kept (its rectangles are counted, so
    // what is kept stays within stopAbove), with its boundary corners.
    std::vector<std::optional<MeshChunkQuads>> chunks(origins.size());
    std::vector<std::vector<glm::ivec3>> corners(origins.size());
    tbb::parallel_for(size_t(0), origins.size(), [&](size_t i) {
        if (stopped()) return;
        MeshChunkQuads c = world.meshChunk(origins[i], options);
        if (c.rects.empty()) return;
        corners[i] = boundaryCorners(c);
        auto bytes = [](const std::vector<gpu::PackedQuad>& r) {
            return vectorBytes<gpu::PackedQuad>(grownCapacity(r.size()), r.size()) + vectorBytes<gpu::PackedQuad>(r.size(), r.size());
        };
        counted += bytes(c.rects);
        for (const MeshLevel& l : c.coarser) counted += bytes(l.rects);
        chunks[i] = std::move(c);
    });
    if (stopped()) return {.liveBytes = counted, .complete = false};
    counted = 0;
    std::map<glm::ivec3, size_t, LiveMesh::Less> index;
    uint64_t cornerBytes = 0;
    for (size_t i = 0; i < origins.size(); ++i)
        if (chunks[i]) {
            index.emplace(origins[i], i);
            // Resident whole: this count's own corners, freed, are what LiveMesh's reuse.
            cornerBytes += sizeof(std::vector<glm::ivec3>) + heapBytes(corners[i].capacity() * sizeof(glm::ivec3));
        }
    // Second pass: each chunk welded to its neighbours as LiveMesh welds it,
    // measured and dropped.
    MeshFootprint total = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, origins.size()), MeshFootprint{},
        [&](const tbb::blocked_range<size_t>& range, MeshFootprint f) {
            for (size_t i = range.begin(); i != range.end() && !stopped(); ++i) {
                if (!chunks[i]) continue;
                MeshChunkQuads& c = *chunks[i];
                std::vector<ChunkBoundary> around;
                for (int k = 0; k < 27; ++k) {
                    const glm::ivec3 n = c.origin + kChunkEdge * glm::ivec3(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
                    if (const auto it = index.find(n); it != index.end()) around.push_back({n, &corners[it->second]});
                }
                weld(c, around);
                const MeshFootprint one = measure(c);
                chunks[i].reset();
                counted += one.liveBytes + one.listBytes;
                f = sum(f, one);
            }
            return f;
        },
        sum);
    total.cornerBytes = cornerBytes;
    total.complete = !stopped();
    return total;
}

}  // namespace grotto::voxel
