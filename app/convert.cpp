// grotto convert MODEL.vox -o MODEL.vdb: a MagicaVoxel model as an OpenVDB grid
// and a world file beside it whose materials are the model's palette.
#include "app/commands.h"
#include "common/file_kind.h"
#include "common/plural.h"
#include "grotto/error.h"
#include "voxel/world.h"

#include <cstdio>

namespace grotto::app {

void addConvertCommand(CLI::App& app) {
    struct Args { std::string input, output; };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("convert", "Write a MagicaVoxel .vox model as a .vdb grid and a world .json");
    cmd->add_option("model", args->input, "MagicaVoxel .vox model")->required();
    cmd->add_option("-o,--output", args->output, "Output .vdb (the world file goes beside it as .json)")->required();
    cmd->callback([args] {
        const std::filesystem::path in = args->input, out = args->output;
        if (lowerExtension(in) != ".vox") throw Error(in.string(), "convert reads MagicaVoxel .vox models", "give a .vox file");
        if (out.extension() != ".vdb") throw Error(out.string(), "output must end in .vdb", "the world file goes beside it as .json");
        const voxel::World world = voxel::World::load(in);
        const voxel::World::SavedFiles saved = world.save(out);
        std::printf("wrote %s and %s (%s, %s)\n", saved.grid.c_str(), saved.world.c_str(),
                    counted(world.stats().solidVoxels, "voxel").c_str(), counted(world.desc().materials.size(), "material").c_str());
    });
}

}  // namespace grotto::app
