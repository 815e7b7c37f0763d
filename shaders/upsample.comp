#version 460
#extension GL_GOOGLE_include_directive : require
// Full-res AO from the half-res chain's output (upsample.glsl), for the AO AOV:
// the same values the composite shades with. Sky pixels hold 1.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D aoHalf;  // AO, edges, view depth, face + 1
layout(set = 0, binding = 2) uniform sampler2D depthBuffer;  // full-res D32, reverse-Z
layout(set = 0, binding = 3) uniform usampler2D surfaceTex;  // full res
layout(set = 0, binding = 4, r32f) uniform writeonly image2D aoFull;

float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"
#include "upsample.glsl"

void upsamplePixel(AoBlock block, ivec2 h, ivec2 offset) {
    ivec2 q = h * int(gtao.scale) + offset;
    if (any(greaterThanEqual(uvec2(q), gtao.fullSize))) return;
    uint face = surfaceKey(texelFetch(surfaceTex, q, 0).r);
    imageStore(aoFull, q, vec4(face == 0u ? 1.0 : upsampledAo(block, h, offset, face)));
}

void main() {
    ivec2 h = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(h), gtao.halfSize))) return;
    AoBlock block = loadAoBlock(h);
    upsamplePixel(block, h, ivec2(0, 0));
    if (gtao.scale == 1u) return;
    upsamplePixel(block, h, ivec2(1, 0));
    upsamplePixel(block, h, ivec2(0, 1));
    upsamplePixel(block, h, ivec2(1, 1));
}
