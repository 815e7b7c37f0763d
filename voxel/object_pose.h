#pragma once
// An object's pose at a time: its keys interpolated (position linearly, rotation
// by slerp, the shorter way round), held before the first key and after the last.
// OpenVDB-free.
#include "voxel/object_desc.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace grotto::voxel {

struct ObjectPose {
    glm::dvec3 position{0.0};                 // where the pivot is, world units
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // object-local to world
    glm::dvec3 pivot{0.0};                    // object-local world units

    glm::dvec3 toWorld(glm::dvec3 local) const { return position + rotation * (local - pivot); }
    glm::dvec3 toLocal(glm::dvec3 world) const { return glm::conjugate(rotation) * (world - position) + pivot; }
    // World from object-local, with `offset` subtracted from the translation (pass the
    // camera's position for a camera-relative matrix that stays exact far from the origin).
    glm::dmat4 worldFromLocal(glm::dvec3 offset = glm::dvec3(0.0)) const;
    bool operator==(const ObjectPose&) const = default;
};

ObjectPose objectPose(const ObjectDesc& object, double time);
std::vector<ObjectPose> objectPoses(const std::vector<ObjectDesc>& objects, double time);

}  // namespace grotto::voxel
