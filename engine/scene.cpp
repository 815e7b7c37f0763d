#include "engine/scene.h"

#include "common/error.h"
#include "voxel/mesh.h"
#include "voxel/world_desc.h"
#include "shaders/shared/frame.h"

#include <algorithm>
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

// The longest run of quads one draw covers: the shared index buffer's length.
uint32_t largestDraw(const voxel::Mesh& mesh) {
    uint32_t n = 1;
    for (const voxel::MeshChunk& c : mesh.chunks)
        for (uint32_t f = 0; f < 6; ++f) n = std::max(n, c.faceCount[f]);
    return n;
}

std::vector<uint32_t> indexData(uint32_t quads) {
    std::vector<uint32_t> indices;
    indices.reserve(6 * size_t(quads));
    for (uint32_t q = 0; q < quads; ++q)
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(4 * q + i);
    return indices;
}

uint64_t slotTotal(const voxel::Mesh& mesh) {
    uint64_t total = 0;
    for (const voxel::MeshChunk& c : mesh.chunks) total += slotQuads(c.quadCount());
    return total;
}

void requireQuadRange(uint64_t quads) {
    if (quads > kMaxQuads)
        throw Error::internal("GPU scene", "the vertex buffer would need " + std::to_string(quads) + " quads",
                              "at most " + std::to_string(kMaxQuads) + " fit the draws' vertex offsets");
}

// One chunk in its slot: face ranges, tight bounds, and its quads packed into
// `vertices` (4 per quad, in face order).
GpuChunk placeChunk(glm::ivec3 index, const std::array<uint32_t, 6>& faceCount,
                    std::span<const gpu::PackedQuad> quads, const GpuScene& scene, uint32_t slotFirst,
                    uint32_t slotQuads, uint32_t* vertices) {
    static const voxel::Mesh geometry;  // corners() needs only the chunk and the quad
    voxel::MeshChunk mc;
    mc.origin = index;
    GpuChunk g;
    g.index = index;
    g.origin = scene.worldOrigin + glm::dvec3(index) * scene.voxelSize;
    g.slotFirst = slotFirst;
    g.slotQuads = slotQuads;
    glm::ivec3 lo(GROTTO_CHUNK_SIZE), hi(0);
    uint32_t first = slotFirst, q = 0;
    for (int f = 0; f < 6; ++f) {
        g.faceFirst[f] = first;
        g.faceCount[f] = faceCount[f];
        for (uint32_t end = q + faceCount[f]; q < end; ++q) {
            const gpu::PackedQuad quad = quads[q];
            for (const glm::ivec3& v : geometry.corners(mc, quad)) {
                const glm::ivec3 p = v - index;
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                *vertices++ = gpu::packVertex(uint32_t(p.x), uint32_t(p.y), uint32_t(p.z), gpu::quadFace(quad.bits),
                                              quad.material);
            }
        }
        first += faceCount[f];
    }
    g.lo = glm::vec3(lo) * float(scene.voxelSize);
    g.hi = glm::vec3(hi) * float(scene.voxelSize);
    return g;
}

}  // namespace

