// grotto flythrough WORLD --path NAME [--size WxH] [--fps N] [--frames A-B | --chunk K/N]
//                   [--warmup K] [--format png|exr] [-o DIR] [--video FILE.mp4] [--quiet | --progress jsonl]
// Renders a camera path to DIR/frame.NNNN.png (or .exr with AOVs; --name and
// --start-number choose the names) and DIR/stats.json, and with --video pipes
// the frames to ffmpeg as well (or instead, without -o). Frame i (1-based)
// shows the path at time (i - 1) / fps and is rendered with frame index i, so a
// run split by --frames or --chunk across machines makes the frames of one whole
// run: the K frames before the first frame written are rendered but not written,
// to rebuild the temporal history. The history is a running average, so a split
// frame converges to the whole run's rather than matching it bit for bit
// (docs/paths.md states the measured difference). Frames already on disk whole
// and recorded in stats.json are skipped, so an interrupted run resumes: it
// re-renders from K frames before the first missing one (history again) and
// writes only missing frames.
// DIR/flythrough.json records the settings (and the --bake) so a resume never
// mixes sequences, and DIR/stats.json keeps every run's frame times, merged by
// frame number as frames are written (app/flythrough_dir.h). Every input is
// checked before DIR is touched. Frames are read back and written while the
// next ones render (app/frame_writer.h).
#include "app/command_session.h"
#include "app/commands.h"
#include "app/flythrough_dir.h"
#include "app/frame_names.h"
#include "app/frame_writer.h"
#include "app/options.h"
#include "app/progress.h"
#include "app/video_pipe.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "common/file_lock.h"
#include "engine/camera_path.h"
#include "engine/image_output.h"
#include "engine/frame/render_memory.h"
#include "engine/session.h"
#include "voxel/face_cache_file.h"
#include "voxel/world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace grotto::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Measured in docs/benchmarks.md ("Capture throughput"): about five times as fast
// to encode as zlib's default level 6, for files about a quarter larger.
constexpr int kFlythroughPngLevel = 2;
constexpr int kDefaultVideoQuality = 18;

struct Args {
    std::string world, path, size = "640x360", output, format = "png", frames, name = kDefaultFramePattern,
                aovs, exrType = "float", video;
    int fps = 24, startNumber = 1, pngLevel = kFlythroughPngLevel, videoQuality = kDefaultVideoQuality;
    std::optional<int> warmup;  // default: four times the temporal history
    bool quiet = false;
    ProgressFormat progress = ProgressFormat::Auto;
    ChunkFlags chunk;
    AoFlags ao;
    CLI::App* cmd = nullptr;
    bool given(const std::string& flag) const { return cmd->count(flag) > 0; }
};

// --aovs: names from kExrAovs, comma-separated, or none; all of them by default.
// Returned in the order they are written.
std::vector<std::string> exrAovs(const Args& a) {
    std::vector<std::string> all(std::begin(kExrAovs), std::end(kExrAovs));
    if (!a.given("--aovs")) return all;
    all.push_back(kBentNormalAov);  // VBAO's, by name only
    all.push_back(kCacheLightAov);  // the face cache's, by name only
    if (a.aovs == "none") return {};
    std::vector<std::string> asked;
    for (size_t from = 0, comma; from <= a.aovs.size(); from = comma + 1) {
        comma = std::min(a.aovs.find(',', from), a.aovs.size());
        const std::string name = a.aovs.substr(from, comma - from);
        if (std::find(all.begin(), all.end(), name) == all.end()) {
            std::string accepted;
            for (const std::string& n : all) accepted += (accepted.empty() ? "" : ", ") + n;
            throw Error("--aovs", "unknown AOV '" + name + "'", "accepted: none, or a comma-separated list of " + accepted);
        }
        asked.push_back(name);
    }
    std::erase_if(all, [&](const std::string& n) { return std::find(asked.begin(), asked.end(), n) == asked.end(); });
    return all;
}

// The flags that only make sense together, checked before anything is loaded.
void requireConsistentFlags(const Args& a) {
    if (a.output.empty() && a.video.empty())
        throw Error("--output", "is required (or --video FILE.mp4 for a video alone)", "e.g. -o out/frames");
    if (a.quiet && a.given("--progress"))
        throw Error("--progress", "cannot be combined with --quiet", "--quiet prints no progress at all");
    if (a.given("--chunk") && a.given("--frames"))
        throw Error("--chunk", "cannot be combined with --frames", "--chunk K/N picks the frames itself");
    const bool png = a.format == "png";
    for (const char* exrOnly : {"--aovs", "--exr-type"})
        if (a.given(exrOnly) && png) throw Error(exrOnly, "applies to --format exr only", "add --format exr");
    if (a.given("--png-level") && !png) throw Error("--png-level", "applies to --format png only", "drop it for EXR");
    if (a.given("--video-quality") && a.video.empty())
        throw Error("--video-quality", "applies to --video only", "add --video FILE.mp4");
    if (a.output.empty())
        for (const char* framesOnly : {"--name", "--start-number", "--aovs", "--exr-type", "--png-level"})
            if (a.given(framesOnly))
                throw Error(framesOnly, "names how frames are written, but no -o DIR is given", "add -o DIR");
}

