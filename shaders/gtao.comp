#version 460
#extension GL_GOOGLE_include_directive : require
// GTAO main pass at half resolution: visibility and packed depth edges per pixel.
#include "shared/gtao.h"
#include "shared/quad.h"

// The loop shape as specialization constants (see the kernel); GtaoPass sets them.
layout(constant_id = 0) const uint specSlices = 3u;
layout(constant_id = 1) const uint specSteps = 3u;
layout(constant_id = 2) const float specPower = 2.0;
#define kGtaoSlices specSlices
#define kGtaoSteps specSteps
#define kGtaoPower specPower

#ifdef GROTTO_VBAO
// VBAO (vbao.comp): the same kernel, each slice a bitmask of 32 sectors that an
// occluder hides only between its front and its back; the open sectors give the
// bent normal when a frame wants it (sky ambient, the bent_normal AOV).
layout(constant_id = 3) const bool specBentNormals = false;
#define kVbaoBentNormals specBentNormals
#include "shared/vbao_sectors.h"
#endif
#include "ao_estimator.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    aoStore(p, gtaoPixel(p));
}
