// The viewer's loop: input, the session's frame, the panel and the present; the
// settings and size changes the loop applies between frames.
#include "app/viewer/viewer_internal.h"

#include "app/options.h"
#include "app/viewer/settings_patch.h"
#include "grotto/error.h"
#include "common/printable.h"
#include "engine/image_output.h"
#include "engine/session_setup.h"
#include "voxel/world.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace grotto::viewer {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kScriptStep = 1.0 / 60.0;  // seconds a scripted frame advances: runs are reproducible
constexpr size_t kGraphFrames = 120;

}  // namespace

Viewer::Viewer(const ViewOptions& o)
    : options_(o),
      script_(o.script ? std::optional<ViewScript>(ViewScript::load(*o.script)) : std::nullopt),
      loaded_(app::loadWorld(o.world, o.ao)),
      desc_(loaded_.desc()),
      window_("grotto view - " + o.world.filename().string(), o.size.width, o.size.height),
      imgui_(window_.handle),
      ctx_(contextOptions(window_)) {
    // Command-line AO flags, as every command takes them, over the world's: kept
    // in desc_ too, so the panel, scripts and a saved world start from them.
    const AoOptions ao = app::resolveAo(loaded_, o.ao);
    desc_.ao = app::aoDescWithFlags(loaded_.desc().ao, o.ao);
    aoOptions_ = ao;
    desc_.detail = app::resolveDetail(loaded_, o.ao);
    renderScale_ = o.renderScale;
    renderSize_ = scaled(window_.framebufferSize());
    session_ = openSession(ctx_, std::move(loaded_),
                           {.ao = ao, .detail = desc_.detail, .width = renderSize_.width, .height = renderSize_.height},
                           "image size");
    // The viewer never waits for a bake: without --bake the GPU traces the faces
    // in view as frames go, now and whenever the cache is needed anew.
    readyFaceCache(*session_, {.bake = o.ao.bake, .progressive = true});
    renderer().setDisplayImage(true);  // the final view: the colour through the tone map
    const voxel::World& world = session_->world();
    presenter_ = std::make_unique<Presenter>(ctx_, window_.framebufferSize(), o.vsync);
    const voxel::CameraDesc start = world.camera(o.camera, aspect());
    const voxel::IndexBox b = world.bounds();
    const double extent = b.empty() ? 10.0 : glm::length(glm::dvec3(b.max - b.min + 1)) * world.voxelSize();
    fly_ = std::make_unique<FlyCamera>(start, extent / 8.0);  // crosses the world in about 8 s
    for (const auto& [name, c] : desc_.cameras) panel_.cameras.push_back(name);
    for (const auto& [name, p] : desc_.paths) panel_.paths.push_back(name);
    panel_.quads = session_->scene().gpu().quadCount;
    panel_.activeVoxels = world.stats().solidVoxels;
    panel_.saveWorldAs = (o.world.parent_path() / (o.world.stem().string() + "-edited.json")).string();
    panel_.savePathAs = (o.world.parent_path() / (o.world.stem().string() + "-recorded.json")).string();
    panel_.hidden = o.hidePanel;
    panel_.renderScale = o.renderScale;
}

Viewer::~Viewer() {
    vk::destroy(ctx_, shown_);
    presenter_.reset();
    session_.reset();
}

void Viewer::run() {
    std::vector<double> frameMs, renderMs, presentMs;
    while (!window_.shouldClose() && (!options_.frames || frame_ < *options_.frames)) {
        const auto start = Clock::now();
        window_.poll();
        applyScript();
        resizeIfNeeded();
        const double dt = script_ ? kScriptStep : std::min(lastFrameSeconds_, 0.25);
        flyFromInput(dt);
        const View view = nextView(dt);
        lastCamera_ = view.camera;
        const VkExtent2D fb = window_.framebufferSize();
        if (fb.width == 0 || fb.height == 0) {  // minimised: nothing to show, so nothing to render
            glfwWaitEventsTimeout(script_ ? 0.0 : 0.05);
            ++frame_;
            continue;
        }
        // The world's full light, baked on its own thread (no --bake): a script's
        // frames wait for it, so that they do not depend on how fast it ran.
        if (script_) session_->waitForLight();
        session_->catchUp();
        const LiveFaceCache* cache = session_->scene().faceCache();
        panel_.lightBaked = cache ? cache->lightBaked() : 1.0;
        if (cache && cache->lightError() && panel_.message.empty())
            panel_.message = std::string("full light: ") + cache->lightError()->what();
        const auto beforeRender = Clock::now();
        panel_.stats = renderer().render(view.camera, view.index);
        const auto afterRender = Clock::now();
        if (panel_.view != "final" || pendingShot_) readback(view.camera);
        ImDrawData* ui = drawUi();
        presenter_->present(panel_.view == "final" ? renderer().displayImage() : shown_, ui,
                            wantWindowCapture() ? &windowPixels_ : nullptr);
        const auto end = Clock::now();
        lastFrameSeconds_ = std::chrono::duration<double>(end - start).count();
        frameMs.push_back(lastFrameSeconds_ * 1e3);
        renderMs.push_back(std::chrono::duration<double, std::milli>(afterRender - beforeRender).count());
        presentMs.push_back(std::chrono::duration<double, std::milli>(end - afterRender).count());
        panel_.frameMs.push_back(float(lastFrameSeconds_ * 1e3));
        if (panel_.frameMs.size() > kGraphFrames) panel_.frameMs.pop_front();
        ++frame_;
    }
    if (options_.screenshot) screenshot(*options_.screenshot);
    if (options_.captureWindow) {
        if (windowPixels_.empty()) throw Error("--capture-window", "no frame was shown to capture", "give --frames 1 or more");
        const VkExtent2D e = presenter_->extent();
        writeSrgb8(*options_.captureWindow, e.width, e.height, windowPixels_);
        std::printf("wrote %s (%ux%u, the window as shown)\n", printable(options_.captureWindow->string()).c_str(),
                    e.width, e.height);
    }
    if (options_.bench) printBench(frameMs, renderMs, presentMs);
    app::requireNoValidationMessages(ctx_);
}