// Everything that decides the files of a frame: a resumed run must match it. The
// frame range and warm-up are not in it: ranges are parts of one sequence. What
// is left at its default is left out, so directories of earlier versions resume.
json runManifest(const Args& a, const voxel::CameraPathDesc& path, const AoOptions& ao, const voxel::Detail& detail,
                 const FrameNames& names, const FrameEncoding& encoding) {
    json m = {{"world", fs::absolute(a.world).lexically_normal().string()}, {"path", a.path},
              {"path_keys", pathManifest(path)}, {"size", a.size}, {"fps", a.fps}, {"format", a.format},
              {"ao", aoSettingsJson(ao)}};
    if (detailJson(detail) != detailJson(voxel::Detail{})) m["detail"] = detailJson(detail);
    if (!names.isDefault()) m["name"] = names.pattern(), m["start_number"] = names.start();
    if (a.format == "exr" && (encoding.exrHalf || encoding.exrAovs.size() != std::size(kExrAovs)))
        m["exr"] = {{"type", encoding.exrHalf ? "half" : "float"}, {"aovs", encoding.exrAovs}};
    return m;
}

// The --bake file as the manifest records it, so chunks never mix bakes. A bake
// is a deterministic function of the world's solid voxels and of these settings
// (farm parts join byte for byte into one machine's bake), so they identify it:
// hashing its texels would read up to gigabytes again on every chunk and tell
// nothing more. Its rays are the ones its header records.
json bakeManifest(RenderSession& session) {
    const LiveFaceCache& cache = *session.scene().faceCache();
    const voxel::FaceBakeSettings& s = cache.settings();
    char voxels[17];
    std::snprintf(voxels, sizeof voxels, "%016llx", (unsigned long long)voxel::solidVoxelHash(session.world()));
    return {{"voxels", voxels},        {"faces", cache.faces().size()},
            {"radius", s.radius},      {"texels", s.texelsPerSide},
            {"rays", s.rays},          {"sun_rays", s.sunRays},
            {"sun", {s.sunDirection.x, s.sunDirection.y, s.sunDirection.z}}, {"sun_angle", s.sunAngleDegrees}};
}

// Host memory one frame in flight holds: decoded images and encoded pixels.
size_t bytesPerFrame(const FramePlan& plan, const FrameEncoding& encoding, bool exr) {
    const size_t n = size_t(plan.width) * plan.height;
    if (!exr) return 16 * n + 2 * 3 * n;  // colour, sRGB for the file and the video
    const size_t images = encoding.exrAovs.empty() ? 16 * n : readbackHostBytes(plan);
    return images + 4 * 18 * n + 3 * n;  // at most 18 channels of float pixels
}

