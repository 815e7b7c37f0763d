// GTAO settings shared by C++ and GLSL: one struct, every field with its default
// and range. Defaults are XeGTAO's published ones (DESIGN.md), except that the
// thin-occluder compensation is compiled in and exposed.
#ifndef GROTTO_SHARED_GTAO_H
#define GROTTO_SHARED_GTAO_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_GTAO_DEPTH_MIPS 5u

struct GtaoSettings {
    float radius;                  // world units; default 4 voxels' worth is set per world (> 0)
    float radiusMultiplier;        // 1.457 (0.3 .. 3): compensates screen-space undersampling
    float falloffRange;            // 0.615 (0 .. 1): fraction of the radius over which occluders fade
    float sampleDistributionPower; // 2.0 (1 .. 3): > 1 puts more samples near the centre
    float thinOccluderCompensation;// 0 (0 .. 0.7): > 0 treats occluders as thinner than they look
    float finalValuePower;         // 2.2 (0.5 .. 5): contrast of the final visibility
    float depthMipSamplingOffset;  // 3.30 (0 .. 30): higher = later switch to coarser depth MIPs
    float maxDistance;             // view depth beyond which AO fades out (world units, > 0)
    float strength;                // 1 (0 .. 1): blend from no AO (0) to full AO (1)
    float denoiseBlurBeta;         // 1.2 (0 .. 10): edge-aware blur weight of the centre
    uint sliceCount;               // slices per pixel: low 1, medium 2, high 3, ultra 9
    uint stepsPerSlice;            // steps per side: low 2, medium 2, high 3, ultra 3
    uint denoisePasses;            // 1 (0 .. 4): edge-aware spatial blur passes
    uint frameIndex;               // advances the noise; the temporal pass steps it
    uint pad0, pad1;
};
GROTTO_STATIC_ASSERT(sizeof(GtaoSettings) == 64);

GROTTO_NAMESPACE_END
#endif
