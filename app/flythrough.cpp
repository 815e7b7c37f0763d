// grotto flythrough WORLD --path NAME [--size WxH] [--fps N] [--frames A-B]
//                   [--warmup K] [--format png|exr] -o DIR
// Renders a camera path to DIR/frame.NNNN.png (or .exr with AOVs) and
// DIR/stats.json. Frame i (1-based) shows the path at time (i - 1) / fps and is
// rendered with frame index i, so a run split by --frames across machines makes
// the frames of one whole run: the K frames before the first frame written are
// rendered but not written, to rebuild the temporal history. The history is a
// running average, so a split frame converges to the whole run's rather than
// matching it bit for bit (docs/paths.md states the measured difference). Frames already on
// disk are skipped, so an interrupted run resumes: it re-renders from K frames
// before the first missing one (history again) and writes only missing frames.
// DIR/flythrough.json records the settings so a resume never mixes sequences,
// and DIR/stats.json keeps every run's frame times, merged by frame number.
#include "app/commands.h"
#include "app/options.h"
#include "app/progress.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_lock.h"
#include "voxel/object_worlds.h"
#include "engine/camera_path.h"
#include "engine/image_output.h"
#include "engine/live_scene.h"
#include "engine/path_edits.h"
#include "engine/render_memory.h"
#include "engine/renderer.h"
#include "voxel/world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace grotto::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Args {
    std::string world, path, size = "640x360", output, format = "png", frames;
    int fps = 24;
    std::optional<int> warmup;  // default: four times the temporal history
    AoFlags ao;
};

json pathJson(const voxel::CameraPathDesc& p) {
    json keys = json::array();
    for (const voxel::PathKey& k : p.keys) {
        json key = {{"time", k.time}, {"position", {k.position.x, k.position.y, k.position.z}}};
        if (k.target) key["target"] = {k.target->x, k.target->y, k.target->z};
        if (k.rotation) key["quaternion"] = {k.rotation->x, k.rotation->y, k.rotation->z, k.rotation->w};
        if (k.fovDegrees) key["fov"] = *k.fovDegrees;
        if (k.cut) key["cut"] = true;
        keys.push_back(key);
    }
    json j = {{"keys", keys}, {"constant_speed", p.constantSpeed}};
    if (!p.edits.empty()) {  // only then: a resumed run of a path without edits keeps its manifest
        json edits = json::array();
        for (const voxel::TimedEdit& t : p.edits) {
            const voxel::Edit& e = t.edit;
            json edit = {{"time", t.time}, {"op", int(e.op)}, {"material", e.material}};
            if (e.shape == voxel::Edit::Shape::Box)
                edit["voxels"] = {{e.box.min.x, e.box.min.y, e.box.min.z}, {e.box.max.x, e.box.max.y, e.box.max.z}};
            else
                edit["sphere"] = {e.centre.x, e.centre.y, e.centre.z, e.radius};
            edits.push_back(edit);
        }
        j["edits"] = edits;
    }
    if (p.fovDegrees) j["fov"] = *p.fovDegrees;
    if (p.nearPlane) j["near"] = *p.nearPlane;
    if (p.farPlane) j["far"] = *p.farPlane;
    return j;
}

// Everything that decides a frame's pixels: a resumed run must match it. The
// frame range and warm-up are not in it: ranges are parts of one sequence.
json runManifest(const Args& a, const voxel::CameraPathDesc& path, const AoOptions& ao, const voxel::Detail& detail) {
    return {{"world", fs::absolute(a.world).lexically_normal().string()}, {"path", a.path},
            {"path_keys", pathJson(path)}, {"size", a.size}, {"fps", a.fps}, {"format", a.format},
            {"ao", aoSettingsJson(ao)}, {"detail", detailJson(detail)}};
}

void writeJson(const fs::path& file, const json& j) {
    const std::string text = j.dump(2, ' ', false, json::error_handler_t::replace);
    writeAtomically(file, [&](const fs::path& tmp) {
        std::ofstream out(tmp);
        out << text << "\n";
        out.close();
        if (!out) throw Error(file.string(), "write failed", "is the disk full?");
    });
}

// Frames already in `dir` are kept only when they came from the same settings,
// recorded in dir/flythrough.json; otherwise the run refuses to mix sequences.
void requireSameRun(const fs::path& dir, const json& manifest) {
    const fs::path file = dir / "flythrough.json";
    if (fs::exists(file)) {
        std::ifstream in(file);
        std::stringstream previous;
        previous << in.rdbuf();
        if (previous.str() != manifest.dump(2, ' ', false, json::error_handler_t::replace) + "\n")
            throw Error(file.string(), "holds frames of a flythrough with other settings",
                        "render into another directory, or delete this one to start over");
        return;
    }
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("frame.", 0) == 0)
            throw Error(dir.string(), "already holds frames but no flythrough.json saying how they were made",
                        "render into another directory");
    writeJson(file, manifest);
}

