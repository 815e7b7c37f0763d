#pragma once
// Small pieces the subcommands share: image sizes and the checks that end a run.
#include "engine/ao_settings.h"
#include "engine/vk/context.h"
#include "voxel/world.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace grotto::app {

struct Size {
    uint32_t width = 0, height = 0;
};

// "WxH" with both in 1..16384; throws grotto::Error (input) naming the option.
Size parseSize(const std::string& text, const std::string& option = "--size");

// "A-B" or "A": an inclusive range of 1-based frame numbers within 1..count;
// throws grotto::Error (input) naming the option.
struct FrameRange {
    int first = 1, last = 1;
};
FrameRange parseFrameRange(const std::string& text, int count, const std::string& option = "--frames");

// A path named in the world file, or a path .json given directly; throws
// grotto::Error (input) listing the world's paths when there is no such one.
voxel::CameraPathDesc findCameraPath(const voxel::World& world, const std::string& name);

// The AO flags every rendering subcommand takes; unset ones keep the world's values.
struct AoFlags {
    std::string method, quality;
    voxel::AoDesc set;  // the settings given, each flag named after its world-file key
    bool fullResolution = false;
};
void addAoFlags(CLI::App* cmd, AoFlags& flags);

// Preset, world file, then flags; throws grotto::Error (input) for nonsense.
AoOptions resolveAo(const voxel::World& world, const AoFlags& flags);

// Everything about the AO that decides the pixels, with the world file's keys:
// what a resumed flythrough or a stability baseline must match.
nlohmann::json aoSettingsJson(const AoOptions& ao);

// The median (0 for none): per-pass and frame times are reported as medians.
double median(std::vector<double> v);

// Fails the run (exit 1) when the validation layer reported anything.
void requireNoValidationMessages(const vk::Context& ctx);

}  // namespace grotto::app
