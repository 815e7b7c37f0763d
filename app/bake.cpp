// grotto bake WORLD -o FILE [--chunk K/N | --chunk auto] [--rays N] [--texels K]
// grotto bake --merge PART... -o FILE
// Converges the face cache (voxel/face_cache.h) of every exposed face on every
// core, with progress and an ETA, and writes it tied to the world and settings
// (voxel/face_cache_file.h). --chunk K/N bakes the K-th of N equal runs of faces
// (1 <= K <= N, as flythrough counts chunks; auto: from the scheduler,
// app/farm_chunk.h), for a farm; --merge joins the parts
// into the file one machine's bake writes.
#include "app/commands.h"
#include "app/options.h"
#include "app/progress.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/brick_table.h"
#include "voxel/daylight.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_file.h"
#include "voxel/light_bake.h"

#include <chrono>
#include <cstdio>

namespace grotto::app {
namespace {

void merge(const std::vector<std::string>& parts, const std::filesystem::path& out) {
    const voxel::FaceCacheFile whole = voxel::mergeFaceCaches({parts.begin(), parts.end()});
    voxel::saveFaceCache(whole, out);
    std::printf("wrote %s (%zu parts, %llu faces)\n", out.c_str(), parts.size(), (unsigned long long)whole.header.totalFaces);
}

}  // namespace

void addBakeCommand(CLI::App& app) {
    struct Args {
        std::string world, output;
        ChunkFlags chunk;
        std::vector<std::string> merge;
        uint32_t rays = voxel::kDefaultBakeRays, sunRays = voxel::kDefaultBakeSunRays, texels = voxel::kDefaultBakeTexels;
        AoFlags ao;
        ProgressFormat progress = ProgressFormat::Auto;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("bake", "Converge the AO, sky light and sun cached on every exposed voxel face");
    cmd->add_option("world", args->world, "World .json or .vdb");
    cmd->add_option("-o,--output", args->output, "Output face cache (.gfc)")->required();
    addChunkOptions(cmd, args->chunk, "bake only the K-th of N equal runs of faces");
    cmd->add_option("--merge", args->merge, "Join these parts (bake --chunk) into one cache")->expected(1, -1);
    cmd->add_option("--rays", args->rays, "Cosine-weighted rays per texel (AO and sky)")
        ->capture_default_str()->check(CLI::Range(1u, 1u << 20));
    cmd->add_option("--sun-rays", args->sunRays, "Rays per texel toward the sun, from all over the texel (and over a soft sun's disc)")
        ->capture_default_str()->check(CLI::Range(1u, 1u << 16));
    cmd->add_option("--texels", args->texels, "Texels per face side (k x k per face)")
        ->capture_default_str()->check(CLI::Range(1u, 16u));
    cmd->add_option("--radius", args->ao.set.radius, "AO radius R in world units (default: the world's)");
    addTimeOfDayFlag(cmd, args->ao);
    addProgressOption(cmd, args->progress);
    cmd->callback([args] {
        const std::filesystem::path out = args->output;
        if (out.extension() != ".gfc") throw Error(out.string(), "output must end in .gfc", "a Grotto face cache");
        requireOutputPath(out);
        removeAbandonedTemporariesOf(out);
        if (!args->merge.empty()) {
            if (!args->world.empty() || !args->chunk.chunk.empty() || args->chunk.chunks)
                throw Error("--merge", "joins parts alone", "give no WORLD and no --chunk with it");
            merge(args->merge, out);
            return;
        }
        if (args->world.empty()) throw Error("bake", "a WORLD is required", "or --merge PART...");
        const std::optional<ChunkOfN> chunk = resolveChunk(args->chunk);  // refused before the world is read
        const voxel::World world = loadWorld(args->world, args->ao);
        const bool fullLight = world.desc().lighting.ambientFrom == voxel::AmbientSource::Full;
        if (fullLight && chunk)
            throw Error("--chunk", "a world with full light (lighting.ambient.from full) is baked whole",
                        "its bounces carry light between every face: bake it on one machine");
        const double radius = double(resolveAo(world, args->ao).estimator.radius);
        const voxel::BrickTable table(world);
        const std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
        uint64_t first = 0, count = faces.size();
        if (chunk) first = faces.size() * (chunk->k - 1) / chunk->n, count = faces.size() * chunk->k / chunk->n - first;
        const voxel::Lighting light = voxel::lightingInEffect(world.desc().lighting);
        const bool day = world.desc().lighting.sunFrom == voxel::SunSource::Day;  // light is the hour's, a fixed sun
        const voxel::FaceBakeSettings settings{.radius = radius, .texelsPerSide = args->texels, .rays = args->rays,
                                               .sunRays = args->sunRays, .sunDirection = glm::dvec3(light.sunDirection),
                                               .sunAngleDegrees = double(light.sunAngle), .fullLight = fullLight,
                                               .day = day ? std::optional(voxel::sunPathOf(light)) : std::nullopt};
        const voxel::LightSources lights = voxel::lightSources(world.desc().lighting);
        if (fullLight) voxel::requireLightBakeFits(world, faces.size(), args->texels, {}, lights.day.has_value());
        voxel::FaceCacheFile cache{.header = {.key = voxel::faceCacheKey(world, radius, args->texels),
                                              .rays = settings.rays, .sunRays = voxel::sunRaysPerTexel(settings),
                                              .totalFaces = faces.size(), .firstFace = first, .faceCount = count}};
        cache.texels.resize(cache.header.texelCount());
        if (voxel::hasDayLight(cache.header)) cache.dayLight.resize(faces.size() * voxel::kDayLightWords);
        const auto start = std::chrono::steady_clock::now();
        FaceBakeProgress progress(stderr, args->progress,
                                  chunk ? nlohmann::ordered_json{{"chunk", chunk->text()}} : nlohmann::ordered_json::object());
        voxel::bakeFacesInSteps(table, world, std::span(faces).subspan(first, count), settings, cache.texels,
                                std::ref(progress));
        progress.finish();
        std::string lightNote;
        if (fullLight) {
            const voxel::LightBakeStats light =
                voxel::bakeLight(table, world, faces, args->texels, lights, {}, cache.texels, {}, cache.dayLight);
            lightNote = ", full light in " + std::to_string(light.passes) + " bounce passes";
            if (day) lightNote += " (by source, for every hour)";
        }
        voxel::saveFaceCache(cache, out);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (day) lightNote += ", the day's sun at " + std::to_string(voxel::kDaySunPositions) + " positions";
        std::printf("wrote %s (faces %llu to %llu of %llu, %u x %u texels each, %u rays a texel%s, %.1f s)\n", out.c_str(),
                    (unsigned long long)first, (unsigned long long)(first + count), (unsigned long long)faces.size(),
                    args->texels, args->texels, args->rays, lightNote.c_str(), seconds);
    });
}

}  // namespace grotto::app
