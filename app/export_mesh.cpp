// grotto export-mesh WORLD -o FILE.ply: exactly the quads that are rasterised.
#include "app/commands.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/ply_export.h"
#include "voxel/world.h"

#include <cstdio>

namespace grotto::app {

void addExportMeshCommand(CLI::App& app) {
    struct Args { std::string world, output; bool faces = false; };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("export-mesh", "Write the rasterised quads as a PLY in world units");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("-o,--output", args->output, "Output .ply")->required();
    cmd->add_flag("--no-greedy", args->faces, "One quad per exposed voxel face");
    cmd->callback([args] {
        const std::filesystem::path out = args->output;
        if (out.extension() != ".ply") throw Error(out.string(), "output must end in .ply");
        requireOutputPath(out);
        const voxel::World world = voxel::World::load(args->world);
        const voxel::Mesh mesh = world.mesh({.greedy = !args->faces});
        voxel::writePly(mesh, out);
        std::printf("wrote %s (%zu quads)\n", out.c_str(), mesh.quads.size());
    });
}

}  // namespace grotto::app
