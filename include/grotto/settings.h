#pragma once
// The settings of a world as plain data: its palette's materials, a camera, the
// lighting and the AO settings. A world file's blocks hold the same; a game sets
// them through Engine (grotto/grotto.h).
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace grotto {

struct Material {
    std::string name;
    glm::vec3 albedo{0.7f};  // linear RGB in [0, 1]
    float ao = 1.0f;         // baked occlusion of the material in [0, 1]; the composite takes min(AO, this)
    // Light the material gives off from every face, the same in every direction:
    // radiance = emissionColor x emissionIntensity, in the scale of the sun and sky
    // (docs/lighting.md, "Units"). Intensity 0: it does not glow.
    glm::vec3 emissionColor{1.0f};  // linear RGB in [0, 1]
    float emissionIntensity = 0.0f; // 0 to 1e5
    glm::vec3 emission() const { return emissionColor * emissionIntensity; }
    bool emits() const { return emissionIntensity > 0.0f && (emissionColor.r > 0.0f || emissionColor.g > 0.0f || emissionColor.b > 0.0f); }
};

struct CameraDesc {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};  // looked-at point, world units
    double fovDegrees = 60.0;           // vertical field of view
    double nearPlane = 0.05;            // world units
    double farPlane = 0.0;              // 0 = infinite (reverse-Z)
};

// How the composite maps lit radiance (times the exposure) to display values.
enum class ToneMap {
    Filmic,  // a filmic curve: a toe for the shadows, highlights rolling off to white
    Linear,  // clamped to [0, 1] only, for comparisons with unmapped radiance
};

// Where the ambient light comes from.
enum class AmbientSource {
    Color,  // a constant colour times the intensity, times AO
    Sky,    // the sky gradient's light on the surface (around VBAO's bent normal), times the intensity, times AO
    Full,   // the face cache's full light: the sky, the glowing materials and every bounce (ao.method cache, baked)
};

// Where the sun stands.
enum class SunSource {
    Direction,  // sunDirection, the colour and the sky as given: a fixed sun from anywhere, even below
    Day,        // the day's path at timeOfDay; the sun's colour and the sky follow its elevation (docs/lighting.md)
};

struct Lighting {
    glm::vec3 sunDirection{0.466002f, 0.828449f, 0.310668f};  // toward the sun, unit length ((0.45, 0.8, 0.3) normalised)
    glm::vec3 sunColor{1.0f, 0.95f, 0.85f};
    float sunIntensity = 1.0f;  // the shipped worlds' daylight, so an untuned .vdb looks like them
    bool sunShadows = true;     // exact voxel shadows from the sun (docs/lighting.md)
    float sunAngle = 0.0f;      // the sun's angular diameter in degrees; 0: a point, hard shadows
    glm::vec3 ambientColor{0.55f, 0.65f, 0.85f};
    float ambientIntensity = 0.7f;
    AmbientSource ambientFrom = AmbientSource::Color;
    glm::vec3 skyZenith{0.28f, 0.45f, 0.78f};
    glm::vec3 skyHorizon{0.75f, 0.82f, 0.92f};
    float exposure = 0.6f;      // radiance multiplier before the tone map (docs/lighting.md: why 0.6)
    ToneMap toneMap = ToneMap::Filmic;
    // The day (sunFrom Day): sunColor x sunIntensity and the sky are then the high
    // sun's, dimmed and reddened as it sets; sunDirection is ignored.
    SunSource sunFrom = SunSource::Direction;
    float timeOfDay = 12.0f;  // hours of local solar time, 0 to 24 (12: noon)
    float latitude = 45.0f;   // degrees north, -90 to 90
    float dayOfYear = 80.0f;  // 1 to 365 (80: the March equinox)
    float north = 0.0f;       // degrees from -z toward +x where north lies (0: north is -z, east +x)
};

// The AO settings, as a world file's "ao" block: method, preset and any
// overrides (unset = the preset's). Keys, ranges and meanings: docs/worlds.md.
struct AoDesc {
    std::string method = "gtao";   // gtao, voxel, hybrid, vbao, cache, ssao, hbao (baselines) or off
    std::string quality = "high";  // low, medium, high, ultra, custom
    std::string thickness = "voxels";  // vbao: voxels, constant or distance
    std::optional<double> radius, radiusMultiplier, falloffRange, sampleDistributionPower, thinOccluder,
        finalValuePower, depthMipOffset, strength, denoiseBlurBeta, maxDistance, thicknessValue;
    std::optional<int> slices, steps, denoisePasses, temporalHistory, rays, cacheRays;
    std::optional<bool> fullResolution;
};

}  // namespace grotto
