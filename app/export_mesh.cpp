// grotto export-mesh WORLD -o FILE.ply | FILE.glb | FILE.gltf: the world's surface
// for other tools. PLY: exactly the quads that are rasterised. glTF: every exposed
// face with its AO baked into the vertex colours (voxel/gltf/gltf_export.h).
// --origin places it (voxel/mesh_origin.h): by default standing on y = 0.
#include "app/commands.h"
#include "app/options.h"
#include "app/progress.h"
#include "common/atomic_file.h"
#include "common/plural.h"
#include "grotto/error.h"
#include "voxel/gltf/gltf_export.h"
#include "voxel/mesh_origin.h"
#include "voxel/ply_export.h"
#include "voxel/world.h"

#include <chrono>
#include <cstdio>

namespace grotto::app {

void addExportMeshCommand(CLI::App& app) {
    struct Args {
        std::string world, output, origin = "base";
        bool faces = false;
        uint32_t rays = voxel::kDefaultBakeRays, texels = voxel::kDefaultBakeTexels, measure = 0;
        AoFlags ao;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("export-mesh", "Write the world's surface as a PLY, or as glTF with its AO baked in");
    cmd->add_option("world", args->world, "World .json, .vdb or .vox")->required();
    cmd->add_option("-o,--output", args->output, "Output .ply, .glb or .gltf")->required();
    cmd->add_option("--origin", args->origin,
                    "Where the mesh sits: base (centred in x and z, standing on y = 0), centre (its centre at the "
                    "origin) or world (the world's own coordinates, as camera paths have them)")
        ->capture_default_str()->check(CLI::IsMember({"base", "centre", "center", "world"}));
    cmd->add_flag("--no-greedy", args->faces, "PLY: one quad per exposed voxel face");
    cmd->add_option("--rays", args->rays, "glTF: AO rays per face-cache texel")
        ->capture_default_str()->check(CLI::Range(1u, 1u << 16));
    cmd->add_option("--texels", args->texels, "glTF: face-cache texels per face side, read at the corners")
        ->capture_default_str()->check(CLI::Range(1u, 16u));
    cmd->add_option("--radius", args->ao.set.radius, "glTF: AO radius R in world units (default: the world's)");
    cmd->add_option("--measure", args->measure,
                    "glTF: also measure the vertex AO at this many random surface points against 4096-ray references")
        ->check(CLI::Range(0u, 1000000u));
    cmd->callback([args] {
        const std::filesystem::path out = args->output;
        const std::string ext = out.extension().string();
        if (ext != ".ply" && ext != ".glb" && ext != ".gltf")
            throw Error(out.string(), "output must end in .ply, .glb or .gltf");
        requireOutputPath(out);
        removeAbandonedTemporariesOf(out);
        const voxel::MeshOrigin origin = voxel::meshOrigin(args->origin, "--origin");
        const voxel::World world = voxel::World::load(args->world);
        const glm::dvec3 shift = voxel::meshShift(world, origin);
        if (ext == ".ply") {
            voxel::Mesh mesh = world.mesh({.greedy = !args->faces});
            mesh.origin += shift;
            voxel::writePly(mesh, out);
            std::printf("wrote %s (%s, origin %s)\n", out.c_str(), counted(mesh.quads.size(), "quad").c_str(),
                        voxel::meshOriginName(origin));
            return;
        }
        const voxel::FaceBakeSettings bake{.radius = double(resolveAo(world, args->ao).estimator.radius),
                                           .texelsPerSide = args->texels, .rays = args->rays, .light = false};
        const auto start = std::chrono::steady_clock::now();
        FaceBakeProgress progress(stderr);
        voxel::AoMesh mesh = voxel::buildAoMesh(world, bake, std::ref(progress));
        progress.finish();
        mesh.offset += shift;
        const uintmax_t bytes = voxel::writeGltfMesh(world, mesh, out);
        size_t vertices = 0, triangles = 0;
        for (const auto& p : mesh.primitives) vertices += p.positions.size(), triangles += p.indices.size() / 3;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("wrote %s (%s, %s, %s, %s, %.1f MiB, AO radius %g, origin %s, %.1f s)\n", out.c_str(),
                    counted(mesh.faces.size(), "face").c_str(), counted(vertices, "vertex", "vertices").c_str(),
                    counted(triangles, "triangle").c_str(), counted(mesh.primitives.size(), "material").c_str(),
                    double(bytes) / (1 << 20), bake.radius, voxel::meshOriginName(origin), seconds);
        if (args->measure) {
            const voxel::AoMeshError e = voxel::measureAoMesh(world, mesh, bake, args->measure, 4096, 1);
            std::printf("vertex AO at %zu random surface points against 4096-ray references: MAE %.4f, RMSE %.4f, "
                        "bias %+.4f, max %.3f; the face cache's %u x %u texels there: MAE %.4f, RMSE %.4f\n",
                        e.points, e.mae, e.rmse, e.bias, e.max, args->texels, args->texels, e.cacheMae, e.cacheRmse);
        }
    });
}

}  // namespace grotto::app
