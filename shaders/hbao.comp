#version 460
#extension GL_GOOGLE_include_directive : require
// HBAO baseline (Bavoil & Sainz 2008): per pixel, directions x steps in screen
// space; along each direction the horizon rises as samples above the tangent
// plane (plus a tangent bias) are found, each rise adding (sin h - sin h_prev)
// attenuated by 1 - r^2 / R^2 (R = the AO radius). Same inputs, noise and output
// as gtao.comp, so only the estimator differs.
#include "shared/gtao.h"
#include "shared/quad.h"

// The same sample budget as GTAO's preset: 2 x slices directions, steps per side.
layout(constant_id = 0) const uint specDirections = 6u;
layout(constant_id = 1) const uint specSteps = 3u;

#include "ao_estimator.glsl"

// sin of the tangent bias angle (~5.7 degrees): keeps flat surfaces open despite
// pixel snapping; the result is rescaled so a fully closed horizon still gives 0.
#define kHbaoSinBias 0.1f

vec2 hbaoPixel(ivec2 pixel) {
    float z = gtaoDepth(pixel, 0);
    float edges = gtaoPixelEdges(pixel);
    float distanceFade = gtaoDistanceFade(z);
    if (z >= kGtaoSky || distanceFade >= 1.0f) return vec2(1.0f, edges);
    vec3 normal = gtaoViewNormal(pixel);
    vec3 position = gtaoViewPosition(vec2(pixel), z);
    float radius = gtao.settings.radius, radius2 = radius * radius;
    float screenRadius = radius / (z * gtao.pixelViewSize);  // AO pixels
    ivec2 last = ivec2(gtao.halfSize) - 1;
    vec2 noise = gtaoNoise(uvec2(pixel), gtao.frameIndex);

    float occlusion = 0.0f;
    for (uint d = 0u; d < specDirections; ++d) {
        float phi = (float(d) + noise.x) / float(specDirections) * 6.28318530718f;
        vec2 omega = vec2(cos(phi), -sin(phi)) * screenRadius;  // pixels: y points down
        float sinHorizon = kHbaoSinBias;
        for (uint s = 0u; s < specSteps; ++s) {
            float t = (float(s) + fract(noise.y + float(d) * 0.6180339887f)) / float(specSteps);
            ivec2 offset = ivec2(floor(clamp(t * omega, vec2(-32768.0f), vec2(32768.0f)) + 0.5f));
            if (offset == ivec2(0)) continue;
            ivec2 q = pixel + offset;
            if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) break;  // off-screen: open
            vec3 delta = gtaoSamplePosition(q, 0) - position;
            float dist2 = dot(delta, delta);
            if (dist2 > radius2) continue;
            float sinH = dot(delta, normal) * inversesqrt(max(dist2, 1e-30f));
            if (sinH > sinHorizon) {
                occlusion += (1.0f - dist2 / radius2) * (sinH - sinHorizon);
                sinHorizon = sinH;
            }
        }
    }
    occlusion /= float(specDirections) * (1.0f - kHbaoSinBias);
    return vec2(mix(gtaoSaturate(1.0f - occlusion), 1.0f, distanceFade), edges);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    aoStore(p, hbaoPixel(p));
}