// The per-frame entries of earlier runs into the directory (DIR/stats.json), by
// frame number, so a resumed run adds to them rather than dropping them. Read
// before rendering, so a damaged file is refused before anything is written.
std::map<int, json> earlierFrames(const fs::path& file) {
    std::map<int, json> frames;
    if (!fs::exists(file)) return frames;
    std::ifstream in(file);
    const json doc = json::parse(in, nullptr, false);
    const std::string hint = "delete it to start the stats afresh";
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("frames") || !doc["frames"].is_array())
        throw Error(file.string(), "is not a flythrough stats file (no \"frames\" array)", hint);
    for (size_t k = 0; k < doc["frames"].size(); ++k) {
        const json& f = doc["frames"][k];
        bool ok = f.is_object() && f.contains("frame") && f["frame"].is_number_integer() && f.contains("wall_ms") &&
                  f["wall_ms"].is_number() && f.contains("pass_ms") && f["pass_ms"].is_object() &&
                  f.contains("written") && f["written"].is_boolean();
        if (ok)
            for (const auto& [name, ms] : f["pass_ms"].items()) ok = ok && ms.is_number();
        if (!ok)
            throw Error(file.string(), "frames[" + std::to_string(k) + "] is not a frame entry",
                        "expected {\"frame\", \"written\", \"wall_ms\", \"pass_ms\"}; " + hint);
        frames[f["frame"].get<int>()] = f;
    }
    return frames;
}

// This run's entry replaces an earlier one of the same frame, except that a
// warm-up render keeps the entry of the run that wrote the frame.
void mergeFrame(std::map<int, json>& frames, const json& entry) {
    json& slot = frames[entry["frame"].get<int>()];
    if (slot.is_null() || entry["written"].get<bool>() || !slot["written"].get<bool>()) slot = entry;
}

// Per-frame times, in frame order, and their medians.
json statsJson(const std::map<int, json>& byFrame) {
    json frames = json::array();
    for (const auto& [i, f] : byFrame) frames.push_back(f);
    std::vector<double> wall;
    std::map<std::string, std::vector<double>> passes;
    for (const json& f : frames) {
        wall.push_back(f["wall_ms"].get<double>());
        for (auto& [name, ms] : f["pass_ms"].items()) passes[name].push_back(ms.get<double>());
    }
    json medians = {{"wall_ms", median(wall)}, {"pass_ms", json::object()}};
    for (auto& [name, ms] : passes) medians["pass_ms"][name] = median(ms);
    return {{"frames", frames}, {"median", medians}};
}

// Serialises the runs that share a directory while they read and write its
// manifest and stats; hidden, like the temporary files.
constexpr const char* kLockFile = ".flythrough.lock";

// The files a flythrough writes into its directory.
bool isOurs(const std::string& name) {
    return name.rfind("frame.", 0) == 0 || name == "stats.json" || name == "flythrough.json";
}

}  // namespace

