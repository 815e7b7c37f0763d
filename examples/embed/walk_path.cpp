// Embedding Grotto: load a world, walk the first frames of one of its camera paths
// with temporal GTAO accumulating (the path's edits and moving objects included),
// and write the last frame as a PNG: what `grotto flythrough` renders, through the
// public API alone.
//   walk_path WORLD.json PATH FRAMES OUT.png
#include <grotto/grotto.h>

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
        const int frames = std::atoi(argv[3]);
        if (frames < 1) throw grotto::Error(argv[3], "is not a frame count", "give a whole number >= 1");
        const double fps = 24.0;
        // Grotto's own device: lavapipe unless GROTTO_DEVICE names another; GROTTO_VALIDATION=1 checks every call.
        grotto::Engine engine({.width = 320, .height = 180});
        engine.loadWorld(argv[1]);
        engine.playPath(argv[2]);
        for (int i = 0; i < frames; ++i) engine.renderPath(i / fps);
        engine.saveFrame(argv[4]);
        if (engine.validationMessages() > 0) {
            std::fprintf(stderr, "walk_path: %d validation messages\n", engine.validationMessages());
            return 1;
        }
        std::printf("wrote %s: frame %d of path '%s' on %s\n", argv[4], frames, argv[2], engine.deviceName().c_str());
        return 0;
    } catch (const grotto::Error& e) {
        std::fprintf(stderr, "walk_path: error: %s\n", e.what());
        return e.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "walk_path: internal error: %s\n", e.what());
        return 1;
    }
}
