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
//
// Built with GROTTO_VBAO_THICKNESS (depth_prefilter_thickness.comp) it also traces,
// per MIP-0 texel, how deep the solid behind the surface runs along the view ray
// (VBAO's voxels thickness) into a second atlas of the same layout, reduced with
// the same filter, which favours the thicker.
#include "shared/gtao.h"
#include "shared/quad.h"
#include "shared/objects.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1) uniform sampler2D depthBuffer;           // full-res D32, reverse-Z
layout(set = 0, binding = 2, r32f) uniform writeonly image2D atlas;  // every MIP, side by side
#ifdef GROTTO_VBAO_THICKNESS
layout(set = 0, binding = 3, r32f) uniform writeonly image2D thicknessAtlas;  // the same layout
layout(set = 0, binding = 4) uniform usampler2D surfaceTex;                  // full resolution
#define GROTTO_TRACE_BINDING 5
#include "trace.glsl"
#define Texel vec2  // view depth, thickness
#else
#define Texel float
#endif

// Only gtaoMipFilter is used here; the kernel's inputs are not needed.
float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"

#if GROTTO_GTAO_DEPTH_MIPS != 5
#error "a group of 8x8 threads reduces 16x16 MIP-0 texels to exactly one MIP-4 texel"
#endif

shared Texel level1[GROTTO_GTAO_GROUP][GROTTO_GTAO_GROUP];
shared Texel level2[GROTTO_GTAO_GROUP / 2u][GROTTO_GTAO_GROUP / 2u];
shared Texel level3[GROTTO_GTAO_GROUP / 4u][GROTTO_GTAO_GROUP / 4u];

float viewDepth(ivec2 texel) {
    ivec2 p = min(texel, ivec2(gtao.halfSize) - 1) * int(gtao.scale);
    float d = texelFetch(depthBuffer, p, 0).r;
    return d > 0.0 ? min(gtao.depthB / (d + gtao.depthA), kGtaoSky) : kGtaoSky;
}

#ifdef GROTTO_VBAO_THICKNESS
// Twice the effective radius: a back farther behind than that is beyond the
// radius from any centre whatever its front, so it stands for "no back".
float maxThickness() { return 2.0 * gtao.settings.radius * gtao.settings.radiusMultiplier; }

// View depth and thickness at a MIP-0 texel. Objects have no occupancy: their
// occluders count as thick, as GTAO has them.
Texel source0(ivec2 texel) {
    float z = viewDepth(texel);
    uint surface = texelFetch(surfaceTex, min(texel, ivec2(gtao.halfSize) - 1) * int(gtao.scale), 0).r;
    if (z >= kGtaoSky || surface == 0u || surfaceObject(surface) != 0u) return vec2(z, maxThickness());
    return vec2(z, traceThickness(gtaoViewPosition(vec2(min(texel, ivec2(gtao.halfSize) - 1)), z), surfaceFace(surface),
                                  maxThickness()));
}

vec2 filter4(vec2 a, vec2 b, vec2 c, vec2 d) {
    return vec2(gtaoMipFilter(a.x, b.x, c.x, d.x), gtaoMipFilter(a.y, b.y, c.y, d.y));
}

void store(ivec2 texel, int mip, vec2 v) {
    ivec4 rect = gtaoMipRect(mip);
    if (!all(lessThan(texel, rect.zw))) return;
    imageStore(atlas, texel + rect.xy, vec4(v.x));
    imageStore(thicknessAtlas, texel + rect.xy, vec4(v.y));
}
#else
float source0(ivec2 texel) { return viewDepth(texel); }
float filter4(float a, float b, float c, float d) { return gtaoMipFilter(a, b, c, d); }

void store(ivec2 texel, int mip, float depth) {
    ivec4 rect = gtaoMipRect(mip);
    if (all(lessThan(texel, rect.zw))) imageStore(atlas, texel + rect.xy, vec4(depth));
}
#endif

// Source texel 2t + offset of texel t of MIP `mip`, clamped to the source MIP's
// last texel (the callers shift it into the group's shared array).
ivec2 source(ivec2 t, int mip, ivec2 offset) { return min(2 * t + offset, gtaoMipRect(mip - 1).zw - 1); }

void main() {
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 group = ivec2(gl_WorkGroupID.xy);

    // MIP 0 (2x2 per thread) and MIP 1 (one per thread).
    ivec2 t1 = group * int(GROTTO_GTAO_GROUP) + local;
    Texel d[4];
    for (int i = 0; i < 4; ++i) {
        ivec2 t0 = 2 * t1 + ivec2(i & 1, i >> 1);
        d[i] = source0(t0);
        store(t0, 0, d[i]);
    }
    // viewDepth clamps to the last texel, so the four are MIP 1's clamped sources.
    Texel m1 = filter4(d[0], d[1], d[2], d[3]);
    store(t1, 1, m1);
    level1[local.y][local.x] = m1;
    barrier();

    ivec2 base2 = group * int(GROTTO_GTAO_GROUP / 2u);
    if (all(lessThan(local, ivec2(GROTTO_GTAO_GROUP / 2u)))) {
        ivec2 t2 = base2 + local;
        ivec2 a = source(t2, 2, ivec2(0)) - 2 * base2, b = source(t2, 2, ivec2(1)) - 2 * base2;
        Texel m2 = filter4(level1[a.y][a.x], level1[a.y][b.x], level1[b.y][a.x], level1[b.y][b.x]);
        store(t2, 2, m2);
        level2[local.y][local.x] = m2;
    }
    barrier();

    ivec2 base3 = group * int(GROTTO_GTAO_GROUP / 4u);
    if (all(lessThan(local, ivec2(GROTTO_GTAO_GROUP / 4u)))) {
        ivec2 t3 = base3 + local;
        ivec2 a = source(t3, 3, ivec2(0)) - 2 * base3, b = source(t3, 3, ivec2(1)) - 2 * base3;
        Texel m3 = filter4(level2[a.y][a.x], level2[a.y][b.x], level2[b.y][a.x], level2[b.y][b.x]);
        store(t3, 3, m3);
        level3[local.y][local.x] = m3;
    }
    barrier();

    if (local == ivec2(0)) {
        ivec2 t4 = group;
        ivec2 a = source(t4, 4, ivec2(0)) - 2 * group, b = source(t4, 4, ivec2(1)) - 2 * group;
        store(t4, 4, filter4(level3[a.y][a.x], level3[a.y][b.x], level3[b.y][a.x], level3[b.y][b.x]));
    }
}
