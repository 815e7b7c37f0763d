#pragma once
// The GPU copy of a voxel world: quads, chunk table and material palette.
// scene.cpp is the one bridge between voxel/ and engine/vk/.
#include "engine/vk/resources.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <vector>

namespace grotto {
namespace voxel { struct Mesh; struct WorldDesc; }

struct GpuChunk {
    glm::dvec3 origin;            // world position of the chunk's corner
    glm::vec3 lo, hi;             // tight bounds of its quads, relative to origin
    std::array<uint32_t, 6> faceFirst{}, faceCount{};  // quad ranges per face
};

// Quads become 4 packed vertices each (shaders/shared/quad.h); one shared index
// buffer (0 1 2 0 2 3, +4 per quad) serves every draw through its vertex offset.
struct GpuScene {
    explicit GpuScene(vk::Context& context) : ctx(context) {}
    ~GpuScene();  // releases the buffers
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    vk::Context& ctx;
    vk::Buffer vertices;
    vk::Buffer indices;
    vk::Buffer palette;                 // uniform buffer of GROTTO_MAX_MATERIALS vec4: albedo, material AO
    std::vector<glm::vec3> albedo;      // host copy of the palette, id k at [k - 1]
    std::vector<GpuChunk> chunks;
    double voxelSize = 1.0;
    uint64_t quadCount = 0;
    size_t gpuBytes() const { return size_t(vertices.size + indices.size + palette.size); }
    size_t hostBytes() const { return chunks.size() * sizeof(GpuChunk); }
};

std::unique_ptr<GpuScene> uploadScene(vk::Context& ctx, const voxel::Mesh& mesh, const voxel::WorldDesc& desc);

// What uploadScene would allocate for these buffers (before allocator rounding),
// without a device: for `grotto info`.
size_t sceneBufferBytes(const voxel::Mesh& mesh);

}  // namespace grotto
