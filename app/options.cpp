#include "app/options.h"

#include "common/error.h"
#include "engine/scene/path_edits.h"

#include <algorithm>
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

FrameRange parseChunk(const std::string& text, int count, const std::string& option) {
    const std::string accepted = "expected K/N with 1 <= K <= N <= " + std::to_string(kMaxPathFrames) + ", e.g. 2/8";
    const size_t slash = text.find('/');
    auto isNumber = [](const std::string& t) {
        return !t.empty() && t.size() <= 9 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (slash == std::string::npos || !isNumber(text.substr(0, slash)) || !isNumber(text.substr(slash + 1)))
        throw Error(option, "'" + text + "' is not a chunk", accepted);
    const int k = std::stoi(text.substr(0, slash)), n = std::stoi(text.substr(slash + 1));
    if (n < 1 || n > kMaxPathFrames || k < 1 || k > n) throw Error(option, "'" + text + "' is out of range", accepted);
    const int base = count / n, longer = count % n;  // chunks 1..longer have base + 1 frames
    const int first = 1 + (k - 1) * base + std::min(k - 1, longer);
    return {first, first + base + (k <= longer ? 1 : 0) - 1};
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

void addAoFlags(CLI::App* cmd, AoFlags& f) {
    cmd->add_option("--ao", f.method,
                    "Ambient occlusion: gtao, voxel (exact rays through the voxels), hybrid (GTAO plus voxel rays), "
                    "ssao, hbao (baselines) or off (default: the world's, else gtao)")
        ->check(CLI::IsMember({"gtao", "voxel", "hybrid", "ssao", "hbao", "off"}));
    cmd->add_option("--quality", f.quality,
                    "Preset: low, medium, high, ultra (SSAO: 8, 16, 32, 64 samples), or custom (high's, with --slices, --steps)")
        ->check(CLI::IsMember({"low", "medium", "high", "ultra", "custom"}));
    voxel::AoDesc& d = f.set;
    // Ranges and defaults: shaders/shared/gtao.h; out-of-range values exit 2 naming the flag.
    cmd->add_option("--radius", d.radius, "AO radius in world units (> 0)");
    cmd->add_option("--thin-occluder", d.thinOccluder, "Thin-occluder compensation, 0 to 0.7");
    cmd->add_option("--max-distance", d.maxDistance, "View depth where AO has faded out, world units (0 = no limit)");
    cmd->add_option("--rays", d.rays, "Voxel and hybrid AO: rays per AO pixel per frame, 1 to 64 (makes the quality custom)");
    cmd->add_option("--slices", d.slices, "GTAO slices per pixel, 1 to 32 (makes the quality custom)");
    cmd->add_option("--steps", d.steps, "GTAO steps per side of a slice, 1 to 32 (makes the quality custom)");
    cmd->add_option("--radius-multiplier", d.radiusMultiplier, "Screen-space radius compensation, 0.3 to 3");
    cmd->add_option("--falloff-range", d.falloffRange, "Fraction of the radius over which occluders fade, 0 to 1");
    cmd->add_option("--sample-distribution-power", d.sampleDistributionPower, "Step spacing power, 1 to 3");
    cmd->add_option("--final-value-power", d.finalValuePower, "Contrast of the final visibility, 0.5 to 5");
    cmd->add_option("--depth-mip-offset", d.depthMipOffset, "Higher = coarser depth MIPs later, 0 to 30");
    cmd->add_option("--strength", d.strength, "AO strength in the composite, 0 (none) to 1");
    cmd->add_option("--denoise", d.denoisePasses, "Spatial denoise passes, 0 to 4");
    cmd->add_option("--denoise-blur-beta", d.denoiseBlurBeta, "Centre weight of the denoise blur, 0 to 10");
    cmd->add_option("--temporal", d.temporalHistory, "Most frames the temporal pass averages, 0 (off) to 64");
    cmd->add_flag("--ao-full-res", f.fullResolution, "Run the AO chain at full instead of half resolution");
    addDetailFlags(cmd, f);
}

void addDetailFlags(CLI::App* cmd, AoFlags& f) {
    cmd->add_option("--lod-bias", f.lodBias,
                    "Largest size in pixels a coarse cell of far chunks may cover, 0 (exact voxels everywhere) to 64 "
                    "(default: the world's detail.lod_bias, else 1)")
        ->check(finiteRange(0.0, 64.0));
    cmd->add_option("--occlusion-culling", f.occlusionCulling,
                    "Skip clusters of quads hidden behind nearer geometry: true or false (default: the world's, else true)");
}

voxel::Detail resolveDetail(const voxel::World& world, const AoFlags& f) {
    voxel::Detail d = world.desc().detail;
    if (f.lodBias) d.lodBias = *f.lodBias;
    if (f.occlusionCulling) d.occlusionCulling = *f.occlusionCulling;
    return d;
}

nlohmann::json detailJson(const voxel::Detail& d) {
    return {{"lod_bias", d.lodBias}, {"occlusion_culling", d.occlusionCulling}};
}

AoOptions resolveAo(const voxel::World& world, const AoFlags& f) {
    voxel::AoDesc desc = world.desc().ao;
    if (!f.method.empty()) desc.method = f.method;
    if (!f.quality.empty()) {
        // A preset on the command line replaces the world's slices and steps too.
        desc.quality = f.quality;
        desc.slices.reset();
        desc.steps.reset();
        desc.rays.reset();
    }
    AoOptions o = aoOptionsFor(desc, world.voxelSize(), world.desc().source.string());
    o.fullResolution = f.fullResolution;
    // Negative counts would wrap in the unsigned settings, so they are refused here.
    struct Count {
        const std::optional<int>& value;
        const char *flag, *range;
    };
    for (const Count& c : {Count{f.set.slices, "--slices", "1 to 32"}, Count{f.set.steps, "--steps", "1 to 32"},
                           Count{f.set.rays, "--rays", "1 to 64"},
                           Count{f.set.denoisePasses, "--denoise", "0 to 4"}, Count{f.set.temporalHistory, "--temporal", "0 (off) to 64"}})
        if (c.value && *c.value < 0)
            throw Error(c.flag, std::to_string(*c.value) + " is out of range", std::string("accepted: ") + c.range);
    applyAoOverrides(f.set, o.gtao);
    if (f.set.rays) {
        if (*f.set.rays < 1 || *f.set.rays > 64)
            throw Error("--rays", std::to_string(*f.set.rays) + " is out of range", "accepted: 1 to 64");
        o.voxelRays = uint32_t(*f.set.rays);
    }
    if (f.set.slices || f.set.steps || f.set.rays) o.quality = "custom";
    validateGtao(o.gtao, kCommandLine);
    return o;
}

nlohmann::json aoSettingsJson(const AoOptions& ao) {
    const gpu::GtaoSettings& g = ao.gtao;
    nlohmann::json j = {{"method", ao.enabled ? aoMethodName(ao.method) : "off"}, {"quality", ao.quality},
            {"full_resolution", ao.fullResolution}, {"ssao_samples", ao.ssaoSamples}, {"radius", g.radius},
            {"radius_multiplier", g.radiusMultiplier}, {"falloff_range", g.falloffRange},
            {"sample_distribution_power", g.sampleDistributionPower}, {"thin_occluder", g.thinOccluderCompensation},
            {"final_value_power", g.finalValuePower}, {"depth_mip_offset", g.depthMipSamplingOffset},
            {"strength", g.strength}, {"denoise_blur_beta", g.denoiseBlurBeta}, {"slices", g.sliceCount},
            {"steps", g.stepsPerSlice}, {"denoise", g.denoisePasses}, {"temporal", g.temporalHistory},
            {"max_distance", g.maxDistance}};
    if (ao.enabled && tracesVoxels(ao.method)) j["rays"] = ao.voxelRays;
    return j;
}

namespace {

voxel::CameraPathDesc lookUpCameraPath(const voxel::World& world, const std::string& name) {
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

}  // namespace

voxel::CameraPathDesc findCameraPath(const voxel::World& world, const std::string& name) {
    voxel::CameraPathDesc path = lookUpCameraPath(world, name);
    checkPathEdits(path, world);
    return path;
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
