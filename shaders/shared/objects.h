// Objects: voxel models drawn into the same G-buffer as the world, each with a
// transform of its own. Shared by C++ and GLSL.
//
// The G-buffer's 16-bit surface id (shared/quad.h) holds face + 1 in bits 0-2,
// the material in bits 3-10 and the object's index in bits 11-15 (0 = the world,
// 1..GROTTO_MAX_OBJECTS). What the AO chain carries per pixel instead of "face + 1"
// is the surface key, face + 1 + 8 x object (the world's keys are its faces + 1),
// and key - 1 is the slot of the face's normal in every normal table: slots 0-5
// are the world's six axes, 8k .. 8k + 5 object k's faces, turned by its rotation.
#ifndef GROTTO_SHARED_OBJECTS_H
#define GROTTO_SHARED_OBJECTS_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_MAX_OBJECTS 31u
#define GROTTO_NORMAL_SLOTS 256

GROTTO_INLINE uint surfaceObject(uint id) { return id >> 11; }
GROTTO_INLINE uint surfaceKey(uint id) { return (id & 7u) | ((id >> 8) & 0xF8u); }
GROTTO_INLINE uint surfaceWithObject(uint id, uint object) { return id | (object << 11); }

// Per frame, for the composite (object faces' lighting) and the temporal pass
// (the plane test in the previous view).
struct ObjectUniforms {
    vec4 worldNormals[GROTTO_NORMAL_SLOTS];         // each slot's normal in world space, this frame
    vec4 previousViewNormals[GROTTO_NORMAL_SLOTS];  // in the previous camera's view, at the previous pose
};
GROTTO_STATIC_ASSERT(sizeof(ObjectUniforms) == 2 * 16 * GROTTO_NORMAL_SLOTS);

// G-buffer push constants of the object pipelines: a chunk's voxel coordinates
// (as the vertex packs them) to clip space this frame and the frame before,
// built in double on the CPU, camera-relative. The object's index is the draw's
// instance index.
struct ObjectPush {
    mat4 clip;
    mat4 previousClip;
};
GROTTO_STATIC_ASSERT(sizeof(ObjectPush) == 128);

GROTTO_NAMESPACE_END
#endif