vk::ContextOptions Viewer::contextOptions(const Window& w) {
    vk::ContextOptions o;
    o.instanceExtensions = w.vulkanExtensions();
    o.createSurface = [&w](VkInstance instance) { return w.createSurface(instance); };
    return o;
}

bool Viewer::wantWindowCapture() const { return options_.captureWindow && options_.frames && frame_ + 1 == *options_.frames; }

// A camera cut or new settings: the history and the noise sequence start again,
// so a still after it matches `render` of the same camera frame for frame.
void Viewer::cut() {
    renderer().resetHistory();
    sequence_ = 0;
}

void Viewer::jumpTo(const std::string& name) {
    fly_->jumpTo(session_->world().camera(name, aspect()));
    cut();
}

void Viewer::applyPatch(const voxel::json& patch, const std::filesystem::path& file, const std::string& field) {
    voxel::WorldDesc d = desc_;
    const AoOptions ao = applyViewerPatch(d, patch, session_->world().voxelSize(), file, field);
    if (patch.contains("lighting")) renderer().setLighting(d.lighting);
    if (patch.contains("ao")) renderer().setAo(ao);
    if (patch.contains("detail")) renderer().setCulling(cullingOptions(d.detail));
    desc_ = std::move(d);
    aoOptions_ = ao;
    cut();
}

// The frame's size for a window of `fb` pixels at the render scale.
VkExtent2D Viewer::scaled(VkExtent2D fb) const {
    return {std::max(uint32_t(std::lround(fb.width * renderScale_)), 1u),
            std::max(uint32_t(std::lround(fb.height * renderScale_)), 1u)};
}

void Viewer::resizeIfNeeded() {
    const VkExtent2D fb = window_.framebufferSize();
    if (fb.width != presented_.width || fb.height != presented_.height) {
        presented_ = fb;
        presenter_->resize(fb);
    }
    if (fb.width == 0 || fb.height == 0) return;  // minimised: keep rendering at the last size
    const VkExtent2D size = scaled(fb);
    if (size.width != renderSize_.width || size.height != renderSize_.height) {
        renderSize_ = size;
        renderer().resize(size.width, size.height);
        sequence_ = 0;
    }
}

// The window system applies size changes asynchronously: give it a moment.
void Viewer::waitForSize() {
    for (int i = 0; i < 20; ++i) {
        glfwWaitEventsTimeout(0.01);
        window_.poll();
    }
}

ImDrawData* Viewer::drawUi() {
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!panel_.hidden) {
        panel_.desc = &desc_;
        panel_.ao = &aoOptions_;
        const voxel::json patch = drawPanel(panel_);
        try {
            if (!patch.empty()) applyPatch(patch, "panel", "panel");
        } catch (const Error& e) {
            panel_.message = e.what();
        }
        if (!panel_.jumpTo.empty()) jumpTo(std::exchange(panel_.jumpTo, ""));
        if (!panel_.play.empty()) playPath(std::exchange(panel_.play, ""));
        if (std::exchange(panel_.screenshot, false)) pendingShot_ = nextShotName();
        try {
            if (panel_.renderScale != renderScale_) renderScale_ = panel_.renderScale;
            if (std::exchange(panel_.undo, false)) undo();
            if (std::exchange(panel_.saveWorld, false)) saveWorld(panel_.saveWorldAs);
            if (std::exchange(panel_.record, false)) recordKey();
            if (std::exchange(panel_.savePath, false)) savePath(panel_.savePathAs);
        } catch (const Error& e) {
            panel_.message = e.what();
        }
    }
    ImGui::Render();
    return ImGui::GetDrawData();
}

void Viewer::printBench(const std::vector<double>& frameMs, const std::vector<double>& renderMs,
                        const std::vector<double>& presentMs) const {
    // The first frames compile pipelines and fill caches.
    const size_t skip = std::min<size_t>(frameMs.size() / 4, 10);
    auto med = [&](const std::vector<double>& v) { return app::median(std::vector<double>(v.begin() + long(skip), v.end())); };
    const double frame = med(frameMs);
    std::printf("view bench: %s, %ux%u, %zu frames (median after %zu warm-up)\n", options_.world.c_str(),
                renderSize_.width, renderSize_.height, frameMs.size() - skip, skip);
    std::printf("  frame %.2f ms (%.1f fps): render %.2f ms, panel + present %.2f ms\n", frame,
                frame > 0 ? 1000.0 / frame : 0.0, med(renderMs), med(presentMs));
}

void runViewer(const ViewOptions& options) {
    Viewer viewer(options);
    viewer.run();
}

}  // namespace grotto::viewer
