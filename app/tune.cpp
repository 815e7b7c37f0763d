// grotto tune WORLD... [--size WxH] [--spp N] [--quality Q] [--ao gtao|vbao]
// [--thickness MODE]: fits the estimator's heuristics (radius multiplier, falloff
// range, final value power, and GTAO's thin-occluder compensation or VBAO's
// distance thickness) to the reference by coordinate search, minimising the mean
// RMSE over the worlds (docs/tuning.md). Temporal accumulation off, one frame each, so
// the fit sees the estimator and the spatial chain, not history.
#include "app/ao_measure.h"
#include "app/command_session.h"
#include "app/commands.h"
#include "app/options.h"
#include "grotto/error.h"
#include "voxel/settings_table.h"

#include <cstdio>
#include <memory>

namespace grotto::app {
namespace {

// A setting of the settings table that the search fits, and the values it tries.
struct Parameter {
    const char* key;
    std::vector<float> candidates;
    // Its place among the estimator's settings (every fitted one is a heuristic of the estimator).
    float voxel::EstimatorSettings::*field() const {
        return std::get<float voxel::EstimatorSettings::*>(voxel::setting(key).value);
    }
    std::string name() const { return std::string(voxel::setting(key).key.substr(3)); }  // past "ao."
};

// What is fitted: the heuristics both estimators share, then GTAO's thin-occluder
// compensation, or VBAO's thickness where it is a share of the view depth (a
// constant one is in world units, which differ between worlds; the voxels'
// thickness has nothing to fit).
std::vector<Parameter> parameters(const AoOptions& ao) {
    std::vector<Parameter> p = {
        {"ao.radius_multiplier", {0.8f, 1.0f, 1.2f, 1.457f, 1.7f, 2.0f, 2.4f}},
        {"ao.falloff_range", {0.1f, 0.3f, 0.45f, 0.615f, 0.8f, 1.0f}},
        {"ao.final_value_power", {0.8f, 1.0f, 1.3f, 1.6f, 1.9f, 2.2f, 2.6f, 3.0f}},
    };
    if (ao.method == AoMethod::Gtao) p.push_back({"ao.thin_occluder", {0.0f, 0.1f, 0.2f, 0.3f, 0.5f, 0.7f}});
    else if (ao.estimator.thicknessMode == voxel::ThicknessMode::Distance)
        p.push_back({"ao.thickness_value", {0.02f, 0.05f, 0.1f, 0.2f, 0.4f, 1.0f}});
    return p;
}

struct Target {
    std::string name;
    const voxel::World* world;
    Camera camera;
    ReferenceView reference;
    std::unique_ptr<RenderSession> session;  // the world (a copy) and its objects, drawn and traced alike
};

}  // namespace

void addTuneCommand(CLI::App& app) {
    struct Args {
        std::vector<std::string> worlds;
        std::string camera, size = "640x360", quality = "high", method = "gtao", thickness;
        int64_t spp = 1024;
        int rounds = 3;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("tune", "Fit GTAO's or VBAO's heuristics to the reference (coordinate search)");
    cmd->add_option("worlds", args->worlds, "World .json or .vdb files")->required();
    cmd->add_option("--camera", args->camera, "Named camera in every world (default: each world's default)");
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--spp", args->spp, "Reference rays per pixel")->capture_default_str()->check(CLI::Range(1, 1 << 24));
    const voxel::Setting& quality = voxel::setting("ao.quality");
    cmd->add_option("--ao", args->method, "Estimator to fit: gtao or vbao")->capture_default_str()
        ->check(CLI::IsMember({"gtao", "vbao"}));
    const voxel::Setting& thickness = voxel::setting("ao.thickness");
    cmd->add_option("--thickness", args->thickness, "vbao: its thickness mode (default: the world's, else voxels)")
        ->check(CLI::IsMember(std::vector<std::string>(thickness.choices.begin(), thickness.choices.end())));
    cmd->add_option("--quality", args->quality, "Preset to fit")->capture_default_str()
        ->check(CLI::IsMember(std::vector<std::string>(quality.choices.begin(), quality.choices.end())));
    cmd->add_option("--rounds", args->rounds, "Most passes over the settings")->capture_default_str()
        ->check(CLI::Range(1, 10));
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        std::vector<voxel::World> worlds;
        for (const std::string& w : args->worlds) worlds.push_back(voxel::World::load(w));
        vk::Context ctx;
        std::vector<Target> targets;
        for (const voxel::World& world : worlds) {
            Target t{world.desc().source.stem().string(), &world,
                     worldCamera(world, args->camera, size.width, size.height), {}, {}};
            t.session = commandSession(ctx, world, resolveAo(world, {}), {}, size, false);  // refused before minutes of tracing
            t.reference = referenceView(world, t.camera, double(resolveAo(world, {}).estimator.radius), uint32_t(args->spp),
                                        &ctx, t.session->posedObjects());
            requireSurface(t.reference, world, args->camera);
            targets.push_back(std::move(t));
        }
        AoFlags flags;
        flags.set.method = args->method;
        flags.set.thickness = args->thickness;
        flags.set.quality = args->quality;
        flags.set.temporalHistory = 0;
        // Each world keeps its own radius; the fitted heuristics are shared.
        std::vector<AoOptions> base;
        for (const Target& t : targets) base.push_back(resolveAo(*t.world, flags));
        voxel::EstimatorSettings best = base[0].estimator;
        const std::vector<Parameter> fitted = parameters(base[0]);

        auto evaluate = [&](const voxel::EstimatorSettings& s, bool print) {
            double sum = 0.0;
            for (size_t i = 0; i < targets.size(); ++i) {
                AoOptions ao = base[i];
                for (const Parameter& p : fitted) ao.estimator.*p.field() = s.*p.field();
                const Target& t = targets[i];
                const CullingOptions culling = cullingOptions(resolveDetail(*t.world, {}));
                const AoError e = measureAo(ctx, *t.session, t.camera, ao, culling, t.reference, 1, 0, false).error;
                if (print)
                    std::printf("    %-8s rmse %.4f  psnr %6.2f dB  mae %.4f  bias %+.4f\n", t.name.c_str(), e.rmse,
                                e.psnr, e.mae, e.bias);
                sum += e.rmse;
            }
            return sum / double(targets.size());
        };
        auto show = [&](const voxel::EstimatorSettings& s) {
            for (const Parameter& p : fitted)
                std::printf("%s%s %.3f", &p == &fitted.front() ? "" : " ", p.name().c_str(), s.*p.field());
        };
        std::printf("before: ");
        show(best);
        std::printf("\n");
        const double beforeRmse = evaluate(best, true);
        double bestRmse = beforeRmse;
        std::printf("  mean rmse %.5f\n", bestRmse);

        for (int round = 1; round <= args->rounds; ++round) {
            bool changed = false;
            for (const Parameter& p : fitted) {
                for (float v : p.candidates) {
                    if (v == best.*p.field()) continue;
                    voxel::EstimatorSettings s = best;
                    s.*p.field() = v;
                    const double rmse = evaluate(s, false);
                    std::printf("round %d %-18s %.3f: mean rmse %.5f%s\n", round, p.name().c_str(), v, rmse,
                                rmse < bestRmse ? "  (better)" : "");
                    std::fflush(stdout);
                    if (rmse < bestRmse) bestRmse = rmse, best = s, changed = true;
                }
            }
            if (!changed) break;
        }
        std::printf("after: ");
        show(best);
        std::printf("\n");
        evaluate(best, true);
        std::printf("  mean rmse %.5f (before %.5f)\n", bestRmse, beforeRmse);
        targets.clear();
        requireNoValidationMessages(ctx);
    });
}

}  // namespace grotto::app
