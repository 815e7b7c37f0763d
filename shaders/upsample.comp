#version 460
#extension GL_GOOGLE_include_directive : require
// Depth-aware upsample of half-res AO to full resolution. Of the four half-res
// samples around a pixel, only those on the same surface contribute, bilinearly
// weighted: same face direction and on the pixel's plane (voxel faces are planes,
// so this holds on grazing floors too, where depths differ a lot). If none
// qualifies, the one nearest in depth is taken. AO never crosses a discontinuity.
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

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(q), gtao.fullSize))) return;
    float d = texelFetch(depthBuffer, q, 0).r;
    if (d <= 0.0) {  // sky
        imageStore(aoFull, q, vec4(1.0));
        return;
    }
    float z = gtao.depthB / (d + gtao.depthA);
    uint face = texelFetch(surfaceTex, q, 0).r & 7u;
    vec3 normal = vec3(gtao.viewNormals[face - 1u]);
    vec3 position = gtaoViewPosition(vec2(q) / float(gtao.scale), z);  // full-res pixel q itself
    int scale = int(gtao.scale);
    ivec2 h = q / scale;
    vec2 f = vec2(q - h * scale) / float(scale);  // how far past the AO sample: 0 or 0.5
    ivec2 last = ivec2(gtao.halfSize) - 1;
    float sum = 0.0, weight = 0.0, nearestAo = 1.0, nearestDz = 1e30;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 s = min(h + ivec2(i, j), last);
            vec4 sample4 = imageLoad(aoHalf, s);
            float ao = sample4.x;
            float dz = abs(sample4.z - z);
            bool sameFace = uint(sample4.w) == face;
            if (dz < nearestDz) {
                nearestDz = dz;
                nearestAo = ao;
            }
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            float offPlane = abs(dot(gtaoViewPosition(vec2(s), sample4.z) - position, normal));
            if (w > 0.0 && sameFace && offPlane <= 1e-3 * z) {
                sum += w * ao;
                weight += w;
            }
        }
    imageStore(aoFull, q, vec4(weight > 1e-4 ? sum / weight : nearestAo));
}
