// grotto mkworld KIND -o FILE.vdb [--seed N] [--size N] [--voxel-size S] [--mesh FILE] [--lamps]
#include "app/commands.h"
#include "voxel/mkworld.h"

#include <cstdio>

namespace grotto::app {

void addMkworldCommand(CLI::App& app) {
    struct Args {
        std::string kind, output;
        voxel::GeneratorOptions options;
    };
    auto args = std::make_shared<Args>();
    std::string kinds;
    for (const std::string& k : voxel::worldKinds()) kinds += (kinds.empty() ? "" : ", ") + k;
    CLI::App* cmd = app.add_subcommand("mkworld", "Generate a deterministic world (" + kinds + ")");
    cmd->add_option("kind", args->kind, "One of: " + kinds)->required();
    cmd->add_option("-o,--output", args->output, "Output .vdb")->required();
    cmd->add_option("--seed", args->options.seed, "Random seed")->capture_default_str();
    cmd->add_option("--size", args->options.size, "Extent in voxels (0 = the kind's default)")->capture_default_str();
    cmd->add_option("--voxel-size", args->options.voxelSize, "World units per voxel")->capture_default_str();
    cmd->add_option("--mesh", args->options.meshFile, "mesh: the OBJ or PLY to voxelise");
    cmd->add_flag("--lamps", args->options.lamps, "houses: a lamp (material 6) on each room's ceiling");
    cmd->callback([args] {
        voxel::makeWorldFile(args->kind, args->options, args->output);
        std::printf("wrote %s\n", args->output.c_str());
    });
}

}  // namespace grotto::app
