// Embedding Grotto: load a world, walk the first frames of one of its camera paths
// with temporal GTAO accumulating, and write the last frame as a PNG. The same
// calls a game prototype makes each frame, without the grotto command line.
//   walk_path WORLD.json PATH FRAMES OUT.png
#include "common/error.h"
#include "engine/ao_settings.h"
#include "engine/camera_path.h"
#include "engine/image_output.h"
#include "engine/renderer.h"
#include "engine/scene/scene.h"
#include "voxel/world.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s WORLD.json PATH FRAMES OUT.png\n", argv[0]);
        return 2;
    }
    try {
        using namespace grotto;
        const voxel::World world = voxel::World::load(argv[1]);
        const auto path = world.desc().paths.find(argv[2]);
        if (path == world.desc().paths.end()) throw Error(argv[1], std::string("has no path named ") + argv[2]);
        const uint32_t width = 320, height = 180;
        const CameraPath walk(path->second, world.camera("", double(width) / height));
        const int frames = std::atoi(argv[3]);
        if (frames < 1) throw Error(argv[3], "is not a frame count", "give a whole number >= 1");
        const double fps = 24.0;

        vk::Context ctx;  // lavapipe unless GROTTO_DEVICE names another; GROTTO_VALIDATION=1 checks every call
        const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), world.desc().source.string());
        {
            const auto scene = uploadScene(ctx, world.mesh(), world.desc());
            Renderer renderer(ctx, *scene, world.desc().lighting, ao, width, height);
            Camera camera;
            for (int i = 0; i < frames; ++i) {
                camera = walk.camera(i / fps, width, height);
                renderer.render(camera, uint32_t(i));  // consecutive indices: the history accumulates
            }
            writeFrame(argv[4], renderer.readback(camera, false), camera, false);
        }
        if (ctx.validationMessages() > 0) {
            std::fprintf(stderr, "walk_path: %d validation messages\n", ctx.validationMessages());
            return 1;
        }
        std::printf("wrote %s: frame %d of path '%s' on %s\n", argv[4], frames, argv[2], ctx.deviceName().c_str());
        return 0;
    } catch (const grotto::Error& e) {
        std::fprintf(stderr, "walk_path: error: %s\n", e.what());
        return e.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "walk_path: internal error: %s\n", e.what());
        return 1;
    }
}