void run(const Args& a) {
    requireConsistentFlags(a);
    const Size size = parseSize(a.size);
    const FrameNames names(a.name, a.startNumber, a.format);
    const FrameEncoding encoding{.pngLevel = a.pngLevel, .exrAovs = a.format == "exr" ? exrAovs(a) : std::vector<std::string>{},
                                 .exrHalf = a.exrType == "half"};
    std::optional<VideoTools> videoTools;
    if (!a.video.empty()) {
        videoTools = findVideoTools();
        requireVideoOutput(a.video, size.width, size.height);
    }
    voxel::World world = loadWorld(a.world, a.ao);
    const voxel::CameraPathDesc desc = findCameraPath(world, a.path);
    const CameraPath path(desc, world.camera("", size.aspect()));
    const int count = pathFrameCount(path, a.fps, a.path);
    const std::optional<ChunkOfN> chunk = resolveChunk(a.chunk);
    const FrameRange range = chunk              ? chunkFrames(*chunk, count)
                             : a.frames.empty() ? FrameRange{1, count}
                                                : parseFrameRange(a.frames, count);
    if (range.count() == 0) {
        std::printf("chunk %s has no frames: the path has %d, fewer than the chunks\n", chunk->text().c_str(), count);
        return;
    }
    const AoOptions ao = resolveAo(world, a.ao);
    const voxel::Detail detail = resolveDetail(world, a.ao);
    if (std::find(encoding.exrAovs.begin(), encoding.exrAovs.end(), kBentNormalAov) != encoding.exrAovs.end() &&
        !(ao.enabled && ao.method == AoMethod::Vbao))
        throw Error("--aovs", "bent_normal is VBAO's", "add --ao vbao, or leave bent_normal out");
    if (std::find(encoding.exrAovs.begin(), encoding.exrAovs.end(), kCacheLightAov) != encoding.exrAovs.end() &&
        !(ao.enabled && ao.method == AoMethod::Cache))
        throw Error("--aovs", "light is the face cache's", "add --ao cache, or leave light out");
    vk::Context ctx;
    const FramePlan plan = planWorldFrame(world.desc(), size.width, size.height, ao);
    const voxel::CameraDesc lens = world.camera("", size.aspect());
    const bool bakeGiven = !a.ao.bake.empty();
    // A bake given is refused (not this world's, damaged) before the directory is touched.
    std::unique_ptr<RenderSession> session = commandSession(ctx, std::move(world), ao, a.ao, size, bakeGiven);
    json manifest = runManifest(a, desc, ao, detail, names, encoding);
    if (bakeGiven) manifest["bake"] = bakeManifest(*session);

    // Frames to write: those of the range not in DIR whole and recorded yet. The
    // video takes them all.
    const fs::path dir = a.output;
    std::vector<int> missing;
    std::optional<FileLock> claim;  // held while the run lasts
    if (!a.output.empty()) {
        // Every refusal comes before the directory or anything in it is made: a
        // refused run leaves it as it was.
        std::error_code ec;
        if (fs::is_directory(dir, ec)) requireSameRun(dir, manifest, names);
        fs::create_directories(dir, ec);
        if (!fs::is_directory(dir)) throw Error(dir.string(), "cannot create the output directory", ec ? ec.message() : "");
        // Chunks of one sequence may start together in one directory (a render
        // farm): they claim it one at a time, and each clears only the temporary
        // files of runs that died (a live run's are locked).
        claim.emplace(claimDirectory(dir, manifest, names));
        missing = framesToWrite(dir, names, range.first, range.last, size.width, size.height);
        if (missing.empty() && a.video.empty()) {
            std::printf("all %d frames already in %s\n", range.count(), dir.c_str());
            return;
        }
    }
    const bool video = !a.video.empty();
    if (video) removeAbandonedTemporariesOf(a.video);  // what killed runs left of this video
    // History: start K frames before the first frame to write. A split run's
    // history starts afresh where the whole run's is full; the difference
    // shrinks by (n-1)/n a frame (n = the history length, 16), so measured at
    // four times n the split frames are within 1/255 of the whole run's
    // (twice n: 3/255); docs/paths.md.
    // The face cache has no history: a chunk needs no warm-up.
    const int warmup = a.warmup.value_or(aoChain(ao) ? 4 * int(ao.chain.temporalHistory) : 0);
    const int first = video ? range.first : missing.front(), end = video ? range.last : missing.back();
    const int start = std::max(1, first - warmup);
    std::optional<StatsRecorder> stats;  // this run's frame entries
    if (!a.output.empty()) stats.emplace(dir);
    if (!bakeGiven) prepareFaceCache(*session, a.ao);  // a bake made here: only once frames are to be rendered
    // The world as the path's edits have made it by the first frame rendered;
    // later edits are applied as their frames come. Objects are drawn at each frame's poses.
    session->playPath(desc, lens);
    session->startPathAt(double(start - 1) / a.fps);
    {
        std::optional<VideoPipe> pipe;
        if (video) pipe.emplace(*videoTools, a.video, size.width, size.height, a.fps, a.videoQuality, range.first);
        const bool exr = a.format == "exr";
        FrameWriter writer(ctx, exr && !encoding.exrAovs.empty(), FrameWriter::threadsFor(bytesPerFrame(plan, encoding, exr)));
        std::optional<Progress> progress;
        if (!a.quiet) progress.emplace(end - start + 1, stdout, a.progress);
        for (int i = start; i <= end; ++i) {
            const double time = double(i - 1) / a.fps;
            const Camera camera = session->pathFrame(time, size.width, size.height).camera;
            const bool write = std::binary_search(missing.begin(), missing.end(), i);
            const bool toVideo = video && i >= range.first;
            FrameCopy* copy = (write || toVideo) ? &writer.slot() : nullptr;
            const FrameStats frameStats = session->renderer().render(camera, uint32_t(i), copy);
            json passMs = json::object();
            for (const auto& [name, ms] : frameStats.passMs) passMs[name] = ms;
            json entry = {{"frame", i}, {"time", time}, {"written", write}, {"wall_ms", frameStats.wallMs}, {"pass_ms", passMs}};
            if (copy)
                writer.submit(*copy, [&, i, camera, write, toVideo, file = write ? dir / names.name(i) : fs::path(),
                                      entry](const FrameImages& frame) {
                    std::vector<uint8_t> rgb = exr && !toVideo ? std::vector<uint8_t>() : srgb8Pixels(frame);
                    if (write && exr) writeFrame(file, frame, camera, encoding);
                    else if (write) writeSrgb8(file, frame.width, frame.height, rgb, &camera, encoding.pngLevel);
                    if (write) stats->add(entry);  // recorded once it is on disk
                    if (toVideo) pipe->frame(i, std::move(rgb));
                });
            if (stats && !write) stats->add(entry);
            if (stats) stats->mergeIfDue();
            const char* state = write ? "written" : toVideo ? "to video" : "warm-up";
            char what[96];
            std::snprintf(what, sizeof what, "frame %04d %s %.0f ms", i, state, frameStats.wallMs);
            nlohmann::ordered_json fields = {{"frame", i}, {"state", state}, {"wall_ms", std::round(frameStats.wallMs * 10) / 10}};
            if (chunk) fields["chunk"] = chunk->text();
            if (progress) progress->step(what, fields);
        }
        writer.finish();
        if (pipe) pipe->finish();
        if (progress) progress->finish();
    }
    session.reset();
    requireNoValidationMessages(ctx);
    if (stats) {
        stats->merge();
        std::printf("wrote %zu frames to %s (%d rendered, %d already there)\n", missing.size(), dir.c_str(),
                    end - start + 1, range.count() - int(missing.size()));
    }
    if (video) std::printf("wrote %s (%d frames at %d fps)\n", a.video.c_str(), range.count(), a.fps);
}

}  // namespace

