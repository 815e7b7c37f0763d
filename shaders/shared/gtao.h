// GTAO settings and per-frame constants, shared by C++ and GLSL. Every setting
// carries its default and range; the defaults are XeGTAO's published values
// except three fitted to our ray-traced reference (docs/tuning.md),
// and thin-occluder compensation is compiled in and exposed.
#ifndef GROTTO_SHARED_GTAO_H
#define GROTTO_SHARED_GTAO_H
#include "common.h"
#include "objects.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_GTAO_DEPTH_MIPS 5
#define GROTTO_GTAO_GROUP 8u

struct GtaoSettings {
    float radius;                   // world units (> 0); default 4 voxels, from the world file or --radius
    float radiusMultiplier;         // 1.7 (0.3 .. 3): compensates for screen-space undersampling (XeGTAO 1.457; fitted)
    float falloffRange;             // 0.615 (0 .. 1): fraction of the radius over which occluders fade out (fit kept it)
    float sampleDistributionPower;  // 2.0 (1 .. 3): > 1 puts more samples near the centre
    float thinOccluderCompensation; // 0.2 (0 .. 0.7): > 0 treats occluders as thinner than they look (XeGTAO 0; fitted)
    float finalValuePower;          // 1.9 (0.5 .. 5): contrast of the final visibility (XeGTAO 2.2; fitted)
    float depthMipSamplingOffset;   // 3.30 (0 .. 30): higher = later switch to coarser depth MIPs
    float strength;                 // 1 (0 .. 1): 0 = no AO, 1 = full AO
    float denoiseBlurBeta;          // 1.2 (0 .. 10): centre weight of the edge-aware blur
    uint sliceCount;                // slices per pixel: low 1, medium 2, high 3, ultra 9 (1 .. 32)
    uint stepsPerSlice;             // steps per side: low 2, medium 2, high 3, ultra 3 (1 .. 32)
    uint denoisePasses;             // 1 (0 .. 4): edge-aware spatial blur passes
    uint temporalHistory;           // 16 (0 .. 64): most frames the temporal pass averages; 0 = no temporal pass
    float maxDistance;              // 0 (0 .. 1e7): view depth, world units, where AO has faded out over the
                                    // last tenth; farther pixels skip the search. 0 = no limit
    uint pad1, pad2;
};
GROTTO_STATIC_ASSERT(sizeof(GtaoSettings) == 64);

// What the GTAO passes need besides the settings, all at half resolution.
struct GtaoConstants {
    GtaoSettings settings;
    vec4 ndcToViewMul_Add;   // view xy = (fullResPixel * mul + add) * depth
    vec4 viewNormals[GROTTO_NORMAL_SLOTS];  // face normals in view space: the world's six (+X -X +Y -Y +Z -Z),
                                            // then 8 slots per object (shared/objects.h)
    uvec2 fullSize;
    uvec2 halfSize;          // AO resolution: ceil(full / 2), or full size when scale is 1
    uint frameIndex;         // advances the noise; the temporal pass will step it
    float pixelViewSize;     // view-space size of one half-res pixel at depth 1
    float depthA, depthB;    // view depth = depthB / (depth buffer value + depthA)
    uint scale;              // full-res pixels per AO pixel: 2 (half res, the default) or 1
    uint pad0, pad1, pad2;
};
GROTTO_STATIC_ASSERT(sizeof(GtaoConstants) == 64 + 16 + 16 * GROTTO_NORMAL_SLOTS + 16 + 16 + 16);

GROTTO_NAMESPACE_END
#endif
