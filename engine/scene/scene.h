#pragma once
// The GPU copy of a voxel world: quads, chunk table and material palette.
// scene.cpp is the one bridge between voxel/ and engine/vk/.
#include "engine/scene/face_atlas.h"
#include "engine/scene/face_cache_gpu.h"
#include "engine/scene/occupancy.h"
#include "engine/scene/quad_slots.h"
#include "engine/scene/staged_uploads.h"
#include "engine/vk/resources.h"
#include "voxel/mesh.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace grotto {
namespace voxel {
struct WorldDesc;
class World;
}  // namespace voxel
class LiveFaceCache;

// A run of one face's quads in one 8^3 block of a chunk: what occlusion culling
// tests and draws as a unit. Bounds in voxels, relative to the chunk's corner.
struct QuadCluster {
    uint32_t first = 0, count = 0;  // in the vertex buffer, in quads
    glm::vec3 lo{0.0f}, hi{0.0f};
};

// One level of detail of a chunk: per-face quad ranges and their clusters.
struct GpuLevel {
    std::array<uint32_t, 6> faceFirst{}, faceCount{};
    std::array<uint32_t, 7> faceClusters{};  // face f's clusters: [faceClusters[f], faceClusters[f + 1])
    std::vector<QuadCluster> clusters;       // by face, nearest-first within a face as the mesher orders slices
    uint32_t quads() const;
};

struct GpuChunk {
    glm::dvec3 origin;            // world position of the chunk's corner
    glm::vec3 lo, hi;             // tight bounds of its quads at every level, relative to origin
    // [0]: the exact voxels; [L]: cells of 2^L voxels (voxel::MeshOptions::coarseLevels),
    // laid out one after another in the chunk's slot.
    std::vector<GpuLevel> levels;
    glm::ivec3 index{0};          // voxel index of its corner: the key updates find it by
    std::vector<uint32_t> atlasBoxes;   // its full-detail greedy rectangles' boxes (face_atlas.h)
    std::vector<uint32_t> atlasRectOf;  // each full-detail quad's rectangle, in vertex order
    uint32_t slotFirst = 0, slotQuads = 0;  // the range of the vertex buffer it owns, in quads
    const GpuLevel& exact() const { return levels.front(); }
};

// Quads become 4 packed vertices each (shaders/shared/quad.h); one shared index
// buffer (0 1 2 0 2 3, +4 per quad) serves every draw through its vertex offset.
// Each chunk owns a slot of the vertex buffer with room to spare (quad_slots.h),
// so a live world rewrites only the chunks an edit touched (updateChunks).
// Each part has one writer: the geometry, uploadScene and updateChunks; the
// occupancy, uploadScene(world) and updateOccupancy; the face cache, LiveFaceCache.
// The renderer asks its frame plan what the scene has (engine/frame/frame_plan.h).
class GpuScene {
public:
    explicit GpuScene(vk::Context& context) : ctx(context), uploads(context) {}
    ~GpuScene();  // releases the buffers
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    vk::Context& ctx;
    vk::Buffer vertices;
    vk::Buffer indices;
    vk::Buffer palette;                 // uniform buffer of GROTTO_PALETTE_VEC4S (shared/frame.h): albedo and AO, emission
    std::vector<glm::vec3> albedo;      // host copy of the palette, id k at [k - 1]
    std::vector<GpuChunk> chunks;       // ordered by index (x, then y, then z), as World::mesh() lists them
    double voxelSize = 1.0;
    glm::dvec3 worldOrigin{0.0};        // world position of voxel corner (0, 0, 0)
    uint64_t quadCount = 0;
    uint32_t indexQuads = 0;            // the longest draw the index buffer serves
    QuadSlots slots;                    // the vertex buffer's free and used quad ranges
    StagedUploads uploads;              // updates waiting for the next frame
    uint64_t stagedBytesLast = 0;       // staged by the last updateChunks
    uint64_t stagedBytesTotal = 0;      // staged by every updateChunks so far
    uint32_t vertexBufferGrowths = 0;   // times the vertex buffer was reallocated larger
    uint64_t updates = 0;               // updateChunks calls so far: the geometry changed
    // The solid voxels for rays (sun shadows, voxel-traced AO); null for a scene
    // uploaded from a mesh alone, which renders without them.
    const GpuOccupancy* occupancy() const { return occupancy_.get(); }
    // The AO cache's light on the exposed faces; null until a bake is loaded or
    // made (engine/scene/live_face_cache.h makes it and keeps it in step with edits).
    const GpuFaceCache* faceCache() const { return faceCache_.get(); }

