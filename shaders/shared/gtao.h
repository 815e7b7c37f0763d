// AO settings and per-frame constants, shared by C++ and GLSL. The settings are
// packed from the estimator's and the chain's (voxel/ao_values.h, which holds the
// defaults; engine/ao_settings.cpp gpuSettings); keys and ranges are in
// voxel/settings_table.cpp. Thin-occluder compensation is compiled in and exposed.
#ifndef GROTTO_SHARED_GTAO_H
#define GROTTO_SHARED_GTAO_H
#include "common.h"
#include "objects.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_GTAO_DEPTH_MIPS 5
#define GROTTO_GTAO_GROUP 8u

struct GtaoSettings {
    float radius;                   // world units
    float radiusMultiplier;         // compensates for screen-space undersampling
    float falloffRange;             // fraction of the radius over which occluders fade out
    float sampleDistributionPower;  // > 1 puts more samples near the centre
    float thinOccluderCompensation; // > 0 treats occluders as thinner than they look
    float finalValuePower;          // contrast of the final visibility
    float depthMipSamplingOffset;   // higher = later switch to coarser depth MIPs
    float strength;                 // 0 = no AO, 1 = full AO
    float denoiseBlurBeta;          // centre weight of the edge-aware blur
    uint sliceCount;                // slices per pixel
    uint stepsPerSlice;             // steps per side
    uint denoisePasses;             // edge-aware spatial blur passes
    uint temporalHistory;           // most frames the temporal pass averages; 0 = no temporal pass
    float maxDistance;              // view depth, world units, where AO has faded out over the
                                    // last tenth; farther pixels skip the search. 0 = no limit
    float thickness;                // VBAO: how deep occluders are (world units, or x view depth)
    uint thicknessMode;             // VBAO: kVbaoThickness*
};
GROTTO_STATIC_ASSERT(sizeof(GtaoSettings) == 64);
#define kVbaoThicknessConstant 0u
#define kVbaoThicknessDistance 1u
#define kVbaoThicknessVoxels 2u  // read from the thickness atlas the depth prefilter traces

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
