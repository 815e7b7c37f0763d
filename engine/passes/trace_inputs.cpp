#include "engine/passes/trace_inputs.h"

#include <algorithm>
#include <cmath>

namespace grotto {

std::vector<VkDescriptorType> withTraceBindings(std::vector<VkDescriptorType> own, bool objects) {
    own.insert(own.end(), objects ? 5 : 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    return own;
}

std::vector<vk::Binding> withTraceBindings(std::vector<vk::Binding> own, const vk::Buffer& constants,
                                           const GpuOccupancy& occupancy, const vk::Buffer* objectGrids) {
    own.insert(own.end(), {vk::storageBuffer(constants.buffer), vk::storageBuffer(occupancy.tiles().buffer),
                           vk::storageBuffer(occupancy.bricks().buffer), vk::storageBuffer(occupancy.masks().buffer)});
    if (objectGrids) own.push_back(vk::storageBuffer(objectGrids->buffer));
    return own;
}

gpu::TraceConstants traceConstants(const Camera& camera, const GpuOccupancy& occupancy, double voxelSize,
                                   glm::dvec3 worldOrigin, glm::vec3 sun, uint32_t rays, double radius) {
    gpu::TraceConstants t{};
    const double tanY = std::tan(camera.fovY * 0.5), tanX = tanY * camera.aspect();
    t.ndcToViewMul_Add = glm::vec4(float(2.0 * tanX / camera.width), float(-2.0 * tanY / camera.height),
                                   float(-tanX), float(tanY));
    const glm::dmat4 p = camera.projection();
    t.depthAB = glm::vec4(float(p[2][2]), float(p[3][2]), 0.0f, 0.0f);
    for (int k = 0; k < 3; ++k) t.viewToWorld[k] = glm::vec4(glm::vec3(camera.basis[k]), 0.0f);
    const CameraVoxel v = cameraVoxel(camera, voxelSize, worldOrigin);  // beyond the index range: rays miss everything
    t.cameraCell = glm::ivec4(v.cell, 0);
    t.cameraFraction = glm::vec4(v.fraction, float(1.0 / voxelSize));
    const voxel::IndexBox& b = occupancy.bounds();
    t.boundsLo = glm::ivec4(b.min, 0);
    t.boundsHi = glm::ivec4(b.max, b.empty() ? 1 : 0);
    t.sunDirection = glm::vec4(glm::normalize(sun), 0.0f);
    t.hashMask = occupancy.hashMask();
    t.rays = rays;
    t.radiusVoxels = float(radius / voxelSize);
    t.normalOffset = 1e-4f;  // the reference's epsilon, in voxels
    return t;
}

}  // namespace grotto
