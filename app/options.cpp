#include "app/options.h"
#include "app/commands.h"

#include "common/file_kind.h"
#include "grotto/error.h"
#include "common/overloaded.h"
#include "engine/scene/path_edits.h"
#include "voxel/face_cache_file.h"
#include "voxel/gltf/gltf_camera.h"
#include "voxel/settings_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace grotto::app {

Size parseSize(const std::string& text, const std::string& option) {
    // Digits only, read without wrapping: sscanf's %u would take 4294967297 as 1 and -1 as 4294967295.
    auto side = [](const char* first, const char* last, uint32_t& v) {
        uint64_t n = 0;
        const auto [end, error] = std::from_chars(first, last, n);
        const bool whole = first != last && end == last && error == std::errc();
        v = whole && n >= 1 && n <= 16384 ? uint32_t(n) : 0;
        return v != 0;
    };
    const size_t x = text.find('x');
    Size s;
    if (x == std::string::npos || !side(text.data(), text.data() + x, s.width) ||
        !side(text.data() + x + 1, text.data() + text.size(), s.height))
        throw Error(option, "'" + text + "' is not a valid size", "expected WxH with both in 1..16384, e.g. 1280x720");
    return s;
}

FrameRange parseFrameRange(const std::string& text, int count, const std::string& option) {
    int a = 0, b = 0, n = 0;
    const char* s = text.c_str();
    const bool range = std::sscanf(s, "%d-%d%n", &a, &b, &n) == 2 && s[n] == 0;
    const bool single = !range && std::sscanf(s, "%d%n", &a, &n) == 1 && s[n] == 0;
    if (single) b = a, a = 1;  // N: the first N frames
    const std::string accepted = "expected A-B with 1 <= A <= B <= " + std::to_string(count) +
                                 " (the path's frames), or N for the first N";
    if (!range && !single) throw Error(option, "'" + text + "' is not a frame range", accepted);
    if (a < 1 || b < a || b > count) throw Error(option, "'" + text + "' is out of range", accepted);
    return {a, b};
}

FrameRange chunkFrames(const ChunkOfN& chunk, int count) {
    const int base = count / chunk.n, longer = count % chunk.n;  // chunks 1..longer have base + 1 frames
    const int first = 1 + (chunk.k - 1) * base + std::min(chunk.k - 1, longer);
    return {first, first + base + (chunk.k <= longer ? 1 : 0) - 1};
}

int pathFrameCount(const CameraPath& path, int fps, const std::string& name) {
    const int64_t count = path.frameCount(fps);
    if (count <= kMaxPathFrames) return int(count);
    char text[160];
    std::snprintf(text, sizeof text, "path '%s' lasts %g s, which makes %lld frames at %d fps", name.c_str(),
                  path.duration(), (long long)count, fps);
    throw Error("--fps", text,
                "accepted: at most " + std::to_string(kMaxPathFrames) + " frames; lower --fps or shorten the path");
}

namespace {

// --help for a setting's flag: what it does, what it accepts, its default.
std::string flagHelp(const voxel::Setting& s) {
    std::string help(s.help);
    if (s.type == voxel::SettingType::Choice || s.type == voxel::SettingType::Bool) help += ":";
    else help += ",";
    help += " " + voxel::acceptedText(s) + " (default: the world's, else " + voxel::defaultText(s);
    return help + (s.presetShaped ? "; setting it makes the quality custom)" : ")");
}

// Where a setting given on the command line is named in the errors that do not name its flag.
const std::string kCommandLine = "command line";

// The world-file settings of `block` ("ao", "detail") that have flags.
template <class F>
void forFlags(std::string_view block, F&& f) {
    for (const voxel::Setting& s : voxel::settingsTable())
        if (!s.flag.empty() && s.key.substr(0, s.key.find('.')) == block) f(s);
}

}  // namespace

void addAoFlags(CLI::App* cmd, AoFlags& f) {
    // Out-of-range values exit 2 naming the flag (validateAo, after the world's values are merged).
    forFlags("ao", [&](const voxel::Setting& s) {
        const std::string flag(s.flag);
        std::visit(Overloaded{[&](std::string voxel::AoDesc::*m) {
                                  std::vector<std::string> choices(s.choices.begin(), s.choices.end());
                                  cmd->add_option(flag, f.set.*m, flagHelp(s))->check(CLI::IsMember(choices));
                              },
                              [&](std::optional<bool> voxel::AoDesc::*m) {
                                  cmd->add_flag_callback(flag, [&f, m] { f.set.*m = true; }, std::string(s.help));
                              },
                              [&](auto voxel::AoDesc::*m) { cmd->add_option(flag, f.set.*m, flagHelp(s)); },
                              [](auto) {}},
                   s.desc);
    });
    cmd->add_option("--bake", f.bake, "Face cache from grotto bake of this world (implies --ao cache)");
    cmd->add_flag("--progressive", f.progressive,
                  "With --ao cache and no --bake: bake nothing first; the GPU traces the faces in view as frames go, "
                  "within --cache-rays a frame (a still renders until they have converged)");
    addDetailFlags(cmd, f);
    addTimeOfDayFlag(cmd, f);
}

