#pragma once
// The per-frame tables that turn a surface key (face and object, shaders/shared/
// objects.h) into a normal: in the view for the AO chain, in the world for the
// lighting, in the previous view for the temporal pass.
#include "engine/camera.h"
#include "shaders/shared/gtao.h"
#include "shaders/shared/objects.h"
#include "voxel/object_pose.h"

#include <span>

namespace grotto {

// The world-space normal of a surface id's face: an axis for the world, turned by
// the object's rotation for an object (poses[k - 1] for object index k).
glm::dvec3 surfaceNormal(uint32_t surfaceId, std::span<const voxel::ObjectPose> poses);

// Writes every slot of `table` (GROTTO_NORMAL_SLOTS entries): the normals in the
// space `rotation` (world to that space) turns them into; slots of absent objects are 0.
void normalTable(glm::vec4* table, const glm::dmat3& rotation, std::span<const voxel::ObjectPose> poses);

// The objects' tables for a frame: world normals now, and view normals in the
// previous camera at the previous poses (the temporal pass's plane test).
gpu::ObjectUniforms objectUniforms(std::span<const voxel::ObjectPose> poses, const Camera& previousCamera,
                                   std::span<const voxel::ObjectPose> previousPoses);

}  // namespace grotto
