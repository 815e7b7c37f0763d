#version 460
#extension GL_GOOGLE_include_directive : require
// SSAO baseline: a normal-oriented, cosine-weighted hemisphere of point samples in
// view space (radius R = the AO radius), each occluded when the visible surface at
// its pixel lies in front of it, above the centre's tangent plane and within range.
// Same inputs, noise and output as gtao.comp, so only the estimator differs.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(constant_id = 0) const uint specSamples = 32u;  // low 8, medium 16, high 32, ultra 64

#include "ao_estimator.glsl"

// View position to (unrounded) AO pixel: gtaoViewPosition solved for the pixel.
vec2 ssaoPixel(ivec2 pixel) {
    float z = gtaoDepth(pixel, 0);
    float edges = gtaoPixelEdges(pixel);
    float distanceFade = gtaoDistanceFade(z);
    if (z >= kGtaoSky || distanceFade >= 1.0f) return vec2(1.0f, edges);
    vec3 normal = gtaoViewNormal(pixel);
    vec3 position = gtaoViewPosition(vec2(pixel), z);
    float radius = gtao.settings.radius;
    ivec2 last = ivec2(gtao.halfSize) - 1;
    vec2 noise = gtaoNoise(uvec2(pixel), gtao.frameIndex);
    // A tangent frame around the normal; the noise turns the kernel per pixel.
    vec3 helper = abs(normal.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f);
    vec3 tangent = normalize(cross(helper, normal));
    vec3 bitangent = cross(normal, tangent);
    float turn = noise.x * 6.28318530718f;

    float occluded = 0.0f;
    for (uint i = 0u; i < specSamples; ++i) {
        // Cosine-weighted direction (Malley: uniform on the disk, lifted) from R2
        // point i; lengths from 0.1 R to R, more of them near the centre.
        float u = fract(0.5f + float(i) * 0.7548776662f), a = fract(0.5f + float(i) * 0.5698402910f);
        float r = sqrt(u), phi = a * 6.28318530718f + turn;
        vec3 dir = tangent * (r * cos(phi)) + bitangent * (r * sin(phi)) + normal * sqrt(max(1.0f - u, 0.0f));
        float t = fract(noise.y + float(i) * 0.6180339887f);
        vec3 s = position + dir * (radius * mix(0.1f, 1.0f, t * t));
        if (s.z >= 0.0f) continue;  // behind the camera: unknown, open
        ivec2 q = ivec2(floor(gtaoPixelOf(s, gtao.ndcToViewMul_Add) + 0.5f));
        if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;  // off-screen: open
        vec3 scene = gtaoSamplePosition(q, 0);
        vec3 delta = scene - position;
        float dist2 = dot(delta, delta);
        // Tangent bias as in GTAO: a surface point on or below the centre's tangent
        // plane cannot occlude (pixel snapping puts floor points in front of samples).
        float above = gtaoSaturate(dot(delta, normal) * inversesqrt(max(dist2, 1e-30f)) * 32.0f);
        // Range check: surfaces beyond R (fading out to 1.25 R) cannot occlude.
        float range = gtaoSaturate((radius - sqrt(dist2)) / (0.25f * radius) + 1.0f);
        occluded += scene.z > s.z ? above * range : 0.0f;
    }
    return vec2(mix(gtaoSaturate(1.0f - occluded / float(specSamples)), 1.0f, distanceFade), edges);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    aoStore(p, ssaoPixel(p));
}