void addFlythroughCommand(CLI::App& app) {
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("flythrough", "Render a camera path to DIR/frame.NNNN.png and DIR/stats.json");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--path", args->path, "Path named in the world file, or a path .json")->required();
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--fps", args->fps, "Frames per second of path time")->capture_default_str()->check(CLI::Range(1, 1000));
    cmd->add_option("--frames", args->frames, "Frames A-B to write, 1-based, or N for the first N (default: the whole path)");
    cmd->add_option("--warmup", args->warmup,
                    "Frames rendered but not written before the first one written; the default (four times the "
                    "temporal history, 64) keeps a split run within 2/255 of the whole run")
        ->check(CLI::Range(0, 10000));
    cmd->add_option("--format", args->format, "png, or exr with AOVs")->capture_default_str()->check(CLI::IsMember({"png", "exr"}));
    cmd->add_option("-o,--output", args->output, "Output directory")->required();
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        voxel::World world = voxel::World::load(args->world);
        const voxel::CameraPathDesc desc = findCameraPath(world, args->path);
        const CameraPath path(desc, world.camera(""));
        const int count = pathFrameCount(path, args->fps, args->path);
        const FrameRange range = args->frames.empty() ? FrameRange{1, count} : parseFrameRange(args->frames, count);
        const AoOptions ao = resolveAo(world, args->ao);
        const voxel::Detail detail = resolveDetail(world, args->ao);
        vk::Context ctx;  // first: a size the device cannot hold is refused before the directory is made
        requireRenderFits(ctx, size.width, size.height, ao, "--size");
        const fs::path dir = args->output;
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (!fs::is_directory(dir)) throw Error(dir.string(), "cannot create the output directory", ec ? ec.message() : "");
        {
            // Chunks of one sequence may start together in one directory (a render
            // farm): they agree on the manifest one at a time, and each clears
            // only the temporary files of runs that died (a live run's are locked).
            FileLock lock(dir / kLockFile);
            requireSameRun(dir, runManifest(*args, desc, ao, detail));
            removeAbandonedTemporaries(dir, isOurs);
        }
        earlierFrames(dir / "stats.json");  // a damaged stats file is refused now, not after rendering

        auto frameFile = [&](int i) {
            char name[32];
            std::snprintf(name, sizeof name, "frame.%04d.%s", i, args->format.c_str());
            return dir / name;
        };
        std::vector<int> missing;  // complete frames are written atomically, so existing ones are whole
        for (int i = range.first; i <= range.last; ++i)
            if (!fs::exists(frameFile(i))) missing.push_back(i);
        if (missing.empty()) {
            std::printf("all %d frames already in %s\n", range.last - range.first + 1, dir.c_str());
            return;
        }
        // History: start K frames before the first frame to write. A split run's
        // history starts afresh where the whole run's is full; the difference
        // shrinks by (n-1)/n a frame (n = the history length, 16), so measured at
        // four times n the split frames are within 1/255 of the whole run's
        // (twice n: 3/255); docs/paths.md.
        const int warmup = args->warmup.value_or(4 * int(ao.gtao.temporalHistory));
        const int start = std::max(1, missing.front() - warmup), end = missing.back();
        std::vector<json> rendered;  // this run's frame entries
        // The world as the path's edits have made it by the first frame rendered;
        // later edits are applied as their frames come. Objects are drawn at each frame's poses.
        const std::vector<voxel::World> objectWorlds = voxel::loadObjectWorlds(world.desc());
        auto objects = objectWorlds.empty() ? nullptr : uploadObjects(ctx, objectWorlds, world.desc());
        std::optional<LiveScene> scene;
        scene.emplace(ctx, std::move(world));
        PathEdits edits(desc, scene->world());
        edits.applyUpTo(double(start - 1) / args->fps, *scene);
        {
            Renderer renderer(ctx, scene->gpu(), scene->world().desc().lighting, ao, size.width, size.height,
                              objects.get());
            renderer.setCulling(cullingOptions(detail));
            Progress progress(end - start + 1, stdout);
            for (int i = start; i <= end; ++i) {
                const double time = double(i - 1) / args->fps;
                const Camera camera = path.camera(time, size.width, size.height);
                if (i > start && path.cutBetween(double(i - 2) / args->fps, time)) renderer.resetHistory();
                edits.applyUpTo(time, *scene, &renderer);
                if (objects) renderer.setObjectPoses(objects->poses(time));
                const FrameStats stats = renderer.render(camera, uint32_t(i));
                const bool write = std::binary_search(missing.begin(), missing.end(), i);
                if (write) {
                    const bool aovs = args->format == "exr";
                    writeFrame(frameFile(i), renderer.readback(camera, aovs), camera, aovs);
                }
                json passMs = json::object();
                for (const auto& [name, ms] : stats.passMs) passMs[name] = ms;
                rendered.push_back({{"frame", i}, {"time", time}, {"written", write}, {"wall_ms", stats.wallMs},
                                    {"pass_ms", passMs}});
                char what[96];
                std::snprintf(what, sizeof what, "frame %04d %s %.0f ms", i, write ? "written" : "warm-up",
                              stats.wallMs);
                progress.step(what);
            }
            progress.finish();
        }
        scene.reset();
        objects.reset();
        requireNoValidationMessages(ctx);
        {
            // Other chunks may have written stats since this run read them: merge
            // this run's frames into what is there now, one writer at a time.
            FileLock lock(dir / kLockFile);
            std::map<int, json> frames = earlierFrames(dir / "stats.json");
            for (const json& entry : rendered) mergeFrame(frames, entry);
            writeJson(dir / "stats.json", statsJson(frames));
        }
        std::printf("wrote %zu frames to %s (%d rendered, %d already there)\n", missing.size(), dir.c_str(),
                    end - start + 1, range.last - range.first + 1 - int(missing.size()));
    });
}

}  // namespace grotto::app