size_t sceneBufferBytes(const voxel::Mesh& mesh) {
    return bufferQuads(slotTotal(mesh)) * kQuadBytes + size_t(largestDraw(mesh)) * kIndexQuadBytes +
           GROTTO_MAX_MATERIALS * sizeof(glm::vec4);
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc) {
    auto scene = std::make_unique<GpuScene>(ctx);
    GpuScene& s = *scene;
    s.voxelSize = mesh.voxelSize;
    s.worldOrigin = mesh.origin;
    s.quadCount = mesh.quads.size();
    // Chunks by index, as updates keep them (World::mesh() lists them so already).
    std::vector<size_t> order(mesh.chunks.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return indexLess(mesh.chunks[a].origin, mesh.chunks[b].origin); });
    const uint64_t capacity = bufferQuads(slotTotal(mesh));
    requireQuadRange(capacity);
    s.slots = QuadSlots(capacity);
    std::vector<uint32_t> vertices(4 * capacity, 0u);  // spare room zeroed: never drawn
    s.chunks.reserve(mesh.chunks.size());
    for (size_t i : order) {
        const voxel::MeshChunk& c = mesh.chunks[i];
        const uint32_t n = c.quadCount(), size = slotQuads(n);
        const uint32_t first = uint32_t(*s.slots.allocate(size));  // consecutive: the buffer was sized for them all
        const std::span<const gpu::PackedQuad> quads(mesh.quads.data() + c.firstQuad, n);
        s.chunks.push_back(placeChunk(c.origin, c.faceCount, quads, s, first, size, vertices.data() + 4 * size_t(first)));
    }
    s.vertices = vk::uploadBuffer(ctx, vertices.data(), vertices.size() * sizeof(uint32_t),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    s.indexQuads = largestDraw(mesh);
    const std::vector<uint32_t> indices = indexData(s.indexQuads);
    s.indices = vk::uploadBuffer(ctx, indices.data(), indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    // The whole palette range the shaders declare, unused entries black.
    std::vector<glm::vec4> palette(GROTTO_MAX_MATERIALS, glm::vec4(0.0f));
    for (size_t i = 0; i < desc.materials.size() && i < palette.size(); ++i)
        palette[i] = glm::vec4(desc.materials[i].albedo, desc.materials[i].ao);
    for (const voxel::Material& m : desc.materials) s.albedo.push_back(m.albedo);
    s.palette = vk::uploadBuffer(ctx, palette.data(), palette.size() * sizeof(glm::vec4),
                                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    return scene;
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::World& world) {
    auto scene = uploadScene(ctx, world.mesh(), world.desc());
    scene->occupancy = std::make_unique<GpuOccupancy>(ctx, world);
    return scene;
}

const GpuChunk* GpuScene::findChunk(glm::ivec3 index) const {
    const auto it = std::lower_bound(chunks.begin(), chunks.end(), index,
                                     [](const GpuChunk& c, const glm::ivec3& i) { return indexLess(c.index, i); });
    return it != chunks.end() && it->index == index ? &*it : nullptr;
}

void GpuScene::updateChunks(std::span<const voxel::MeshChunkQuads> replaced, std::span<const glm::ivec3> removed) {
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
        freeSlot(*it);
        quadCount -= quadsOf(it->faceCount);
        chunks.erase(it);
    };
    for (const glm::ivec3& index : removed) remove(index);

    uint64_t staged = 0;
    uint32_t longest = 0;
    std::vector<uint32_t> words;
    for (const voxel::MeshChunkQuads& q : replaced) {
        const uint32_t n = quadsOf(q.faceCount);
        if (n != q.quads.size())
            throw Error::internal("GpuScene::updateChunks",
                                  "chunk at voxel (" + std::to_string(q.origin.x) + " " + std::to_string(q.origin.y) +
                                      " " + std::to_string(q.origin.z) + ") has " + std::to_string(q.quads.size()) +
                                      " quads but face counts adding up to " + std::to_string(n));
        if (n == 0) {
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
        const GpuChunk g = placeChunk(q.origin, q.faceCount, q.quads, *this, first, size, words.data());
        uploads.write(vertices, first * kQuadBytes, words.data(), n * kQuadBytes);
        staged += n * kQuadBytes;
        quadCount += n;
        if (known) {
            quadCount -= quadsOf(it->faceCount);
            *it = g;
        } else {
            chunks.insert(it, g);
        }
        longest = std::max(longest, *std::max_element(q.faceCount.begin(), q.faceCount.end()));
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

void GpuScene::recordUploads(VkCommandBuffer cmd) {
    // The occupancy's buffers are read by the passes that trace rays.
    uploads.record(cmd, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
}

GpuScene::~GpuScene() {
    occupancy.reset();
    vk::destroy(ctx, vertices);
    vk::destroy(ctx, indices);
    vk::destroy(ctx, palette);
}

}  // namespace grotto
