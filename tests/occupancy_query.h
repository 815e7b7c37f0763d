#pragma once
// For the occupancy tests: whether each of a list of voxels is solid in the GPU
// occupancy (shaders/occupancy_query.comp, which asks trace.glsl), to compare
// with the CPU's World::solid.
#include "engine/passes/compute_pass.h"
#include "engine/passes/trace_inputs.h"
#include "engine/scene/live_scene.h"
#include "engine/vk/readback.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cstring>
#include <vector>

namespace grotto::test {

// traceSolid on the GPU for a list of voxels.
class OccupancyQuery {
public:
    explicit OccupancyQuery(vk::Context& ctx)
        : ctx_(ctx),
          pass_(ctx, "occupancy_query.comp",
                withTraceBindings({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}),
                2 * sizeof(uint32_t)) {}

    // 1 where the occupancy holds a solid voxel, 0 elsewhere, for each cell. With a
    // scene, its staged uploads are recorded first in the same command buffer, as a
    // frame does.
    std::vector<uint8_t> solid(const GpuOccupancy& occupancy, const std::vector<glm::ivec3>& cells,
                               GpuScene* pending = nullptr) {
        std::vector<uint8_t> out(cells.size());
        if (cells.empty()) return out;
        // Only hashMask matters to traceSolid; any camera fills the rest.
        const gpu::TraceConstants t = traceConstants(Camera{}, occupancy, 1.0, glm::dvec3(0.0),
                                                     glm::vec3(0.0f, 1.0f, 0.0f), 1, 1.0);
        vk::Buffer constants = vk::createBuffer(ctx_, sizeof t, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        std::memcpy(constants.mapped(), &t, sizeof t);
        vk::Buffer staging;  // for the scene's uploads
        constexpr size_t kChunk = size_t(1) << 21, kWidth = 1024;
        vk::Buffer in = vk::createBuffer(ctx_, std::min(cells.size(), kChunk) * sizeof(glm::ivec4),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        vk::Buffer answers = vk::createBuffer(ctx_, std::min(cells.size(), kChunk) * sizeof(uint32_t),
                                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        for (size_t first = 0; first < cells.size(); first += kChunk) {
            const size_t n = std::min(kChunk, cells.size() - first);
            auto* c = static_cast<glm::ivec4*>(in.mapped());
            for (size_t i = 0; i < n; ++i) c[i] = glm::ivec4(cells[first + i], 0);
            const uint32_t push[2] = {uint32_t(n), uint32_t(kWidth)};
            ctx_.submitAndWait([&](VkCommandBuffer cmd) {
                if (pending) pending->recordUploads(cmd, staging);
                // The scene's occupancy buffers may have been replaced by recordUploads' reallocations:
                // bind them as they are now.
                pass_.dispatch(cmd,
                               withTraceBindings({vk::storageBuffer(in.buffer), vk::storageBuffer(answers.buffer)},
                                                 constants, occupancy),
                               VkExtent2D{uint32_t(kWidth), uint32_t((n + kWidth - 1) / kWidth)}, 8, push);
                computeToHost(cmd);
            });
            pending = nullptr;
            const auto* a = static_cast<const uint32_t*>(answers.mapped());
            for (size_t i = 0; i < n; ++i) out[first + i] = uint8_t(a[i]);
        }
        vk::destroy(ctx_, staging);
        vk::destroy(ctx_, in);
        vk::destroy(ctx_, answers);
        vk::destroy(ctx_, constants);
        return out;
    }

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto::test
