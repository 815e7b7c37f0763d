#version 460
#extension GL_GOOGLE_include_directive : require
// Half-resolution view-depth MIP chain. MIP 0 point-samples the top-left pixel of
// each 2x2 block: every half-res depth is then a real surface point whose position
// and normal are known exactly (a min, max or average would invent positions
// between surfaces). MIPs 1-4 average with gtaoMipFilter, which favours the nearest.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1) uniform sampler2D depthBuffer;   // full-res D32, reverse-Z
layout(set = 0, binding = 2) uniform sampler2D atlasIn;       // the atlas, MIP level - 1 read
layout(set = 0, binding = 3, r32f) uniform writeonly image2D atlasOut;  // MIP level written
layout(push_constant) uniform Push { int level; };

// Only gtaoMipFilter is used here; the kernel's inputs are not needed.
float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec4 target = gtaoMipRect(level);
    if (any(greaterThanEqual(p, target.zw))) return;
    float depth;
    if (level == 0) {
        float d = texelFetch(depthBuffer, p * int(gtao.scale), 0).r;
        depth = d > 0.0 ? min(gtao.depthB / (d + gtao.depthA), kGtaoSky) : kGtaoSky;
    } else {
        ivec4 source = gtaoMipRect(level - 1);
        ivec2 last = source.zw - 1;
        depth = gtaoMipFilter(texelFetch(atlasIn, min(p * 2, last) + source.xy, 0).r,
                              texelFetch(atlasIn, min(p * 2 + ivec2(1, 0), last) + source.xy, 0).r,
                              texelFetch(atlasIn, min(p * 2 + ivec2(0, 1), last) + source.xy, 0).r,
                              texelFetch(atlasIn, min(p * 2 + ivec2(1, 1), last) + source.xy, 0).r);
    }
    imageStore(atlasOut, p + target.xy, vec4(depth));
}
