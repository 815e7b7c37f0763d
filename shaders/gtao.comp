#version 460
#extension GL_GOOGLE_include_directive : require
// GTAO main pass at half resolution: visibility and packed depth edges per pixel.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1) uniform sampler2D depthMip0;
layout(set = 0, binding = 2) uniform sampler2D depthMip1;
layout(set = 0, binding = 3) uniform sampler2D depthMip2;
layout(set = 0, binding = 4) uniform sampler2D depthMip3;
layout(set = 0, binding = 5) uniform sampler2D depthMip4;
layout(set = 0, binding = 6) uniform usampler2D surfaceTex;  // full resolution
layout(set = 0, binding = 7, rg32f) uniform writeonly image2D aoEdges;

// Point sampling with explicit, clamped texel coordinates, so the CPU twin can
// reproduce every fetch exactly whatever the image size.
float gtaoDepth(ivec2 texel, int mip) {
    ivec2 t = texel >> mip;
    switch (mip) {
        case 0: return texelFetch(depthMip0, clamp(t, ivec2(0), textureSize(depthMip0, 0) - 1), 0).r;
        case 1: return texelFetch(depthMip1, clamp(t, ivec2(0), textureSize(depthMip1, 0) - 1), 0).r;
        case 2: return texelFetch(depthMip2, clamp(t, ivec2(0), textureSize(depthMip2, 0) - 1), 0).r;
        case 3: return texelFetch(depthMip3, clamp(t, ivec2(0), textureSize(depthMip3, 0) - 1), 0).r;
        default: return texelFetch(depthMip4, clamp(t, ivec2(0), textureSize(depthMip4, 0) - 1), 0).r;
    }
}
uint gtaoSurface(ivec2 pixel) { return texelFetch(surfaceTex, pixel, 0).r; }

#include "shared/gtao_kernel.h"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    imageStore(aoEdges, p, vec4(gtaoPixel(p), 0.0, 0.0));
}
