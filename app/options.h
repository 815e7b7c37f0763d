#pragma once
// Small pieces the subcommands share: image sizes and the checks that end a run.
#include "app/farm_chunk.h"
#include "engine/ao_settings.h"
#include "engine/camera_path.h"
#include "engine/frame/chunk_culling.h"
#include "engine/session.h"
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
    double aspect() const { return double(width) / double(height); }
};

// "WxH" with both in 1..16384; throws grotto::Error (input) naming the option.
Size parseSize(const std::string& text, const std::string& option = "--size");

// "A-B": frames A to B, or "N": the first N frames (1-N); 1-based, inclusive,
// within 1..count. Throws grotto::Error (input) naming the option.
struct FrameRange {
    int first = 1, last = 1;
    int count() const { return last - first + 1; }
};
FrameRange parseFrameRange(const std::string& text, int count, const std::string& option = "--frames");

// The K-th (1-based) of N contiguous ranges that split frames 1..count as evenly
// as can be (the first count % N ranges one frame longer than the rest); empty
// (count() 0) when N > count leaves chunk K without frames.
FrameRange chunkFrames(const ChunkOfN& chunk, int count);

// The most frames a path may have (11.5 hours at 24 fps): frame numbers stay
// well inside int, and a typo in --fps or a key time is caught before rendering.
inline constexpr int64_t kMaxPathFrames = 1'000'000;

// The path's frames at `fps`; throws grotto::Error (input) naming --fps and the
// path's duration when there would be more than kMaxPathFrames.
int pathFrameCount(const CameraPath& path, int fps, const std::string& name);

// A path named in the world file, or a path file given directly (a path .json, or
// a glTF .glb/.gltf whose animated camera becomes the path: voxel/gltf/gltf_camera.h),
// with its edits checked against the world (checkPathEdits); throws grotto::Error
// (input) listing the world's paths when there is no such one. A path with a
// day track lights `world` by the day's sun from its first hour on, so a face
// cache given or baked for its frames is the day's (docs/face-cache.md).
voxel::CameraPathDesc findCameraPath(voxel::World& world, const std::string& name);

// --path NAME and --path-file FILE, one of them required, both into `path`.
void addPathOptions(CLI::App* cmd, std::string& path);

// The AO flags every rendering subcommand takes, with the level-of-detail ones:
// one per setting of voxel/settings_table.cpp that has a flag; unset ones keep
// the world's values.
struct AoFlags {
    voxel::AoDesc set{.method = {}, .quality = {}, .thickness = {}};  // the AO settings given; choices empty when not
    std::string bake;  // --bake: a face cache from grotto bake (implies --ao cache)
    bool progressive = false;  // --progressive: --ao cache without a bake starts empty, traced on the GPU in view
    nlohmann::ordered_json detail = nlohmann::ordered_json::object();  // the "detail" block's fields given
    std::optional<double> timeOfDay;  // --time-of-day: hours; the sun on the world's day path
};
void addAoFlags(CLI::App* cmd, AoFlags& flags);
// Only --lod-bias and --occlusion-culling (addAoFlags adds them too): for a
// command that chooses the AO settings itself.
void addDetailFlags(CLI::App* cmd, AoFlags& flags);
// --time-of-day alone: for a command that takes no AO flags (bake, reference).
void addTimeOfDayFlag(CLI::App* cmd, AoFlags& flags);

// World::load, then the lighting flags over the world's (--time-of-day puts its
// sun on the day's path at that hour). Throws as World::load does.
voxel::World loadWorld(const std::filesystem::path& path, const AoFlags& flags);

// The world's "ao" block with the flags given over it (--quality replaces the
// world's slices, steps and rays): what a viewer starts from.
voxel::AoDesc aoDescWithFlags(const voxel::AoDesc& world, const AoFlags& flags);

// Preset, world file, then flags; throws grotto::Error (input) for nonsense,
// and for a --bake whose header is not this world's (voxel::requireBakeOf).
AoOptions resolveAo(const voxel::World& world, const AoFlags& flags);

// The world file's "detail" block, then --lod-bias and --occlusion-culling.
voxel::Detail resolveDetail(const voxel::World& world, const AoFlags& flags);
nlohmann::json detailJson(const voxel::Detail& detail);  // the settings table's manifest keys

// Everything about the AO that decides the pixels, with the settings table's
// manifest keys: what a resumed flythrough or a stability baseline must match.
nlohmann::json aoSettingsJson(const AoOptions& ao);

// CLI::Range for floating options that also refuses NaN (which compares false
// with both bounds, so CLI::Range lets it through) and infinities.
CLI::Validator finiteRange(double min, double max);

// The same for whole-number options: a fraction or a word is refused with the
// range too, not with CLI11's bare "could not be converted".
CLI::Validator wholeRange(int min, int max);

// The median (0 for none): per-pass and frame times are reported as medians.
double median(std::vector<double> v);

// Fails the run (exit 1) when the validation layer reported anything.
void requireNoValidationMessages(const vk::Context& ctx);

}  // namespace grotto::app
