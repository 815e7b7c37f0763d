#pragma once
// `grotto view`: a window onto a world. Fly, flip AO and lighting settings live,
// look at the AO chain's buffers, take screenshots; scripted runs for tests.
#include "app/options.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace grotto::viewer {

struct ViewOptions {
    std::filesystem::path world;
    std::string camera;                 // empty: the world's default
    app::Size size{1280, 720};
    bool vsync = true;
    app::AoFlags ao;
    std::optional<std::filesystem::path> script;      // timed actions (view_script.h)
    std::optional<uint32_t> frames;                   // exit after this many frames
    std::optional<std::filesystem::path> screenshot;  // at exit, as `render` writes it
    std::optional<std::filesystem::path> captureWindow;  // at exit, the window as shown, panel included
    bool hidePanel = false;
    double renderScale = 1.0;           // frame pixels per window pixel, 0.25 to 1 (the blit scales it up)
    bool bench = false;                 // time frames, print fps
};

// Runs until the window closes or `frames` have been shown; throws grotto::Error.
void runViewer(const ViewOptions& options);

}  // namespace grotto::viewer
