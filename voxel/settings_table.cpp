#include "voxel/settings_table.h"

#include "grotto/error.h"
#include "common/overloaded.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>
#include <type_traits>

namespace grotto::voxel {
namespace {

using T = SettingType;

constexpr std::string_view kMethods[] = {"gtao", "voxel", "hybrid", "ssao", "hbao", "vbao", "cache", "off"};
constexpr auto kQualities = [] {
    std::array<std::string_view, std::size(kAoPresets)> names;
    for (size_t i = 0; i < names.size(); ++i) names[i] = kAoPresets[i].name;
    return names;
}();
constexpr std::string_view kToneMaps[] = {"filmic", "linear"};  // ToneMap's order
constexpr std::string_view kAmbientSources[] = {"color", "sky", "full"};  // AmbientSource's order
constexpr std::string_view kSunSources[] = {"direction", "day"};  // SunSource's order
constexpr std::string_view kThicknessModes[] = {"constant", "distance", "voxels"};  // ThicknessMode's order

// Colours are linear RGB; above 1 is allowed (a bright sun), up to 1000.
constexpr double kMaxRadiance = 1e3;
// A direction needs no length: far beyond any typed one, well inside a float.
constexpr double kMaxDirection = 1e12;

// In world-file order: each block's fields in the order the reader reads and the
// writer writes them.
const Setting kSettings[] = {
    // Lighting (no flags: a world's light is its own).
    {.key = "lighting.sun.direction", .type = T::Direction, .desc = &Lighting::sunDirection,
     .lo = -kMaxDirection, .hi = kMaxDirection, .uiLo = -1.0, .uiHi = 1.0,
     .help = "Toward the sun; any length but zero (sun.from direction)"},
    {.key = "lighting.sun.color", .type = T::Color, .desc = &Lighting::sunColor, .lo = 0.0, .hi = kMaxRadiance,
     .help = "The sun's colour, linear RGB"},
    {.key = "lighting.sun.intensity", .type = T::Number, .desc = &Lighting::sunIntensity, .lo = 0.0,
     .hi = kMaxRadiance, .uiLo = 0.0, .uiHi = 4.0, .help = "The sun's radiance, times its colour"},
    {.key = "lighting.sun.shadows", .type = T::Bool, .desc = &Lighting::sunShadows,
     .help = "Exact voxel shadows from the sun"},
    {.key = "lighting.sun.angle", .type = T::Number, .desc = &Lighting::sunAngle, .lo = 0.0, .hi = 30.0,
     .help = "The sun's angular diameter in degrees; 0: a point, hard shadows"},
    {.key = "lighting.sun.from", .type = T::Choice, .desc = &Lighting::sunFrom,
     .help = "direction: a fixed sun along sun.direction, its colour and the sky as given; day: the sun on the "
             "day's path at day.time, its colour and the sky (given for the high sun) dimming and reddening as it "
             "sets, night below the horizon",
     .choices = kSunSources},
    {.key = "lighting.day.time", .type = T::Number, .desc = &Lighting::timeOfDay, .lo = 0.0, .hi = 24.0,
     .help = "Hours of local solar time (12: noon), for sun.from day"},
    {.key = "lighting.day.latitude", .type = T::Number, .desc = &Lighting::latitude, .lo = -90.0, .hi = 90.0,
     .help = "Degrees north of the equator the world lies at, for sun.from day"},
    {.key = "lighting.day.day_of_year", .type = T::Number, .desc = &Lighting::dayOfYear, .lo = 1.0, .hi = 365.0,
     .help = "The day of the year (80: the March equinox, 172: the June solstice), for sun.from day"},
    {.key = "lighting.day.north", .type = T::Number, .desc = &Lighting::north, .lo = -360.0, .hi = 360.0,
     .help = "Degrees from -z toward +x where north lies (0: north is -z, east +x), for sun.from day"},
    {.key = "lighting.ambient.color", .type = T::Color, .desc = &Lighting::ambientColor, .lo = 0.0,
     .hi = kMaxRadiance, .help = "The ambient light's colour, linear RGB"},
    {.key = "lighting.ambient.intensity", .type = T::Number, .desc = &Lighting::ambientIntensity, .lo = 0.0,
     .hi = kMaxRadiance, .uiLo = 0.0, .uiHi = 4.0, .help = "The ambient light, times its colour, before AO"},
    {.key = "lighting.ambient.from", .type = T::Choice, .desc = &Lighting::ambientFrom,
     .help = "color: the ambient colour on every surface; sky: the sky gradient's light on each surface, "
             "around VBAO's bent normal (times the intensity, before AO); full: the face cache's baked light, "
             "the sky, glowing materials and every bounce (ao.method cache and a bake)",
     .choices = kAmbientSources},
    {.key = "lighting.sky.zenith", .type = T::Color, .desc = &Lighting::skyZenith, .lo = 0.0, .hi = kMaxRadiance,
     .help = "The sky straight up, linear RGB"},
    {.key = "lighting.sky.horizon", .type = T::Color, .desc = &Lighting::skyHorizon, .lo = 0.0, .hi = kMaxRadiance,
     .help = "The sky at the horizon, linear RGB"},
    {.key = "lighting.exposure", .type = T::Number, .desc = &Lighting::exposure, .lo = 1e-3, .hi = 1e3,
     .uiLo = 0.05, .uiHi = 4.0, .help = "Radiance multiplier before the tone map"},
    {.key = "lighting.tone_map", .type = T::Choice, .desc = &Lighting::toneMap,
     .help = "How lit radiance maps to display values", .choices = kToneMaps},

    // AO.
    {.key = "ao.method", .flag = "--ao", .type = T::Choice, .desc = &AoDesc::method,
     .help = "Ambient occlusion (voxel: exact rays through the voxels; hybrid: GTAO plus voxel rays; "
             "vbao: GTAO's slices as sector bitmasks, occluders of finite thickness; cache: AO, sky light and sun "
             "cached on the voxel faces, from grotto bake or baked at load; ssao, hbao: baselines)",
     .manifest = "method", .choices = kMethods},
    {.key = "ao.quality", .flag = "--quality", .type = T::Choice, .desc = &AoDesc::quality,
     .help = "Preset of the loop shape (SSAO: 8, 16, 32, 64 samples; custom: high's, for --slices, --steps, "
             "--rays)",
     .manifest = "quality", .choices = kQualities},
    {.key = "ao.radius", .flag = "--radius", .type = T::Number, .desc = &AoDesc::radius,
     .value = &EstimatorSettings::radius, .lo = 1e-15, .hi = 1e15, .uiLo = 1.0 / 16.0, .uiHi = 16.0,
     .help = "AO radius", .accepted = "1e-15 to 1e15 world units", .defaultNote = "4 voxels",
     .manifest = "radius", .uiRelative = true},
    {.key = "ao.radius_multiplier", .flag = "--radius-multiplier", .type = T::Number,
     .desc = &AoDesc::radiusMultiplier, .value = &EstimatorSettings::radiusMultiplier, .lo = 0.3, .hi = 3.0,
     .help = "Screen-space radius compensation", .defaultNote = "1.7 (vbao: 2)", .manifest = "radius_multiplier"},
    {.key = "ao.falloff_range", .flag = "--falloff-range", .type = T::Number, .desc = &AoDesc::falloffRange,
     .value = &EstimatorSettings::falloffRange, .lo = 0.0, .hi = 1.0,
     .help = "Fraction of the radius over which occluders fade", .defaultNote = "0.615 (vbao: 0.3)",
     .manifest = "falloff_range"},
    {.key = "ao.sample_distribution_power", .flag = "--sample-distribution-power", .type = T::Number,
     .desc = &AoDesc::sampleDistributionPower, .value = &EstimatorSettings::sampleDistributionPower, .lo = 1.0,
     .hi = 3.0, .help = "Step spacing power", .manifest = "sample_distribution_power"},
    {.key = "ao.thin_occluder", .flag = "--thin-occluder", .type = T::Number, .desc = &AoDesc::thinOccluder,
     .value = &EstimatorSettings::thinOccluder, .lo = 0.0, .hi = 0.7, .help = "Thin-occluder compensation",
     .manifest = "thin_occluder"},
    {.key = "ao.final_value_power", .flag = "--final-value-power", .type = T::Number,
     .desc = &AoDesc::finalValuePower, .value = &EstimatorSettings::finalValuePower, .lo = 0.5, .hi = 5.0,
     .help = "Contrast of the final visibility", .defaultNote = "1.9 (vbao: 1.6)", .manifest = "final_value_power"},
    {.key = "ao.depth_mip_offset", .flag = "--depth-mip-offset", .type = T::Number, .desc = &AoDesc::depthMipOffset,
     .value = &EstimatorSettings::depthMipOffset, .lo = 0.0, .hi = 30.0,
     .help = "Higher = coarser depth MIPs later", .manifest = "depth_mip_offset"},
    {.key = "ao.strength", .flag = "--strength", .type = T::Number, .desc = &AoDesc::strength,
     .value = &ChainSettings::strength, .lo = 0.0, .hi = 1.0, .help = "AO strength in the composite (0: none)",
     .manifest = "strength"},
    {.key = "ao.max_distance", .flag = "--max-distance", .type = T::Number, .desc = &AoDesc::maxDistance,
     .value = &EstimatorSettings::maxDistance, .lo = 0.0, .hi = 1e7, .uiLo = 0.0, .uiHi = 1e3,
     .help = "View depth where AO has faded out", .accepted = "0 (no limit) to 1e7 world units",
     .manifest = "max_distance"},
    {.key = "ao.thickness", .flag = "--thickness", .type = T::Choice, .desc = &AoDesc::thickness,
     .help = "VBAO: how deep an occluder reaches behind what the depth buffer shows (constant: "
             "--thickness-value world units; distance: --thickness-value times its view depth; voxels: "
             "as far as its voxels go along the view ray)",
     .manifest = "thickness", .choices = kThicknessModes,
     .vbaoOnly = true},
    {.key = "ao.thickness_value", .flag = "--thickness-value", .type = T::Number, .desc = &AoDesc::thicknessValue,
     .value = &EstimatorSettings::thickness, .lo = 0.0, .hi = 1e7, .uiLo = 0.0, .uiHi = 16.0,
     .help = "VBAO: the thickness, in world units (constant) or times the view depth (distance)",
     .accepted = "0 to 1e7", .defaultNote = "1 voxel (constant), 0.1 (distance)", .manifest = "thickness_value",
     .vbaoOnly = true},
    {.key = "ao.denoise_blur_beta", .flag = "--denoise-blur-beta", .type = T::Number,
     .desc = &AoDesc::denoiseBlurBeta, .value = &ChainSettings::denoiseBlurBeta, .lo = 0.0, .hi = 10.0,
     .help = "Centre weight of the denoise blur", .manifest = "denoise_blur_beta"},
    {.key = "ao.slices", .flag = "--slices", .type = T::Whole, .desc = &AoDesc::slices,
     .value = &EstimatorSettings::slices, .lo = 1, .hi = 32, .help = "GTAO slices per pixel",
     .defaultNote = "the preset's", .manifest = "slices",
     .presetShaped = true},
    {.key = "ao.steps", .flag = "--steps", .type = T::Whole, .desc = &AoDesc::steps,
     .value = &EstimatorSettings::steps, .lo = 1, .hi = 32, .help = "GTAO steps per side of a slice",
     .defaultNote = "the preset's", .manifest = "steps",
     .presetShaped = true},
    {.key = "ao.denoise", .flag = "--denoise", .type = T::Whole, .desc = &AoDesc::denoisePasses,
     .value = &ChainSettings::denoisePasses, .lo = 0, .hi = 4, .help = "Spatial denoise passes",
     .manifest = "denoise"},
    {.key = "ao.temporal_history", .flag = "--temporal", .type = T::Whole, .desc = &AoDesc::temporalHistory,
     .value = &ChainSettings::temporalHistory, .lo = 0, .hi = 64,
     .help = "Most frames the temporal pass averages (0: off)", .manifest = "temporal"},
    {.key = "ao.rays", .flag = "--rays", .type = T::Whole, .desc = &AoDesc::rays, .value = &EstimatorSettings::rays,
     .lo = 1, .hi = 64, .help = "Voxel and hybrid AO: rays per AO pixel per frame", .defaultNote = "the preset's",
     .manifest = "rays", .presetShaped = true, .tracingOnly = true},
    {.key = "ao.cache_rays", .flag = "--cache-rays", .type = T::Whole, .desc = &AoDesc::cacheRays,
     .value = &ChainSettings::cacheRays, .lo = 0, .hi = 1e9, .uiLo = 0, .uiHi = 64e6,
     .help = "Face cache: rays per frame for the texels in view that have not converged (0: the device's default)",
     .manifest = "cache_rays"},
    {.key = "ao.full_resolution", .flag = "--ao-full-res", .type = T::Bool, .desc = &AoDesc::fullResolution,
     .value = &ChainSettings::fullResolution, .help = "Run the AO chain at full instead of half resolution",
     .manifest = "full_resolution"},

    // Detail.
    {.key = "detail.lod_bias", .flag = "--lod-bias", .type = T::Number, .desc = &Detail::lodBias, .lo = 0.0,
     .hi = 64.0, .uiLo = 0.0, .uiHi = 16.0,
     .help = "Largest size in pixels a coarse cell of far chunks may cover (0: exact voxels everywhere)",
     .manifest = "lod_bias"},
    {.key = "detail.occlusion_culling", .flag = "--occlusion-culling", .type = T::Bool,
     .desc = &Detail::occlusionCulling, .help = "Skip clusters of quads hidden behind nearer geometry",
     .manifest = "occlusion_culling"},
};

std::string number(double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", d);
    return text;
}

std::string joined(std::span<const std::string_view> names) {
    std::string s;
    for (std::string_view n : names) s += (s.empty() ? "" : ", ") + std::string(n);
    return s;
}

}  // namespace

std::span<const Setting> settingsTable() { return kSettings; }

const Setting* findSetting(std::string_view key) {
    for (const Setting& s : kSettings)
        if (s.key == key) return &s;
    return nullptr;
}

const Setting& setting(std::string_view key) {
    if (const Setting* s = findSetting(key)) return *s;
    throw Error::internal("settings table", "no setting '" + std::string(key) + "'");
}

std::string acceptedText(const Setting& s) {
    if (!s.accepted.empty()) return std::string(s.accepted);
    if (s.type == SettingType::Choice) return joined(s.choices);
    if (s.type == SettingType::Bool) return "true or false";
    return number(s.lo) + " to " + number(s.hi);
}

std::string settingLabel(const Setting& s) {
    const std::string_view key = s.key;
    const size_t block = key.find('.');
    std::string label(key.substr(block + 1));
    std::replace(label.begin(), label.end(), '.', ' ');
    std::replace(label.begin(), label.end(), '_', ' ');
    return key.substr(0, block) == "ao" && s.type == SettingType::Choice ? "AO " + label : label;
}

std::string defaultText(const Setting& s) {
    if (!s.defaultNote.empty()) return std::string(s.defaultNote);
    const WorldDesc desc;
    if (s.type == SettingType::Choice) {
        if (const auto* m = std::get_if<std::string AoDesc::*>(&s.desc)) return desc.ao.*(*m);
        return std::visit(Overloaded{[&]<class E>(E Lighting::*m) -> std::string requires std::is_enum_v<E> {
                                         return std::string(s.choices[size_t(desc.lighting.*m)]);
                                     },
                                     [&](auto) -> std::string {
                                         throw Error::internal("settings table", "'" + std::string(s.key) + "' is no choice");
                                     }},
                          s.desc);
    }
    if (s.type == SettingType::Color || s.type == SettingType::Direction) {
        const glm::vec3 v = desc.lighting.*std::get<glm::vec3 Lighting::*>(s.desc);
        return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
    }
    const double v = settingNumber(s, desc, EstimatorSettings{}, ChainSettings{});
    return s.type == SettingType::Bool ? (v != 0.0 ? "true" : "false") : number(v);
}

std::pair<double, double> uiRange(const Setting& s) {
    return s.uiLo != 0.0 || s.uiHi != 0.0 ? std::pair(s.uiLo, s.uiHi) : std::pair(s.lo, s.hi);
}

double settingNumber(const Setting& s, const WorldDesc& desc, const EstimatorSettings& estimator,
                     const ChainSettings& chain) {
    if (!std::holds_alternative<std::monostate>(s.value))
        return std::visit(Overloaded{[](std::monostate) { return 0.0; },
                                     [&](auto EstimatorSettings::*m) { return double(estimator.*m); },
                                     [&](auto ChainSettings::*m) { return double(chain.*m); }},
                          s.value);
    return std::visit(Overloaded{[&](float Lighting::*m) { return double(desc.lighting.*m); },
                                 [&](bool Lighting::*m) { return desc.lighting.*m ? 1.0 : 0.0; },
                                 [&](double Detail::*m) { return desc.detail.*m; },
                                 [&](bool Detail::*m) { return desc.detail.*m ? 1.0 : 0.0; },
                                 [&](auto) -> double {
                                     throw Error::internal("settings table", "'" + std::string(s.key) + "' is not a number");
                                 }},
                      s.desc);
}

void resetPresetShaped(AoDesc& ao) {
    for (const Setting& s : kSettings)
        if (s.presetShaped) std::visit(Overloaded{[&](auto AoDesc::*m) { ao.*m = {}; }, [](auto) {}}, s.desc);
}

bool usedBy(const Setting& s, std::string_view method) {
    if (method == "cache" && s.key.substr(0, 3) == "ao.")
        return s.key == "ao.method" || s.key == "ao.radius" || s.key == "ao.strength" || s.key == "ao.cache_rays";
    if (s.key == "ao.cache_rays") return false;
    if (s.tracingOnly) return method == "voxel" || method == "hybrid";
    if (s.vbaoOnly) return method == "vbao";
    return true;
}

void overlayAo(const AoDesc& over, AoDesc& ao) {
    for (const Setting& s : kSettings)
        std::visit(Overloaded{[&](std::string AoDesc::*m) {
                                  if (!(over.*m).empty()) ao.*m = over.*m;  // a choice given
                              },
                              [&](auto AoDesc::*m) {
                                  if (over.*m) ao.*m = over.*m;
                              },
                              [](auto) {}},
                   s.desc);
}

}  // namespace grotto::voxel
