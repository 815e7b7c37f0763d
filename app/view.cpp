// grotto view: the interactive window (app/viewer/viewer.h).
#include "app/commands.h"
#include "app/options.h"
#include "app/viewer/viewer.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "engine/image_output.h"

#include <memory>

namespace grotto::app {

void addViewCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("view", "Open a window onto a world: fly, tune AO and lighting, take screenshots");
    struct Args {
        viewer::ViewOptions o;
        std::string size = "1280x720";
        std::string script, screenshot, capture;
        uint32_t frames = 0;
        bool noVsync = false;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("world", args->o.world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->o.camera, "Named camera to start from (default: the world's default)");
    cmd->add_option("--size", args->size, "Window size WxH")->capture_default_str();
    cmd->add_flag("--no-vsync", args->noVsync, "Present as fast as frames come, not at the display's rate");
    cmd->add_option("--script", args->script, "Timed key, mouse and panel actions (JSON; docs/viewer.md)");
    cmd->add_option("--frames", args->frames, "Exit after this many frames")->check(wholeRange(1, 1000000));
    cmd->add_option("--screenshot", args->screenshot, "At exit, write what the view shows (.png; .exr: the scene-linear colour and every AOV)");
    cmd->add_option("--capture-window", args->capture, "At the last of --frames, write the window as shown, panel included (.png)");
    cmd->add_flag("--hide-panel", args->o.hidePanel, "Start with the panel hidden (Tab toggles it)");
    cmd->add_option("--render-scale", args->o.renderScale,
                    "Frame pixels per window pixel, 0.25 to 1: render smaller, scaled up to the window")
        ->capture_default_str()->check(finiteRange(0.25, 1.0));
    cmd->add_flag("--bench", args->o.bench, "Print the median frame time and fps at exit");
    addAoFlags(cmd, args->o.ao);
    cmd->callback([args] {
        viewer::ViewOptions o = args->o;
        o.size = parseSize(args->size);
        o.vsync = !args->noVsync;
        if (!args->script.empty()) o.script = args->script;
        if (args->frames) o.frames = args->frames;
        if (!args->screenshot.empty()) {
            imageFormatFor(args->screenshot);
            requireOutputPath(args->screenshot);
            o.screenshot = args->screenshot;
        }
        if (!args->capture.empty()) {
            if (imageFormatFor(args->capture) != ImageFormat::Png)
                throw Error(args->capture, "--capture-window writes a .png", "the window holds 8-bit colour");
            if (!o.frames) throw Error("--capture-window", "needs --frames", "the window is captured at the last frame");
            requireOutputPath(args->capture);
            o.captureWindow = args->capture;
        }
        viewer::runViewer(o);
    });
}

}  // namespace grotto::app
