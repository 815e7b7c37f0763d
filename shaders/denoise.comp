#version 460
#extension GL_GOOGLE_include_directive : require
// One edge-aware blur pass over half-res AO (denoise_blur.glsl). Edges, depth and
// face pass through unchanged.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D denoiseSource;  // AO, packed edges, depth, face + 1
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D target;
layout(push_constant) uniform Push { uint finalPass; };

float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"
#include "denoise_blur.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    vec2 range;
    float ao = denoiseBlur(p, denoiseBeta(finalPass != 0u), range);
    imageStore(target, p, vec4(ao, imageLoad(denoiseSource, p).gba));
}
