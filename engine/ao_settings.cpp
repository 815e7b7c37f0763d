#include "engine/ao_settings.h"

#include "common/error.h"
#include "voxel/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grotto {

const char* aoMethodName(AoMethod m) {
    switch (m) {
    case AoMethod::Ssao: return "ssao";
    case AoMethod::Hbao: return "hbao";
    case AoMethod::Voxel: return "voxel";
    case AoMethod::Hybrid: return "hybrid";
    default: return "gtao";
    }
}

AoMethod parseAoMethod(const std::string& name, const std::string& where) {
    if (name == "gtao") return AoMethod::Gtao;
    if (name == "ssao") return AoMethod::Ssao;
    if (name == "hbao") return AoMethod::Hbao;
    if (name == "voxel") return AoMethod::Voxel;
    if (name == "hybrid") return AoMethod::Hybrid;
    throw Error(where, "unknown AO method '" + name + "'", "accepted: gtao, voxel, hybrid, ssao, hbao, off");
}

uint32_t voxelRaysPreset(AoMethod method, const std::string& quality) {
    const uint32_t rays = quality == "low" ? 2 : quality == "medium" ? 4 : quality == "ultra" ? 16 : 6;
    return method == AoMethod::Hybrid ? std::max(rays / 2, 1u) : rays;
}

gpu::GtaoSettings gtaoPreset(const std::string& quality, double radius) {
    gpu::GtaoSettings s{};
    s.radius = float(radius);
    // Fitted to the reference (docs/tuning.md: coordinate search, mean RMSE over
    // rooms, caves and thin at 640x360, 0.0771 -> 0.0741). XeGTAO's values in brackets.
    s.radiusMultiplier = 1.7f;           // [1.457]
    s.falloffRange = 0.615f;             // [0.615], the fit kept it
    s.sampleDistributionPower = 2.0f;
    s.thinOccluderCompensation = 0.2f;   // [0, compiled out there]
    s.finalValuePower = 1.9f;            // [2.2]
    s.depthMipSamplingOffset = 3.30f;
    s.strength = 1.0f;
    s.maxDistance = 0.0f;                // no limit
    s.denoiseBlurBeta = 1.2f;
    s.denoisePasses = 1;
    s.temporalHistory = kDefaultTemporalHistory;
    if (quality == "low") s.sliceCount = 1, s.stepsPerSlice = 2;
    else if (quality == "medium") s.sliceCount = 2, s.stepsPerSlice = 2;
    else if (quality == "high" || quality == "custom") s.sliceCount = 3, s.stepsPerSlice = 3;
    else if (quality == "ultra") s.sliceCount = 9, s.stepsPerSlice = 3;
    else throw Error("--quality", "unknown quality '" + quality + "'", "accepted: low, medium, high, ultra, custom");
    return s;
}

