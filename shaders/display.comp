#version 460
#extension GL_GOOGLE_include_directive : require
// The window's and a game's picture: the composite's scene-linear colour through
// the tone map (shared/tone_map.h, as the image writers apply it on the CPU),
// display-linear in [0, 1]. An sRGB target encodes it (the window's blit).
#include "shared/tone_map.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0, rgba32f) uniform readonly image2D sceneColor;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D displayColor;
layout(push_constant) uniform Push { uint curve; };  // GROTTO_TONE_MAP_*

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(displayColor)))) return;
    vec4 c = imageLoad(sceneColor, p);
    imageStore(displayColor, p, vec4(toneMap(c.r, curve), toneMap(c.g, curve), toneMap(c.b, curve), c.a));
}
