// Per-frame constants read by the G-buffer and composite passes (a uniform buffer:
// lavapipe reads those far faster than storage buffers). Positions are
// camera-relative (the camera sits at the origin) so precision does not depend
// on where in the world the camera is.
#ifndef GROTTO_SHARED_FRAME_H
#define GROTTO_SHARED_FRAME_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

struct FrameUniforms {
    mat4 viewProj;       // camera-relative world -> clip (reverse-Z)
    vec4 sunDirection;   // xyz: unit vector toward the sun
    vec4 sunRadiance;    // rgb: colour x intensity
    vec4 ambient;        // rgb: colour x intensity
    vec4 skyZenith;      // rgb
    vec4 skyHorizon;     // rgb
    vec4 rayOrigin;      // xyz: unnormalised view ray through pixel corner (0, 0)
    vec4 rayStepX;       // xyz: its change per pixel to the right
    vec4 rayStepY;       // xyz: its change per pixel down
    vec4 aoStrength;     // x: 0 = AO off, 1 = full AO
    vec4 exposure;       // x: radiance multiplier (the composite's colour is radiance x this); yzw unused
    uvec2 size;          // full-resolution width, height
    uvec2 pad;
};
GROTTO_STATIC_ASSERT(sizeof(FrameUniforms) == 64 + 10 * 16 + 16);

// G-buffer push constants: one chunk's corner, camera-relative, and the voxel size.
struct ChunkPush {
    vec4 offsetAndVoxelSize;
};
GROTTO_STATIC_ASSERT(sizeof(ChunkPush) == 16);

#define GROTTO_MAX_MATERIALS 255

GROTTO_NAMESPACE_END
#endif
