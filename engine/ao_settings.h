#pragma once
// Which AO a frame gets and with what settings: presets, world-file values and
// command-line overrides merged in that order, then checked against their ranges
// (voxel/settings_table.cpp holds the rows). The settings are the estimator's and
// the chain's (voxel/ao_values.h), packed into the GPU's struct for the shaders.
#include "shaders/shared/gtao.h"
#include "voxel/ao_values.h"
#include "voxel/world_desc.h"

#include <optional>
#include <string>

namespace grotto {
namespace voxel { struct Setting; }

// The estimator in the AO chain, in the order of ao.method's choices. Voxel
// traces exact rays through the world's voxels (the reference's definition, a
// few rays a frame); hybrid adds such rays to GTAO's horizons; VBAO keeps GTAO's
// slices but as bitmasks of 32 sectors, so an occluder hides only the sectors
// between its front and its back (docs/vbao.md). Cache is no chain at all: the
// composite reads AO, sky light and sun visibility converged on the voxel faces
// (docs/face-cache.md) at each full-resolution pixel. SSAO and HBAO are
// baselines for measuring GTAO against (docs/tradeoff.md). Each replaces only the
// main pass, writing the same image, so depth prefilter, denoise, temporal and
// upsample are shared.
enum class AoMethod { Gtao, Voxel, Hybrid, Ssao, Hbao, Vbao, Cache };

struct AoOptions {
    bool enabled = true;               // false for --ao off (no AO chain at all)
    AoMethod method = AoMethod::Gtao;  // --ao gtao | voxel | hybrid | ssao | hbao | vbao | cache
    std::string quality = "high";      // low, medium, high, ultra or custom
    voxel::EstimatorSettings estimator;
    voxel::ChainSettings chain;
};

// "gtao", "voxel", "hybrid", "ssao", "hbao", "vbao", "cache" (the timestamp names the main pass by too).
const char* aoMethodName(AoMethod method);
// Throws grotto::Error (input) naming `where` for anything but those.
AoMethod parseAoMethod(const std::string& name, const std::string& where);
// Is there a screen-space AO chain (estimator, denoise, temporal) at AO resolution?
inline bool aoChain(const AoOptions& ao) { return ao.enabled && ao.method != AoMethod::Cache; }
// Does the composite read the face cache (voxel/face_cache.h)?
inline bool faceCached(const AoOptions& ao) { return ao.enabled && ao.method == AoMethod::Cache; }
// Does the method trace rays through the world's voxels (and so need its occupancy)?
inline bool tracesVoxels(AoMethod m) { return m == AoMethod::Voxel || m == AoMethod::Hybrid; }
// Does VBAO read its occluders' thickness from the voxels (a traced thickness
// atlas beside the depth MIPs, and so the world's occupancy)?
inline bool voxelThickness(const AoOptions& ao) {
    return ao.enabled && ao.method == AoMethod::Vbao && ao.estimator.thicknessMode == voxel::ThicknessMode::Voxels;
}
// Rays per AO pixel per frame of a quality preset (docs/tradeoff.md measured them).
uint32_t voxelRaysPreset(AoMethod method, const std::string& quality);

// The AO radius's range in world units: the shaders square it (and its product
// with the radius multiplier) in 32-bit floats, which stay finite and normal
// within these bounds. The default radius is four voxels.
inline constexpr double kMinAoRadius = 1e-15, kMaxAoRadius = 1e15;
inline constexpr double kDefaultRadiusVoxels = 4.0;
// VBAO's own fit of the heuristics it shares with GTAO (grotto tune --ao vbao,
// docs/tuning.md): GTAO's fitted falloff fades VBAO's samples too soon.
inline constexpr double kVbaoFalloffRange = 0.3, kVbaoRadiusMultiplier = 2.0, kVbaoFinalValuePower = 1.6;
// VBAO's default thickness: one voxel behind each depth sample (constant), or a
// tenth of its view depth (distance).
inline constexpr double kDefaultThicknessVoxels = 1.0, kDefaultThicknessDistance = 0.1;

// Frames the temporal pass averages by default.
inline constexpr uint32_t kDefaultTemporalHistory = voxel::ChainSettings{}.temporalHistory;

// The defaults with the preset's loop shape (slices, steps, SSAO samples, rays);
// radius in world units. Throws grotto::Error (input) for an unknown quality.
voxel::EstimatorSettings estimatorPreset(const std::string& quality, double radius);

// The settings `desc` sets, over those in `ao` (unset ones stay); unchecked.
void applyAoOverrides(const voxel::AoDesc& desc, AoOptions& ao);

// Preset and values from the world file; throws grotto::Error naming `where`.
AoOptions aoOptionsFor(const voxel::AoDesc& desc, double voxelSize, const std::string& where);
// The same with the ranges unchecked (aoOutOfRange): for a caller that names a
// setting out of range in words of its own (the command line, its flag).
AoOptions uncheckedAoOptions(const voxel::AoDesc& desc, double voxelSize, const std::string& where);

// The first setting out of its accepted range: its row of the settings table and
// its value as text; none when all are in range.
struct AoOutOfRange {
    const voxel::Setting* row = nullptr;
    std::string value;
};
std::optional<AoOutOfRange> aoOutOfRange(const AoOptions& ao);
// Throws grotto::Error (input) naming `where`, the setting and its accepted range.
void validateAo(const AoOptions& ao, const std::string& where);

// The settings as the shaders take them (shaders/shared/gtao.h).
gpu::GtaoSettings gpuSettings(const AoOptions& ao);

}  // namespace grotto
