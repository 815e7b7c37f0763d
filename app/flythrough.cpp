// grotto flythrough WORLD [--camera NAME] [--frames N] [--size WxH] -o DIR
// Until camera paths land, the flythrough is one orbit of the chosen camera about
// its target. Frames already on disk are skipped, so an interrupted run resumes;
// dir/flythrough.json records the settings so a resume never mixes sequences.
#include "app/commands.h"
#include "app/options.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "engine/image_output.h"
#include "engine/renderer.h"
#include "voxel/world.h"

#include <glm/gtc/matrix_transform.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace grotto::app {

namespace {

struct Args {
    std::string world, camera, size = "640x360", output, format = "png";
    int frames = 24;
    AoFlags ao;
};

// Everything that decides a frame's pixels: a resumed run must match it.
nlohmann::json runManifest(const Args& a, const AoOptions& ao) {
    const gpu::GtaoSettings& g = ao.gtao;
    return {{"world", std::filesystem::absolute(a.world).lexically_normal().string()}, {"camera", a.camera},
            {"size", a.size}, {"frames", a.frames}, {"format", a.format}, {"ao", ao.enabled},
            {"ao_full_res", ao.fullResolution},
            {"gtao", {g.radius, g.radiusMultiplier, g.falloffRange, g.sampleDistributionPower,
                      g.thinOccluderCompensation, g.finalValuePower, g.depthMipSamplingOffset, g.strength,
                      g.denoiseBlurBeta, g.sliceCount, g.stepsPerSlice, g.denoisePasses}}};
}

// Frames already in `dir` are kept only when they came from the same settings,
// recorded in dir/flythrough.json; otherwise the run refuses to mix sequences.
void requireSameRun(const std::filesystem::path& dir, const nlohmann::json& manifest) {
    const std::filesystem::path file = dir / "flythrough.json";
    const std::string mine = manifest.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    if (std::filesystem::exists(file)) {
        std::ifstream in(file);
        std::stringstream previous;
        previous << in.rdbuf();
        if (previous.str() != mine + "\n")
            throw Error(file.string(), "holds frames of a flythrough with other settings",
                        "render into another directory, or delete this one to start over");
        return;
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().filename().string().rfind("frame.", 0) == 0)
            throw Error(dir.string(), "already holds frames but no flythrough.json saying how they were made",
                        "render into another directory");
    writeAtomically(file, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out << mine << "\n";
        out.close();
        if (!out) throw Error(file.string(), "write failed", "is the disk full?");
    });
}

}  // namespace

void addFlythroughCommand(CLI::App& app) {
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("flythrough", "Render an orbit of a camera to DIR/frame.NNNN.png");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera to orbit (default: the world's default)");
    cmd->add_option("--frames", args->frames, "Frames in the orbit")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--format", args->format, "png or exr")->capture_default_str()->check(CLI::IsMember({"png", "exr"}));
    cmd->add_option("-o,--output", args->output, "Output directory")->required();
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        const std::filesystem::path dir = args->output;
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (!std::filesystem::is_directory(dir))
            throw Error(dir.string(), "cannot create the output directory", ec ? ec.message() : "");
        const voxel::World world = voxel::World::load(args->world);
        const voxel::CameraDesc start = world.camera(args->camera);
        const AoOptions ao = resolveAo(world, args->ao);
        requireSameRun(dir, runManifest(*args, ao));
        vk::Context ctx;
        auto scene = uploadScene(ctx, world.mesh(), world.desc());
        int written = 0;
        {
            Renderer renderer(ctx, *scene, world.desc().lighting, ao, size.width, size.height);
            for (int i = 0; i < args->frames; ++i) {
                char name[32];
                std::snprintf(name, sizeof name, "frame.%04d.%s", i + 1, args->format.c_str());
                const std::filesystem::path file = dir / name;
                if (std::filesystem::exists(file)) continue;  // complete frames are written atomically
                voxel::CameraDesc cd = start;
                const double angle = 2.0 * M_PI * i / args->frames;
                const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0, 1, 0));
                cd.position = cd.target + glm::dvec3(turn * glm::dvec4(start.position - start.target, 0.0));
                const Camera camera = makeCamera(cd, size.width, size.height);
                renderer.render(camera);
                writeFrame(file, renderer.readback(camera, false), camera, false);
                ++written;
                std::printf("frame %d/%d %s\n", i + 1, args->frames, file.c_str());
                std::fflush(stdout);
            }
        }
        scene.reset();
        requireNoValidationMessages(ctx);
        std::printf("wrote %d frames to %s (%d already there)\n", written, dir.c_str(), args->frames - written);
    });
}

}  // namespace grotto::app
