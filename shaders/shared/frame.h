// Per-frame constants read by the G-buffer and composite passes (a uniform buffer:
// lavapipe reads those far faster than storage buffers). Positions are
// camera-relative (the camera sits at the origin) so precision does not depend
// on where in the world the camera is.
#ifndef GROTTO_SHARED_FRAME_H
#define GROTTO_SHARED_FRAME_H
#include "common.h"
#include "sky.h"

GROTTO_NAMESPACE_BEGIN

struct FrameUniforms {
    mat4 viewProj;       // camera-relative world -> clip (reverse-Z)
    vec4 sunDirection;   // xyz: unit vector toward the sun; w: 1 a point sun, 0 a disc
    vec4 sunRadiance;    // rgb: colour x intensity
    vec4 ambient;        // rgb: colour x intensity (from the sky: the intensity); w: 1 = from the sky
    vec4 skyZenith;      // rgb
    vec4 skyHorizon;     // rgb
    vec4 rayOrigin;      // xyz: unnormalised view ray through pixel corner (0, 0)
    vec4 rayStepX;       // xyz: its change per pixel to the right
    vec4 rayStepY;       // xyz: its change per pixel down
    vec4 aoStrength;     // x: 0 = AO off, 1 = full AO
    vec4 exposure;       // x: radiance multiplier (the composite's colour is radiance x this); yzw unused
    uvec2 size;          // full-resolution width, height
    uvec2 faceCache;     // --ao cache: the face cache's table shape and texels per face side (shared/face_cache.h)
    vec4 skyLight[GROTTO_SKY_LIGHT_ROWS];  // rgb: the sky's light on a surface facing height -1 + k / 4
    // Where a pixel's surface is, in voxels (--ao cache): rayOrigin's ray times the
    // view depth, from the camera's place in its voxel.
    vec4 depthAB;        // x, y: view depth = y / (depth buffer value + x)
    ivec4 cameraCell;    // xyz: the voxel holding the camera (index space); w: the frame's index
    vec4 cameraFraction; // xyz: the camera within that voxel, in voxels; w: 1 / voxel size
    // The day's sun from the face cache (shared/face_cache.h's faceCacheDaySun):
    // x the first word of its bits, 0 without; y and z the positions before and
    // after the hour; w 1 before sunrise or after sunset (every pixel traced);
    // daySunBefore and daySunAfter: toward the sun at those two.
    uvec4 daySun;
    vec4 daySunBefore;
    vec4 daySunAfter;
    // Full light over the day from the face cache (shared/face_cache.h's
    // faceCacheDayLight's `day`): x 0 without it.
    uvec4 dayLight;
};
GROTTO_STATIC_ASSERT(sizeof(FrameUniforms) == 64 + 10 * 16 + 16 + 16 * GROTTO_SKY_LIGHT_ROWS + 7 * 16);

// G-buffer push constants: one chunk's corner in whole voxels from the camera's
// voxel, and the camera's place in that voxel. A vertex's position is computed from
// its voxel index alone, so the chunks on either side of a border put their shared
// corners at the very same bits and meet without cracks.
struct ChunkPush {
    ivec4 voxel;                // xyz: the chunk's corner minus the camera's voxel
    vec4 cameraAndVoxelSize;    // xyz: the camera within its voxel (0..1); w: the voxel size
};
GROTTO_STATIC_ASSERT(sizeof(ChunkPush) == 32);

#define GROTTO_MAX_MATERIALS 255
// The palette's uniform buffer: per material, vec4(albedo, material AO) then
// vec4(emission, 0) (the radiance its faces give off).
#define GROTTO_PALETTE_VEC4S (2 * GROTTO_MAX_MATERIALS)

GROTTO_NAMESPACE_END
#endif
