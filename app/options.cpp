#include "app/options.h"

#include "common/error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace grotto::app {

Size parseSize(const std::string& text, const std::string& option) {
    unsigned w = 0, h = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
        throw Error(option, "'" + text + "' is not a valid size", "expected WxH with both in 1..16384, e.g. 1280x720");
    return {w, h};
}

FrameRange parseFrameRange(const std::string& text, int count, const std::string& option) {
    int a = 0, b = 0, n = 0;
    const char* s = text.c_str();
    const bool range = std::sscanf(s, "%d-%d%n", &a, &b, &n) == 2 && s[n] == 0;
    const bool single = !range && std::sscanf(s, "%d%n", &a, &n) == 1 && s[n] == 0;
    if (single) b = a;
    const std::string accepted = "expected A-B with 1 <= A <= B <= " + std::to_string(count) + " (the path's frames)";
    if (!range && !single) throw Error(option, "'" + text + "' is not a frame range", accepted);
    if (a < 1 || b < a || b > count) throw Error(option, "'" + text + "' is out of range", accepted);
    return {a, b};
}

void addAoFlags(CLI::App* cmd, AoFlags& f) {
    cmd->add_option("--ao", f.method, "Ambient occlusion: gtao, ssao, hbao (baselines) or off (default: the world's, else gtao)")
        ->check(CLI::IsMember({"gtao", "ssao", "hbao", "off"}));
    cmd->add_option("--quality", f.quality, "Preset: low, medium, high, ultra (SSAO: 8, 16, 32, 64 samples)")
        ->check(CLI::IsMember({"low", "medium", "high", "ultra"}));
    cmd->add_option("--radius", f.radius, "AO radius in world units (> 0)");
    cmd->add_option("--thin-occluder", f.thinOccluder, "Thin-occluder compensation, 0 to 0.7");
    cmd->add_option("--max-distance", f.maxDistance, "View depth where AO has faded out, world units (0 = no limit)");
    cmd->add_option("--denoise", f.denoise, "Spatial denoise passes, 0 to 4");
    cmd->add_option("--temporal", f.temporal, "Most frames the temporal pass averages, 0 (off) to 64");
    cmd->add_flag("--ao-full-res", f.fullResolution, "Run the AO chain at full instead of half resolution");
}

AoOptions resolveAo(const voxel::World& world, const AoFlags& f) {
    voxel::AoDesc desc = world.desc().ao;
    if (!f.method.empty()) desc.method = f.method;
    if (!f.quality.empty()) {
        // A preset on the command line replaces the world's slices and steps too.
        desc.quality = f.quality;
        desc.slices.reset();
        desc.steps.reset();
    }
    AoOptions o = aoOptionsFor(desc, world.voxelSize(), world.desc().source.string());
    o.fullResolution = f.fullResolution;
    if (f.radius) o.gtao.radius = float(*f.radius);
    if (f.thinOccluder) o.gtao.thinOccluderCompensation = float(*f.thinOccluder);
    if (f.maxDistance) {
        if (!(*f.maxDistance >= 0.0 && *f.maxDistance <= 1e7))
            throw Error("--max-distance", std::to_string(*f.maxDistance) + " is out of range", "accepted: 0 (no limit) to 1e7 world units");
        o.gtao.maxDistance = float(*f.maxDistance);
    }
    if (f.denoise) {
        if (*f.denoise < 0 || *f.denoise > 4) throw Error("--denoise", std::to_string(*f.denoise) + " is out of range", "accepted: 0 to 4");
        o.gtao.denoisePasses = uint32_t(*f.denoise);
    }
    if (f.temporal) {
        if (*f.temporal < 0 || *f.temporal > 64) throw Error("--temporal", std::to_string(*f.temporal) + " is out of range", "accepted: 0 (off) to 64");
        o.gtao.temporalHistory = uint32_t(*f.temporal);
    }
    if (f.radius && !(*f.radius > 0.0 && *f.radius <= 1e6))
        throw Error("--radius", std::to_string(*f.radius) + " is out of range", "accepted: > 0 world units");
    if (f.thinOccluder && !(*f.thinOccluder >= 0.0 && *f.thinOccluder <= 0.7))
        throw Error("--thin-occluder", std::to_string(*f.thinOccluder) + " is out of range", "accepted: 0 to 0.7");
    validateGtao(o.gtao, "command line");
    return o;
}

voxel::CameraPathDesc findCameraPath(const voxel::World& world, const std::string& name) {
    const auto& paths = world.desc().paths;
    if (auto it = paths.find(name); it != paths.end()) return it->second;
    std::string known;
    for (auto& [n, p] : paths) known += (known.empty() ? "" : ", ") + n;
    const std::string hint = known.empty() ? "the world defines no paths; give --path FILE.json" : "paths: " + known;
    if (std::filesystem::path(name).extension() == ".json") {
        // As given (relative to the current directory), else beside the world
        // file, where the shipped path files live.
        const std::filesystem::path beside = world.desc().source.parent_path() / name;
        if (std::filesystem::exists(name)) return voxel::loadCameraPath(name);
        if (std::filesystem::exists(beside)) return voxel::loadCameraPath(beside);
        throw Error(name, "no such path file in the current directory or beside " + world.desc().source.string(), hint);
    }
    throw Error(world.desc().source.string(), "has no path named '" + name + "'", hint);
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void requireNoValidationMessages(const vk::Context& ctx) {
    if (ctx.validationMessages() > 0)
        throw Error::internal("vulkan", std::to_string(ctx.validationMessages()) +
                                            " validation message(s) reported (printed above)");
}

}  // namespace grotto::app
