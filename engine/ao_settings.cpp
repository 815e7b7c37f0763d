#include "engine/ao_settings.h"

#include "grotto/error.h"
#include "common/overloaded.h"
#include "voxel/settings_table.h"
#include "voxel/world.h"

#include <algorithm>
#include <cstdio>

namespace grotto {
namespace {

const voxel::Setting& methodRow() { return voxel::setting("ao.method"); }

voxel::ThicknessMode parseThicknessMode(const std::string& name, const std::string& where) {
    const voxel::Setting& row = voxel::setting("ao.thickness");
    for (size_t i = 0; i < row.choices.size(); ++i)
        if (name == row.choices[i]) return voxel::ThicknessMode(i);
    throw Error(where, "unknown AO thickness '" + name + "'", "accepted: " + acceptedText(row));
}

const voxel::AoPreset* findPreset(const std::string& quality) {
    for (const voxel::AoPreset& p : voxel::kAoPresets)
        if (quality == p.name) return &p;
    return nullptr;
}

}  // namespace

const char* aoMethodName(AoMethod m) { return methodRow().choices[size_t(m)].data(); }

AoMethod parseAoMethod(const std::string& name, const std::string& where) {
    const voxel::Setting& row = methodRow();
    for (size_t i = 0; i < row.choices.size(); ++i)
        if (name == row.choices[i] && name != "off") return AoMethod(i);
    throw Error(where, "unknown AO method '" + name + "'", "accepted: " + acceptedText(row));
}

uint32_t voxelRaysPreset(AoMethod method, const std::string& quality) {
    const voxel::AoPreset* p = findPreset(quality);
    const uint32_t rays = p ? p->rays : voxel::EstimatorSettings{}.rays;
    return method == AoMethod::Hybrid ? std::max(rays / 2, 1u) : rays;
}

voxel::EstimatorSettings estimatorPreset(const std::string& quality, double radius) {
    const voxel::AoPreset* p = findPreset(quality);
    if (!p)
        throw Error("AO quality", "unknown quality '" + quality + "'",
                    "accepted: " + acceptedText(voxel::setting("ao.quality")));
    voxel::EstimatorSettings s;
    s.radius = float(radius);
    s.slices = p->slices;
    s.steps = p->steps;
    s.ssaoSamples = p->ssaoSamples;
    s.rays = p->rays;
    return s;
}

std::optional<AoOutOfRange> aoOutOfRange(const AoOptions& ao) {
    for (const voxel::Setting& row : voxel::settingsTable()) {
        // Compared as the shaders hold them: floats with the bounds as floats.
        const bool ok = std::visit(
            Overloaded{[](std::monostate) { return true; }, [](bool voxel::ChainSettings::*) { return true; },
                       [&](float voxel::EstimatorSettings::*m) {
                           return ao.estimator.*m >= float(row.lo) && ao.estimator.*m <= float(row.hi);
                       },
                       [&](uint32_t voxel::EstimatorSettings::*m) {
                           return ao.estimator.*m >= row.lo && ao.estimator.*m <= row.hi;
                       },
                       [&](float voxel::ChainSettings::*m) {
                           return ao.chain.*m >= float(row.lo) && ao.chain.*m <= float(row.hi);
                       },
                       [&](uint32_t voxel::ChainSettings::*m) { return ao.chain.*m >= row.lo && ao.chain.*m <= row.hi; }},
            row.value);
        if (ok) continue;
        char value[32];
        std::snprintf(value, sizeof value, "%g", settingNumber(row, {}, ao.estimator, ao.chain));
        return AoOutOfRange{&row, value};
    }
    return std::nullopt;
}

void validateAo(const AoOptions& ao, const std::string& where) {
    const std::optional<AoOutOfRange> bad = aoOutOfRange(ao);
    if (!bad) return;
    const std::string name(bad->row->key.substr(bad->row->key.find('.') + 1));
    throw Error(where, "AO setting '" + name + "' = " + bad->value + " is out of range",
                "accepted: " + acceptedText(*bad->row));
}

void applyAoOverrides(const voxel::AoDesc& d, AoOptions& ao) {
    for (const voxel::Setting& row : voxel::settingsTable()) {
        // The world-file value, where it is set, into its place among the settings in effect.
        auto set = [&](auto& to) {
            std::visit(Overloaded{[&](auto voxel::AoDesc::*from) {
                                      if constexpr (requires { (d.*from).has_value(); })
                                          if (d.*from) to = std::remove_reference_t<decltype(to)>(*(d.*from));
                                  },
                                  [](auto) {}},
                       row.desc);
        };
        std::visit(Overloaded{[](std::monostate) {}, [&](auto voxel::EstimatorSettings::*to) { set(ao.estimator.*to); },
                              [&](auto voxel::ChainSettings::*to) { set(ao.chain.*to); }},
                   row.value);
    }
}

AoOptions aoOptionsFor(const voxel::AoDesc& d, double voxelSize, const std::string& where) {
    AoOptions o = uncheckedAoOptions(d, voxelSize, where);
    validateAo(o, where);
    return o;
}

AoOptions uncheckedAoOptions(const voxel::AoDesc& d, double voxelSize, const std::string& where) {
    AoOptions o;
    o.enabled = d.method != "off";
    if (o.enabled) o.method = parseAoMethod(d.method, where);
    o.quality = d.quality;
    // Without a radius of its own the world gets four voxels: always in range,
    // since a world's voxel size is (voxel/world.h).
    static_assert(kDefaultRadiusVoxels * voxel::kMinVoxelSize >= kMinAoRadius &&
                  kDefaultRadiusVoxels * voxel::kMaxVoxelSize <= kMaxAoRadius);
    o.estimator = estimatorPreset(d.quality, d.radius ? *d.radius : kDefaultRadiusVoxels * voxelSize);
    o.estimator.rays = voxelRaysPreset(o.method, d.quality);
    o.estimator.thicknessMode = parseThicknessMode(d.thickness, where);
    if (o.method == AoMethod::Vbao) {  // its own fit (docs/vbao.md)
        o.estimator.falloffRange = float(kVbaoFalloffRange);
        o.estimator.radiusMultiplier = float(kVbaoRadiusMultiplier);
        o.estimator.finalValuePower = float(kVbaoFinalValuePower);
    }
    o.estimator.thickness = float(o.estimator.thicknessMode == voxel::ThicknessMode::Distance
                                      ? kDefaultThicknessDistance
                                      : kDefaultThicknessVoxels * voxelSize);
    applyAoOverrides(d, o);
    return o;
}

gpu::GtaoSettings gpuSettings(const AoOptions& ao) {
    const voxel::EstimatorSettings& e = ao.estimator;
    const voxel::ChainSettings& c = ao.chain;
    gpu::GtaoSettings s{};
    s.radius = e.radius;
    s.radiusMultiplier = e.radiusMultiplier;
    s.falloffRange = e.falloffRange;
    s.sampleDistributionPower = e.sampleDistributionPower;
    s.thinOccluderCompensation = e.thinOccluder;
    s.finalValuePower = e.finalValuePower;
    s.depthMipSamplingOffset = e.depthMipOffset;
    s.strength = c.strength;
    s.denoiseBlurBeta = c.denoiseBlurBeta;
    s.sliceCount = e.slices;
    s.stepsPerSlice = e.steps;
    s.denoisePasses = c.denoisePasses;
    s.temporalHistory = c.temporalHistory;
    s.maxDistance = e.maxDistance;
    s.thickness = e.thickness;
    s.thicknessMode = uint32_t(e.thicknessMode);
    return s;
}

}  // namespace grotto