std::string aoFlagName(const std::string& setting) {
    if (setting == "temporal_history") return "--temporal";
    std::string flag = "--" + setting;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

void validateGtao(const gpu::GtaoSettings& s, const std::string& where) {
    // From the command line the error names the flag; from a file, file and setting.
    const bool flags = where == kCommandLine;
    auto check = [&](bool ok, const char* name, double value, const char* range) {
        if (ok) return;
        const std::string accepted = std::string("accepted: ") + range;
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        if (flags) throw Error(aoFlagName(name), std::string(text) + " is out of range", accepted);
        throw Error(where, "AO setting '" + std::string(name) + "' = " + text + " is out of range", accepted);
    };
    auto finite = [](double v) { return std::isfinite(v); };
    check(s.radius >= kMinAoRadius && s.radius <= kMaxAoRadius, "radius", s.radius, "1e-15 to 1e15 world units");
    check(s.radiusMultiplier >= 0.3f && s.radiusMultiplier <= 3.0f, "radius_multiplier", s.radiusMultiplier, "0.3 to 3");
    check(s.falloffRange >= 0.0f && s.falloffRange <= 1.0f, "falloff_range", s.falloffRange, "0 to 1");
    check(s.sampleDistributionPower >= 1.0f && s.sampleDistributionPower <= 3.0f, "sample_distribution_power",
          s.sampleDistributionPower, "1 to 3");
    check(s.thinOccluderCompensation >= 0.0f && s.thinOccluderCompensation <= 0.7f, "thin_occluder",
          s.thinOccluderCompensation, "0 to 0.7");
    check(s.finalValuePower >= 0.5f && s.finalValuePower <= 5.0f, "final_value_power", s.finalValuePower, "0.5 to 5");
    check(s.depthMipSamplingOffset >= 0.0f && s.depthMipSamplingOffset <= 30.0f, "depth_mip_offset",
          s.depthMipSamplingOffset, "0 to 30");
    check(finite(s.maxDistance) && s.maxDistance >= 0.0f && s.maxDistance <= 1e7f, "max_distance",
          s.maxDistance, "0 (no limit) to 1e7 world units");
    check(s.strength >= 0.0f && s.strength <= 1.0f, "strength", s.strength, "0 to 1");
    check(s.denoiseBlurBeta >= 0.0f && s.denoiseBlurBeta <= 10.0f, "denoise_blur_beta", s.denoiseBlurBeta, "0 to 10");
    check(s.sliceCount >= 1 && s.sliceCount <= 32, "slices", s.sliceCount, "1 to 32");
    check(s.stepsPerSlice >= 1 && s.stepsPerSlice <= 32, "steps", s.stepsPerSlice, "1 to 32");
    check(s.denoisePasses <= 4, "denoise", s.denoisePasses, "0 to 4");
    check(s.temporalHistory <= 64, "temporal_history", s.temporalHistory, "0 to 64");
}

void applyAoOverrides(const voxel::AoDesc& d, gpu::GtaoSettings& s) {
    if (d.radius) s.radius = float(*d.radius);
    if (d.radiusMultiplier) s.radiusMultiplier = float(*d.radiusMultiplier);
    if (d.falloffRange) s.falloffRange = float(*d.falloffRange);
    if (d.sampleDistributionPower) s.sampleDistributionPower = float(*d.sampleDistributionPower);
    if (d.thinOccluder) s.thinOccluderCompensation = float(*d.thinOccluder);
    if (d.finalValuePower) s.finalValuePower = float(*d.finalValuePower);
    if (d.depthMipOffset) s.depthMipSamplingOffset = float(*d.depthMipOffset);
    if (d.strength) s.strength = float(*d.strength);
    if (d.maxDistance) s.maxDistance = float(*d.maxDistance);
    if (d.denoiseBlurBeta) s.denoiseBlurBeta = float(*d.denoiseBlurBeta);
    if (d.slices) s.sliceCount = uint32_t(*d.slices);
    if (d.steps) s.stepsPerSlice = uint32_t(*d.steps);
    if (d.denoisePasses) s.denoisePasses = uint32_t(*d.denoisePasses);
    if (d.temporalHistory) s.temporalHistory = uint32_t(*d.temporalHistory);
}

AoOptions aoOptionsFor(const voxel::AoDesc& d, double voxelSize, const std::string& where) {
    AoOptions o;
    o.enabled = d.method != "off";
    if (o.enabled) o.method = parseAoMethod(d.method, where);
    o.quality = d.quality;
    o.ssaoSamples = d.quality == "low" ? 8 : d.quality == "medium" ? 16 : d.quality == "ultra" ? 64 : 32;
    o.voxelRays = d.rays ? uint32_t(*d.rays) : voxelRaysPreset(o.method, d.quality);
    // Without a radius of its own the world gets four voxels: always in range,
    // since a world's voxel size is (voxel/world.h).
    static_assert(kDefaultRadiusVoxels * voxel::kMinVoxelSize >= kMinAoRadius &&
                  kDefaultRadiusVoxels * voxel::kMaxVoxelSize <= kMaxAoRadius);
    o.gtao = gtaoPreset(d.quality, d.radius ? *d.radius : kDefaultRadiusVoxels * voxelSize);
    applyAoOverrides(d, o.gtao);
    validateGtao(o.gtao, where);
    return o;
}

}  // namespace grotto