void addTimeOfDayFlag(CLI::App* cmd, AoFlags& f) {
    const voxel::Setting& s = voxel::setting("lighting.day.time");
    cmd->add_option("--time-of-day", f.timeOfDay,
                    "Hours of local solar time, 0 to 24 (12: noon): the sun on the world's day path (lighting.day; "
                    "latitude 45, the equinox where the world states none), its colour and the sky following it")
        ->check(finiteRange(s.lo, s.hi));
}

voxel::World loadWorld(const std::filesystem::path& path, const AoFlags& f) {
    voxel::World world = voxel::World::load(path);
    if (f.timeOfDay) {
        voxel::Lighting l = world.desc().lighting;
        l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(*f.timeOfDay);
        world.setLighting(l);
    }
    return world;
}

void addDetailFlags(CLI::App* cmd, AoFlags& f) {
    forFlags("detail", [&](const voxel::Setting& s) {
        const std::string flag(s.flag), field(s.key.substr(s.key.find('.') + 1));
        // Checked here: a value given becomes the world's, read as its file would be.
        if (s.type == voxel::SettingType::Bool)
            cmd->add_option_function<bool>(flag, [&f, field](bool v) { f.detail[field] = v; }, flagHelp(s));
        else
            cmd->add_option_function<double>(flag, [&f, field](double v) { f.detail[field] = v; }, flagHelp(s))
                ->check(finiteRange(s.lo, s.hi));
    });
}

voxel::Detail resolveDetail(const voxel::World& world, const AoFlags& f) {
    voxel::WorldDesc desc = world.desc();
    if (!f.detail.empty()) voxel::applySettingsPatch(desc, {{"detail", f.detail}}, kCommandLine, "");
    return desc.detail;
}

nlohmann::json detailJson(const voxel::Detail& d) {
    voxel::WorldDesc desc;
    desc.detail = d;
    nlohmann::json j = nlohmann::json::object();
    for (const voxel::Setting& s : voxel::settingsTable())
        if (s.key.starts_with("detail.")) {
            const double v = voxel::settingNumber(s, desc, {}, {});
            if (s.type == voxel::SettingType::Bool) j[std::string(s.manifest)] = v != 0.0;
            else j[std::string(s.manifest)] = v;
        }
    return j;
}

voxel::AoDesc aoDescWithFlags(const voxel::AoDesc& world, const AoFlags& f) {
    voxel::AoDesc d = world;
    if (!f.bake.empty()) {  // the cache's file: its method
        if (!f.set.method.empty() && f.set.method != "cache")
            throw Error("--bake", "is the face cache --ao cache reads, not --ao " + f.set.method + "'s",
                        "drop --ao " + f.set.method + " or --bake");
        d.method = "cache";
    }
    if (!f.set.method.empty()) d.method = f.set.method;
    if (f.progressive && !f.bake.empty())
        throw Error("--progressive", "starts the face cache empty, and --bake loads one", "drop one of them");
    if (f.progressive && d.method != "cache")
        throw Error("--progressive", "is for --ao cache's face cache, not --ao " + d.method + "'s", "add --ao cache");
    if (!f.set.quality.empty()) {
        d.quality = f.set.quality;
        voxel::resetPresetShaped(d);  // a preset on the command line replaces the world's loop shape
    }
    voxel::overlayAo(f.set, d);
    return d;
}

AoOptions resolveAo(const voxel::World& world, const AoFlags& f) {
    // Negative counts would wrap in the unsigned settings, so they are refused here.
    forFlags("ao", [&](const voxel::Setting& s) {
        if (const auto* m = std::get_if<std::optional<int> voxel::AoDesc::*>(&s.desc))
            if (const std::optional<int>& v = f.set.*(*m); v && *v < 0)
                throw Error(std::string(s.flag), std::to_string(*v) + " is out of range",
                            "accepted: " + voxel::acceptedText(s));
    });
    AoOptions o = uncheckedAoOptions(aoDescWithFlags(world.desc().ao, f), world.voxelSize(), kCommandLine);
    // The engine names a setting out of range; the command line names its flag.
    if (const std::optional<AoOutOfRange> bad = aoOutOfRange(o))
        throw Error(std::string(bad->row->flag), bad->value + " is out of range", "accepted: " + voxel::acceptedText(*bad->row));
    bool shaped = false;  // slices, steps or rays given: no preset's any more
    forFlags("ao", [&](const voxel::Setting& s) {
        if (const auto* m = std::get_if<std::optional<int> voxel::AoDesc::*>(&s.desc))
            shaped |= s.presetShaped && (f.set.*(*m)).has_value();
    });
    if (shaped) o.quality = "custom";
    // A --bake that is not this world's is refused now, from its header alone,
    // before a device or any output is made and before its texels are read.
    if (!f.bake.empty())
        voxel::requireBakeOf(world, double(o.estimator.radius), voxel::countExposedFaces(world).faces, f.bake);
    return o;
}

