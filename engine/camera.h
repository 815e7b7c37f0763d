#pragma once
// A pinhole camera in double precision. Rendering uses camera-relative matrices
// (the camera at the origin); depth is reverse-Z, infinite far plane by default.
#include "voxel/camera_frame.h"
#include "voxel/world_desc.h"

#include <glm/glm.hpp>

#include <string>

namespace grotto {
namespace voxel {
class World;
}

struct Camera {
    glm::dvec3 position{0.0};
    glm::dmat3 basis{1.0};      // columns: right, up, back (view looks down -Z)
    double fovY = glm::radians(60.0);
    double nearPlane = 0.05;
    double farPlane = 0.0;      // 0 = infinite
    uint32_t width = 1, height = 1;

    double aspect() const { return double(width) / double(height); }
    glm::dmat4 viewFromWorld() const;                 // absolute, for file metadata
    glm::dmat4 projection(bool flipY = true) const;  // reverse-Z; Vulkan's y points down
    glm::dmat4 viewProjRelativeDouble() const;       // camera-relative world -> clip, in double
    glm::mat4 viewProjRelative() const;              // the same in float, for shaders
    // Positive distance along the view axis for a depth-buffer value (inf for 0 with
    // an infinite far plane); read from the projection matrix, never a constant.
    double linearDepth(double depth) const;
    // World-space direction through a pixel position (pixel centres at +0.5).
    glm::dvec3 rayDirection(double px, double py) const;
    // The world point seen through a pixel position at a view-axis distance.
    glm::dvec3 pointAt(double px, double py, double viewDepth) const;
};

Camera makeCamera(const voxel::CameraDesc& desc, uint32_t width, uint32_t height);

// The voxel holding the camera (index space) and the camera's place in it, in
// voxels, split in double so that what the GPU adds to them stays exact far from
// the origin. A camera beyond the index range is clamped to its edge.
struct CameraVoxel {
    glm::ivec3 cell{0};
    glm::vec3 fraction{0.0f};
};
CameraVoxel cameraVoxel(const Camera& camera, double voxelSize, glm::dvec3 worldOrigin);
// The world's camera `name` (its default one when empty: voxel::World::camera) for
// an image of width x height.
Camera worldCamera(const voxel::World& world, const std::string& name, uint32_t width, uint32_t height);

using voxel::lookAtBasis;  // voxel/camera_frame.h: the orientation a CameraDesc gives

}  // namespace grotto
