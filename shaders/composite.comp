#version 460
#extension GL_GOOGLE_include_directive : require
// Sun Lambert + ambient x AO on surfaces, a gradient sky where nothing was drawn.
#include "shared/frame.h"

layout(local_size_x = GROTTO_COMPOSITE_GROUP, local_size_y = GROTTO_COMPOSITE_GROUP) in;
layout(set = 0, binding = 0, std430) readonly buffer Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2) uniform sampler2D normalTex;
layout(set = 0, binding = 3) uniform sampler2D albedoTex;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outColor;

vec3 sky(ivec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.size) * 2.0 - 1.0;
    vec4 p = frame.invViewProj * vec4(ndc, 1.0, 1.0);  // a point on the near plane
    vec3 dir = normalize(p.xyz / p.w);
    float up = clamp(dir.y, 0.0, 1.0);
    return dir.y >= 0.0 ? mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, sqrt(up))
                        : frame.skyHorizon.rgb * 0.8;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), frame.size))) return;
    float depth = texelFetch(depthTex, pixel, 0).r;
    vec3 color;
    if (depth <= 0.0) {  // reverse-Z: cleared to 0 where no surface was drawn
        color = sky(pixel);
    } else {
        vec3 n = normalize(texelFetch(normalTex, pixel, 0).xyz);
        vec3 albedo = texelFetch(albedoTex, pixel, 0).rgb;
        float ao = 1.0;
        float sun = max(dot(n, frame.sunDirection.xyz), 0.0);
        color = albedo * (frame.sunRadiance.rgb * sun + frame.ambient.rgb * ao);
    }
    imageStore(outColor, pixel, vec4(color, 1.0));
}
