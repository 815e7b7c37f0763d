#pragma once
// Which AO a frame gets and with what settings: presets, world-file values and
// command-line overrides merged in that order, then checked against their ranges.
#include "shaders/shared/gtao.h"
#include "voxel/world_desc.h"

#include <string>

namespace grotto {

struct AoOptions {
    bool enabled = true;           // --ao gtao | off
    std::string quality = "high";  // low, medium, high, ultra or custom
    bool fullResolution = false;   // run the chain at full resolution (for comparison)
    gpu::GtaoSettings gtao{};
};

// XeGTAO's defaults with the preset's slices and steps; radius in world units.
gpu::GtaoSettings gtaoPreset(const std::string& quality, double radius);

// Preset and values from the world file; throws grotto::Error naming `where`.
AoOptions aoOptionsFor(const voxel::AoDesc& desc, double voxelSize, const std::string& where);

// Throws grotto::Error (input) naming the setting and its accepted range.
void validateGtao(const gpu::GtaoSettings& s, const std::string& where);

}  // namespace grotto
