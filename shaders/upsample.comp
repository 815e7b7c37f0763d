#version 460
#extension GL_GOOGLE_include_directive : require
// Depth-aware upsample of half-res AO to full resolution. Of the four half-res
// samples around a pixel, only those on the same surface contribute, bilinearly
// weighted: same face direction and on the pixel's plane (voxel faces are planes,
// so this holds on grazing floors too, where depths differ a lot). If none
// qualifies, the one nearest in depth is taken. AO never crosses a discontinuity.
//
// One invocation per AO pixel writes its whole scale x scale block of full-res
// pixels, so the four samples, their planes and normals are read once per block
// rather than once per pixel (lavapipe pays per fetch and per instruction).
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

// One AO sample: its visibility, view depth, face + 1 (0 = sky) and the offset of
// its face's plane along that face's normal.
struct Sample {
    float ao, depth, plane;
    uint face;
};

Sample loadSample(ivec2 s) {
    vec4 v = imageLoad(aoHalf, s);
    Sample r;
    r.ao = v.x;
    r.depth = v.z;
    r.face = uint(v.w);
    r.plane = dot(gtaoViewPosition(vec2(s), v.z), vec3(gtao.viewNormals[max(r.face, 1u) - 1u]));
    return r;
}

// Blends the samples that lie on full-res pixel q's own plane with bilinear
// weights w; falls back to the sample nearest in depth.
void resolve(ivec2 q, Sample s[4], vec4 w) {
    if (any(greaterThanEqual(uvec2(q), gtao.fullSize))) return;
    float d = texelFetch(depthBuffer, q, 0).r;
    if (d <= 0.0) {  // sky
        imageStore(aoFull, q, vec4(1.0));
        return;
    }
    float z = gtao.depthB / (d + gtao.depthA);
    uint face = texelFetch(surfaceTex, q, 0).r & 7u;
    float plane = dot(gtaoViewPosition(vec2(q) / float(gtao.scale), z), vec3(gtao.viewNormals[face - 1u]));
    float sum = 0.0, weight = 0.0, nearestAo = 1.0, nearestDz = 1e30;
    for (int i = 0; i < 4; ++i) {
        float dz = abs(s[i].depth - z);
        if (dz < nearestDz) {
            nearestDz = dz;
            nearestAo = s[i].ao;
        }
        if (w[i] > 0.0 && s[i].face == face && abs(s[i].plane - plane) <= 1e-3 * z) {
            sum += w[i] * s[i].ao;
            weight += w[i];
        }
    }
    imageStore(aoFull, q, vec4(weight > 1e-4 ? sum / weight : nearestAo));
}

void main() {
    ivec2 h = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(h), gtao.halfSize))) return;
    ivec2 q = h * int(gtao.scale);
    // The AO pixel stands for full-res pixel q exactly (its depth, face and plane
    // are q's), so q takes it unchanged; sky AO pixels hold 1.
    Sample s0 = loadSample(h);
    imageStore(aoFull, q, vec4(s0.ao));
    if (gtao.scale == 1u) return;

    ivec2 last = ivec2(gtao.halfSize) - 1;
    Sample s[4] = Sample[4](s0, loadSample(min(h + ivec2(1, 0), last)), loadSample(min(h + ivec2(0, 1), last)),
                            loadSample(min(h + ivec2(1, 1), last)));
    resolve(q + ivec2(1, 0), s, vec4(0.5, 0.5, 0.0, 0.0));
    resolve(q + ivec2(0, 1), s, vec4(0.5, 0.0, 0.5, 0.0));
    resolve(q + ivec2(1, 1), s, vec4(0.25));
}
