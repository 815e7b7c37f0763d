#include "engine/scene/scene.h"

#include "engine/scene/face_atlas.h"
#include "engine/scene/scene_memory.h"

#include "grotto/error.h"
#include "voxel/live_mesh.h"
#include "voxel/mesh_footprint.h"
#include "voxel/mesh.h"
#include "voxel/world_desc.h"
#include "shaders/shared/frame.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <numeric>
#include <string>

namespace grotto {

namespace {

constexpr VkDeviceSize kQuadBytes = 4 * sizeof(uint32_t);  // four packed vertices
constexpr VkDeviceSize kIndexQuadBytes = 6 * sizeof(uint32_t);

// Draws reach a quad through a signed 32-bit vertex offset.
constexpr uint64_t kMaxQuads = uint64_t(INT32_MAX) / 4;

bool indexLess(const glm::ivec3& a, const glm::ivec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

uint32_t quadsOf(const std::array<uint32_t, 6>& faceCount) {
    return std::accumulate(faceCount.begin(), faceCount.end(), 0u);
}

// Every level's quads of a chunk: what its slot holds.
uint32_t slotContent(const voxel::MeshChunkQuads& c) {
    uint32_t n = uint32_t(c.quads.size());
    for (const voxel::MeshLevel& l : c.coarser) n += uint32_t(l.quads.size());
    return n;
}

// The longest run of quads one draw covers: the shared index buffer's length.
uint32_t longestFace(const voxel::MeshChunkQuads& c) {
    uint32_t n = *std::max_element(c.faceCount.begin(), c.faceCount.end());
    for (const voxel::MeshLevel& l : c.coarser) n = std::max(n, *std::max_element(l.faceCount.begin(), l.faceCount.end()));
    return n;
}

uint32_t largestDraw(std::span<const voxel::MeshChunkQuads> chunks) {
    uint32_t n = 1;
    for (const voxel::MeshChunkQuads& c : chunks) n = std::max(n, longestFace(c));
    return n;
}

std::vector<uint32_t> indexData(uint32_t quads) {
    std::vector<uint32_t> indices;
    indices.reserve(6 * size_t(quads));
    for (uint32_t q = 0; q < quads; ++q)
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(4 * q + i);
    return indices;
}

uint64_t slotTotal(std::span<const voxel::MeshChunkQuads> chunks) {
    uint64_t total = 0;
    for (const voxel::MeshChunkQuads& c : chunks) total += slotQuads(slotContent(c));
    return total;
}

void requireQuadRange(uint64_t quads) {
    if (quads > kMaxQuads)
        throw Error::internal("GPU scene", "the vertex buffer would need " + std::to_string(quads) + " quads",
                              "at most " + std::to_string(kMaxQuads) + " fit the draws' vertex offsets");
}

void requireFaceCounts(const voxel::MeshChunkQuads& q) {
    bool ok = quadsOf(q.faceCount) == q.quads.size();
    for (const voxel::MeshLevel& l : q.coarser) ok = ok && quadsOf(l.faceCount) == l.quads.size();
    if (!ok)
        throw Error::internal("GpuScene::updateChunks",
                              "chunk at voxel (" + std::to_string(q.origin.x) + " " + std::to_string(q.origin.y) + " " +
                                  std::to_string(q.origin.z) + ") has a level whose face counts do not add up to its quads");
}

// Quads of one face in cluster order: by 8^3 block, blocks nearest-first along the
// face's axis as the mesher orders slices (each block keeps the mesher's order).
constexpr int kClusterShift = 3;

// The block of the voxel behind the quad's lowest corner.
int blockOf(const voxel::MeshQuad& q) {
    glm::ivec3 lo = q.corner(0);
    for (int i = 1; i < 4; ++i) lo = glm::min(lo, q.corner(i));
    if (gpu::facePositive(q.face())) lo[int(gpu::faceAxis(q.face()))] -= 1;
    int b = 0;
    for (int axis = 0; axis < 3; ++axis) b |= (lo[axis] >> kClusterShift) << (2 * axis);
    return b;
}

// The block order of face f: its axis first (descending for + faces), then the others.
int blockRank(int block, uint32_t f) {
    const uint32_t a = gpu::faceAxis(f);
    int along = (block >> (2 * a)) & 3;
    if (gpu::facePositive(f)) along = 3 - along;
    return along << 4 | (block & ~(3 << (2 * a)));
}

// Face f's quads, [q, q + count) of a level, in cluster order: a stable counting
// sort over the 64 ranks, each quad's block found once (a comparison sort found
// it twice a comparison, and an edit's chunk updates spent most of their time there).
std::vector<uint32_t> clusterOrder(std::span<const voxel::MeshQuad> quads, uint32_t q, uint32_t count, uint32_t f) {
    constexpr int kRanks = 64;  // blockRank's values: 6 bits
    std::vector<uint8_t> rank(count);
    std::array<uint32_t, kRanks + 1> start{};
    for (uint32_t k = 0; k < count; ++k) {
        rank[k] = uint8_t(blockRank(blockOf(quads[q + k]), f));
        ++start[size_t(rank[k]) + 1];
    }
    for (int r = 0; r < kRanks; ++r) start[size_t(r) + 1] += start[size_t(r)];
    std::vector<uint32_t> order(count);
    for (uint32_t k = 0; k < count; ++k) order[start[rank[k]]++] = q + k;
    return order;
}

// One level of a chunk written at `first` in the vertex buffer (`vertices` points
// there): face ranges, clusters, and the level's bounds grown into lo/hi.
GpuLevel placeLevel(const std::array<uint32_t, 6>& faceCount, std::span<const voxel::MeshQuad> quads, uint32_t first,
                    uint32_t* vertices, glm::ivec3& lo, glm::ivec3& hi) {
    GpuLevel g;
    uint32_t q = 0;
    for (uint32_t f = 0; f < 6; ++f) {
        g.faceFirst[f] = first;
        g.faceCount[f] = faceCount[f];
        g.faceClusters[f] = uint32_t(g.clusters.size());
        const std::vector<uint32_t> order = clusterOrder(quads, q, faceCount[f], f);
        int block = -1;
        for (uint32_t k = 0; k < order.size(); ++k) {
            const voxel::MeshQuad& quad = quads[order[k]];
            if (blockOf(quad) != block) {
                block = blockOf(quad);
                g.clusters.push_back({.first = first + k, .count = 0, .lo = glm::vec3(GROTTO_CHUNK_SIZE), .hi = glm::vec3(0.0f)});
            }
            QuadCluster& cluster = g.clusters.back();
            ++cluster.count;
            for (int i = 0; i < 4; ++i) {
                const glm::ivec3 p = quad.corner(i);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                cluster.lo = glm::min(cluster.lo, glm::vec3(p));
                cluster.hi = glm::max(cluster.hi, glm::vec3(p));
                *vertices++ = quad.corners[size_t(i)];
            }
        }
        q += faceCount[f];
        first += faceCount[f];
    }
    g.faceClusters[6] = uint32_t(g.clusters.size());
    return g;
}

// One chunk in its slot, every level one after another: its levels, tight bounds,
// and its quads packed into `vertices` (4 per quad).
GpuChunk placeChunk(const voxel::MeshChunkQuads& c, const GpuScene& scene, uint32_t slotFirst, uint32_t slotQuads,
                    uint32_t* vertices) {
    GpuChunk g;
    g.index = c.origin;
    g.origin = scene.worldOrigin + glm::dvec3(c.origin) * scene.voxelSize;
    g.slotFirst = slotFirst;
    g.slotQuads = slotQuads;
    glm::ivec3 lo(GROTTO_CHUNK_SIZE), hi(0);
    uint32_t first = slotFirst;
    g.levels.push_back(placeLevel(c.faceCount, c.quads, first, vertices, lo, hi));
    first += uint32_t(c.quads.size());
    for (const voxel::MeshLevel& l : c.coarser) {
        g.levels.push_back(placeLevel(l.faceCount, l.quads, first, vertices + 4 * size_t(first - slotFirst), lo, hi));
        first += uint32_t(l.quads.size());
    }
    // The full-detail rectangles' boxes, and each full-detail quad's (in the order
    // its vertices were written). A mesh without its rectangles has no atlas.
    if (!c.rects.empty()) {
        g.atlasBoxes.reserve(c.rects.size());
        for (const gpu::PackedQuad& r : c.rects) g.atlasBoxes.push_back(packAtlasBox(r));
        g.atlasRectOf = atlasRectsOf(c.rects, {vertices, 4 * c.quads.size()});
    }
    g.lo = glm::vec3(lo) * float(scene.voxelSize);
    g.hi = glm::vec3(hi) * float(scene.voxelSize);
    return g;
}


}  // namespace

std::vector<voxel::MeshChunkQuads> meshChunks(const voxel::Mesh& mesh) {
    std::vector<voxel::MeshChunkQuads> chunks;
    chunks.reserve(mesh.chunks.size());
    for (const voxel::MeshChunk& c : mesh.chunks)
        chunks.push_back({.origin = c.origin, .faceCount = c.faceCount,
                          .quads = std::vector<voxel::MeshQuad>(mesh.quads.begin() + c.firstQuad,
                                                                mesh.quads.begin() + c.firstQuad + c.quadCount())});
    return chunks;
}

uint32_t GpuLevel::quads() const { return quadsOf(faceCount); }

size_t GpuScene::hostBytes() const {
    size_t n = chunks.size() * sizeof(GpuChunk);
    for (const GpuChunk& c : chunks) {
        for (const GpuLevel& l : c.levels) n += sizeof(GpuLevel) + l.clusters.size() * sizeof(QuadCluster);
        n += (c.atlasBoxes.capacity() + c.atlasRectOf.capacity()) * sizeof(uint32_t);
    }
    return n + uploads.pendingBytes() + (occupancy_ ? occupancy_->hostBytes() : 0);
}

size_t sceneBufferBytes(std::span<const voxel::MeshChunkQuads> chunks) {
    return bufferQuads(slotTotal(chunks)) * kQuadBytes + size_t(largestDraw(chunks)) * kIndexQuadBytes +
           GROTTO_PALETTE_VEC4S * sizeof(glm::vec4);
}

size_t sceneBufferBytes(const voxel::Mesh& mesh) { return sceneBufferBytes(meshChunks(mesh)); }

size_t faceAtlasBufferBytes(std::span<const voxel::MeshChunkQuads> chunks, uint32_t texelsPerSide) {
    FaceAtlasLayout layout(texelsPerSide);
    std::vector<uint32_t> boxes;
    for (const voxel::MeshChunkQuads& c : chunks) {
        boxes.clear();
        for (const gpu::PackedQuad& r : c.rects) boxes.push_back(packAtlasBox(r));
        layout.place(c.origin, boxes);
    }
    return (layout.capacity() + bufferQuads(slotTotal(chunks))) * sizeof(glm::uvec2);  // cells, and a record a quad
}

namespace {

uint64_t levelClusters(const std::array<uint32_t, 6>& faceCount, std::span<const voxel::MeshQuad> quads) {
    uint64_t clusters = 0;
    for (uint32_t n : faceClusters(faceCount, quads)) clusters += n;
    return clusters;
}

}  // namespace

std::array<uint32_t, 6> faceClusters(const std::array<uint32_t, 6>& faceCount, std::span<const voxel::MeshQuad> quads) {
    std::array<uint32_t, 6> clusters{};
    uint32_t q = 0;
    for (uint32_t f = 0; f < 6; ++f) {
        int block = -1;  // a cluster starts wherever the block changes in cluster order, as placeLevel makes them
        for (uint32_t k : clusterOrder(quads, q, faceCount[f], f)) {
            const int b = blockOf(quads[k]);
            clusters[f] += b != block;
            block = b;
        }
        q += faceCount[f];
    }
    return clusters;
}

size_t sceneHostBytes(std::span<const voxel::MeshChunkQuads> chunks) {
    // Each level's clusters pushed back one by one.
    auto level = [](const std::array<uint32_t, 6>& faceCount, std::span<const voxel::MeshQuad> quads) {
        return voxel::heapBytes(std::bit_ceil(levelClusters(faceCount, quads)) * sizeof(QuadCluster));
    };
    size_t n = voxel::heapBytes(chunks.size() * sizeof(GpuChunk));
    for (const voxel::MeshChunkQuads& c : chunks) {
        if (c.quads.empty()) continue;
        n += voxel::heapBytes(std::bit_ceil(1 + c.coarser.size()) * sizeof(GpuLevel)) + level(c.faceCount, c.quads);
        // The face atlas's rectangles and each quad's (GpuChunk::atlasBoxes, atlasRectOf).
        if (!c.rects.empty()) n += voxel::heapBytes(c.rects.size() * 4) + voxel::heapBytes(c.quads.size() * 4);
        for (const voxel::MeshLevel& l : c.coarser) n += level(l.faceCount, l.quads);
    }
    return n;
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, std::span<const voxel::MeshChunkQuads> chunks,
                                      double voxelSize, glm::dvec3 worldOrigin, const voxel::WorldDesc& desc) {
    auto scene = std::make_unique<GpuScene>(ctx);
    GpuScene& s = *scene;
    s.voxelSize = voxelSize;
    s.worldOrigin = worldOrigin;
    // Chunks by index, as updates keep them.
    std::vector<size_t> order;
    for (size_t i = 0; i < chunks.size(); ++i) {
        requireFaceCounts(chunks[i]);
        if (!chunks[i].quads.empty()) order.push_back(i);
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return indexLess(chunks[a].origin, chunks[b].origin); });
    const uint64_t capacity = bufferQuads(slotTotal(chunks));
    requireQuadRange(capacity);
    s.slots = QuadSlots(capacity);
    s.chunks.reserve(order.size());
    // Packed straight into the staging buffer: no third copy of the vertices at the peak.
    s.vertices = vk::uploadBuffer(ctx, 4 * capacity * sizeof(uint32_t),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, [&](void* staging) {
        uint32_t* vertices = static_cast<uint32_t*>(staging);
        std::fill(vertices, vertices + 4 * capacity, 0u);  // spare room zeroed: never drawn
        for (size_t i : order) {
            const voxel::MeshChunkQuads& c = chunks[i];
            const uint32_t size = slotQuads(slotContent(c));
            const uint32_t first = uint32_t(*s.slots.allocate(size));  // consecutive: the buffer was sized for them all
            s.chunks.push_back(placeChunk(c, s, first, size, vertices + 4 * size_t(first)));
            s.quadCount += c.quads.size();
        }
    });
    s.indexQuads = largestDraw(chunks);
    const std::vector<uint32_t> indices = indexData(s.indexQuads);
    s.indices = vk::uploadBuffer(ctx, indices.data(), indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    // The whole palette range the shaders declare, unused entries black.
    std::vector<glm::vec4> palette(GROTTO_PALETTE_VEC4S, glm::vec4(0.0f));
    for (size_t i = 0; i < desc.materials.size() && i < GROTTO_MAX_MATERIALS; ++i) {
        palette[2 * i] = glm::vec4(desc.materials[i].albedo, desc.materials[i].ao);
        palette[2 * i + 1] = glm::vec4(desc.materials[i].emission(), 0.0f);
    }
    for (const voxel::Material& m : desc.materials) s.albedo.push_back(m.albedo);
    s.palette = vk::uploadBuffer(ctx, palette.data(), palette.size() * sizeof(glm::vec4),
                                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    return scene;
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc) {
    return uploadScene(ctx, meshChunks(mesh), mesh.voxelSize, mesh.origin, desc);
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::World& world) {
    return uploadScene(ctx, voxel::LiveMesh(world, {.coarseLevels = voxel::kMaxCoarseLevels}).take(), world);
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, std::span<const voxel::MeshChunkQuads> chunks,
                                      const voxel::World& world) {
    auto scene = uploadScene(ctx, chunks, world.voxelSize(), world.origin(), world.desc());
    scene->occupancy_ = std::make_unique<GpuOccupancy>(ctx, world);
    return scene;
}

void GpuScene::updateOccupancy(const voxel::World& world, const voxel::IndexBox& changed) {
    occupancy_->update(world, changed, uploads);
}

const GpuChunk* GpuScene::findChunk(glm::ivec3 index) const {
    const auto it = std::lower_bound(chunks.begin(), chunks.end(), index,
                                     [](const GpuChunk& c, const glm::ivec3& i) { return indexLess(c.index, i); });
    return it != chunks.end() && it->index == index ? &*it : nullptr;
}

void GpuScene::updateChunks(std::span<const voxel::MeshChunkQuads> replaced, std::span<const glm::ivec3> removed) {
    ++updates;
    atlasCurrent_ = false;  // its records and cells: until the next fill
    auto find = [&](glm::ivec3 index) {
        return std::lower_bound(chunks.begin(), chunks.end(), index,
                                [](const GpuChunk& c, const glm::ivec3& i) { return indexLess(c.index, i); });
    };
    // A slot given up may be reused in this same update: its pending data goes too.
    auto freeSlot = [&](const GpuChunk& c) {
        slots.release(c.slotFirst, c.slotQuads);
        uploads.discard(vertices, c.slotFirst * kQuadBytes, c.slotQuads * kQuadBytes);
    };
    auto remove = [&](glm::ivec3 index) {
        const auto it = find(index);
        if (it == chunks.end() || it->index != index) return;
        if (atlasLayout_) atlasLayout_->remove(index);
        freeSlot(*it);
        quadCount -= it->exact().quads();
        chunks.erase(it);
    };
    for (const glm::ivec3& index : removed) remove(index);

    uint64_t staged = 0;
    uint32_t longest = 0;
    std::vector<uint32_t> words;
    for (const voxel::MeshChunkQuads& q : replaced) {
        requireFaceCounts(q);
        const uint32_t n = slotContent(q);
        if (q.quads.empty()) {
            remove(q.origin);
            continue;
        }
        auto it = find(q.origin);
        const bool known = it != chunks.end() && it->index == q.origin;
        uint32_t first, size;
        if (known && n <= it->slotQuads) {  // rewritten in place
            first = it->slotFirst;
            size = it->slotQuads;
            uploads.discard(vertices, first * kQuadBytes, size * kQuadBytes);
        } else {  // a new chunk, or one that outgrew its slot: a new slot
            if (known) freeSlot(*it);
            size = slotQuads(n);
            std::optional<uint64_t> slot = slots.allocate(size);
            if (!slot) {
                // Rare: no free range is long enough. A larger buffer takes the old
                // contents by a GPU copy in the next frame (StagedUploads::reallocate);
                // the old buffer is freed once that frame has finished.
                const uint64_t capacity = grownQuads(slots.capacity(), size);
                requireQuadRange(capacity);
                uploads.reallocate(vertices, capacity * kQuadBytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true);
                slots.grow(capacity);
                ++vertexBufferGrowths;
                slot = slots.allocate(size);
            }
            first = uint32_t(*slot);
        }
        words.resize(4 * size_t(n));
        const GpuChunk g = placeChunk(q, *this, first, size, words.data());
        uploads.write(vertices, first * kQuadBytes, words.data(), n * kQuadBytes);
        staged += n * kQuadBytes;
        quadCount += q.quads.size();
        if (atlasLayout_) atlasLayout_->place(g.index, g.atlasBoxes);
        if (known) {
            quadCount -= it->exact().quads();
            *it = g;
        } else {
            chunks.insert(it, g);
        }
        longest = std::max(longest, longestFace(q));
    }
    if (longest > indexQuads) {  // a draw longer than the index buffer: a longer one, written whole
        indexQuads = std::max(longest, indexQuads + indexQuads / 2);
        const std::vector<uint32_t> data = indexData(indexQuads);
        const VkDeviceSize bytes = data.size() * sizeof(uint32_t);
        uploads.reallocate(indices, bytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, false);
        uploads.write(indices, 0, data.data(), bytes);
        staged += bytes;
    }
    stagedBytesLast = staged;
    stagedBytesTotal += staged;
}

void GpuScene::recordUploads(VkCommandBuffer cmd, vk::Buffer& staging) {
    // The occupancy's buffers are read by the passes that trace rays.
    uploads.record(cmd, staging, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
}

GpuScene::~GpuScene() {
    occupancy_.reset();
    vk::destroy(ctx, atlasRecords_);
    vk::destroy(ctx, atlasCells_);
    vk::destroy(ctx, vertices);
    vk::destroy(ctx, indices);
    vk::destroy(ctx, palette);
}

}  // namespace grotto
