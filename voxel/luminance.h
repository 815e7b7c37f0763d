#pragma once
// Rec. 709 luminance of linear RGB: how light is weighed where one number stands for a colour.
#include <glm/vec3.hpp>

namespace grotto::voxel {

inline double luminance(glm::dvec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace grotto::voxel
