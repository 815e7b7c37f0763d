#version 460
#extension GL_GOOGLE_include_directive : require
// Half-resolution view-depth MIP chain, all five levels in one dispatch. MIP 0
// point-samples the top-left pixel of each 2x2 block: every half-res depth is then
// a real surface point whose position and normal are known exactly (a min, max or
// average would invent positions between surfaces). MIPs 1-4 average with
// gtaoMipFilter, which favours the far side.
//
// Each group of 8x8 threads covers 16x16 MIP-0 texels: a thread writes its 2x2 of
// MIP 0 and the MIP-1 texel they make, and the group reduces MIPs 2-4 in shared
// memory, so no level is read back from the atlas. A source texel past a level's
// last is clamped to the last, as a separate pass per level would read it; that
// texel always lies in the same group.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1) uniform sampler2D depthBuffer;           // full-res D32, reverse-Z
layout(set = 0, binding = 2, r32f) uniform writeonly image2D atlas;  // every MIP, side by side

// Only gtaoMipFilter is used here; the kernel's inputs are not needed.
float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"

#if GROTTO_GTAO_DEPTH_MIPS != 5
#error "a group of 8x8 threads reduces 16x16 MIP-0 texels to exactly one MIP-4 texel"
#endif

shared float level1[GROTTO_GTAO_GROUP][GROTTO_GTAO_GROUP];
shared float level2[GROTTO_GTAO_GROUP / 2u][GROTTO_GTAO_GROUP / 2u];
shared float level3[GROTTO_GTAO_GROUP / 4u][GROTTO_GTAO_GROUP / 4u];

float viewDepth(ivec2 texel) {
    ivec2 p = min(texel, ivec2(gtao.halfSize) - 1) * int(gtao.scale);
    float d = texelFetch(depthBuffer, p, 0).r;
    return d > 0.0 ? min(gtao.depthB / (d + gtao.depthA), kGtaoSky) : kGtaoSky;
}

void store(ivec2 texel, int mip, float depth) {
    ivec4 rect = gtaoMipRect(mip);
    if (all(lessThan(texel, rect.zw))) imageStore(atlas, texel + rect.xy, vec4(depth));
}

// Source texel 2t + offset of texel t of MIP `mip`, clamped to the source MIP's
// last texel (the callers shift it into the group's shared array).
ivec2 source(ivec2 t, int mip, ivec2 offset) { return min(2 * t + offset, gtaoMipRect(mip - 1).zw - 1); }

void main() {
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 group = ivec2(gl_WorkGroupID.xy);

    // MIP 0 (2x2 per thread) and MIP 1 (one per thread).
    ivec2 t1 = group * int(GROTTO_GTAO_GROUP) + local;
    float d[4];
    for (int i = 0; i < 4; ++i) {
        ivec2 t0 = 2 * t1 + ivec2(i & 1, i >> 1);
        d[i] = viewDepth(t0);
        store(t0, 0, d[i]);
    }
    // viewDepth clamps to the last texel, so the four are MIP 1's clamped sources.
    float m1 = gtaoMipFilter(d[0], d[1], d[2], d[3]);
    store(t1, 1, m1);
    level1[local.y][local.x] = m1;
    barrier();

    ivec2 base2 = group * int(GROTTO_GTAO_GROUP / 2u);
    if (all(lessThan(local, ivec2(GROTTO_GTAO_GROUP / 2u)))) {
        ivec2 t2 = base2 + local;
        ivec2 a = source(t2, 2, ivec2(0)) - 2 * base2, b = source(t2, 2, ivec2(1)) - 2 * base2;
        float m2 = gtaoMipFilter(level1[a.y][a.x], level1[a.y][b.x], level1[b.y][a.x], level1[b.y][b.x]);
        store(t2, 2, m2);
        level2[local.y][local.x] = m2;
    }
    barrier();

    ivec2 base3 = group * int(GROTTO_GTAO_GROUP / 4u);
    if (all(lessThan(local, ivec2(GROTTO_GTAO_GROUP / 4u)))) {
        ivec2 t3 = base3 + local;
        ivec2 a = source(t3, 3, ivec2(0)) - 2 * base3, b = source(t3, 3, ivec2(1)) - 2 * base3;
        float m3 = gtaoMipFilter(level2[a.y][a.x], level2[a.y][b.x], level2[b.y][a.x], level2[b.y][b.x]);
        store(t3, 3, m3);
        level3[local.y][local.x] = m3;
    }
    barrier();

    if (local == ivec2(0)) {
        ivec2 t4 = group;
        ivec2 a = source(t4, 4, ivec2(0)) - 2 * group, b = source(t4, 4, ivec2(1)) - 2 * group;
        store(t4, 4, gtaoMipFilter(level3[a.y][a.x], level3[a.y][b.x], level3[b.y][a.x], level3[b.y][b.x]));
    }
}
