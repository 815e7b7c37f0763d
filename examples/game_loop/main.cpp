// A game loop embedding Grotto on the game's own Vulkan device: build a world in
// memory and add a crate, then for 120 frames dig a tunnel into the hill while the
// crate slides and turns in front of it and the camera follows the digging, with
// two frames in flight, the game copying each frame's display image with its own
// commands (as a game compositing it would). At the end, write the last frame and
// measure how much of the game's CPU work overlaps Grotto's frames.
//   game_loop OUT.png
#include "frame_reader.h"
#include "vulkan_device.h"

#include <grotto/grotto.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <vector>

namespace {

constexpr int kFrames = 120;
constexpr glm::ivec3 kSize{96, 40, 96};

// Grass ground with a rock hill on it, as a game's generator would make it.
grotto::VoxelGrid buildWorld() {
    grotto::VoxelGrid grid{.size = kSize, .materials = std::vector<uint8_t>(size_t(kSize.x) * kSize.y * kSize.z, 0)};
    for (int z = 0; z < kSize.z; ++z)
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                const bool ground = y < 6, hill = x >= 28 && x < 72 && z >= 24 && z < 64 && y < 30 - std::abs(x - 50) / 3;
                // The default palette: 1 stone, 2 grass.
                grid.materials[(size_t(z) * kSize.y + y) * kSize.x + x] = ground ? 2 : hill ? 1 : 0;
            }
    return grid;
}

// A crate: an object the game adds and moves itself, turning about its base's centre.
grotto::Object crate() {
    return {.name = "crate", .voxels = {.size = {4, 4, 4}, .materials = std::vector<uint8_t>(64, 4)},  // 4: brick
            .pivot = {2.0, 0.0, 2.0}};
}

// The game's own CPU work of a frame (simulation, AI, audio...): a fixed amount
// of arithmetic, so it takes longer when it competes for the CPU.
double gameWork(int units) {
    double x = 0.5;
    for (int i = 0; i < units * 100000; ++i) x = x * 3.7 * (1.0 - x);  // the logistic map: no shortcut
    return x;
}

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// How much of the game's CPU work hides behind Grotto's frames with two frames in
// flight: the same frames with the same work, rendered and waited for (render())
// against submitted in flight (submit()), and the work alone.
void measureOverlap(grotto::Engine& engine, int frames, int units) {
    volatile double sink = 0.0;  // the work's result is used: it cannot be optimised away
    auto run = [&](int mode) {  // 0: work alone, 1: work + render(), 2: work + submit()
        const Clock::time_point start = Clock::now();
        for (int i = 0; i < frames; ++i) {
            sink = sink + gameWork(units);
            if (mode == 1) engine.render();
            if (mode == 2) engine.submit();
        }
        if (mode == 2) engine.readPixels();  // waits for the last frame
        return secondsSince(start);
    };
    run(2);  // warm: pipelines, targets
    const double work = run(0), serial = run(1), inFlight = run(2);
    std::printf("overlap: %d frames, game work %.1f ms/frame, render() + work %.1f ms/frame, submit() + work %.1f "
                "ms/frame: %.0f%% of the game's work hidden behind Grotto's frames\n",
                frames, 1e3 * work / frames, 1e3 * serial / frames, 1e3 * inFlight / frames,
                100.0 * (serial - inFlight) / work);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    try {
        GameDevice game;
        uint64_t carved = 0;
        {
            grotto::Engine engine(game.handles(), {.width = 320, .height = 180});
            engine.setWorld(buildWorld());
            engine.addObject(crate());
            FrameReader reader(game, {320, 180});
            grotto::RenderedFrame frame;
            for (int i = 0; i < kFrames; ++i) {
                // The digging head moves into the hill's side at z = 63, one sphere a frame.
                const double t = double(i) / (kFrames - 1);
                const glm::dvec3 head(50.0, 11.0, 66.0 - 24.0 * t);
                carved += engine.edit(grotto::Edit::carveSphere(head, 3.0)).changed;
                // The crate slides across the tunnel's mouth on the grass, turning as it goes.
                engine.setObjectPose(0, glm::dvec3(40.0 + 20.0 * t, 6.0, 70.0),
                                     glm::angleAxis(3.0 * t, glm::dvec3(0.0, 1.0, 0.0)));
                // The camera stands back outside the hill, looking into the tunnel.
                engine.setCamera({.position = glm::dvec3(58.0, 16.0, 92.0), .target = head, .fovDegrees = 50.0});
                // Two frames in flight: this one is submitted without waiting, and the
                // game's copy of its display image follows it on the queue, before the next.
                frame = engine.submit();
                reader.read(frame, i % 2);
            }
            // The game's last copy is Grotto's last frame through the tone map, and its
            // own copy of the colour image is the frame Grotto reads back.
            const std::vector<uint16_t> shown = reader.pixels((kFrames - 1) % 2);
            const grotto::Pixels pixels = engine.readPixels();
            if (reader.copyNow(frame.color) != pixels.rgba)
                throw std::runtime_error("the colour image copied by the game differs from Grotto's readback");
            size_t lit = 0;
            for (size_t k = 0; k < shown.size(); k += 4) lit += shown[k] != 0;
            if (lit < shown.size() / 8) throw std::runtime_error("the game's copy of the display image is dark");
            engine.saveFrame(argv[1]);
            std::printf("wrote %s: frame %d on %s, %llu voxels dug, %llu quads drawn\n", argv[1], kFrames,
                        game.name().c_str(), (unsigned long long)carved, (unsigned long long)frame.quadsDrawn);
            measureOverlap(engine, 24, 40);
        }
        if (game.validationMessages() > 0) {
            std::fprintf(stderr, "game_loop: %d validation messages\n", game.validationMessages());
            return 1;
        }
        return carved > 0 ? 0 : 1;
    } catch (const grotto::Error& e) {
        std::fprintf(stderr, "game_loop: error: %s\n", e.what());
        return e.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "game_loop: %s\n", e.what());
        return 1;
    }
}
