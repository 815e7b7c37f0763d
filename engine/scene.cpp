#include "engine/scene.h"

#include "voxel/mesh.h"
#include "voxel/world_desc.h"

namespace grotto {

GpuScene uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc) {
    GpuScene s;
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
    s.quads = vk::uploadBuffer(ctx, mesh.quads.data(), mesh.quads.size() * sizeof(gpu::PackedQuad),
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::vector<glm::vec4> palette;
    for (const voxel::Material& m : desc.materials) palette.emplace_back(m.albedo, 1.0f);
    s.palette = vk::uploadBuffer(ctx, palette.data(), palette.size() * sizeof(glm::vec4),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    return s;
}

void destroy(vk::Context& ctx, GpuScene& scene) {
    vk::destroy(ctx, scene.quads);
    vk::destroy(ctx, scene.palette);
    scene.chunks.clear();
}

}  // namespace grotto
