#include "engine/scene.h"

#include "voxel/mesh.h"

#include <algorithm>
#include "voxel/world_desc.h"
#include "shaders/shared/frame.h"

namespace grotto {

namespace {

// The longest run of quads one draw covers: the shared index buffer's length.
uint32_t largestDraw(const voxel::Mesh& mesh) {
    uint32_t n = 1;
    for (const voxel::MeshChunk& c : mesh.chunks)
        for (uint32_t f = 0; f < 6; ++f) n = std::max(n, c.faceCount[f]);
    return n;
}

}  // namespace

size_t sceneBufferBytes(const voxel::Mesh& mesh) {
    return mesh.quads.size() * 4 * sizeof(uint32_t) + size_t(largestDraw(mesh)) * 6 * sizeof(uint32_t) +
           GROTTO_MAX_MATERIALS * sizeof(glm::vec4);
}

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc) {
    auto scene = std::make_unique<GpuScene>(ctx);
    GpuScene& s = *scene;
    s.voxelSize = mesh.voxelSize;
    s.quadCount = mesh.quads.size();
    s.chunks.reserve(mesh.chunks.size());
    for (const voxel::MeshChunk& c : mesh.chunks) {
        GpuChunk g;
        g.origin = mesh.origin + glm::dvec3(c.origin) * mesh.voxelSize;
        glm::ivec3 lo(GROTTO_CHUNK_SIZE), hi(0);
        uint32_t first = c.firstQuad;
        for (int f = 0; f < 6; ++f) {
            g.faceFirst[f] = first;
            g.faceCount[f] = c.faceCount[f];
            for (uint32_t q = first; q < first + c.faceCount[f]; ++q)
                for (const glm::ivec3& v : mesh.corners(c, mesh.quads[q])) {
                    lo = glm::min(lo, v - c.origin);
                    hi = glm::max(hi, v - c.origin);
                }
            first += c.faceCount[f];
        }
        g.lo = glm::vec3(lo) * float(mesh.voxelSize);
        g.hi = glm::vec3(hi) * float(mesh.voxelSize);
        s.chunks.push_back(g);
    }
    std::vector<uint32_t> vertices;
    vertices.reserve(4 * mesh.quads.size());
    for (const voxel::MeshChunk& c : mesh.chunks) {
        for (uint32_t q = c.firstQuad; q < c.firstQuad + c.quadCount(); ++q) {
            const gpu::PackedQuad quad = mesh.quads[q];
            for (const glm::ivec3& v : mesh.corners(c, quad)) {
                const glm::uvec3 p(v - c.origin);
                vertices.push_back(gpu::packVertex(p.x, p.y, p.z, gpu::quadFace(quad.bits), quad.material));
            }
        }
    }
    s.vertices = vk::uploadBuffer(ctx, vertices.data(), vertices.size() * sizeof(uint32_t),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    const uint32_t drawQuads = largestDraw(mesh);
    std::vector<uint32_t> indices;
    indices.reserve(6 * size_t(drawQuads));
    for (uint32_t q = 0; q < drawQuads; ++q)
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(4 * q + i);
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

GpuScene::~GpuScene() {
    vk::destroy(ctx, vertices);
    vk::destroy(ctx, indices);
    vk::destroy(ctx, palette);
}

}  // namespace grotto
