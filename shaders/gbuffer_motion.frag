#version 460
#extension GL_GOOGLE_include_directive : require
// The surface id, and the motion of the surface point under the pixel: where it
// was in the previous frame (pixels, previous minus current; both positions from
// the same interpolated clip coordinates, so what did not move reads exactly 0)
// and its view depth then.
#include "shared/frame.h"

layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };

layout(location = 0) flat in uint inSurface;
layout(location = 1) in vec4 inClip;
layout(location = 2) in vec4 inPreviousClip;
layout(location = 0) out uint outSurface;
layout(location = 1) out vec4 outMotion;

vec2 pixelOf(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * vec2(frame.size); }

void main() {
    outSurface = inSurface;
    outMotion = vec4(pixelOf(inPreviousClip) - pixelOf(inClip), inPreviousClip.w, 0.0);
}