    // Replaces the quads of `replaced` chunks (new ones are added; one without
    // quads is removed) and removes the chunks at `removed` (voxel indices of their
    // corners; unknown ones are ignored). Only these chunks' vertices are staged;
    // recordUploads copies them into place in the next frame's command buffer.
    // The host chunk table changes at once. Throws grotto::Error (internal) for a
    // chunk whose face counts do not add up to its quads.
    void updateChunks(std::span<const voxel::MeshChunkQuads> replaced, std::span<const glm::ivec3> removed);
    // The occupancy after an edit of `world` within `changed` (voxels), staged like the chunks.
    void updateOccupancy(const voxel::World& world, const voxel::IndexBox& changed);
    // Records the staged copies through `staging` (StagedUploads::record) and a
    // barrier to vertex input; the renderer calls it first in every frame's command
    // buffer, with its frame slot's staging. Nothing when nothing is staged.
    void recordUploads(VkCommandBuffer cmd, vk::Buffer& staging);
    bool uploadsPending() const { return uploads.pending(); }
    const GpuChunk* findChunk(glm::ivec3 index) const;

    size_t gpuBytes() const {
        return size_t(vertices.size + indices.size + palette.size) +
               (occupancy_ ? occupancy_->gpuBytes() : 0) + (faceCache_ ? faceCache_->gpuBytes() : 0) + faceAtlasBytes();
    }

    // The face cache laid out for reading (face_atlas.h), written by LiveFaceCache
    // with the cache. layFaceAtlas places every chunk's regions at k texels a side
    // (kept across edits: updateChunks re-places the chunks it rewrites);
    // fillFaceAtlas writes each quad's record, parallel to the vertex
    // buffer, and the cells from the cache's arrays, on every core (no frame may be
    // in flight). The atlas is current from a fill until the geometry changes or
    // staleFaceAtlas; only a current one is read.
    void layFaceAtlas(uint32_t texelsPerSide);
    void fillFaceAtlas(const voxel::FaceCacheArrays& arrays);
    void staleFaceAtlas() { atlasCurrent_ = false; }
    bool faceAtlasCurrent() const { return atlasCurrent_; }
    const vk::Buffer& faceAtlasRecords() const { return atlasRecords_; }  // uvec2 a vertex-buffer quad
    const vk::Buffer& faceAtlasCells() const { return atlasCells_; }      // uvec2 a cell
    const FaceAtlasLayout* faceAtlasLayout() const { return atlasLayout_.get(); }
    size_t faceAtlasBytes() const { return size_t(atlasRecords_.size + atlasCells_.size); }
    size_t hostBytes() const;

private:
    friend std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, std::span<const voxel::MeshChunkQuads> chunks,
                                                 const voxel::World& world);
    friend class LiveFaceCache;  // writes faceCache_ alone
    std::unique_ptr<GpuOccupancy> occupancy_;
    std::unique_ptr<GpuFaceCache> faceCache_;
    std::unique_ptr<FaceAtlasLayout> atlasLayout_;
    vk::Buffer atlasRecords_, atlasCells_;
    bool atlasCurrent_ = false;
};

// From chunks as a voxel::LiveMesh keeps them (with their coarser levels, if any).
std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, std::span<const voxel::MeshChunkQuads> chunks,
                                      double voxelSize, glm::dvec3 worldOrigin, const voxel::WorldDesc& desc);
// A mesh's chunks, as a voxel::LiveMesh keeps them (no coarser levels): a copy.
std::vector<voxel::MeshChunkQuads> meshChunks(const voxel::Mesh& mesh);
// A mesh alone: the exact voxels only, no levels of detail.
std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc);
// The world's mesh with its levels of detail, and its occupancy: what rendering
// with sun shadows and voxel-traced AO needs.
std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::World& world);
// The same from the world's chunks as a voxel::LiveMesh keeps them.
std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, std::span<const voxel::MeshChunkQuads> chunks,
                                      const voxel::World& world);

// What uploadScene would allocate for these buffers (the vertex buffer with its
// spare room, before allocator rounding), without a device: for `grotto info`.
size_t sceneBufferBytes(std::span<const voxel::MeshChunkQuads> chunks);
size_t sceneBufferBytes(const voxel::Mesh& mesh);
// What the face cache's atlas at k texels a side would allocate for these chunks
// (GpuScene::fillFaceAtlas: its cells and its records), without a device: for `grotto info`.
size_t faceAtlasBufferBytes(std::span<const voxel::MeshChunkQuads> chunks, uint32_t texelsPerSide);
// A level's clusters of each face, as uploadScene makes them: one for each block its quads lie in.
std::array<uint32_t, 6> faceClusters(const std::array<uint32_t, 6>& faceCount, std::span<const voxel::MeshQuad> quads);
// What uploadScene keeps in host memory beside them (the chunks, their levels and
// clusters), at the capacities they grow to.
size_t sceneHostBytes(std::span<const voxel::MeshChunkQuads> chunks);

}  // namespace grotto
