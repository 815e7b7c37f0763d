// Constants of the temporal pass, shared by C++ and GLSL: how the current view
// maps to the previous frame's, the previous camera's projection, and where an
// edit restarts the history.
#ifndef GROTTO_SHARED_TEMPORAL_H
#define GROTTO_SHARED_TEMPORAL_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

// How far the history may lie outside this frame's raw 3x3 AO range before it is
// clamped: beyond the estimator's noise by this much, it is stale (a halo that moved
// on, an occluder that came into view). Clamping to the bare range cut into the
// noise itself and cost both flicker and error on every shipped path
// (docs/temporal.md).
#define GROTTO_TEMPORAL_CLAMP_MARGIN 0.2f

// Boxes of a frame within which history restarts (edited voxels, grown by the AO's
// reach); more edits than this in one frame merge into fewer, larger boxes.
#define GROTTO_TEMPORAL_MAX_BOXES 8

struct TemporalConstants {
    mat4 currentToPrevious;          // current view space -> previous view space, built in double
    vec4 previousNdcToViewMul_Add;   // as GtaoConstants::ndcToViewMul_Add, for the previous camera
    vec4 previousViewNormals[6];     // the six face normals in the previous view space
    uint reset;                      // 1 = no usable history: first frame, camera cut, new sequence
    uint boxCount;                   // boxes in use below, 0 .. GROTTO_TEMPORAL_MAX_BOXES
    uint pad1, pad2;
    vec4 viewToWorld[3];             // the current camera's axes (right, up, back): view -> camera-relative world
    vec4 boxMin[GROTTO_TEMPORAL_MAX_BOXES];  // xyz: camera-relative world boxes where history restarts
    vec4 boxMax[GROTTO_TEMPORAL_MAX_BOXES];
};
GROTTO_STATIC_ASSERT(sizeof(TemporalConstants) == 64 + 16 + 96 + 16 + 48 + 2 * 16 * GROTTO_TEMPORAL_MAX_BOXES);

GROTTO_NAMESPACE_END
#endif
