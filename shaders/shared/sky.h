// The sky, written once for GLSL and C++: the gradient the composite draws where
// nothing was, and the light it casts on a surface, which the composite reads from
// a table of the surface direction's height (FrameUniforms::skyLight) that the CPU
// integrates from the same gradient (engine/frame/sky_light.cpp).
#ifndef GROTTO_SHARED_SKY_H
#define GROTTO_SHARED_SKY_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_SKY_LIGHT_ROWS 9  // surface directions with height -1, -0.75, ..., 1

// Radiance from unit direction `up`'s height: zenith to horizon by the square
// root of the height, and a darker horizon colour below it.
GROTTO_FUNCTION vec3 skyRadiance(float up, vec3 zenith, vec3 horizon) {
    return up >= 0.0f ? mix(horizon, zenith, sqrt(up)) : horizon * 0.8f;
}

GROTTO_NAMESPACE_END
#endif
