#pragma once
// The AO settings in effect once preset, world file and command line are merged:
// what the estimator computes with, and what the chain after it (denoise,
// temporal, upsample, composite) does with its output. Plain data with the
// defaults; the engine packs both into the GPU's struct (shaders/shared/gtao.h).
// Keys, ranges and help: voxel/settings_table.cpp.
#include <cstdint>

namespace grotto::voxel {

// How VBAO sizes an occluder behind its depth sample (shaders/shared/gtao.h's
// kVbaoThickness* values, in this order).
enum class ThicknessMode : uint32_t { Constant, Distance, Voxels };

struct EstimatorSettings {
    float radius = 4.0f;  // world units; a world's default is 4 of its voxels
    // Fitted to the reference (docs/tuning.md: coordinate search, mean RMSE over
    // rooms, caves and thin at 640x360, 0.0771 -> 0.0741). XeGTAO's values in brackets.
    float radiusMultiplier = 1.7f;  // [1.457]
    float falloffRange = 0.615f;    // [0.615], the fit kept it
    float sampleDistributionPower = 2.0f;
    float thinOccluder = 0.2f;      // [0, compiled out there]
    float finalValuePower = 1.9f;   // [2.2]
    float depthMipOffset = 3.30f;
    float maxDistance = 0.0f;       // no limit
    // VBAO: how far behind each depth sample its occluder reaches, in world units
    // (constant; a world's default is one of its voxels) or as a share of the
    // sample's view depth (distance); voxels reads it from the world's voxels.
    float thickness = 1.0f;
    ThicknessMode thicknessMode = ThicknessMode::Voxels;
    uint32_t slices = 3, steps = 3;  // the loop shape: the quality preset's (these are high's)
    uint32_t rays = 6;               // voxel and hybrid: rays per AO pixel per frame
    uint32_t ssaoSamples = 32;       // SSAO's kernel, from the quality alone
};

struct ChainSettings {
    uint32_t denoisePasses = 1;
    float denoiseBlurBeta = 1.2f;
    uint32_t temporalHistory = 16;  // most frames the temporal pass averages; 0: no temporal pass
    float strength = 1.0f;          // how much of the AO the composite applies
    bool fullResolution = false;    // the chain at full instead of half resolution
    // The face cache: rays per frame for the texels in view that have not
    // converged (0: the device's default, engine/passes/face_cache_trace_pass.h).
    uint32_t cacheRays = 0;
};

// A quality preset: the estimator's loop shape. HBAO takes GTAO's sample budget
// (2 x slices directions, steps per side); rays are the voxel method's (hybrid
// halves them); docs/tradeoff.md measured them. Custom is high's, for flags to change.
struct AoPreset {
    const char* name;
    uint32_t slices, steps, ssaoSamples, rays;
};
inline constexpr AoPreset kAoPresets[] = {{"low", 1, 2, 8, 2},
                                          {"medium", 2, 2, 16, 4},
                                          {"high", 3, 3, 32, 6},
                                          {"ultra", 9, 3, 64, 16},
                                          {"custom", 3, 3, 32, 6}};

}  // namespace grotto::voxel
