#version 460
#extension GL_GOOGLE_include_directive : require
// Edge-aware 3x3 blur of half-res AO. A neighbour counts only as far as both its
// own and the centre's edge weights agree they lie on one surface; diagonals
// through both of their paths. Edges pass through unchanged.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D source;  // AO, packed edges, depth, face + 1
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D target;
layout(push_constant) uniform Push { uint finalPass; };

float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"

vec2 fetch(ivec2 p) { return imageLoad(source, clamp(p, ivec2(0), ivec2(gtao.halfSize) - 1)).rg; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    vec2 c = fetch(p);
    vec2 l = fetch(p + ivec2(-1, 0)), r = fetch(p + ivec2(1, 0));
    vec2 t = fetch(p + ivec2(0, -1)), b = fetch(p + ivec2(0, 1));
    vec2 tl = fetch(p + ivec2(-1, -1)), tr = fetch(p + ivec2(1, -1));
    vec2 bl = fetch(p + ivec2(-1, 1)), br = fetch(p + ivec2(1, 1));
    vec4 ec = gtaoUnpackEdges(c.y);
    vec4 el = gtaoUnpackEdges(l.y), er = gtaoUnpackEdges(r.y), et = gtaoUnpackEdges(t.y), eb = gtaoUnpackEdges(b.y);
    // Symmetric: the neighbour's edge back towards the centre must agree.
    float wl = ec.x * el.y, wr = ec.y * er.x, wt = ec.z * et.w, wb = ec.w * eb.z;
    // A corner counts through either side neighbour, and that neighbour's own edge
    // towards the corner, so nothing leaks round a silhouette's corner.
    const float diagonal = 0.425;
    float wtl = diagonal * (wl * el.z + wt * et.x);
    float wtr = diagonal * (wt * et.y + wr * er.z);
    float wbl = diagonal * (wb * eb.x + wl * el.w);
    float wbr = diagonal * (wr * er.w + wb * eb.y);
    float beta = finalPass != 0u ? gtao.settings.denoiseBlurBeta : gtao.settings.denoiseBlurBeta / 5.0;
    float sum = beta * c.x + wl * l.x + wr * r.x + wt * t.x + wb * b.x + wtl * tl.x + wtr * tr.x + wbl * bl.x + wbr * br.x;
    float weight = beta + wl + wr + wt + wb + wtl + wtr + wbl + wbr;
    vec2 depthFace = imageLoad(source, p).ba;  // carried through for the upsample
    imageStore(target, p, vec4(weight > 0.0 ? sum / weight : c.x, c.y, depthFace));
}
