// grotto reference WORLD [--camera NAME] [--size WxH] --spp N [--radius R] [--require-stderr E] -o ref.exr
// The ray-traced reference AO from the G-buffer's own surface points (docs/reference.md).
// Its last line says whether every pixel's standard error met the target (0.005,
// or E); with --require-stderr a miss exits 3, the EXR written all the same.
// With --light full, the path-traced light of the view instead (reference_light.cpp).
#include "app/commands.h"
#include "app/options.h"
#include "app/reference_light.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/object_worlds.h"
#include "engine/image_output.h"
#include "engine/lab/reference_view.h"
#include "voxel/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace grotto::app {
namespace {

// The reference's own error that makes it a reference (docs/reference.md).
constexpr double kStderrTarget = 0.005;

}  // namespace
}  // namespace grotto::app

namespace grotto::app {

void addReferenceCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size = "640x360", output;
        int64_t spp = 0;
        std::optional<double> requireStderr;
        double time = 0.0;
        AoFlags ao;
        std::string light = "ao";
        std::optional<int64_t> bounces;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("reference", "Ray-trace the reference AO of a view to an EXR (AO, AO_stderr)");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera from the world file (default: its default)");
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--spp", args->spp, "Rays per pixel (>= 1; 10000 keeps every standard error below 0.005)")
        ->required();
    cmd->add_option("--radius", args->ao.set.radius, "AO radius R in world units (default: the world's GTAO radius)");
    addTimeOfDayFlag(cmd, args->ao);
    cmd->add_option("-o,--output", args->output,
                    "Output .exr (with --light full also .png: the light as a display shows it, the world's exposure and tone map)")
        ->required();
    cmd->add_option("--time", args->time, "Seconds: where the world's objects are (their keys)")
        ->capture_default_str()->check(finiteRange(0.0, 1e9));
    cmd->add_option("--light", args->light,
                    "ao: the reference AO (channels AO, AO_stderr); full: the path-traced light, radiance R G B "
                    "with every bounce, sky, sun and glowing materials (docs/reference.md)")
        ->capture_default_str()->check(CLI::IsMember({"ao", "full"}));
    cmd->add_option("--bounces", args->bounces,
                    "--light full: bounces at most (0: direct light only; default: every bounce)");
    cmd->add_option("--require-stderr", args->requireStderr,
                    "Exit 3 when a pixel's standard error is above E (the target is 0.005 without it)")
        ->check(finiteRange(1e-6, 1.0));
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        if (args->spp < 1 || args->spp > (int64_t(1) << 24))
            throw Error("--spp", std::to_string(args->spp) + " is out of range", "accepted: 1 to 16777216 rays per pixel");
        const uint32_t spp = uint32_t(args->spp);
        const std::filesystem::path out = args->output;
        if (imageFormatFor(out) != ImageFormat::Exr && args->light != "full")
            throw Error(out.string(), "the reference needs an .exr output", "it holds the float channels AO and AO_stderr");
        if (args->bounces && args->light != "full")
            throw Error("--bounces", "applies to --light full only", "add --light full, or leave --bounces out");
        if (args->bounces && (*args->bounces < 0 || *args->bounces > 1000000))
            throw Error("--bounces", std::to_string(*args->bounces) + " is out of range", "accepted: 0 to 1000000");
        if (args->light == "full" && args->ao.set.radius)
            throw Error("--radius", "applies to --light ao only", "the light's paths have no radius");
        requireOutputPath(out);
        const voxel::World world = loadWorld(args->world, args->ao);
        const Camera camera = worldCamera(world, args->camera, size.width, size.height);
        if (args->light == "full") {
            const std::vector<voxel::World> objects = voxel::loadObjectWorlds(world.desc());
            const auto posed = voxel::posedWorlds(objects, voxel::objectPoses(world.desc().objects, args->time));
            voxel::PathTraceSettings settings;
            settings.spp = spp;
            if (args->bounces) settings.maxBounces = uint32_t(*args->bounces);
            writeLightReference(out, world, camera, settings, posed, args->requireStderr);
            return;
        }
        // R is the radius GTAO is given (before its radius multiplier), so both measure the same thing.
        const double radius = double(resolveAo(world, args->ao).estimator.radius);

        const std::vector<voxel::World> objects = voxel::loadObjectWorlds(world.desc());
        const auto posed = voxel::posedWorlds(objects, voxel::objectPoses(world.desc().objects, args->time));
        ReferenceView t = referenceView(world, camera, radius, spp, nullptr, posed);
        if (t.cacheHit) std::printf("cache hit: %s (nothing traced)\n", t.cacheFile.c_str());
        writeChannels(out, size.width, size.height,
                      std::vector<Channel>{{"AO", &t.ao}, {"AO_stderr", &t.stderror}}, camera);

        const double target = args->requireStderr.value_or(kStderrTarget);
        size_t surface = 0, above = 0;
        double sumError = 0.0, maxError = 0.0, sumAo = 0.0;
        for (size_t i = 0; i < t.ao.size(); ++i) {
            if (!t.surface[i]) continue;
            ++surface;
            sumAo += t.ao[i];
            sumError += t.stderror[i];
            maxError = std::max(maxError, double(t.stderror[i]));
            above += t.stderror[i] > target;
        }
        const double meanError = surface ? sumError / surface : 0.0;
        std::printf("wrote %s (%ux%u, R %g, %u spp)\n", out.c_str(), size.width, size.height, radius, spp);
        std::printf("pixels %zu (%zu sky), rays %llu", surface, t.ao.size() - surface,
                    (unsigned long long)(uint64_t(surface) * spp));
        if (t.rays > 0) std::printf(" traced in %.2f s, %.2f M rays/s", t.traceSeconds, t.rays / t.traceSeconds * 1e-6);
        std::printf(", mean V %.4f, stderr mean %.5f max %.5f\n", surface ? sumAo / surface : 1.0, meanError, maxError);
        // The standard error falls as 1 / sqrt(spp): what would meet the target.
        const double needed = std::ceil(double(spp) * (maxError / target) * (maxError / target));
        char verdict[160];
        if (above == 0)
            std::snprintf(verdict, sizeof verdict, "met");
        else
            std::snprintf(verdict, sizeof verdict, "NOT met at %zu pixels (max %.5f; about %.0f spp would meet it)",
                          above, maxError, needed);
        std::printf("standard error target (every pixel <= %g): %s\n", target, verdict);
        if (above > 0 && args->requireStderr)
            throw Error::regression("--require-stderr", std::string("standard error target not met: ") + verdict,
                                    "the EXR is written: " + out.string());
    });
}

}  // namespace grotto::app
