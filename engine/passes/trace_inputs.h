#pragma once
// What every pass that traces the world's voxels binds after its own inputs (the
// trace constants, then the occupancy's tiles, bricks and masks, then for a pass
// whose rays see objects their grids: shaders/trace.glsl), and those constants for
// a frame.
#include "engine/camera.h"
#include "engine/scene/occupancy.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/trace.h"

#include <vector>

namespace grotto {

// The binding types the tracing passes list most.
inline constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
inline constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;

// Appends the trace bindings' types to a pass's own: four, five with `objects`.
std::vector<VkDescriptorType> withTraceBindings(std::vector<VkDescriptorType> own, bool objects = false);
// Appends the trace bindings to a pass's own; `objectGrids` for a pass built with
// GROTTO_TRACE_OBJECTS (engine/scene/object_grids.h).
std::vector<vk::Binding> withTraceBindings(std::vector<vk::Binding> own, const vk::Buffer& constants,
                                           const GpuOccupancy& occupancy, const vk::Buffer* objectGrids = nullptr);

// The camera's voxel and its place in it are split in double, so rays stay exact
// far from the origin. `sun`: unit, toward the sun. AO rays: `rays` per pixel of
// length `radius` (world units).
gpu::TraceConstants traceConstants(const Camera& camera, const GpuOccupancy& occupancy, double voxelSize,
                                   glm::dvec3 worldOrigin, glm::vec3 sun, uint32_t rays, double radius);

}  // namespace grotto
