// The tone map, written once for GLSL and C++: scene-linear colour (radiance
// times the exposure, what the composite writes) to display-linear values in
// [0, 1], which sRGB encoding then turns into a PNG's bytes, a video's frames or
// the window's pixels. Wherever a display-referred image is made it applies
// this: the display pass on the GPU (display.comp), the image writers on the CPU.
// One channel at a time, so both languages read it alike.
#ifndef GROTTO_SHARED_TONE_MAP_H
#define GROTTO_SHARED_TONE_MAP_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_TONE_MAP_FILMIC 0u  // lighting.tone_map "filmic"
#define GROTTO_TONE_MAP_CLAMP 1u   // lighting.tone_map "linear": clamped to [0, 1] only

// Narkowicz's fit of the ACES filmic curve: a soft toe keeps ambient-lit shade
// from crushing to black, the shoulder rolls bright sunlit faces off toward
// white instead of clipping them. Negative input is black (the rational fit
// would turn it up again), the output clamped to [0, 1]; NaN stays NaN (8-bit
// encoding makes it 0).
GROTTO_INLINE float toneMap(float value, uint curve) {
    float x = value < 0.0f ? 0.0f : value;
    float y = curve == GROTTO_TONE_MAP_FILMIC ? (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f) : x;
    return y < 0.0f ? 0.0f : (y > 1.0f ? 1.0f : y);
}

GROTTO_NAMESPACE_END
#endif
