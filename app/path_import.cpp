// grotto path import SHOT.glb -o SHOT.json: a glTF camera animation as a path file.
#include "app/commands.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/gltf/gltf_camera.h"
#include "voxel/world_json.h"

#include <cstdio>

namespace grotto::app {

void addPathCommand(CLI::App& app) {
    struct Args {
        std::string input, output;
        voxel::GltfCameraChoice choice;
    };
    auto args = std::make_shared<Args>();
    CLI::App* path = app.add_subcommand("path", "Camera path files");
    path->require_subcommand(1);
    CLI::App* cmd = path->add_subcommand("import", "Write a glTF file's animated camera as a path .json (docs/paths.md)");
    cmd->add_option("file", args->input, "glTF .glb or .gltf with an animated camera")->required();
    cmd->add_option("-o,--output", args->output, "Output path .json")->required();
    cmd->add_option("--camera", args->choice.camera, "The camera's node or camera name (default: the first animated one)");
    cmd->add_option("--animation", args->choice.animation, "The animation's name (default: the first that moves the camera)");
    cmd->callback([args] {
        const std::filesystem::path out = args->output;
        if (out.extension() != ".json") throw Error(out.string(), "output must end in .json", "a path file");
        requireOutputPath(out);
        const voxel::GltfCameraAnimation camera(args->input, args->choice);
        const voxel::CameraPathDesc desc = camera.path();
        writeAtomically(out, voxel::cameraPathJson(desc).dump(2) + "\n");
        std::printf("wrote %s (%zu keys from %zu key times, %.3f s, fov %.2f)\n", out.c_str(), desc.keys.size(),
                    camera.keyTimes().size(), desc.keys.back().time, camera.fovDegrees());
    });
}

}  // namespace grotto::app
