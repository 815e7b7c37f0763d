#version 460
#extension GL_GOOGLE_include_directive : require
// Sun Lambert + ambient x AO on surfaces, a gradient sky where nothing was drawn.
#include "shared/frame.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_COMPOSITE_GROUP, local_size_y = GROTTO_COMPOSITE_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std140) uniform Palette { vec4 albedo[GROTTO_MAX_MATERIALS]; };
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;
layout(set = 0, binding = 3) uniform sampler2D aoTex;  // full-res visibility
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outColor;

// Multi-bounce fit (Jimenez et al. 2016): light bouncing between bright surfaces
// brightens what plain visibility would leave dark.
vec3 multiBounce(float v, vec3 albedo) {
    vec3 a = 2.0404 * albedo - 0.3324;
    vec3 b = -4.7951 * albedo + 0.6417;
    vec3 c = 2.7552 * albedo + 0.6903;
    return max(vec3(v), ((a * v + b) * v + c) * v);
}

vec3 sky(ivec2 pixel) {
    vec2 p = vec2(pixel) + 0.5;
    vec3 ray = frame.rayOrigin.xyz + p.x * frame.rayStepX.xyz + p.y * frame.rayStepY.xyz;
    float up = ray.y * inversesqrt(dot(ray, ray));
    return up >= 0.0 ? mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, sqrt(up)) : frame.skyHorizon.rgb * 0.8;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), frame.size))) return;
    uint surface = texelFetch(surfaceTex, pixel, 0).r;
    vec3 color;
    if (surface == 0u) {
        color = sky(pixel);
    } else {
        uint face = surfaceFace(surface);
        // The sun term for an axis normal is one component of the sun direction.
        float cosSun = (facePositive(face) ? 1.0 : -1.0) * frame.sunDirection[faceAxis(face)];
        vec4 material = albedo[surfaceMaterial(surface) - 1u];  // rgb albedo, a: material AO
        vec3 base = material.rgb;
        // Without AO the bound image is a 1x1 placeholder: do not read it.
        float visibility = frame.aoStrength.x > 0.0 ? mix(1.0, texelFetch(aoTex, pixel, 0).r, frame.aoStrength.x) : 1.0;
        visibility = min(visibility, material.a);
        color = base * (frame.sunRadiance.rgb * max(cosSun, 0.0) + frame.ambient.rgb * multiBounce(visibility, base));
    }
    imageStore(outColor, pixel, vec4(color, 1.0));
}
