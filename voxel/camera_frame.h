#pragma once
// Where a camera description looks: its roll-free orientation, and the default
// camera that frames a box (a world's bounds) in an image of a given shape.
#include "voxel/world_desc.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace grotto::voxel {

// Columns right, up, back of a roll-free camera at `position` looking at `target`
// (Y up; straight up or down falls back to a horizontal right vector).
glm::dmat3 lookAtBasis(glm::dvec3 position, glm::dvec3 target);

// How much of the image a framed box spans on the axis that binds it: the rest
// is an even margin on both sides.
inline constexpr double kFramedFill = 0.9;

// A camera looking at the box [lo, hi] from above and to the side (60 degrees
// vertical field of view), placed so the box's eight corners project inside an
// image of `aspect` (width / height), spanning kFramedFill of its width or its
// height, centred. The near plane follows the box's size alone, not the aspect.
CameraDesc frameBox(glm::dvec3 lo, glm::dvec3 hi, double aspect);

}  // namespace grotto::voxel
