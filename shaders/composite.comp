#version 460
#extension GL_GOOGLE_include_directive : require
// Sun Lambert + ambient x AO on surfaces, a gradient sky where nothing was drawn.
#include "shared/frame.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_COMPOSITE_GROUP, local_size_y = GROTTO_COMPOSITE_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std140) uniform Palette { vec4 albedo[GROTTO_MAX_MATERIALS]; };
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D outColor;

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
        float ao = 1.0;
        color = albedo[surfaceMaterial(surface) - 1u].rgb *
                (frame.sunRadiance.rgb * max(cosSun, 0.0) + frame.ambient.rgb * ao);
    }
    imageStore(outColor, pixel, vec4(color, 1.0));
}
