#pragma once
// The sky gradient's light on a surface (irradiance over pi, so a uniform sky of
// radiance L gives L), by the height of the direction the surface faces: the
// gradient depends on height alone, so the light does too.
#include "shaders/shared/sky.h"

#include <array>

namespace grotto {

// Rows for heights -1, -0.75, ..., 1 (GROTTO_SKY_LIGHT_ROWS): the composite
// interpolates between them.
std::array<glm::vec3, GROTTO_SKY_LIGHT_ROWS> skyLightTable(glm::vec3 zenith, glm::vec3 horizon);

// The light itself at height `up` of the surface's direction, integrated directly.
glm::vec3 skyLight(double up, glm::vec3 zenith, glm::vec3 horizon);

}  // namespace grotto