nlohmann::json aoSettingsJson(const AoOptions& ao) {
    nlohmann::json j = {{"method", ao.enabled ? aoMethodName(ao.method) : "off"},
                        {"quality", ao.quality},
                        {"ssao_samples", ao.estimator.ssaoSamples}};
    const std::string method = ao.enabled ? aoMethodName(ao.method) : "off";
    if (ao.enabled && ao.method == AoMethod::Vbao)
        j["thickness"] = voxel::setting("ao.thickness").choices[size_t(ao.estimator.thicknessMode)];
    for (const voxel::Setting& s : voxel::settingsTable()) {
        if (s.manifest.empty() || !voxel::usedBy(s, method)) continue;
        std::visit(Overloaded{[](std::monostate) {},
                              [&](auto voxel::EstimatorSettings::*m) { j[std::string(s.manifest)] = ao.estimator.*m; },
                              [&](auto voxel::ChainSettings::*m) { j[std::string(s.manifest)] = ao.chain.*m; }},
                   s.value);
    }
    return j;
}

namespace {

voxel::CameraPathDesc lookUpCameraPath(const voxel::World& world, const std::string& name) {
    const auto& paths = world.desc().paths;
    if (auto it = paths.find(name); it != paths.end()) return it->second;
    std::string known;
    for (auto& [n, p] : paths) known += (known.empty() ? "" : ", ") + n;
    const std::string hint = known.empty() ? "the world defines no paths; give --path-file FILE.json or FILE.glb" : "paths: " + known;
    const std::string ext = lowerExtension(name);
    std::error_code ec;
    if (ext != ".json" && ext != ".glb" && ext != ".gltf" && std::filesystem::is_regular_file(name, ec))
        throw Error(name, "is not a path file", "a path .json, or a glTF .glb or .gltf with an animated camera");
    if (ext == ".json" || ext == ".glb" || ext == ".gltf") {
        auto load = [&](const std::filesystem::path& file) {
            return ext == ".json" ? voxel::loadCameraPath(file) : voxel::importGltfCameraPath(file);
        };
        // As given (relative to the current directory), else beside the world
        // file, where the shipped path files live.
        const std::filesystem::path beside = world.desc().source.parent_path() / name;
        if (std::filesystem::exists(name)) return load(name);
        if (std::filesystem::exists(beside)) return load(beside);
        throw Error(name, "no such path file in the current directory or beside " + world.desc().source.string(), hint);
    }
    throw Error(world.desc().source.string(), "has no path named '" + name + "'", hint);
}

}  // namespace

voxel::CameraPathDesc findCameraPath(voxel::World& world, const std::string& name) {
    voxel::CameraPathDesc path = lookUpCameraPath(world, name);
    checkPathEdits(path, world);
    if (!path.day.empty()) {
        voxel::Lighting l = world.desc().lighting;
        l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(voxel::hourAt(path.day, 0.0));
        world.setLighting(l);
    }
    return path;
}

void addPathOptions(CLI::App* cmd, std::string& path) {
    CLI::Option_group* group = cmd->add_option_group("path", "The camera path: one of");
    group->add_option("--path", path, "Path named in the world file, or a path .json");
    group->add_option("--path-file", path,
                      "A path file: a path .json, or a glTF .glb/.gltf whose animated camera plays (docs/paths.md)");
    group->require_option(1);
}

CLI::Validator finiteRange(double min, double max) {
    char range[64];
    std::snprintf(range, sizeof range, "%g to %g", min, max);
    const std::string accepted = range;
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != 0 || !(v >= min && v <= max))
                return "'" + text + "' is out of range (accepted: a number from " + accepted + ")";
            return {};
        },
        "FLOAT in " + accepted);
}

CLI::Validator wholeRange(int min, int max) {
    const std::string accepted = std::to_string(min) + " to " + std::to_string(max);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            char* end = nullptr;
            const long v = std::strtol(text.c_str(), &end, 10);
            if (end == text.c_str() || *end != 0) return "'" + text + "' is not a whole number from " + accepted;
            if (v < min || v > max)
                return "'" + text + "' is out of range (accepted: a whole number from " + accepted + ")";
            return {};
        },
        "INT in " + accepted);
}

void refuseEmptyValues(CLI::App& app) {
    // No description: --help shows the options as they were.
    const CLI::Validator nonEmpty(
        [](std::string& text) {
            return text.empty() ? std::string("an empty value is not accepted: give one, or leave the flag out") : "";
        },
        "");
    for (CLI::Option* option : app.get_options())  // first of its checks (transform puts it there): the message says why
        if (option->get_expected_min() > 0) option->transform(nonEmpty);
    for (CLI::App* sub : app.get_subcommands({})) refuseEmptyValues(*sub);  // option groups are among them
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * v[m - 1] + 0.5 * v[m];  // halves first: the sum of two large values overflows
}

void requireNoValidationMessages(const vk::Context& ctx) {
    if (ctx.validationMessages() > 0)
        throw Error::internal("vulkan", std::to_string(ctx.validationMessages()) +
                                            " validation message(s) reported (printed above)");
}

}  // namespace grotto::app