void addFlythroughCommand(CLI::App& app) {
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("flythrough", "Render a camera path to DIR/frame.NNNN.png and DIR/stats.json");
    args->cmd = cmd;
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    addPathOptions(cmd, args->path);
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--fps", args->fps, "Frames per second of path time")->capture_default_str()->check(CLI::Range(1, 1000));
    cmd->add_option("--frames", args->frames, "Frames A-B to write, 1-based, or N for the first N (default: the whole path)");
    addChunkOptions(cmd, args->chunk, "the K-th of N equal contiguous parts of the path's frames");
    cmd->add_option("--warmup", args->warmup,
                    "Frames rendered but not written before the first one written; the default (four times the "
                    "temporal history, 64; 0 with --ao cache, which keeps none) keeps a split run within 2/255 of "
                    "the whole run")
        ->check(CLI::Range(0, 10000));
    cmd->add_option("--format", args->format, "png, or exr with AOVs")->capture_default_str()->check(CLI::IsMember({"png", "exr"}));
    cmd->add_option("-o,--output", args->output, "Output directory (required unless --video)");
    cmd->add_option("--name", args->name, "File name pattern with one integer conversion, before the extension")
        ->capture_default_str();
    cmd->add_option("--start-number", args->startNumber, "The number of the path's first frame in file names")
        ->capture_default_str()
        ->check(wholeRange(0, 1'000'000'000));
    cmd->add_option("--png-level", args->pngLevel, "PNG zlib compression, 0 (none, fastest) to 9 (smallest)")
        ->capture_default_str()
        ->check(wholeRange(0, 9));
    cmd->add_option("--exr-type", args->exrType, "EXR channels: float, or half (Z stays float)")
        ->capture_default_str()
        ->check(CLI::IsMember({"float", "half"}));
    cmd->add_option("--aovs", args->aovs,
                    "EXR AOV layers, comma-separated: Z, N, albedo, AO, AO_raw, AO_spatial, AO_temporal, AO_history, "
                    "edges, shadow; or none (default: all)");
    cmd->add_option("--video", args->video,
                    std::string("Also (or, without -o, only) encode the frames to this video with ffmpeg: ") +
                        kVideoExtensions + " (H.264, or VP9 for .webm)");
    cmd->add_option("--video-quality", args->videoQuality,
                    "Constant rate factor, 0 (best) to 51 (smallest): x264's, or VP9's for .webm")
        ->capture_default_str()
        ->check(wholeRange(0, 51));
    cmd->add_flag("--quiet", args->quiet, "No progress lines, only the results");
    addProgressOption(cmd, args->progress);
    addAoFlags(cmd, args->ao);
    cmd->callback([args] { run(*args); });
}

}  // namespace grotto::app
