// grotto render WORLD [--camera NAME] [--size WxH] [--aov] [--accumulate N] -o FILE
// A still: the camera rendered N times with consecutive frame indices, so the
// temporal pass averages N frames of GTAO noise, and the last frame written.
#include "app/command_session.h"
#include "app/commands.h"
#include "app/options.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "engine/image_output.h"
#include "voxel/world.h"

#include <algorithm>
#include <cstdio>
#include <optional>

namespace grotto::app {
namespace {

// A --progressive still stops here even if faces in view are left to trace.
constexpr uint32_t kMaxProgressiveFrames = 4096;

// Frames to accumulate: --accumulate, else the history (a converged still) of
// the temporal pass or, with --ao cache, of the objects' light (16 frames unless
// set), else 1 where there is nothing to average in. The history is raised to
// --accumulate where that is longer, so every frame counts. Asking for more than
// one frame without one is refused: it would render the same single-frame
// estimate, whatever the flag says.
uint32_t framesToAccumulate(const std::optional<int>& requested, const AoFlags& flags, AoOptions& ao,
                            const voxel::WorldDesc& world) {
    const FramePlan plan = planWorldFrame(world, 1, 1, ao);
    const bool temporal = plan.temporal, objectLight = plan.objectLight;
    if (!requested)
        return temporal ? ao.chain.temporalHistory : objectLight ? std::max(ao.chain.temporalHistory, kDefaultTemporalHistory) : 1;
    const uint32_t frames = uint32_t(*requested);
    if (frames > 1 && !temporal && !objectLight) {
        const std::string off = !ao.enabled                  ? "AO is off"
                                : faceCached(ao)             ? "--ao cache is converged on the faces already and the world has no objects"
                                : flags.set.temporalHistory ? "--temporal 0 turns the temporal pass off"
                                                             : "the world's ao.temporal_history is 0";
        throw Error("--accumulate", std::to_string(frames) + " frames have nothing to average: " + off,
                    "accepted without the temporal pass: 1, or leave --accumulate out");
    }
    if (temporal || objectLight) ao.chain.temporalHistory = std::max(ao.chain.temporalHistory, frames);
    return frames;
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size = "1280x720", output;
        bool aov = false;
        double time = 0.0;
        std::string show;
        std::optional<int> accumulate;
        AoFlags ao;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a still of a world to a PNG or EXR, its AO converged over --accumulate frames");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera from the world file (default: its default)");
    cmd->add_option("--size", args->size, "Image size WxH (refused when it cannot fit the device's memory)")->capture_default_str();
    cmd->add_flag("--aov", args->aov, "EXR only: also write Z, N.xyz, albedo.RGB, AO, AO_raw, AO_spatial, edges, shadow (and AO_temporal, AO_history with the temporal pass; bent_normal.xyz with --ao vbao; light.RGB, the face cache's light, with --ao cache)");
    cmd->add_option("-o,--output", args->output, "Output .png or .exr")->required();
    cmd->add_option("--show", args->show, std::string("PNG only: write one AOV instead of colour (") + kShownAovs + ")")
        ->check(CLI::IsMember({"ao", "normal", "depth", "edges", "shadow", "raw", "spatial", "temporal", "history", "bent_normal",
                               "light"}));
    cmd->add_option("--time", args->time, "Seconds: where the world's objects are (their keys)")
        ->capture_default_str()->check(finiteRange(0.0, 1e9));
    cmd->add_option("--accumulate", args->accumulate,
                    "Frames of the still camera the temporal pass (or with --ao cache, objects' light) averages, "
                    "1 to 64 (default: the AO's temporal history, 16 unless set, for converged AO; 1: the "
                    "single-frame estimate; with neither, 1 frame)")
        ->check(wholeRange(1, 64));
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        const std::filesystem::path out = args->output;
        // Check everything about the output before any work, so bad input writes nothing.
        if (imageFormatFor(out) != ImageFormat::Exr && args->aov)
            throw Error(out.string(), "--aov needs an .exr output", "PNG holds colour only; try --show");
        if (imageFormatFor(out) != ImageFormat::Png && !args->show.empty())
            throw Error(out.string(), "--show needs a .png output", "EXR holds every AOV with --aov");
        requireOutputPath(out);
        voxel::World world = loadWorld(args->world, args->ao);
        const Camera camera = worldCamera(world, args->camera, size.width, size.height);
        AoOptions ao = resolveAo(world, args->ao);
        // The engine's error would name the AOV; the command line names the flag, before any frame.
        if (args->show == kBentNormalAov && !(ao.enabled && ao.method == AoMethod::Vbao))
            throw Error("--show", "bent_normal is VBAO's", "render with --ao vbao");
        if (args->show == kCacheLightAov && !(ao.enabled && ao.method == AoMethod::Cache))
            throw Error("--show", "light is the face cache's", "render with --ao cache");
        const uint32_t frames = framesToAccumulate(args->accumulate, args->ao, ao, world.desc());
        const bool aovs = args->aov || !args->show.empty();
        vk::Context ctx;
        uint32_t rendered = 0;
        {
            const std::unique_ptr<RenderSession> session = commandSession(ctx, std::move(world), ao, args->ao, size);
            if (const uint64_t bytes = session->memoryEstimate())  // .vox worlds (engine/scene/scene_memory.h)
                std::printf("memory: an estimated %.1f MiB to load, mesh and render (budget %zu MiB)\n",
                            double(bytes) / (1 << 20), session->world().desc().memoryBudgetBytes >> 20);
            session->setTime(args->time);  // the objects, held for every frame
            Renderer& renderer = session->renderer();
            for (; rendered < frames; ++rendered) renderer.render(camera, rendered);
            // --progressive: on until a frame finds no face in view left to trace.
            while (args->ao.progressive && rendered < kMaxProgressiveFrames && !session->faceCacheConverged())
                renderer.render(camera, rendered++);
            const FrameImages frame = renderer.readback(camera, aovs);
            if (!args->show.empty())
                writeSrgb8(out, frame.width, frame.height, encodeSrgb8(aovDisplay(frame, args->show)), &camera);
            else
                writeFrame(out, frame, camera, args->aov);
        }
        requireNoValidationMessages(ctx);
        std::printf("wrote %s (%ux%u, %u frame%s, %s)\n", out.c_str(), size.width, size.height, rendered,
                    rendered == 1 ? "" : "s", ctx.deviceName().c_str());
    });
}

}  // namespace grotto::app
